/* finite FILE...: exit 0 when every sample of every field file (EXR, PNG or
 * TSV, read by the library) is finite, 1 naming the first file that is not
 * or cannot be read.  Used by the catalogue of hostile inputs. */
#include "../../core/io.h"
#include "../../core/nl_error.h"

#include <math.h>
#include <stdio.h>

int main(int argc, char **argv)
{
    for (int i = 1; i < argc; i++) {
        nl_field *f = NULL;
        /* nl_field_read refuses non-finite samples with NL_EINPUT */
        if (nl_field_read(argv[i], &f, NULL)) {
            printf("%s: %s\n", argv[i], nl_errmsg());
            return 1;
        }
        for (size_t k = 0; k < f->count; k++)
            if (!isfinite(f->data[k])) {
                printf("%s: sample %zu is %g\n", argv[i], k, f->data[k]);
                nl_field_free(f);
                return 1;
            }
        nl_field_free(f);
    }
    return 0;
}
