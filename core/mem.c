/* Large aligned blocks with transparent huge pages advised; the memory limit. */
#include "mem.h"
#include "nl_error.h"

#include <errno.h>

#include <stdint.h>
#include <stdlib.h>
#include <sys/mman.h>

enum { HUGE_PAGE = 2 << 20, HUGE_FROM = 4 * HUGE_PAGE, SIMD_ALIGN = 64 };

void *nl_alloc(size_t bytes)
{
    void *p = NULL;
    if (bytes >= HUGE_FROM) {
        size_t len = (bytes + HUGE_PAGE - 1) / HUGE_PAGE * HUGE_PAGE;
        if (len < bytes || posix_memalign(&p, HUGE_PAGE, len))
            return NULL;
        (void)madvise(p, len, MADV_HUGEPAGE);
        return p;
    }
    return posix_memalign(&p, SIMD_ALIGN, bytes ? bytes : 1) ? NULL : p;
}

void nl_free(void *p) { free(p); }

int nl_mem_limit(size_t *bytes)
{
    const char *s = getenv("NOISELAB_MEMORY_LIMIT");
    char *end;
    unsigned long long v;
    *bytes = 0;
    if (!s)
        return NL_OK;
    errno = 0;
    v = strtoull(s, &end, 10);
    /* digits only: no sign, space, fraction, exponent or unit */
    if (*s < '0' || *s > '9' || *end || v == 0)
        return NL_ERROR(NL_EINVAL, "NOISELAB_MEMORY_LIMIT: expected a positive whole number of bytes "
                                   "(e.g. 2000000000), got \"%.64s\"", s);
    if (errno == ERANGE || v > SIZE_MAX)
        return NL_ERROR(NL_EINVAL, "NOISELAB_MEMORY_LIMIT: expected at most %zu bytes, got \"%.64s\"", (size_t)SIZE_MAX,
                        s);
    *bytes = (size_t)v;
    return NL_OK;
}
