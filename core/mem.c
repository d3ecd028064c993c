/* Large aligned blocks with transparent huge pages advised. */
#include "mem.h"

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
