/* Expressions checked before libmatheval: see matheval_internal.h. */
#include "matheval_internal.h"
#include "nl_error.h"

#include <matheval.h>
#include <stdio.h>
#include <string.h>

static int allowed(unsigned char c)
{
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
           (c && strchr("_.+-*/^() \t", c));
}

size_t nl_matheval_bad_char(const char *text)
{
    size_t i = 0;
    while (text[i] && allowed((unsigned char)text[i]))
        i++;
    return i;
}

/* `text` with every byte outside printable ASCII written \xHH (at most
 * `size` - 1 bytes, cut with "..."), so that a message stays one line. */
static void escape(const char *text, char *buf, size_t size)
{
    size_t o = 0;
    for (const unsigned char *p = (const unsigned char *)text; *p; p++) {
        char one[8];
        int k = *p >= 0x20 && *p < 0x7f ? snprintf(one, sizeof one, "%c", *p) : snprintf(one, sizeof one, "\\x%02x", *p);
        if (o + (size_t)k + 4 > size) {
            memcpy(buf + o, "...", 4);
            return;
        }
        memcpy(buf + o, one, (size_t)k);
        o += (size_t)k;
    }
    buf[o] = 0;
}

int nl_matheval_create(const char *what, const char *text, void **out)
{
    size_t at = nl_matheval_bad_char(text);
    char shown[160], c[8];
    *out = NULL;
    escape(text, shown, sizeof shown);
    if (text[at]) {
        unsigned char b = (unsigned char)text[at];
        if (b > 0x20 && b < 0x7f)
            snprintf(c, sizeof c, "'%c'", b);
        else
            snprintf(c, sizeof c, "\\x%02x", b);
        return NL_ERROR(NL_EINVAL, "%s: unexpected character %s at position %zu of \"%s\"; expected " NL_MATHEVAL_CHARS,
                        what, c, at + 1, shown);
    }
    if (!(*out = evaluator_create((char *)text)))
        return NL_ERROR(NL_EINVAL, "%s: malformed expression \"%s\"", what, shown);
    return NL_OK;
}
