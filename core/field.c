/* Allocation of n-D fields with the size checks done before allocating. */
#include "field.h"
#include "mem.h"
#include "nl_error.h"

#include <stdio.h>
#include <fftw3.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

size_t nl_mem_available(void)
{
    FILE *fp = fopen("/proc/meminfo", "r");
    char line[256];
    unsigned long long kb = 0;
    if (fp) {
        while (fgets(line, sizeof line, fp))
            if (sscanf(line, "MemAvailable: %llu kB", &kb) == 1)
                break;
        fclose(fp);
    }
    size_t avail = (size_t)(kb * 1024ULL);
    if (kb == 0) {
        long pages = sysconf(_SC_AVPHYS_PAGES), psize = sysconf(_SC_PAGESIZE);
        avail = pages > 0 && psize > 0 ? (size_t)pages * (size_t)psize : 0;
    }
    /* NOISELAB_MEMORY_LIMIT (bytes) lowers the ceiling, e.g. on shared machines */
    size_t lim; /* a malformed limit is refused by nl_size_check */
    if (nl_mem_limit(&lim) == NL_OK && lim && (avail == 0 || lim < avail))
        avail = lim;
    return avail;
}

int nl_size_check(int dim, const size_t *n, size_t elem, size_t copies, size_t *count)
{
    size_t c = 1, bytes, lim;
    int st = nl_mem_limit(&lim);
    if (st)
        return st;
    if (dim < 1 || dim > 3)
        return NL_ERROR(NL_EINVAL, "dimension: expected 1, 2 or 3, got %d", dim);
    for (int a = 0; a < dim; a++) {
        if (n[a] == 0)
            return NL_ERROR(NL_EINVAL, "size: expected at least 1 sample per axis, got 0");
        if (__builtin_mul_overflow(c, n[a], &c))
            return NL_ERROR(NL_ETOOBIG, "size: the sample count overflows");
    }
    if (__builtin_mul_overflow(c, elem, &bytes) || __builtin_mul_overflow(bytes, copies, &bytes))
        return NL_ERROR(NL_ETOOBIG, "size: %zu samples overflow the memory size", c);
    size_t avail = nl_mem_available();
    if (avail && bytes > avail)
        return NL_ERROR(NL_ETOOBIG, "size: %zu samples need %.3g GB but %.3g GB are available",
                        c, bytes / 1e9, avail / 1e9);
    if (count)
        *count = c;
    return NL_OK;
}

nl_field *nl_field_alloc(int dim, const size_t *n, const double *h, int *status)
{
    size_t count;
    int st = nl_size_check(dim, n, sizeof(double), 1, &count);
    if (st) {
        if (status)
            *status = st;
        return NULL;
    }
    for (int a = 0; h && a < dim; a++)
        if (!(h[a] > 0) || !isfinite(h[a])) {
            if (status)
                *status = NL_ERROR(NL_EINVAL, "spacing: expected a positive finite number, got %g", h[a]);
            return NULL;
        }
    nl_field *f = calloc(1, sizeof *f);
    if (f)
        f->data = nl_alloc(count * sizeof(double));
    if (f && f->data)
        memset(f->data, 0, count * sizeof(double));
    if (!f || !f->data) {
        free(f);
        if (status)
            *status = NL_ERROR(NL_ENOMEM, "out of memory for %zu samples", count);
        return NULL;
    }
    f->dim = dim;
    f->count = count;
    for (int a = 0; a < 3; a++) {
        f->n[a] = a < dim ? n[a] : 1;
        f->h[a] = (a < dim && h) ? h[a] : 1.0;
    }
    if (status)
        *status = NL_OK;
    return f;
}

void nl_field_free(nl_field *f)
{
    if (!f)
        return;
    nl_free(f->data);
    free(f);
}

int nl_field_check_finite(const nl_field *f, double limit, size_t *first)
{
    for (size_t k = 0; k < f->count; k++) {
        double v = f->data[k];
        if (isfinite(v) && fabs(v) <= limit)
            continue;
        size_t i = k % f->n[0], j = k / f->n[0] % f->n[1], l = k / (f->n[0] * f->n[1]);
        if (first)
            *first = k;
        if (!isfinite(v))
            return NL_ERROR(NL_EINVAL, "sample %zu (x %zu, y %zu, z %zu) is %g, expected a finite number", k, i, j,
                            l, v);
        return NL_ERROR(NL_EINVAL, "sample %zu (x %zu, y %zu, z %zu) is %g, beyond the largest magnitude %g", k, i,
                        j, l, v, limit);
    }
    if (first)
        *first = f->count;
    return NL_OK;
}
