/* Allocation of large numeric arrays.
 *
 * Arrays of fields and FFT buffers are touched once per sample right after
 * allocation; on this kind of machine every 4 KiB page fault is expensive
 * (a third of a 2048^2 circulant synthesis was spent in them).  Blocks of
 * 8 MiB and more are aligned to 2 MiB and advised for transparent huge
 * pages (madvise(MADV_HUGEPAGE); a no-op where the kernel does not do
 * them), which cuts the faults 512-fold.  Every block is at least 64-byte
 * aligned, as FFTW's SIMD code wants. */
#ifndef NL_MEM_H
#define NL_MEM_H

#ifdef __cplusplus
extern "C" {
#endif

#include <stddef.h>

/* An uninitialised block of `bytes` (NULL when out of memory; bytes = 0
 * gives a valid 1-byte block), released by nl_free (not by fftw_free).
 * No status and no message: callers raise NL_ENOMEM.  Thread-safe. */
void *nl_alloc(size_t bytes);

/* Free a block from nl_alloc (NULL is a no-op).  Thread-safe. */
void nl_free(void *p);

/* The limit set by NOISELAB_MEMORY_LIMIT: a positive whole number of bytes
 * (decimal digits only) in *bytes, 0 when the variable is not set.
 * NL_EINVAL, naming the variable and its value, when it is set to anything
 * else (empty, signed, fractional, with a unit, 0, beyond SIZE_MAX): a limit
 * that does not parse is refused, not ignored.  Thread-safe as long as no
 * thread changes the environment. */
int nl_mem_limit(size_t *bytes);

#ifdef __cplusplus
}
#endif

#endif
