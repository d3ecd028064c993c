/* The global search of a likelihood fit over its parameter box: a local
 * optimisation from the start, a profile grid over the scale (each point
 * optimised in the other parameters), refinement of the grid's best local
 * minima, and a convergence test on the projected gradient.  A likelihood
 * can have several local minima in the scale (the spherical range: each
 * pair distance the range passes changes the correlation's support), and
 * a simplex from one start finds the nearest; the grid sees them all at a
 * resolution of a factor (3 hmax / hmin')^(1/8). */
#include "fit_internal.h"
#include "../core/nl_error.h"

#include <gsl/gsl_multimin.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#define SR_GRID 9          /* profile grid points */
#define SR_GRID_HI 3.0     /* the grid's largest scale, times hmax */
#define SR_GRID_SPAN 1e3   /* and its smallest at least hmax / this */
#define SR_REFINE 2        /* grid minima refined at most */
#define SR_MARGIN 2.0      /* ... among those within this of the best -2 l */
#define SR_GRAD_TOL 1e-4   /* projected gradient test, per datum (see nl_fit_ml_gradient) */
#define SR_GRAD_STEP 1e-4  /* its central-difference step, transformed units */
#define SR_SIMPLEX 1e-5    /* the simplex size of a local optimisation */
#define SR_INNER 1e-3      /* and of a grid point's */
#define SR_STEPS 2000      /* simplex steps per round at most */
#define SR_INNER_STEPS 300 /* ... per grid point */

typedef struct {
    nl_fit_mldata *d;               /* the likelihood */
    size_t j;                       /* the parameter held (SIZE_MAX: none) */
    double t;                       /* its value */
} sr_fn;

static double sr_objective(const gsl_vector *v, void *params)
{
    sr_fn *s = params;
    double u[NL_FIT_MAX_PARAMS];
    size_t k = s->d->p->nfree;
    if (s->j == SIZE_MAX)
        return nl_fit_ml_minus2l_box(s->d, v->data, SIZE_MAX);
    for (size_t i = 0, m = 0; i < k; i++)
        u[i] = i == s->j ? s->t : v->data[m++];
    return nl_fit_ml_minus2l_box(s->d, u, s->j);
}

/* Nelder-Mead over the free parameters but s->j from u (in/out), initial
 * step, simplex size tol, at most steps; returns the minimum. */
static double simplex(sr_fn *s, double *u, double step, double tol, int steps, int *used)
{
    size_t k = s->d->p->nfree, m = s->j == SIZE_MAX ? k : k - 1;
    double v[NL_FIT_MAX_PARAMS], f;
    gsl_multimin_fminimizer *nm;
    if (m == 0)
        return nl_fit_ml_minus2l_u(s->d, u);
    if (!(nm = gsl_multimin_fminimizer_alloc(gsl_multimin_fminimizer_nmsimplex2, m)))
        return NAN;
    for (size_t i = 0, q = 0; i < k; i++)
        if (i != s->j)
            v[q++] = u[i];
    gsl_vector_view vv = gsl_vector_view_array(v, m);
    gsl_vector *sv = gsl_vector_alloc(m);
    gsl_multimin_function F = {sr_objective, m, s};
    if (!sv) {
        gsl_multimin_fminimizer_free(nm);
        return NAN;
    }
    gsl_vector_set_all(sv, step);
    gsl_multimin_fminimizer_set(nm, &F, &vv.vector, sv);
    int it = 0;
    while (it++ < steps && !gsl_multimin_fminimizer_iterate(nm) &&
           gsl_multimin_test_size(gsl_multimin_fminimizer_size(nm), tol) == GSL_CONTINUE)
        ;
    *used += it;
    f = gsl_multimin_fminimizer_minimum(nm);
    for (size_t i = 0, q = 0; i < k; i++)
        if (i != s->j)
            u[i] = gsl_vector_get(gsl_multimin_fminimizer_x(nm), q++);
    gsl_vector_free(sv);
    gsl_multimin_fminimizer_free(nm);
    return f;
}

/* Back into the box (the simplex may end a little outside it). */
static void into_box(const nl_fit_params *p, double *u)
{
    for (size_t k = 0; k < p->nfree; k++) {
        size_t i = p->free_idx[k];
        u[k] = fmax(p->ulo[i], fmin(p->uhi[i], u[k]));
    }
}

double nl_fit_ml_gradient(nl_fit_mldata *d, const double *u0)
{
    const nl_fit_params *p = d->p;
    double u[NL_FIT_MAX_PARAMS], gmax = 0;
    memcpy(u, u0, p->nfree * sizeof *u);
    for (size_t k = 0; k < p->nfree; k++) {
        size_t i = p->free_idx[k];
        double h = SR_GRAD_STEP, fp, fm, g;
        u[k] = u0[k] + h, fp = nl_fit_ml_minus2l_u(d, u);
        u[k] = u0[k] - h, fm = nl_fit_ml_minus2l_u(d, u);
        u[k] = u0[k];
        g = (fp - fm) / (2 * h);
        if (!(fp < NL_FIT_ML_BAD && fm < NL_FIT_ML_BAD))
            g = INFINITY;
        /* pointing out of the box at its edge: the box holds it */
        if ((u0[k] >= p->uhi[i] - 2 * h && g < 0) || (u0[k] <= p->ulo[i] + 2 * h && g > 0))
            g = 0;
        gmax = fmax(gmax, fabs(g));
    }
    nl_fit_ml_minus2l_u(d, u0);
    return gmax;
}

