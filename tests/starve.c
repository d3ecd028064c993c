/* Allocation failure on demand (see starve.h). */
#include "starve.h"

#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/resource.h>
#include <unistd.h>

#if defined(__SANITIZE_ADDRESS__)
#define NL_TEST_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define NL_TEST_ASAN 1
#endif
#endif

static void *hoard;          /* singly linked list through the blocks */
static struct rlimit saved;  /* the limit before starve_begin */

int starve_begin(void) { return starve_begin_leaving(0); }

int starve_begin_leaving(size_t bytes)
{
#ifdef NL_TEST_ASAN
    return 0;
#else
    long pages = 0;
    FILE *fp = fopen("/proc/self/statm", "r");
    if (!fp || fscanf(fp, "%ld", &pages) != 1 || pages <= 0) {
        if (fp)
            fclose(fp);
        return 0;
    }
    fclose(fp);
    void *reserve = bytes ? malloc(bytes) : NULL;
    getrlimit(RLIMIT_AS, &saved);
    struct rlimit r = saved;
    r.rlim_cur = (rlim_t)pages * (rlim_t)sysconf(_SC_PAGESIZE);
    if (setrlimit(RLIMIT_AS, &r))
        return 0;
    /* take the free heap, largest blocks first */
    for (size_t sz = (size_t)1 << 24; sz >= sizeof(void *); sz /= 2) {
        void **p;
        while ((p = malloc(sz)))
            *p = hoard, hoard = p;
    }
    free(reserve);
    return 1;
#endif
}

void starve_end(void)
{
    while (hoard) {
        void *next = *(void **)hoard;
        free(hoard);
        hoard = next;
    }
    setrlimit(RLIMIT_AS, &saved);
}
