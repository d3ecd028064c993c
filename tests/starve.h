/* Allocation failure on demand, for the tests of NL_ENOMEM paths: the
 * address space is capped at its present size (RLIMIT_AS) and whatever the
 * heap has left is taken, so the next malloc (and mmap) of the code under
 * test fails.  Each Criterion test runs in its own process, so the cap
 * ends with the test; starve_end gives the memory back before asserting.
 * Under AddressSanitizer (which reserves its shadow memory up front and
 * aborts on allocation failure) starve_begin returns 0 and the test
 * should skip. */
#ifndef NL_TEST_STARVE_H
#define NL_TEST_STARVE_H

#include <stddef.h>

/* 1 when memory is now exhausted, 0 when this build cannot do it. */
int starve_begin(void);

/* The same, with a free block of `bytes` left for small allocations (of
 * libgomp, say) while larger ones fail. */
int starve_begin_leaving(size_t bytes);

/* Release the hoard and lift the cap. */
void starve_end(void);

#endif
