/* Weighted least squares of a model semivariogram to an empirical one
 * (Cressie 1985; gstat's fit.variogram, fit.method 1, 2, 6 and 7), by GSL's
 * nonlinear least squares. */
#include "fit_internal.h"
#include "../core/gsl_guard_internal.h"
#include "../core/nl_error.h"

#include <gsl/gsl_blas.h>
#include <gsl/gsl_multifit_nlinear.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    nl_fit_params *p;       /* parameters, updated at each evaluation */
    const double *h, *g, *n;/* used bins: distance, semivariance, pairs */
    size_t m;               /* used bins */
    nl_fit_weights weights; /* the weighting */
    double *w;              /* m weights held fixed (reweighted, distance) */
    unsigned flags[NL_FIT_MAX_PARAMS]; /* the free parameters' NL_FIT_PARAM_* of the last solve */
    double rcond;           /* J^T J's reciprocal condition number, last solve */
} wls_data;

/* Outer steps of the reweighted fit at most, and its stop: every free
 * transformed parameter moved less than this in one step. */
#define WLS_REWEIGHT_STEPS 200
#define WLS_REWEIGHT_TOL 1e-10

/* gamma(h) = R(0) - R(h) of the current parameters at the m distances. */
static int model_gamma(nl_fit_params *p, const double *h, size_t m, double *out)
{
    nl_model *mod;
    double zero[3] = {0, 0, 0}, r0;
    int st = nl_fit_params_model(p, &mod);
    if (st)
        return st;
    r0 = nl_model_acf(mod, p->dim, zero);
    for (size_t j = 0; j < m; j++) {
        double lag[3] = {h[j], 0, 0};
        out[j] = r0 - nl_model_acf(mod, p->dim, lag);
    }
    nl_model_free(mod);
    return NL_OK;
}

static int residuals(const gsl_vector *x, void *params, gsl_vector *f)
{
    wls_data *d = params;
    double *gm = malloc(d->m * sizeof *gm);
    if (!gm)
        return GSL_ENOMEM;
    nl_fit_params_from_u(d->p, x->data);
    if (model_gamma(d->p, d->h, d->m, gm)) {
        free(gm);
        return GSL_EDOM;
    }
    for (size_t j = 0; j < d->m; j++) {
        double r = d->weights == NL_FIT_CRESSIE ? sqrt(d->n[j]) * (d->g[j] / gm[j] - 1)
                 : d->weights == NL_FIT_PAIRS   ? sqrt(d->n[j]) * (gm[j] - d->g[j])
                 : d->weights == NL_FIT_OLS     ? gm[j] - d->g[j]
                                                : sqrt(d->w[j]) * (gm[j] - d->g[j]);
        gsl_vector_set(f, j, isfinite(r) ? r : 1e150);
    }
    free(gm);
    return GSL_SUCCESS;
}

/* Automatic start: the sill from the far half of the bins, the scale where gamma first reaches 1 - 1/e of the sill
 * (times the family's factor: twice that for the spherical model's range). */
static void wls_start(nl_fit_params *p, const wls_data *d, const double *start)
{
    double sill = 0, cnt = 0, scale = d->h[d->m - 1] / 3;
    for (size_t j = d->m / 2; j < d->m; j++)
        sill += d->g[j], cnt++;
    sill = cnt > 0 && sill > 0 ? sill / cnt : 1;
    for (size_t j = 0; j < d->m; j++)
        if (d->g[j] >= (1 - exp(-1)) * sill) {
            scale = d->h[j];
            break;
        }
    nl_fit_params_start(p, sill, scale, start);
}

static size_t used_bins(const double *h, const double *g, const double *n, size_t nbins, double *buf)
{
    size_t m = 0;
    for (size_t j = 0; j < nbins; j++)
        if (n[j] > 0 && isfinite(h[j]) && h[j] > 0 && isfinite(g[j]) && g[j] >= 0) {
            buf[m] = h[j];
            buf[nbins + m] = g[j];
            buf[2 * nbins + m] = n[j];
            m++;
        }
    return m;
}

/* s^2 (J^T J)^-1 where J^T J is regular (nl_fit_info_check), else the
 * flagged parameters NaN and the others from the pseudo-inverse; the
 * parameters at a bound of their fit range are flagged too. */
