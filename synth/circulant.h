/* Circulant embedding (Dietrich and Newsam 1993; Wood and Chan 1994): an
 * exact stationary Gaussian field on a NON-periodic grid.
 *
 * The n_a-sample grid is embedded in a periodic grid of m_a >= 2 (n_a - 1)
 * samples (m_a even and 2, 3, 5-smooth for FFTW), on which the wrapped R is
 * a circulant covariance whose eigenvalues are the DFT of its first row.
 * When all are non-negative (the clamping rule of synth/fft.h), periodic
 * FFT synthesis on the m grid cropped to the first n_a samples per axis has
 * covariance exactly R(lag) for every pair of the n grid.  A negative
 * eigenvalue beyond that rule doubles m (up to max_factor * n per axis);
 * a model whose embedding never becomes non-negative is refused
 * (NL_ENOTPD) unless clamping is accepted. */
#ifndef NL_SYNTH_CIRCULANT_H
#define NL_SYNTH_CIRCULANT_H

#include "fft.h"

typedef struct {
    size_t m[3];          /* embedding size per axis */
    double min_eigenvalue;/* smallest eigenvalue of the embedding covariance matrix */
    double max_eigenvalue;/* largest */
    double clamp_error;   /* covariance change from zeroing negatives, / R(0) */
    int doublings;        /* times the embedding was doubled */
} nl_synth_circulant_info;

typedef struct nl_synth_circulant_plan nl_synth_circulant_plan;

int nl_synth_circulant_plan_alloc(const nl_model *m, int dim, const size_t *n, const double *h, unsigned flags,
                               int max_factor, nl_synth_circulant_plan **out);
void nl_synth_circulant_plan_info(const nl_synth_circulant_plan *p, nl_synth_circulant_info *info);
/* Not thread-safe: the plan holds the embedding-size work field. */
int nl_synth_circulant_execute(const nl_synth_circulant_plan *p, uint64_t seed, nl_field *out);
void nl_synth_circulant_plan_free(nl_synth_circulant_plan *p);

#endif
