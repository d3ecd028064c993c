/* Radial averages over wrapped lag or frequency grids. */
#include "radial.h"
#include "../core/nl_error.h"
#include "../core/wk.h"

#include <math.h>
#include <stdlib.h>

int nl_radial(const nl_field *g, int kind, double step, size_t nbins, double *r, double *v, size_t *cnt)
{
    double unit[3] = {0, 0, 0};
    if (!(step > 0))
        return NL_ERROR(NL_EINVAL, "radial average: expected a positive bin width, got %g", step);
    for (int a = 0; a < g->dim; a++)
        unit[a] = kind == NL_GRID_FREQ ? 1.0 / ((double)g->n[a] * g->h[a]) : g->h[a];
    for (size_t b = 0; b < nbins; b++)
        r[b] = v[b] = 0, cnt[b] = 0;
    for (size_t k = 0; k < g->n[2]; k++)
        for (size_t j = 0; j < g->n[1]; j++)
            for (size_t i = 0; i < g->n[0]; i++) {
                size_t idx[3] = {i, j, k};
                double d2 = 0, d;
                size_t b;
                for (int a = 0; a < g->dim; a++) {
                    double c = nl_wrap(idx[a], g->n[a]) * unit[a];
                    d2 += c * c;
                }
                d = sqrt(d2);
                double q = floor(d / step + 0.5);
                if (!(q < (double)nbins)) /* also NaN and inf, before the conversion */
                    continue;
                b = (size_t)q;
                r[b] += d;
                v[b] += g->data[(k * g->n[1] + j) * g->n[0] + i];
                cnt[b]++;
            }
    for (size_t b = 0; b < nbins; b++) {
        r[b] = cnt[b] ? r[b] / (double)cnt[b] : NAN;
        v[b] = cnt[b] ? v[b] / (double)cnt[b] : NAN;
    }
    return NL_OK;
}
