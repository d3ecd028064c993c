/* Profile-likelihood intervals of ML and REML fits (Cox and Hinkley 1974,
 * sec. 9.3; Venzon and Moolgavkar 1988): the values of one parameter whose
 * profile -2 l, the other parameters re-optimised, stays within the 95%
 * point of chi^2_1 of the minimum.  Each end is bracketed outwards from the
 * optimum and found by GSL's Brent solver; the inner optimisations are
 * GSL's Nelder-Mead simplex, warm-started from the previous profile point. */
#include "fit_internal.h"
#include "../core/nl_error.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_multimin.h>
#include <gsl/gsl_roots.h>
#include <math.h>
#include <string.h>

#define PR_CHI2 3.841458820694124 /* chi^2_1's 0.95 quantile */
#define PR_REACH 12.0             /* farthest end searched, transformed units */
#define PR_TOL 1e-3               /* ends to this, transformed units */
#define PR_SIMPLEX 1e-3           /* inner simplex size at convergence */
#define PR_INNER_STEPS 500        /* inner simplex steps at most */
#define PR_ROOT_STEPS 60          /* Brent steps at most */
#define PR_WINDOW 10              /* inner steps between progress checks */
#define PR_GAIN 1e-4              /* least gain of -2 l per window */

typedef struct {
    nl_fit_mldata *d;              /* the likelihood */
    size_t j;                      /* the profiled free parameter */
    double t;                      /* its transformed value */
    double u[NL_FIT_MAX_PARAMS];   /* the last profile point (the others' warm start) */
    double cutoff;                 /* minimum -2 l + chi^2_1(0.95) */
    gsl_multimin_fminimizer *nm;   /* over the other free parameters; NULL when none */
    double f_hat;                  /* the optimum's -2 l */
    double *better;                /* a point below f_hat - NL_FIT_PROFILE_DROP, when found */
    int found;                     /* better holds one */
    double f_best;                 /* its -2 l */
    double last[NL_FIT_MAX_PARAMS];/* the last profile point evaluated */
} profile;

/* -2 l with the profiled parameter at t and the others at v. */
static double inner(const gsl_vector *v, void *params)
{
    profile *pr = params;
    double u[NL_FIT_MAX_PARAMS];
    for (size_t i = 0, m = 0; i < pr->d->p->nfree; i++)
        u[i] = i == pr->j ? pr->t : v->data[m++];
    return nl_fit_ml_minus2l_box(pr->d, u, pr->j);
}

/* f minus the cutoff; a point below the optimum (by more than the inner
 * optimisations' noise) is kept for a restart. */
static double below(profile *pr, double f, const double *u)
{
    size_t k = pr->d->p->nfree;
    if (f < pr->f_hat - NL_FIT_PROFILE_DROP && pr->better && (!pr->found || f < pr->f_best)) {
        memcpy(pr->better, u, k * sizeof *u);
        pr->found = 1, pr->f_best = f;
    }
    memcpy(pr->last, u, k * sizeof *u);
    /* the next point starts from the last one inside the interval: one
     * outside may have sent the others to another valley (a nugget to 0) */
    if (f < pr->cutoff)
        memcpy(pr->u, u, k * sizeof *u);
    return f - pr->cutoff;
}

/* The profile -2 l at t minus the cutoff (negative inside the interval). */
static double excess(double t, void *params)
{
    profile *pr = params;
    size_t k = pr->d->p->nfree;
    double v[NL_FIT_MAX_PARAMS], step[NL_FIT_MAX_PARAMS], un[NL_FIT_MAX_PARAMS], f;
    pr->t = t;
    if (!pr->nm) {
        memcpy(v, pr->u, k * sizeof *v);
        v[pr->j] = t;
        return below(pr, nl_fit_ml_minus2l_u(pr->d, v), v);
    }
    for (size_t i = 0, m = 0; i < k; i++)
        if (i != pr->j)
            step[m] = 0.1, v[m++] = pr->u[i];
    gsl_vector_view vv = gsl_vector_view_array(v, k - 1), sv = gsl_vector_view_array(step, k - 1);
    gsl_multimin_function F = {inner, k - 1, pr};
    gsl_multimin_fminimizer_set(pr->nm, &F, &vv.vector, &sv.vector);
    /* until the simplex is small, or -2 l gained less than PR_GAIN over
     * the last PR_WINDOW steps (a flat direction, such as a nugget heading
     * to 0, would take the simplex far for nothing) */
    for (int it = 1, prev = 0; it <= PR_INNER_STEPS; it++) {
        double fm;
        if (gsl_multimin_fminimizer_iterate(pr->nm) ||
            gsl_multimin_test_size(gsl_multimin_fminimizer_size(pr->nm), PR_SIMPLEX) != GSL_CONTINUE)
            break;
        fm = gsl_multimin_fminimizer_minimum(pr->nm);
        if (it % PR_WINDOW == 0) {
            if (prev && f - fm < PR_GAIN)
                break;
            f = fm, prev = 1;
        }
    }
    f = gsl_multimin_fminimizer_minimum(pr->nm);
    {
        const gsl_vector *x = gsl_multimin_fminimizer_x(pr->nm);
        for (size_t i = 0, m = 0; i < k; i++)
            un[i] = i == pr->j ? t : gsl_vector_get(x, m++);
    }
    return below(pr, f, un);
}