static void wls_covariance(wls_data *d, const gsl_matrix *J, double ss, gsl_matrix *C, double *cov)
{
    size_t k = d->p->nfree;
    double s2 = d->m > k ? ss / (double)(d->m - k) : NAN, info[NL_FIT_MAX_PARAMS * NL_FIT_MAX_PARAMS];
    int any = 0;
    gsl_matrix_view I = gsl_matrix_view_array(info, k, k);
    memset(d->flags, 0, sizeof d->flags);
    nl_fit_params_at_bound(d->p, d->flags);
    gsl_blas_dgemm(CblasTrans, CblasNoTrans, 1.0, J, J, 0.0, &I.matrix);
    d->rcond = nl_fit_info_check(info, k, d->flags, cov);
    for (size_t i = 0; i < k; i++)
        any |= d->flags[i] != 0;
    if (!any && gsl_multifit_nlinear_covar(J, 0.0, C) == GSL_SUCCESS)
        memcpy(cov, C->data, k * k * sizeof *cov);
    for (size_t i = 0; i < k * k; i++)
        cov[i] *= s2;
}

static int solve(wls_data *d, nl_fit_result *res, double *cov)
{
    const gsl_multifit_nlinear_type *T = gsl_multifit_nlinear_trust;
    gsl_multifit_nlinear_parameters fp = gsl_multifit_nlinear_default_parameters();
    gsl_multifit_nlinear_fdf fdf = {residuals, NULL, NULL, d->m, d->p->nfree, d, 0, 0, 0};
    gsl_multifit_nlinear_workspace *w = gsl_multifit_nlinear_alloc(T, &fp, d->m, d->p->nfree);
    gsl_vector *u = gsl_vector_alloc(d->p->nfree);
    gsl_matrix *C = gsl_matrix_alloc(d->p->nfree, d->p->nfree);
    int info = 0, st = NL_OK, gst;
    if (!w || !u || !C) {
        st = NL_ERROR(NL_ENOMEM, "out of memory");
        goto done;
    }
    nl_fit_params_to_u(d->p, u->data);
    if ((gst = gsl_multifit_nlinear_init(u, &fdf, w))) {
        st = NL_ERROR(NL_EFAIL, "fit: the model cannot be evaluated at the start: %s", nl_gsl_reason(gst));
        goto done;
    }
    gst = gsl_multifit_nlinear_driver(500, 1e-10, 1e-10, 1e-12, NULL, NULL, &info, w);
    res->converged = gst == GSL_SUCCESS;
    res->iterations = (int)gsl_multifit_nlinear_niter(w);
    nl_fit_params_from_u(d->p, w->x->data);
    {
        gsl_vector *f = gsl_multifit_nlinear_residual(w);
        double ss;
        gsl_blas_ddot(f, f, &ss);
        res->objective = ss;
        if (!isfinite(ss) || ss >= 1e299) {
            st = NL_ERROR(NL_EFAIL, "fit: no finite objective near the data (model %s)", d->p->family);
            goto done;
        }
        wls_covariance(d, gsl_multifit_nlinear_jac(w), ss, C, cov);
    }
done:
    gsl_matrix_free(C);
    gsl_vector_free(u);
    gsl_multifit_nlinear_free(w);
    return st;
}

/* Fixed weights: N_j / h_j^2 (distance), or N_j / g(h_j)^2 of the current
 * parameters (reweighted); NL_EFAIL where the model's gamma is 0. */
static int set_weights(wls_data *d)
{
    if (d->weights == NL_FIT_REWEIGHTED) {
        int st = model_gamma(d->p, d->h, d->m, d->w);
        if (st)
            return st;
    }
    for (size_t j = 0; j < d->m; j++) {
        double s = d->weights == NL_FIT_DISTANCE ? d->h[j] : d->w[j];
        d->w[j] = d->n[j] / (s * s);
        if (!isfinite(d->w[j]))
            return NL_ERROR(NL_EFAIL, "fit: the model's semivariogram is 0 at distance %g: no weight N/gamma^2",
                            d->h[j]);
    }
    return NL_OK;
}

/* Least squares with weights held fixed, re-computed from the fitted model
 * after each solve until the parameters stop moving (gstat's fit.method 2
 * fixed point); one solve for the other weightings. */
