/* An n-D field: a grid of doubles in 1, 2 or 3 dimensions.
 *
 * Layout is row-major with x fastest: sample (i, j, k) (x, y, z index) is
 * data[(k * n[1] + j) * n[0] + i].  Axes beyond `dim` have n = 1 and h = 1.
 * h[a] is the grid spacing along axis a, so the lag between samples i and
 * i + m along x is m * h[0] (lags are always lengths: index times spacing).
 *
 * Thread safety: every function here is thread-safe; a field itself is
 * plain memory (concurrent reads are fine, writes need the caller's care). */
#ifndef NL_FIELD_H
#define NL_FIELD_H

#ifdef __cplusplus
extern "C" {
#endif

#include <stddef.h>

typedef struct {
    int dim;         /* 1, 2 or 3 */
    size_t n[3];     /* samples per axis (x, y, z); 1 beyond dim */
    double h[3];     /* grid spacing per axis; 1 beyond dim */
    size_t count;    /* n[0] * n[1] * n[2] */
    double *data;    /* count samples, row-major, x fastest; nl_alloc'ed (core/mem.h, 64-byte aligned) */
} nl_field;

/* Check that a grid of n[0..dim-1] samples of `elem` bytes each, times
 * `copies` arrays alive at once, neither overflows size_t nor exceeds the
 * memory available on this machine (nl_mem_available; 0, unknown, skips
 * that test).  Returns NL_OK (and the sample count in *count when count is
 * not NULL), NL_EINVAL (dim not 1..3, some n[a] = 0, or NOISELAB_MEMORY_LIMIT
 * set to a value that does not parse: nl_mem_limit) or NL_ETOOBIG (the
 * count or the bytes overflow size_t, or exceed the memory available). */
int nl_size_check(int dim, const size_t *n, size_t elem, size_t copies, size_t *count);

/* Allocate a zeroed field of dim 1..3 with n[a] >= 1 samples and spacing
 * h[a] > 0 (h may be NULL for unit spacing); n and h hold dim entries.
 * Returns the field (release it with nl_field_free), or NULL with the
 * message set and, when status is not NULL, *status = NL_EINVAL (dim, a zero
 * size or a spacing that is not positive), NL_ETOOBIG (nl_size_check) or
 * NL_ENOMEM (allocation failed); *status = NL_OK on success. */
nl_field *nl_field_alloc(int dim, const size_t *n, const double *h, int *status);

/* Release a field from nl_field_alloc or any reader; NULL is a no-op. */
void nl_field_free(nl_field *f);

/* Check every sample: NL_OK when each is finite and its magnitude at most
 * `limit` (INFINITY: finiteness only; FLT_MAX: representable in a float32
 * file); otherwise NL_EINVAL with a message naming the first bad sample
 * (its index, x, y, z and value).  *first (when not NULL) receives that
 * index, or f->count when every sample passes.  Reads f only; thread-safe. */
int nl_field_check_finite(const nl_field *f, double limit, size_t *first);

/* Bytes of memory available to this process now (MemAvailable, lowered by
 * the environment variable NOISELAB_MEMORY_LIMIT in bytes when set to a
 * positive integer; see nl_mem_limit), or 0 if unknown.  Reads /proc/meminfo on every call. */
size_t nl_mem_available(void);

#ifdef __cplusplus
}
#endif

#endif