double nl_fit_ml_refine(nl_fit_mldata *d, double *u, int maxround, int *conv, int *steps)
{
    sr_fn s = {d, SIZE_MAX, 0};
    double f = NL_FIT_ML_BAD, tol = SR_GRAD_TOL * (double)d->n;
    *conv = 0;
    for (int round = 0; round < maxround; round++) {
        f = simplex(&s, u, round ? 0.1 : 0.5, SR_SIMPLEX, SR_STEPS, steps);
        into_box(d->p, u);
        f = nl_fit_ml_minus2l_u(d, u);
        /* two rounds at least: a simplex can collapse before the minimum */
        if (round >= 1 && (*conv = nl_fit_ml_gradient(d, u) <= tol))
            break;
    }
    return f;
}

/* The first free scale (the profile grid's axis), or SIZE_MAX. */
static size_t grid_axis(const nl_fit_params *p)
{
    for (size_t k = 0; k < p->nfree; k++) {
        size_t i = p->free_idx[k];
        if (p->param[i]->role == NL_ROLE_SCALE && p->tr[i] == NL_FIT_LOG)
            return k;
    }
    return SIZE_MAX;
}

/* The profile -2 l on the grid (pf), each point's parameters (ug), from u's
 * other parameters at the first point and the previous point's after. */
static void grid_profile(nl_fit_mldata *d, size_t j, const double *u, double pf[SR_GRID],
                         double ug[SR_GRID][NL_FIT_MAX_PARAMS], int *steps)
{
    const nl_fit_params *p = d->p;
    size_t i = p->free_idx[j], k = p->nfree;
    double lo = fmax(log(fmax(d->hmin, d->hmax / SR_GRID_SPAN)), p->ulo[i]);
    double hi = fmin(log(SR_GRID_HI * d->hmax), p->uhi[i]);
    sr_fn s = {d, j, 0};
    for (int g = 0; g < SR_GRID; g++) {
        memcpy(ug[g], g ? ug[g - 1] : u, k * sizeof **ug);
        s.t = ug[g][j] = lo + (hi - lo) * g / (SR_GRID - 1);
        pf[g] = simplex(&s, ug[g], 0.5, SR_INNER, SR_INNER_STEPS, steps);
        if (!(pf[g] < NL_FIT_ML_BAD)) {
            /* from the start's parameters instead of a failed neighbour */
            memcpy(ug[g], u, k * sizeof **ug);
            ug[g][j] = s.t;
            pf[g] = simplex(&s, ug[g], 0.5, SR_INNER, SR_INNER_STEPS, steps);
        }
        into_box(p, ug[g]);
        if (!isfinite(pf[g]))
            pf[g] = NL_FIT_ML_BAD;
    }
}

int nl_fit_ml_search(nl_fit_mldata *d, int global, nl_fit_result *res, double *u, unsigned *flags)
{
    nl_fit_params *p = d->p;
    size_t k = p->nfree, j = global ? grid_axis(p) : SIZE_MAX;
    double f, pf[SR_GRID], ug[SR_GRID][NL_FIT_MAX_PARAMS];
    int conv = 0;
    nl_fit_params_to_u(p, u);
    into_box(p, u);
    f = nl_fit_ml_refine(d, u, 4, &conv, &res->iterations);
    res->starts = 1;
    if (j != SIZE_MAX) {
        int used[SR_GRID] = {0};
        grid_profile(d, j, u, pf, ug, &res->iterations);
        /* refine the grid's lowest local minima near the best */
        for (int r = 0; r < SR_REFINE; r++) {
            int best = -1;
            double uc[NL_FIT_MAX_PARAMS], fc;
            int cc = 0;
            for (int g = 0; g < SR_GRID; g++)
                if (!used[g] && pf[g] < NL_FIT_ML_BAD && (g == 0 || pf[g] <= pf[g - 1]) &&
                    (g == SR_GRID - 1 || pf[g] <= pf[g + 1]) && pf[g] < f + SR_MARGIN &&
                    (best < 0 || pf[g] < pf[best]))
                    best = g;
            if (best < 0)
                break;
            used[best] = 1;
            memcpy(uc, ug[best], k * sizeof *uc);
            fc = nl_fit_ml_refine(d, uc, 4, &cc, &res->iterations);
            res->starts++;
            if (fc < f) {
                f = fc, conv = cc;
                memcpy(u, uc, k * sizeof *u);
            }
        }
    }
    res->objective = nl_fit_ml_minus2l_u(d, u);
    if (!(res->objective < NL_FIT_ML_BAD))
        return NL_ERROR(NL_EFAIL, "fit: no parameters of %s give a positive definite covariance of the data",
                        p->family);
    res->gradient = nl_fit_ml_gradient(d, u);
    /* a scale or variance at the edge of the box ran away: no optimum inside */
    for (size_t q = 0; q < k; q++)
        if (nl_fit_params_runaway(p, q))
            flags[q] |= NL_FIT_PARAM_AT_BOUND, conv = 0;
    res->converged = conv;
    return NL_OK;
}
