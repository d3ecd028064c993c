/* Text for help and messages made from the registries: a paragraph filled
 * to a width. */
#include "cli.h"

#include <string.h>

void cli_fill_lead(FILE *f, const char *lead, const char *text, int width)
{
    const char *p = text;
    int indent = (int)strlen(lead), col = indent;
    fputs(lead, f);
    while (*p) {
        size_t len = strcspn(p, " ");
        if (col > indent && col + 1 + (int)len > width) {
            fprintf(f, "\n%*s", indent, "");
            col = indent;
        } else if (col > indent) {
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

void cli_fill(FILE *f, const char *text, int width)
{
    cli_fill_lead(f, "", text, width);
}
