/* What a likelihood fit refuses before it starts: data it cannot fit
 * (non-finite, without variation, coincident without a nugget) and work
 * beyond its budget. */
#include "fit_internal.h"
#include "../core/nl_error.h"

#include <math.h>
#include <stdio.h>

/* Likelihood evaluations of a fit with k free parameters and m profile
 * intervals (the estimate of fit.h's "Cost"): the search (its grid of 35
 * profile points and up to two local optimisations: measured 700 to
 * 1500 for k = 3 on Meuse, analysis/fit_search.c), the Hessian's stencil,
 * and per interval two ends of about 10 profile points, each an inner
 * Nelder-Mead over the other k - 1 parameters. */
static double evaluations(size_t k, size_t m)
{
    double kk = (double)k;
    return 450 * kk + 2 * kk * kk + 1 + (double)m * 20 * (1 + 40 * (kk - 1));
}

/* One evaluation: the Cholesky factor (n^3 / 3) and the n^2 / 2 model
 * values (about 100 operations each). */
static double per_evaluation(double n) { return n * n * n / 3 + 50 * n * n; }

static size_t profiled(const nl_fit_params *p, nl_fit_intervals which)
{
    if (which == NL_FIT_INTERVALS_ALL)
        return p->nfree;
    return which == NL_FIT_INTERVALS_SCALE ? 1 : 0;
}

double nl_fit_ml_work(size_t n, int dim, const nl_fit_options *o)
{
    nl_fit_params p;
    if (nl_fit_params_init(o, dim, &p) || p.nfree == 0)
        return 0;
    return evaluations(p.nfree, profiled(&p, o->intervals)) * per_evaluation((double)n);
}

static int check_work(const nl_fit_params *p, size_t n, const nl_fit_options *o)
{
    double e = evaluations(p->nfree, profiled(p, o->intervals)), work = e * per_evaluation((double)n);
    double budget = o->max_work > 0 ? o->max_work : NL_FIT_ML_WORK_MAX;
    size_t most = (size_t)cbrt(3 * budget / e);
    if (n > NL_FIT_ML_MAX)
        return NL_ERROR(NL_ETOOBIG, "fit: %zu data for a likelihood fit; expected at most %d (use the variogram "
                        "fit)", n, NL_FIT_ML_MAX);
    if (!(work <= budget)) {
        while (most > 2 && e * per_evaluation((double)most) > budget)
            most--;
        return NL_ERROR(NL_ETOOBIG, "fit: a likelihood fit of %zu data costs about %.3g operations (%.0f "
                        "evaluations of O(n^3); some %.0f s at 1e10 a second), over the budget of %.3g; expected at "
                        "most %zu data: fit the variogram (method wls), or fit a subsample", n, work, e, work / 1e10,
                        budget, most);
    }
    return NL_OK;
}

static void where(const double *x, int dim, char *buf, size_t size)
{
    size_t len = 0;
    for (int a = 0; a < dim && len < size; a++)
        len += (size_t)snprintf(buf + len, size - len, "%s%g", a ? ", " : "(", x[a]);
    if (len < size)
        snprintf(buf + len, size - len, ")");
}

/* Two data at one place: their covariance rows are equal, so without a
 * nugget C is singular (different values: the likelihood is unbounded). */
static int check_coincident(const nl_fit_params *p, const double *x, const double *z, size_t n)
{
    int dim = p->dim;
    size_t d = (size_t)dim;
    char at[96];
    if (nl_fit_params_has_nugget(p))
        return NL_OK;
    for (size_t i = 1; i < n; i++)
        for (size_t j = 0; j < i; j++) {
            size_t a = 0;
            while (a < d && x[i * d + a] == x[j * d + a])
                a++;
            if (a < d)
                continue;
            where(x + i * d, dim, at, sizeof at);
            if (z[i] != z[j])
                return NL_ERROR(NL_EINVAL, "fit: points %zu and %zu are both at %s with values %g and %g: "
                                "expected a nugget (--nugget) to fit data that differ at one place", j + 1,
                                i + 1, at, z[j], z[i]);
            return NL_ERROR(NL_EINVAL, "fit: points %zu and %zu are both at %s (value %g): expected distinct "
                            "locations without a nugget (remove the duplicate, or --nugget)", j + 1, i + 1, at,
                            z[i]);
        }
    return NL_OK;
}

/* Finite values, finite coordinates spanning a finite extent, not all at
 * one place, some variation. */
#define ML_SPREAD_MIN 1e-150
#define ML_SPREAD_MAX 1e150

static int check_values(const double *x, const double *z, size_t n, int dim)
{
    size_t d = (size_t)dim;
    double zlo = z[0], zhi = z[0];
    for (size_t i = 0; i < n; i++) {
        if (!isfinite(z[i]))
            return NL_ERROR(NL_EINVAL, "fit: value %zu is not finite (%g)", i + 1, z[i]);
        for (size_t a = 0; a < d; a++)
            if (!isfinite(x[i * d + a]))
                return NL_ERROR(NL_EINVAL, "fit: coordinate %zu of point %zu is not finite (%g)", a + 1, i + 1,
                                x[i * d + a]);
    }
    for (size_t a = 0, moved = 0; a < d; a++) {
        double lo = INFINITY, hi = -INFINITY;
        for (size_t i = 0; i < n; i++)
            lo = fmin(lo, x[i * d + a]), hi = fmax(hi, x[i * d + a]);
        if (!isfinite(hi - lo))
            return NL_ERROR(NL_EINVAL, "fit: coordinate %zu spans %g to %g; expected a finite extent", a + 1, lo,
                            hi);
        moved += hi > lo;
        if (a == d - 1 && !moved)
            return NL_ERROR(NL_EINVAL, "fit: all %zu points are identical; expected distinct locations", n);
    }
    for (size_t i = 1; i < n; i++)
        zlo = fmin(zlo, z[i]), zhi = fmax(zhi, z[i]);
    if (zlo == zhi)
        return NL_ERROR(NL_EINVAL, "fit: no variation: all %zu values are %g; nothing to fit", n, z[0]);
    /* the variance, about the square of the spread, must be a normal double */
    if (!(zhi - zlo >= ML_SPREAD_MIN && zhi - zlo <= ML_SPREAD_MAX))
        return NL_ERROR(NL_EINVAL, "fit: the values spread over %g (%g to %g): expected a spread between %g and "
                        "%g, whose square is a normal double (rescale them)", zhi - zlo, zlo, zhi, ML_SPREAD_MIN,
                        ML_SPREAD_MAX);
    return NL_OK;
}

int nl_fit_ml_check(const nl_fit_params *p, const double *x, const double *z, size_t n, const nl_fit_options *o)
{
    int st;
    if (n < p->nfree + 2)
        return NL_ERROR(NL_EINVAL, "fit: %zu data; expected at least %zu (the %zu free parameters and the mean + 1)",
                        n, p->nfree + 2, p->nfree);
    if ((st = check_work(p, n, o)) || (st = check_values(x, z, n, p->dim)))
        return st;
    return check_coincident(p, x, z, n);
}
