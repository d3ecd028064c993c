/* Text for help and messages made from the registries: a paragraph filled
 * to a width. */
#include "cli.h"

#include <string.h>

void cli_fill(FILE *f, const char *text, int width)
{
    const char *p = text;
    int col = 0;
    while (*p) {
        size_t len = strcspn(p, " ");
        if (col > 0 && col + 1 + (int)len > width) {
            fputc('\n', f);
            col = 0;
        } else if (col > 0) {
            fputc(' ', f);
            col++;
        }
        fwrite(p, 1, len, f);
        col += (int)len;
        p += len;
        if (*p == ' ')
            p++;
    }
    fputc('\n', f);
}
