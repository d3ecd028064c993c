/* The per-thread last error message. */
#include "nl_error.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static _Thread_local char msg[NL_ERRMSG_MAX];
static _Thread_local char where[128];

/* The bytes kept from the start of a message too long for msg: the rest
 * is its end, where the reason usually stands ("SPEC: why; expected"). */
enum { HEAD = 1024 };

/* A message longer than msg: its first HEAD bytes, a marker, and its end. */
static void elide(const char *fmt, va_list ap, size_t n)
{
    char *full = malloc(n + 1), mark[64];
    size_t m, tail;
    if (!full)
        return; /* msg keeps vsnprintf's truncation */
    vsnprintf(full, n + 1, fmt, ap);
    m = (size_t)snprintf(mark, sizeof mark, " [... %zu bytes left out ...] ", n);
    tail = sizeof msg - 1 - HEAD - m;
    memcpy(msg, full, HEAD);
    memcpy(msg + HEAD, mark, m);
    memcpy(msg + HEAD + m, full + strlen(full) - tail, tail);
    msg[HEAD + m + tail] = '\0';
    free(full);
}

int nl_error_set(int code, const char *file, int line, const char *fmt, ...)
{
    va_list ap, again;
    int n;
    va_start(ap, fmt);
    va_copy(again, ap);
    n = vsnprintf(msg, sizeof msg, fmt, ap);
    if (n > 0 && (size_t)n >= sizeof msg)
        elide(fmt, again, (size_t)n);
    va_end(again);
    va_end(ap);
    snprintf(where, sizeof where, "%s:%d", file, line);
    return code;
}

const char *nl_errmsg(void) { return msg; }

const char *nl_errwhere(void) { return where; }

int nl_error_is_input(int code)
{
    return code == NL_EINVAL || code == NL_EINPUT || code == NL_ETOOBIG || code == NL_ENOTPD;
}
