/* Profiles and angular sectors of spectra on wrapped grids. */
#include "spectral.h"
#include "radial.h"
#include "../core/nl_error.h"
#include "../core/wk.h"

#include <math.h>
#include <stdlib.h>

static void radial_grid(const nl_field *P, double *step, double *fmax)
{
    *step = INFINITY, *fmax = INFINITY;
    for (int a = 0; a < P->dim; a++) {
        *step = fmin(*step, 1.0 / ((double)P->n[a] * P->h[a]));
        *fmax = fmin(*fmax, 0.5 / P->h[a]);
    }
}

size_t nl_psd_profile_size(const nl_field *P)
{
    double step, fmax;
    if (P->dim == 1)
        return P->n[0] / 2 + 1;
    radial_grid(P, &step, &fmax);
    return (size_t)floor(fmax / step) + 1;
}

int nl_psd_profile(const nl_field *P, double *freq, double *val, size_t *cnt, size_t *nf)
{
    double step, fmax;
    *nf = nl_psd_profile_size(P);
    if (P->dim == 1) {
        for (size_t i = 0; i < *nf; i++) {
            freq[i] = (double)i / ((double)P->n[0] * P->h[0]);
            val[i] = P->data[i];
        }
        return NL_OK;
    }
    radial_grid(P, &step, &fmax);
    return nl_radial(P, NL_GRID_FREQ, step, *nf, freq, val, cnt);
}

int nl_psd_model_profile(const nl_model *m, int dim, const size_t *n, const double *h, double *val, size_t *nf)
{
    int st;
    nl_field *S = nl_field_alloc(dim, n, h, &st);
    double *freq = NULL;
    size_t *cnt = NULL;
    if (!S)
        return st;
    freq = malloc(nl_psd_profile_size(S) * sizeof *freq);
    cnt = malloc(nl_psd_profile_size(S) * sizeof *cnt);
    if (!freq || !cnt)
        st = NL_ERROR(NL_ENOMEM, "out of memory for the model's profile");
    else if (!(st = nl_wk_sample_spectrum(m, S)))
        st = nl_psd_profile(S, freq, val, cnt, nf);
    free(freq), free(cnt);
    nl_field_free(S);
    return st;
}

int nl_psd_sectors(const nl_field *P, size_t nsec, double flo, double fhi, double *sector, double *aniso)
{
    size_t *sc;
    double mn = INFINITY, mx = 0;
    if (P->dim != 2 || nsec == 0 || !(flo >= 0 && fhi >= flo))
        return NL_ERROR(NL_EINVAL, "sectors: expected a 2D spectrum, sectors >= 1 and 0 <= fmin <= fmax, got %dD, "
                        "%zu, %g, %g", P->dim, nsec, flo, fhi);
    if (!(sc = calloc(nsec, sizeof *sc)))
        return NL_ERROR(NL_ENOMEM, "out of memory for %zu sectors", nsec);
    for (size_t b = 0; b < nsec; b++)
        sector[b] = 0;
    for (size_t j = 0; j < P->n[1]; j++)
        for (size_t i = 0; i < P->n[0]; i++) {
            double fx = (double)nl_wrap(i, P->n[0]) / (double)P->n[0], fy = (double)nl_wrap(j, P->n[1]) / (double)P->n[1];
            double r = hypot(fx, fy), a = atan2(fy, fx);
            if (r < flo || r > fhi)
                continue;
            if (a < 0)
                a += M_PI;
            size_t b = (size_t)(a / M_PI * (double)nsec) % nsec;
            sector[b] += P->data[j * P->n[0] + i], sc[b]++;
        }
    for (size_t b = 0; b < nsec; b++) {
        sector[b] = sc[b] ? sector[b] / (double)sc[b] : NAN;
        mn = fmin(mn, sector[b]), mx = fmax(mx, sector[b]);
    }
    *aniso = mx / mn;
    free(sc);
    return NL_OK;
}
