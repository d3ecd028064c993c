/* Poisson faulting: steps in 1D, random lines in 2D. */
#include "faulting.h"
#include "../core/nl_error.h"
#include "../core/rng.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The expected number of faults, or a negative number for bad arguments. */
static double expected(double density, const nl_field *f)
{
    size_t nx = f->n[0], ny = f->dim == 2 ? f->n[1] : 1;
    if (f->dim > 2 || !(density > 0) || !isfinite(density))
        return -1;
    return density * (f->dim == 1 ? (double)nx : (double)(nx + ny));
}

size_t nl_synth_faulting_count(uint64_t seed, double density, const nl_field *f)
{
    double mean = expected(density, f);
    return mean < 0 || mean > 1e8 ? 0 : nl_rng_poisson(seed, NL_SYNTH_FAULT_STREAM + 1, 0, 0, mean);
}

int nl_synth_faulting(uint64_t seed, double density, nl_field *f, size_t *count)
{
    size_t nx = f->n[0], ny = f->dim == 2 ? f->n[1] : 1, K;
    double mean;
    if (f->dim > 2)
        return NL_ERROR(NL_EINVAL, "faulting: expected a 1D or 2D field, got %dD", f->dim);
    if (!(density > 0) || !isfinite(density))
        return NL_ERROR(NL_EINVAL, "density: expected a positive number of faults per sample, got %g", density);
    mean = density * (f->dim == 1 ? (double)nx : (double)(nx + ny));
    if (mean > 1e8)
        return NL_ERROR(NL_ETOOBIG, "density: %g faults are too many; expected at most 1e8", mean);
    K = nl_rng_poisson(seed, NL_SYNTH_FAULT_STREAM + 1, 0, 0, mean);
    memset(f->data, 0, f->count * sizeof *f->data);
    if (f->dim == 1) {
        double *step = calloc(nx + 1, sizeof *step), s = 0;
        if (!step)
            return NL_ERROR(NL_ENOMEM, "out of memory");
        for (size_t k = 0; k < K; k++) {
            double t = nl_rng_uniform(seed, NL_SYNTH_FAULT_STREAM, 2 * k) * (double)nx;
            step[(size_t)ceil(t) <= nx ? (size_t)ceil(t) : nx] += nl_rng_gauss(seed, NL_SYNTH_FAULT_STREAM, 2 * k + 1);
        }
        for (size_t i = 0; i < nx; i++)
            f->data[i] = (s += step[i]);
        free(step);
    } else {
        double cx = 0.5 * (double)(nx - 1), cy = 0.5 * (double)(ny - 1), half = 0.5 * hypot((double)nx, (double)ny);
        double *diff = calloc(ny * (nx + 1), sizeof *diff);
        if (!diff)
            return NL_ERROR(NL_ENOMEM, "out of memory");
        for (size_t k = 0; k < K; k++) {
            double th = M_PI * nl_rng_uniform(seed, NL_SYNTH_FAULT_STREAM, 3 * k);
            double rho = half * (2 * nl_rng_uniform(seed, NL_SYNTH_FAULT_STREAM, 3 * k + 1) - 1);
            double a = nl_rng_gauss(seed, NL_SYNTH_FAULT_STREAM, 3 * k + 2), c = cos(th), s = sin(th);
            for (size_t j = 0; j < ny; j++) {
                /* samples with (x - cx) c + (y - cy) s > rho get +a */
                double *d = diff + j * (nx + 1), r = rho - ((double)j - cy) * s;
                long first, last;
                if (fabs(c) < 1e-12) {
                    if (0 > r)
                        d[0] += a, d[nx] -= a;
                    continue;
                }
                double xs = cx + r / c;  /* the line crosses row j at x = xs */
                if (c > 0)
                    first = (long)floor(xs) + 1, last = (long)nx - 1;
                else
                    first = 0, last = (long)ceil(xs) - 1;
                if (first < 0) first = 0;
                if (last > (long)nx - 1) last = (long)nx - 1;
                if (first <= last)
                    d[first] += a, d[last + 1] -= a;
            }
        }
        for (size_t j = 0; j < ny; j++) {
            double s = 0;
            for (size_t i = 0; i < nx; i++)
                f->data[j * nx + i] = (s += diff[j * (nx + 1) + i]);
        }
        free(diff);
    }
    if (count)
        *count = K;
    return NL_OK;
}
