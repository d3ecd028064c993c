/* The defaults of an interpolated noise lattice, and the check of a
 * spectrum model on its output grid. */
#include "lattice.h"
#include "fft.h"
#include "../core/mem.h"
#include "../core/nl_error.h"
#include "../core/wk.h"

#include <math.h>

double nl_synth_lattice_default_cell(const size_t *n) { return (double)n[0] / 4; }

int nl_synth_lattice_default_octaves(double cell0)
{
    int O;
    for (O = 1; cell0 / pow(2, O) >= 2 && O < NL_LATTICE_MAX_OCTAVES; O++)
        ;
    return O;
}

/* The positive-definiteness rule of fft (synth/fft.h) on the output grid:
 * the weight fit ignores where a spectrum model is negative, so the
 * negative mass, sampled on the grid at unit spacing (the lattice's units),
 * must stay within NL_SYNTH_FFT_CLAMP_TOL of the positive mass. */
int nl_synth_lattice_check_grid(const nl_model *m, int dim, const size_t *n, unsigned flags, double *clamp_error)
{
    const double one[3] = {1, 1, 1};
    size_t h0 = n[0] / 2 + 1, rows = 1, negs = 0;
    double *S, neg = 0, pos = 0, lmin = INFINITY, err;
    int st;
    *clamp_error = 0;
    if (!nl_model_is_spectral(m))
        return NL_OK;
    for (int a = 1; a < dim; a++)
        rows *= n[a];
    if ((st = nl_wk_sample_spectrum_half(m, dim, n, one, &S)))
        return st;
    for (size_t k = 0; k < rows * h0; k++) {
        size_t i = k % h0;
        double w = i == 0 || 2 * i == n[0] ? 1 : 2;
        if (S[k] < 0)
            neg -= w * S[k], negs += (size_t)w;
        else
            pos += w * S[k];
        lmin = fmin(lmin, S[k]);
    }
    nl_free(S);
    err = pos > 0 ? neg / pos : INFINITY;
    if (!(pos > 0))
        return NL_ERROR(NL_EINVAL, "%s: the sampled spectrum has no positive part on this grid", nl_model_spec(m));
    if (err > NL_SYNTH_FFT_CLAMP_TOL && !(flags & NL_SYNTH_LATTICE_CLAMP))
        return NL_ERROR(NL_ENOTPD, "%s: not positive definite on this grid: min spectrum %.3g; the lattice would drop "
                        "the %zu negative values, changing the covariance by up to %.2g of R(0), above %.0e (use "
                        "--clamp to accept)", nl_model_spec(m), lmin, negs, err, NL_SYNTH_FFT_CLAMP_TOL);
    if (err > NL_SYNTH_FFT_CLAMP_TOL)
        *clamp_error = err;
    return NL_OK;
}