static int solve_weighted(wls_data *d, nl_fit_result *res, double *cov)
{
    int st = NL_OK, steps = 0, moved = 1;
    double u0[NL_FIT_MAX_PARAMS], u1[NL_FIT_MAX_PARAMS];
    if (d->weights == NL_FIT_CRESSIE || d->weights == NL_FIT_PAIRS || d->weights == NL_FIT_OLS)
        return solve(d, res, cov);
    while (!st && moved && steps++ < WLS_REWEIGHT_STEPS) {
        int before = res->iterations;
        nl_fit_params_to_u(d->p, u0);
        if ((st = set_weights(d)) || (st = solve(d, res, cov)))
            break;
        res->iterations += before;
        nl_fit_params_to_u(d->p, u1);
        moved = 0;
        for (size_t k = 0; d->weights == NL_FIT_REWEIGHTED && k < d->p->nfree; k++)
            moved |= fabs(u1[k] - u0[k]) >= WLS_REWEIGHT_TOL;
    }
    /* reweighted: converged when the weights' fixed point is (the last
     * solve starts at its answer, where GSL may report no progress) */
    if (d->weights == NL_FIT_REWEIGHTED)
        res->converged = !moved;
    return st;
}

static int fit_variogram(const double *distance, const double *gamma, const double *pairs, size_t nbins, int dim,
                         const nl_fit_options *o, nl_fit_result *res)
{
    nl_fit_params p;
    wls_data d;
    double cov[NL_FIT_MAX_PARAMS * NL_FIT_MAX_PARAMS], *buf;
    int st;
    memset(res, 0, sizeof *res);
    res->mean = NAN;
    if ((st = nl_fit_params_init(o, dim, &p)))
        return st;
    if (p.nfree == 0)
        return NL_ERROR(NL_EINVAL, "fix: every parameter of %s is fixed; expected at least one free", p.family);
    if ((unsigned)o->weights > NL_FIT_OLS)
        return NL_ERROR(NL_EINVAL, "weights: expected cressie, pairs, reweighted, distance or ols, got %d",
                        (int)o->weights);
    if (!(buf = malloc((4 * nbins + 1) * sizeof *buf)))
        return NL_ERROR(NL_ENOMEM, "out of memory");
    d = (wls_data){.p = &p, .h = buf, .g = buf + nbins, .n = buf + 2 * nbins,
                   .m = used_bins(distance, gamma, pairs, nbins, buf), .weights = o->weights, .w = buf + 3 * nbins};
    for (size_t j = 0; j < nbins && d.m < p.nfree + 1; j++)
        if (pairs[j] > 0 && gamma[j] == INFINITY) {
            free(buf);
            return NL_ERROR(NL_EINVAL, "fit: the variogram overflows (infinite at distance %g): expected values "
                            "below about 1e154 (rescale them)", distance[j]);
        }
    if (d.m < p.nfree + 1) {
        free(buf);
        return NL_ERROR(NL_EINVAL, "fit: %zu variogram bins with pairs; expected at least %zu (the %zu free "
                        "parameters + 1)", d.m, p.nfree + 1, p.nfree);
    }
    for (size_t j = 0; j < d.m && d.g[j] == 0; j++)
        if (j == d.m - 1) {
            free(buf);
            return NL_ERROR(NL_EINVAL, "fit: no variation: the variogram is 0 in all %zu bins (the values are equal, "
                            "or differ by less than about 1e-154, whose squares underflow); nothing to fit", d.m);
        }
    wls_start(&p, &d, o->start);
    st = solve_weighted(&d, res, cov);
    if (!st) {
        res->nobs = d.m;
        res->aic = (double)d.m * log(res->objective / (double)d.m) + 2.0 * (double)p.nfree;
        if (!(st = nl_fit_params_result(&p, cov, NULL, NULL, res))) {
            nl_fit_result_flags(&p, d.flags, res);
            res->rcond = d.rcond;
        }
    }
    free(buf);
    return st;
}

int nl_fit_variogram(const double *distance, const double *gamma, const double *pairs, size_t nbins, int dim,
                     const nl_fit_options *o, nl_fit_result *res)
{
    int st;
    nl_gsl_enter();
    st = fit_variogram(distance, gamma, pairs, nbins, dim, o, res);
    nl_gsl_leave();
    return st;
}
