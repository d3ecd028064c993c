/* y = F_y^-1(F_x(x)) by table lookup or by ranks. */
#include "shape.h"
#include "../core/gsl_guard_internal.h"
#include "../core/nl_error.h"

#include <gsl/gsl_cdf.h>
#include <gsl/gsl_sort.h>
#include <gsl/gsl_statistics_double.h>
#include <math.h>
#include <stdlib.h>

static int synth_shape(nl_field *f, const nl_dist *to, int empirical)
{
    if (f->count < 2)
        return NL_ERROR(NL_EINVAL, "shape: expected at least 2 samples, got %zu", f->count);
    if (empirical) {
        size_t *rank = malloc(f->count * sizeof *rank);
        if (!rank)
            return NL_ERROR(NL_ENOMEM, "out of memory");
        gsl_sort_index(rank, f->data, 1, f->count);  /* rank[r] = index of the r-th smallest */
        for (size_t r = 0; r < f->count; r++) {
            double u = ((double)r + 0.5) / (double)f->count;
            /* a nonlinearity maps the Gaussian score of the rank */
            f->data[rank[r]] = nl_dist_is_function(to) ? nl_dist_transform(to, gsl_cdf_ugaussian_Pinv(u))
                                                       : nl_dist_quantile(to, u);
        }
        free(rank);
        return NL_OK;
    }
    double mean = gsl_stats_mean(f->data, 1, f->count), sd = gsl_stats_sd_m(f->data, 1, f->count, mean);
    double *g = malloc((NL_SHAPE_TABLE + 1) * sizeof *g), step = 2 * NL_SHAPE_ZMAX / NL_SHAPE_TABLE;
    if (!g)
        return NL_ERROR(NL_ENOMEM, "out of memory");
    if (!(sd > 0)) {
        free(g);
        return NL_ERROR(NL_EINVAL, "shape: the field is constant; expected a random field");
    }
    for (int i = 0; i <= NL_SHAPE_TABLE; i++)
        g[i] = nl_dist_transform(to, -NL_SHAPE_ZMAX + i * step);
    for (size_t i = 0; i < f->count; i++) {
        double t = ((f->data[i] - mean) / sd + NL_SHAPE_ZMAX) / step;
        if (t <= 0)
            f->data[i] = g[0];
        else if (t >= NL_SHAPE_TABLE)
            f->data[i] = g[NL_SHAPE_TABLE];
        else {
            size_t k = (size_t)t;
            double w = t - (double)k;
            f->data[i] = (1 - w) * g[k] + w * g[k + 1];
        }
    }
    free(g);
    return NL_OK;
}

/* Bracketed for GSL (core/gsl_guard_internal.h): its errors come back as statuses. */
int nl_synth_shape(nl_field *f, const nl_dist *to, int empirical)
{
    int st;
    nl_gsl_enter();
    st = synth_shape(f, to, empirical);
    nl_gsl_leave();
    return st;
}