/* Did the search box, not the data, end the interval at t?  When another
 * parameter sits at the edge of its box at the end's profile point, the
 * profile there is optimised again with that edge moved PR_WIDEN further
 * out: a drop by more than PR_RELEASE means the box held the profile up
 * (var's upper end while the scale runs away), a smaller one that the data
 * end it (the nugget's, there). */
#define PR_WIDEN 2.302585092994046 /* ln 10 */
#define PR_RELEASE 0.5

static int ran_away(profile *pr, double t)
{
    nl_fit_params *p = pr->d->p;
    double uhi[NL_FIT_MAX_PARAMS], *better = pr->better, e;
    int out = 0;
    nl_fit_params_from_u(p, pr->last);
    memcpy(uhi, p->uhi, sizeof uhi);
    for (size_t k = 0; k < p->nfree; k++)
        if (k != pr->j && nl_fit_params_runaway(p, k))
            p->uhi[p->free_idx[k]] += PR_WIDEN, out = 1;
    if (!out)
        return 0;
    memcpy(pr->u, pr->last, p->nfree * sizeof *pr->u);
    pr->better = NULL;
    e = excess(t, pr);
    pr->better = better;
    memcpy(p->uhi, uhi, sizeof uhi);
    return e < -PR_RELEASE;
}

/* The end of the interval on side dir (+1 upper, -1 lower) in transformed
 * units, or dir x infinity when the profile stays below the cutoff for
 * PR_REACH units; se: the Hessian's standard error of u_j (a first step). */
static double find_end(profile *pr, gsl_root_fsolver *rs, const double *u_hat, double se, int dir)
{
    size_t j = pr->j;
    double step = isfinite(se) && se > 0 ? fmin(1.96 * se, PR_REACH) : 0.5, a = u_hat[j], b, lo, hi;
    gsl_function F = {excess, pr};
    memcpy(pr->u, u_hat, pr->d->p->nfree * sizeof *pr->u);
    for (;;) {
        b = u_hat[j] + dir * step;
        if (excess(b, pr) >= 0 || pr->found)
            break;
        if (step >= PR_REACH)
            return dir * INFINITY;
        a = b;
        step = fmin(2 * step, PR_REACH);
    }
    lo = fmin(a, b), hi = fmax(a, b);
    if (pr->found || gsl_root_fsolver_set(rs, &F, lo, hi))
        return b; /* no sign change on a second look: the conservative end */
    for (int it = 0; it < PR_ROOT_STEPS; it++) {
        if (gsl_root_fsolver_iterate(rs) || pr->found)
            break;
        lo = gsl_root_fsolver_x_lower(rs), hi = gsl_root_fsolver_x_upper(rs);
        if (gsl_root_test_interval(lo, hi, PR_TOL, 0) != GSL_CONTINUE)
            break;
    }
    b = gsl_root_fsolver_root(rs);
    return ran_away(pr, b) ? dir * INFINITY : b;
}

/* A transformed value back to the parameter's (infinities to the domain's
 * edges, or to the ends of its fit range). */
static double value_of(const nl_fit_params *p, size_t k, double u)
{
    size_t i = p->free_idx[k];
    double v = p->tr[i] == NL_FIT_LOG ? exp(u) : p->hi[i] / (1 + exp(-u));
    return p->param[i]->fit_hi > 0 ? fmin(fmax(v, p->param[i]->fit_lo), p->param[i]->fit_hi) : v;
}

int nl_fit_profile(nl_fit_mldata *d, const double *u_hat, double f_hat, const double *cov, int which,
                   double *lower, double *upper, unsigned *flags, double *better)
{
    nl_fit_params *p = d->p;
    size_t k = p->nfree;
    profile pr = {d, 0, 0, {0}, f_hat + PR_CHI2, NULL, f_hat, better, 0, 0, {0}};
    gsl_root_fsolver *rs = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
    int st = NL_OK;
    for (size_t i = 0; i < p->np; i++)
        lower[i] = upper[i] = NAN;
    if (k > 1)
        pr.nm = gsl_multimin_fminimizer_alloc(gsl_multimin_fminimizer_nmsimplex2, k - 1);
    if (!rs || (k > 1 && !pr.nm)) {
        st = NL_ERROR(NL_ENOMEM, "out of memory");
        goto done;
    }
    for (size_t j = 0; j < k; j++) {
        size_t q = p->free_idx[j];
        double se = sqrt(cov[j * k + j]), lo, hi;
        if ((flags[j] & NL_FIT_PARAM_SINGULAR) || (which == NL_FIT_INTERVALS_SCALE && p->param[q]->role != NL_ROLE_SCALE))
            continue;
        pr.j = j;
        lo = find_end(&pr, rs, u_hat, se, -1);
        hi = pr.found ? lo : find_end(&pr, rs, u_hat, se, +1);
        if (pr.found) {
            st = NL_FIT_PROFILE_LOWER;
            break;
        }
        /* narrower than the solver resolves: no curvature the data give */
        if (hi - lo < 2 * PR_TOL) {
            flags[j] |= NL_FIT_PARAM_SINGULAR;
            continue;
        }
        lower[q] = value_of(p, j, lo);
        upper[q] = value_of(p, j, hi);
    }
done:
    if (pr.nm)
        gsl_multimin_fminimizer_free(pr.nm);
    if (rs)
        gsl_root_fsolver_free(rs);
    nl_fit_ml_minus2l_u(d, u_hat); /* back to the optimum (values and beta) */
    return st;
}
