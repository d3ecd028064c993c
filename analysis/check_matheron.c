/* Lewis 1987, eq. (14), after Matheron (1973): the isotropic 2D
 * correlation produced by sweeping a 1D profile C_1 over every direction of
 * the plane (the turning-bands construction),
 *     C_2(r) = (2/pi) int_0^1 C_1(v r) (1 - v^2)^(-1/2) dv
 *            = (2/pi) int_0^(pi/2) C_1(r sin phi) dphi,
 * the second form (v = sin phi) free of the endpoint singularity.  C_1 is a
 * valid 1D covariance exactly when C_2 is a valid isotropic 2D one, so this
 * turns any 1D model into a 2D model that is positive definite. */
#include "check.h"
#include "../core/gsl_guard_internal.h"
#include "../core/nl_error.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <math.h>

/* Subintervals of the adaptive quadrature: an oscillatory profile at lag r
 * has about r / period oscillations over [0, pi/2], and a 21-point rule
 * resolves about one each.  GSL keeps its subintervals sorted by insertion,
 * so a lag costs up to LIMIT^2 / 2 steps and 42 LIMIT evaluations: 1000
 * keeps a failing lag near a millisecond.  The whole call stops after
 * MAX_EVALS evaluations of the profile (about ten seconds for expr:). */
enum { LIMIT = 1000 };
#define MAX_EVALS 1e7

struct sweep {
    const nl_model *m;
    double r;
    double *evals; /* evaluations so far, over every lag */
};

static double integrand(double phi, void *p)
{
    const struct sweep *s = p;
    double lag = s->r * sin(phi);
    if (++*s->evals > MAX_EVALS)
        return NAN; /* ends the quadrature at its next test */
    return nl_model_acf(s->m, 1, &lag);
}

/* One C_2(r): adaptive Gauss-Kronrod (21 points) on [0, pi/2]; the
 * tolerance 1e-13 R(0) absolute, 1e-12 relative. */
static int one(const nl_model *m, double r, double r0, gsl_integration_workspace *w, double *evals, double *out)
{
    struct sweep s = {m, r, evals};
    gsl_function f = {integrand, &s};
    double v, err;
    int st = gsl_integration_qag(&f, 0, M_PI / 2, 1e-13 * r0, 1e-12, LIMIT, GSL_INTEG_GAUSS21, w, &v, &err);
    if (*evals > MAX_EVALS)
        return NL_ERROR(NL_ETOOBIG, "eq. (14) at lag %g: over %.0e evaluations of %s in all; expected fewer or "
                        "smaller lags", r, MAX_EVALS, nl_model_spec(m));
    if (st == GSL_EMAXITER || st == GSL_EROUND)
        return NL_ERROR(NL_ETOOBIG, "eq. (14) at lag %g: the integral did not converge within %d subintervals (%s): "
                        "%s varies too often over the sweep at this lag; expected smaller lags", r, LIMIT,
                        nl_gsl_reason(st), nl_model_spec(m));
    if (st || !isfinite(v))
        return NL_ERROR(NL_EFAIL, "eq. (14) at lag %g: the integral did not converge (%s)", r,
                        st ? nl_gsl_reason(st) : "not finite");
    *out = 2 / M_PI * v;
    return NL_OK;
}

int nl_check_matheron_2d(const nl_model *m, size_t n, const double *r, double *c2)
{
    double zero = 0, r0, evals = 0;
    gsl_integration_workspace *w;
    int st = NL_OK;
    if (!nl_model_has_acf(m) || nl_model_check_dim(m, 1))
        return NL_ERROR(NL_EINVAL, "%s: eq. (14) sweeps a 1D profile R(t); expected a model defined by R in 1D",
                        nl_model_spec(m));
    r0 = nl_model_acf(m, 1, &zero);
    if (!(r0 > 0) || !isfinite(r0))
        return NL_ERROR(NL_EINVAL, "%s: R(0) = %g; expected a positive variance", nl_model_spec(m), r0);
    for (size_t i = 0; i < n; i++)
        if (!(r[i] >= 0) || !isfinite(r[i]))
            return NL_ERROR(NL_EINVAL, "eq. (14): expected lags >= 0, got %g", r[i]);
    nl_gsl_enter();
    if (!(w = gsl_integration_workspace_alloc(LIMIT)))
        st = NL_ERROR(NL_ENOMEM, "out of memory");
    for (size_t i = 0; !st && i < n; i++)
        st = r[i] == 0 ? (c2[i] = r0, NL_OK) : one(m, r[i], r0, w, &evals, &c2[i]);
    gsl_integration_workspace_free(w);
    nl_gsl_leave();
    return st;
}
