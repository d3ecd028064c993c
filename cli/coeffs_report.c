/* noiselab coeffs: the parts of the report beyond the coefficients, the
 * correlated displacements' filters and the exact method error. */
#include "coeffs.h"
#include "../analysis/subdiv_exact.h"

#include <math.h>
#include <stdlib.h>

json_t *cli_coeffs_filter_json(const nl_subdiv_level *l, const nl_model *m, int dim)
{
    const int nc = l->nclass, M = l->taps, T = 2 * M + 1, TY = dim == 2 ? T : 1;
    json_t *taps = json_array(), *cov = json_array();
    for (int a = 0; a < nc; a++) {
        json_t *row = json_array();
        for (int b = 0; b < nc; b++) {
            const double *g = l->filt + (size_t)(a * nc + b) * (size_t)(TY * T);
            json_t *t = json_array();
            for (int py = 0; py < TY; py++)
                json_array_append_new(t, cli_json_array(g + py * T, (size_t)T));
            json_array_append_new(row, dim == 1 ? json_incref(json_array_get(t, 0)) : json_incref(t));
            json_decref(t);
        }
        json_array_append_new(taps, dim == 1 ? json_incref(json_array_get(row, 0)) : json_incref(row));
        json_decref(row);
    }
    for (int a = 0; a < nc; a++)
        for (int b = 0; b < nc; b++)
            for (int axis = 0; axis < dim; axis++)
                for (int k = 0; k <= 2 * M; k++) {
                    int mx = axis ? 0 : k, my = axis ? k : 0;
                    if (axis && k == 0)
                        continue;
                    json_array_append_new(
                        cov, json_pack("{s:s,s:s,s:[i,i],s:f,s:f}", "a", nl_subdiv_class_name(l->cls[a].cls), "b",
                                       nl_subdiv_class_name(l->cls[b].cls), "offset", mx, my, "realised",
                                       nl_subdiv_disp_realised(l, dim, a, b, mx, my), "target",
                                       nl_subdiv_disp_target(l, m, dim, NL_SUBDIV_DISP_ERROR, a, b, mx, my)));
                }
    return json_pack("{s:i,s:o,s:f,s:o}", "taps", M, "filter", taps, "filter_error", l->filt_error, "covariance",
                     cov);
}

/* One direction (dx, dy) of lags 0..n-1. */
static json_t *direction(const char *name, const double *ex, const double *tg, size_t n, long dx, long dy)
{
    json_t *lag = json_array();
    for (size_t i = 0; i < n; i++)
        json_array_append_new(lag, dy ? json_pack("[i,i]", (json_int_t)i * dx, (json_int_t)i * dy)
                                      : json_integer((json_int_t)i));
    return json_pack("{s:s,s:o,s:o,s:o}", "direction", name, "lag", lag, "exact_acf", cli_json_array(ex, n),
                     "target_acf", cli_json_array(tg, n));
}

json_t *cli_coeffs_error_json(const nl_subdiv_coeffs *c, const nl_model *m, const size_t *n, double *err)
{
    static const char *const names[] = {"x", "y", "diagonal"};
    static const long dirs[3][2] = {{1, 0}, {0, 1}, {1, 1}};
    const int dim = c->dim, nd = dim == 1 ? 1 : 3;
    size_t nl = (dim == 1 ? n[0] : (n[0] < n[1] ? n[0] : n[1])) / 2;
    double h = ldexp(c->spacing0, -c->levels);
    long *lags;
    double *ex, *tg;
    json_t *out = json_array();
    if (nl > 64)
        nl = 64;
    lags = malloc(2 * nl * sizeof *lags), ex = malloc(nl * sizeof *ex), tg = malloc(nl * sizeof *tg);
    if (!lags || !ex || !tg)
        cli_die(1, "coeffs: out of memory");
    *err = 0;
    for (int d = 0; d < nd; d++) {
        for (size_t i = 0; i < nl; i++) {
            double lag[3] = {(double)i * (double)dirs[d][0] * h, (double)i * (double)dirs[d][1] * h, 0};
            lags[2 * i] = (long)i * dirs[d][0], lags[2 * i + 1] = (long)i * dirs[d][1];
            tg[i] = nl_model_acf(m, dim, lag);
        }
        cli_check(nl_subdiv_exact_acf(c, m, n[0], dim == 2 ? n[1] : 1, nl, lags, ex));
        for (size_t i = 0; i < nl; i++)
            *err = fmax(*err, fabs(ex[i] - tg[i]) / c->r0);
        json_array_append_new(out, direction(names[d], ex, tg, nl, dirs[d][0], dim == 2 ? dirs[d][1] : 0));
    }
    free(lags), free(ex), free(tg);
    return out;
}
