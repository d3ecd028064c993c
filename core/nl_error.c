/* The per-thread last error message. */
#include "nl_error.h"

#include <stdarg.h>
#include <stdio.h>

static _Thread_local char msg[512];
static _Thread_local char where[128];

int nl_error_set(int code, const char *file, int line, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
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
