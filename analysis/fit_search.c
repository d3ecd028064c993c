/* The global search of a likelihood fit over its parameter box: a rough
 * optimisation from the start, a profile grid over the scale (each point
 * optimised in the other parameters, the common variance factor in closed
 * form), zoomed around its lowest minima, local optimisations from the
 * lowest points of distinct valleys, and a convergence test on the
 * projected gradient.  A likelihood can have several local minima in the
 * scale (the spherical range: each pair distance the range passes changes
 * the correlation's support), and a simplex from one start finds the
 * nearest (analysis/fit.h, "Search").  The gradient test: every component
 * of the projected gradient of -2 l in the transformed (unit-free)
 * parameters below 1e-4 n; -2 l grows about as n, so this is a relative
 * test, and a step of du changes -2 l by under 1e-4 n du there. */
#include "fit_internal.h"
#include "../core/nl_error.h"

#include <gsl/gsl_multimin.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#define SR_GRID 17          /* profile grid points */
#define SR_GRID_HI 3.0     /* the grid's largest scale, times hmax */
#define SR_GRID_SPAN 1e3   /* and its smallest at least hmax / this */
#define SR_REFINE 2        /* grid points refined at most */
#define SR_ZOOM 3          /* coarse minima zoomed into */
#define SR_ZOOM_STEPS 3    /* points either side of each */
#define SR_POINTS (SR_GRID + 2 * SR_ZOOM * SR_ZOOM_STEPS + 1)
#define SR_MARGIN 2.0      /* ... among those within this of the best -2 l */
#define SR_GAIN 0.5        /* ... and, after the first, within this of the best refined: a
                              refinement gains less (Meuse: 0.22 from the grid's 195.13) */
#define SR_GRAD_TOL 1e-4   /* projected gradient test, per datum (see nl_fit_ml_gradient) */
#define SR_GRAD_STEP 1e-4  /* its central-difference step, transformed units */
#define SR_SIMPLEX 1e-5    /* the simplex size of a local optimisation */
#define SR_INNER 1e-2      /* and of a grid point's (its -2 l to ~1e-4) */
#define SR_STEPS 2000      /* simplex steps per round at most */
#define SR_INNER_STEPS 200 /* ... per grid point */

typedef struct {
    nl_fit_mldata *d;               /* the likelihood */
    size_t j;                       /* the parameter held (SIZE_MAX: none) */
    double t;                       /* its value */
    int conc;                       /* the variances concentrated out (can_concentrate) */
    size_t anchor;                  /* then the free variance held (their common factor) */
    double u[NL_FIT_MAX_PARAMS];    /* the held parameters' values */
} sr_fn;

/* Concentrating the variances out (the profile over a common factor s of
 * every variance and nugget, in closed form; Mardia and Marshall 1984,
 * sec. 3): when they are all free and the model a sum, C(s) = s C and
 * -2 l(s) = -2 l + m ln s + Q (1/s - 1) with m = n (ML) or n - q (REML),
 * Q = r' C^-1 r, minimal at s = Q / m.  The grid then searches one
 * dimension fewer (none for var, scale and a nugget beyond the scale). */
static int can_concentrate(const nl_fit_params *p)
{
    int any = 0;
    for (size_t t = 0; t + 1 < p->nstruct; t++)
        if (p->op[t] != '+')
            return 0;
    for (size_t i = 0; i < p->np; i++) {
        nl_param_role r = p->param[i]->role;
        if ((r == NL_ROLE_VARIANCE || r == NL_ROLE_NUGGET) && p->fixed[i] && p->value[i] != 0)
            return 0;
        any |= r == NL_ROLE_VARIANCE && !p->fixed[i];
    }
    return any;
}

static int is_var(const nl_fit_params *p, size_t k)
{
    nl_param_role r = p->param[p->free_idx[k]]->role;
    return (r == NL_ROLE_VARIANCE || r == NL_ROLE_NUGGET) && p->tr[p->free_idx[k]] == NL_FIT_LOG;
}

/* -2 l at u minimised over the common factor; u's variances moved to it
 * when apply. */
static double concentrated(nl_fit_mldata *d, double *u, int apply)
{
    double f = nl_fit_ml_minus2l_u(d, u), m = (double)d->n - (d->lik == NL_FIT_REML ? (double)d->q : 0);
    double q = d->quad, sh = log(q / m);
    if (!(f < NL_FIT_ML_BAD) || !(q > 0))
        return f;
    for (size_t k = 0; apply && k < d->p->nfree; k++)
        if (is_var(d->p, k))
            u[k] += sh;
    return f - q + m + m * sh;
}

static int held(const sr_fn *s, size_t k) { return k == s->j || (s->conc && k == s->anchor); }

static double sr_objective(const gsl_vector *v, void *params)
{
    sr_fn *s = params;
    double u[NL_FIT_MAX_PARAMS], f;
    size_t k = s->d->p->nfree;
    for (size_t i = 0, m = 0; i < k; i++)
        u[i] = held(s, i) ? s->u[i] : v->data[m++];
    if (!s->conc)
        return nl_fit_ml_minus2l_box(s->d, u, s->j);
    f = concentrated(s->d, u, 0);
    return f < NL_FIT_ML_BAD ? f + nl_fit_ml_penalty(s->d->p, u, s->j) : f;
}

/* Nelder-Mead over the free parameters not held from u (in/out), initial
 * step, simplex size tol, at most steps; returns the minimum. */
static double simplex(sr_fn *s, double *u, double step, double tol, int steps, int *used)
{
    size_t k = s->d->p->nfree, m = 0;
    double v[NL_FIT_MAX_PARAMS], f;
    gsl_multimin_fminimizer *nm;
    gsl_vector *sv;
    memcpy(s->u, u, k * sizeof *u);
    for (size_t i = 0; i < k; i++)
        if (!held(s, i))
            v[m++] = u[i];
    if (m == 0)
        return s->conc ? concentrated(s->d, u, 1) : nl_fit_ml_minus2l_u(s->d, u);
    if (!(nm = gsl_multimin_fminimizer_alloc(gsl_multimin_fminimizer_nmsimplex2, m)))
        return NAN;
    gsl_vector_view vv = gsl_vector_view_array(v, m);
    gsl_multimin_function F = {sr_objective, m, s};
    if (!(sv = gsl_vector_alloc(m))) {
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
        if (!held(s, i))
            u[i] = gsl_vector_get(gsl_multimin_fminimizer_x(nm), q++);
    gsl_vector_free(sv);
    gsl_multimin_fminimizer_free(nm);
    if (s->conc)
        concentrated(s->d, u, 1);
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
    sr_fn s = {.d = d, .j = SIZE_MAX};
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

/* The profile grid: its points' scales (transformed), profile -2 l and
 * parameters; the start's rough optimum is one more point. */
typedef struct {
    size_t n;                                /* points */
    double t[SR_POINTS];                     /* the scale (transformed) */
    double f[SR_POINTS];                     /* the profile -2 l there */
    double u[SR_POINTS][NL_FIT_MAX_PARAMS];  /* the parameters there */
    unsigned char used[SR_POINTS];           /* refined */
} sr_grid;

/* One profile point at scale t, from u's other parameters: each from the
 * start's, as a neighbour's can sit in a flat valley (a nugget near 0 at
 * small scales) that a simplex leaves slowly. */
static void grid_point(sr_fn *s, const double *u, double t, sr_grid *g, int *steps)
{
    size_t n = g->n++, k = s->d->p->nfree;
    memcpy(g->u[n], u, k * sizeof *u);
    s->t = g->t[n] = g->u[n][s->j] = t;
    g->f[n] = simplex(s, g->u[n], 0.5, SR_INNER, SR_INNER_STEPS, steps);
    into_box(s->d->p, g->u[n]);
    if (!isfinite(g->f[n]))
        g->f[n] = NL_FIT_ML_BAD;
}

/* The coarse grid of SR_GRID scales from max(hmin, hmax / SR_GRID_SPAN)
 * to SR_GRID_HI hmax, evenly in log, then SR_ZOOM_STEPS points either
 * side of each of its SR_ZOOM lowest local minima at a
 * (SR_ZOOM_STEPS + 1)-th of its spacing: a spherical likelihood's valleys
 * in the range can be a tenth of the range wide (Meuse, REML with a linear
 * drift: 186.27 at 1773, 187.59 at 1600, 188.34 at 2000). */
static void grid_profile(nl_fit_mldata *d, size_t j, const double *u, sr_grid *g, int *steps)
{
    const nl_fit_params *p = d->p;
    size_t i = p->free_idx[j], k = p->nfree, nc;
    double lo = fmax(log(fmax(d->hmin, d->hmax / SR_GRID_SPAN)), p->ulo[i]);
    double hi = fmin(log(SR_GRID_HI * d->hmax), p->uhi[i]), dt = (hi - lo) / (SR_GRID - 1);
    int taken[SR_GRID] = {0};
    sr_fn s = {.d = d, .j = j, .conc = can_concentrate(p)};
    for (size_t q = 0; q < k && s.conc; q++)
        if (p->param[p->free_idx[q]]->role == NL_ROLE_VARIANCE) {
            s.anchor = q;
            break;
        }
    for (int c = 0; c < SR_GRID; c++)
        grid_point(&s, u, lo + dt * c, g, steps);
    nc = g->n;
    for (int z = 0; z < SR_ZOOM; z++) {
        int best = -1;
        for (size_t c = 0; c < nc; c++)
            if (!taken[c] && g->f[c] < NL_FIT_ML_BAD && (c == 0 || g->f[c] <= g->f[c - 1]) &&
                (c + 1 == nc || g->f[c] <= g->f[c + 1]) && (best < 0 || g->f[c] < g->f[best]))
                best = (int)c;
        if (best < 0)
            break;
        taken[best] = 1;
        for (int side = -1; side <= 1; side += 2)
            for (int q = 1; q <= SR_ZOOM_STEPS; q++)
                grid_point(&s, g->u[best], g->t[best] + side * dt * q / (SR_ZOOM_STEPS + 1), g, steps);
    }
}

/* The next point to refine: the lowest not refined, within SR_MARGIN of
 * the lowest and SR_GAIN of the best refined f, and not within an eighth
 * of the coarse spacing of one refined (the same valley); -1 when none. */
static int next_candidate(const sr_grid *g, double f, double dt)
{
    double lowest = NL_FIT_ML_BAD;
    int best = -1;
    for (size_t c = 0; c < g->n; c++)
        lowest = fmin(lowest, g->f[c]);
    for (size_t c = 0; c < g->n; c++) {
        int near = 0;
        for (size_t e = 0; e < g->n; e++)
            near |= g->used[e] && fabs(g->t[e] - g->t[c]) < dt / 8;
        if (!near && g->f[c] < lowest + SR_MARGIN && g->f[c] < f + SR_GAIN && (best < 0 || g->f[c] < g->f[best]))
            best = (int)c;
    }
    return best;
}

int nl_fit_ml_search(nl_fit_mldata *d, int global, nl_fit_result *res, double *u, unsigned *flags)
{
    nl_fit_params *p = d->p;
    size_t k = p->nfree, j = global ? grid_axis(p) : SIZE_MAX;
    double f;
    int conv = 0;
    sr_fn s = {.d = d, .j = SIZE_MAX};
    nl_fit_params_to_u(p, u);
    into_box(p, u);
    if (j == SIZE_MAX) {
        f = nl_fit_ml_refine(d, u, 4, &conv, &res->iterations);
        res->starts = 1;
    } else {
        /* candidates: the grid's points and the start, optimised roughly;
         * the lowest of distinct valleys refined fully */
        static const sr_grid empty;
        sr_grid *g = malloc(sizeof *g);
        double u0[NL_FIT_MAX_PARAMS], lo, hi, dt;
        size_t i = p->free_idx[j];
        if (!g)
            return NL_ERROR(NL_ENOMEM, "out of memory");
        *g = empty;
        memcpy(u0, u, k * sizeof *u);
        f = simplex(&s, u0, 0.5, SR_INNER, SR_STEPS, &res->iterations);
        into_box(p, u0);
        grid_profile(d, j, u0, g, &res->iterations);
        memcpy(g->u[g->n], u0, k * sizeof *u0);
        g->t[g->n] = u0[j], g->f[g->n++] = f;
        lo = fmax(log(fmax(d->hmin, d->hmax / SR_GRID_SPAN)), p->ulo[i]);
        hi = fmin(log(SR_GRID_HI * d->hmax), p->uhi[i]);
        dt = (hi - lo) / (SR_GRID - 1);
        f = NL_FIT_ML_BAD;
        for (int r = 0, c; r < SR_REFINE && (c = next_candidate(g, f, dt)) >= 0; r++) {
            double uc[NL_FIT_MAX_PARAMS], fc;
            int cc = 0;
            g->used[c] = 1;
            memcpy(uc, g->u[c], k * sizeof *uc);
            fc = nl_fit_ml_refine(d, uc, 4, &cc, &res->iterations);
            res->starts++;
            if (fc < f) {
                f = fc, conv = cc;
                memcpy(u, uc, k * sizeof *u);
            }
        }
        free(g);
        /* no candidate with a positive definite covariance: from the start */
        if (!(f < NL_FIT_ML_BAD)) {
            f = nl_fit_ml_refine(d, u, 4, &conv, &res->iterations);
            res->starts++;
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
