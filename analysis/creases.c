/* Curvature by level of creation: the crease index. */
#include "creases.h"
#include "../core/nl_error.h"

#include <gsl/gsl_sort.h>
#include <gsl/gsl_statistics_double.h>
#include <math.h>

static int tz(size_t i, int max)
{
    int t = 0;
    while (t < max && i % 2 == 0) {
        i /= 2;
        t++;
        if (i == 0)
            return max;
    }
    return t;
}

int nl_creases_measure(const nl_field *f, int levels, nl_creases *out)
{
    size_t nx = f->n[0], ny = f->dim == 2 ? f->n[1] : 1;
    double sum[41] = {0}, use[40];
    size_t nuse = 0;
    if (f->dim > 2)
        return NL_ERROR(NL_EINVAL, "creases: expected a 1D or 2D field, got %dD", f->dim);
    if (levels < 1 || levels > 40 || nx % ((size_t)1 << levels) || (f->dim == 2 && ny % ((size_t)1 << levels)))
        return NL_ERROR(NL_EINVAL, "creases: expected each size a multiple of 2^levels, got %zu with %d levels", nx,
                        levels);
    out->levels = levels;
    for (int k = 0; k <= levels; k++)
        out->count[k] = 0;
    for (size_t j = 0; j < ny; j++)
        for (size_t i = 0; i < nx; i++) {
            const double *x = f->data;
            /* across the column i: the second difference along x */
            double c = x[j * nx + (i + 1) % nx] - 2 * x[j * nx + i] + x[j * nx + (i + nx - 1) % nx];
            int t = tz(i, levels);
            sum[levels - t] += c * c;
            out->count[levels - t]++;
            if (f->dim == 2) {
                /* across the row j: the second difference along y */
                c = x[((j + 1) % ny) * nx + i] - 2 * x[j * nx + i] + x[((j + ny - 1) % ny) * nx + i];
                t = tz(j, levels);
                sum[levels - t] += c * c;
                out->count[levels - t]++;
            }
        }
    for (int k = 0; k <= levels; k++) {
        out->ratio[k] = out->count[k] >= 64 && sum[levels] > 0
                            ? (sum[k] / (double)out->count[k]) / (sum[levels] / (double)out->count[levels])
                            : NAN;
        if (k >= 1 && k < levels && !isnan(out->ratio[k]))
            use[nuse++] = out->ratio[k];
    }
    if (!(sum[levels] > 0))
        return NL_ERROR(NL_EINVAL, "creases: the finest level has no curvature (second differences all 0: a "
                        "constant or linear field); expected a random field");
    if (nuse == 0)
        return NL_ERROR(NL_EINVAL, "creases: no level between the coarsest and the finest holds 64 samples; "
                        "use a larger field or more levels");
    gsl_sort(use, 1, nuse);
    out->index = gsl_stats_median_from_sorted_data(use, 1, nuse);
    out->flagged = out->index > NL_CREASE_MAX;
    return NL_OK;
}
