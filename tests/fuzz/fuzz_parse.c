/* libFuzzer targets for the parsers: FUZZ_TARGET selects one.
 *   model  nl_model_parse, then R at a few lags
 *   dist   nl_dist_parse, then its quantiles
 *   field  nl_field_read (EXR, PNG or TSV by content) from a temporary file */
#include "../../core/dist.h"
#include "../../core/io.h"
#include "../../core/model.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static char path[64];
    /* a file may declare any size: refuse beyond 512 MB, as a small machine would */
    setenv("NOISELAB_MEMORY_LIMIT", "536870912", 0);
#if FUZZ_TARGET == 1 || FUZZ_TARGET == 2
    char *s = malloc(size + 1);
    if (!s)
        return 0;
    memcpy(s, data, size);
    s[size] = 0;
#if FUZZ_TARGET == 1
    nl_model *m;
    if (nl_model_parse(s, &m) == 0) {
        for (int d = 1; d <= 3; d++) {
            double lag[3] = {0.37, -1.2, 2.0};
            if (nl_model_check_dim(m, d) == 0 && !nl_model_is_spectral(m))
                (void)nl_model_acf(m, d, lag);
        }
        nl_model_free(m);
    }
#else
    nl_dist *d;
    if (nl_dist_parse(s, &d) == 0) {
        for (double u = 0.01; u < 1; u += 0.2)
            (void)nl_dist_quantile(d, u);
        nl_dist_free(d);
    }
#endif
    free(s);
#else
    if (!path[0]) {
        snprintf(path, sizeof path, "/tmp/noiselab-fuzz-%ld", (long)getpid());
    }
    FILE *fp = fopen(path, "wb");
    if (!fp)
        return 0;
    fwrite(data, 1, size, fp);
    fclose(fp);
    nl_field *f;
    nl_meta meta;
    if (nl_field_read(path, &f, &meta) == 0)
        nl_field_free(f);
#endif
    return 0;
}
