/* Interpolated noise lattice (Perlin's gradient noise) and its sum over
 * octaves approximating a target spectrum (Lewis 1987, "Comparison of
 * Stochastic Synthesis Methods": "interpolated noise lattice").
 *
 * Basis: gradient noise of cell c samples: at every lattice point a random
 * gradient (1D: uniform in [-1, 1]; 2D: a unit vector at a uniform angle),
 * from nl_rng_uniform(seed, NL_LATTICE_STREAM + octave, lattice index); the
 * value between lattice points blends the corners' linear ramps with the
 * quintic fade 6t^5 - 15t^4 + 10t^3 (Perlin 2002).  Any sample can be
 * computed alone.
 *
 * Octaves: c_o = c_0 / 2^o.  The basis spectrum is measured once at plan
 * time (the mean periodogram of 8 periodic realizations at cell 16, radial
 * in 2D) and rescaled to each cell: S_o(f) = S_b(f c_o / 16) (c_o / 16)^dim.
 * The weights v_o = w_o^2 >= 0 minimise the relative squared error of
 * sum_o v_o S_o(f) against the target on 96 log-spaced frequencies from
 * half the coarsest octave's peak f_0 to Nyquist (GSL weighted least
 * squares, octaves with negative weights dropped and the rest refitted).
 * The sum's spectrum is sum_o w_o^2 S_o(f).
 *
 * Leakage (Lewis: "the low frequency power in the noise lattice is not
 * removed and cannot be removed in summation"): the fraction of each
 * octave's power below f_o / sqrt 2, reported per octave. */
#ifndef NL_SYNTH_LATTICE_H
#define NL_SYNTH_LATTICE_H

#ifdef __cplusplus
extern "C" {
#endif

#include "../core/field.h"
#include "../core/model.h"

#include <stdint.h>

#define NL_LATTICE_STREAM 500u
#define NL_LATTICE_MAX_OCTAVES 16

typedef struct {
    int octaves;                          /* number of octaves */
    double cell[NL_LATTICE_MAX_OCTAVES];     /* cell size per octave, samples */
    double weight[NL_LATTICE_MAX_OCTAVES];   /* amplitude w_o */
    double peak[NL_LATTICE_MAX_OCTAVES];     /* f_o, cycles per sample */
    double leakage[NL_LATTICE_MAX_OCTAVES];  /* fraction of octave power below its band */
    size_t negatives;                     /* fit frequencies where the target is negative (clamped) */
    double clamp_error;                   /* their power relative to the positive power (0: none) */
} nl_synth_lattice_plan;

#define NL_SYNTH_LATTICE_CLAMP 1u  /* flag: fit a target that is negative somewhere, without those values */

/* The plan is a plain struct the caller owns and nl_synth_lattice_plan_init
 * fills in: it allocates nothing, so there is nothing to free.
 * Thread safety: the basis spectrum of each dimension is measured once per
 * process into static tables, on the first plan of that dimension; make the
 * first plan of each dimension from one thread.  After that, plans are
 * reentrant, and executing one plan concurrently into distinct fields is
 * safe (execute itself runs OpenMP loops above 65536 samples). */

/* Plan the octaves for model m on a dim-D grid (spacing 1 sample; the
 * model's lags in samples): c_0 = cell0, `octaves` octaves (cell >= 2).
 * Errors: NL_EINVAL for dim not 1 or 2, octaves outside
 * 1..NL_LATTICE_MAX_OCTAVES, cells below 2 samples, a model without a
 * closed-form spectrum in dim dimensions or with a nugget (lattice noise is
 * smooth between nodes: white noise has no closed form there), or a fit
 * whose octave sum carries less than 1e-3 of the target's power over the
 * fit band (every weight 0: a spectrum falling faster than the basis, such
 * as a Gaussian one); NL_ENOMEM.  (GSL's weighted
 * least squares, an SVD of finite values, does not fail; it would give
 * NL_EFAIL.)  The positive-definiteness rule of the other methods holds on
 * the target at the 96 fit frequencies: a target that is not finite there
 * is NL_EINVAL; one that is negative there is NL_ENOTPD, or with flags
 * NL_SYNTH_LATTICE_CLAMP (else 0) fitted without those values,
 * p->negatives and p->clamp_error (their power, weighted by f^dim on the
 * log-spaced frequencies, relative to the positive power) saying so. */
int nl_synth_lattice_plan_init(const nl_model *m, int dim, double cell0, int octaves, unsigned flags,
                               nl_synth_lattice_plan *p);

/* The basis spectrum at cell c (samples) and frequency f (cycles per
 * sample), dim 1 or 2, per (cycles per sample)^dim; 0 from 8 / c up.  0
 * everywhere when the measurement could not run (out of memory);
 * nl_synth_lattice_plan_init reports that case. */
double nl_synth_lattice_basis_spectrum(int dim, double c, double f);

/* x = sum_o w_o noise_o into out (1D or 2D, periodic when every cell
 * divides the size, otherwise a window at the origin).  NL_EINVAL: out
 * 3D. */
int nl_synth_lattice_execute(const nl_synth_lattice_plan *p, uint64_t seed, nl_field *out);

/* Defaults (synth/lattice_octaves.c; pure): the largest cell, n[0] / 4
 * samples, and the octaves from cell0 down to a cell of 2 samples or more
 * (the O with cell0 / 2^O < 2, at least 1, at most NL_LATTICE_MAX_OCTAVES). */
double nl_synth_lattice_default_cell(const size_t *n);
int nl_synth_lattice_default_octaves(double cell0);

/* The positive-definiteness rule of fft (synth/fft.h) for a spectrum model
 * on the dim-D output grid n (unit spacing): the lattice's weight fit
 * ignores where the spectrum is negative, so the negative mass relative to
 * the positive must stay within NL_SYNTH_FFT_CLAMP_TOL, or flags
 * NL_SYNTH_LATTICE_CLAMP (else 0) accepts it and *clamp_error receives that
 * ratio (0 when within, and for models that are not spectrum: models, which
 * are not checked here).  Returns NL_OK, NL_ENOTPD (beyond the tolerance
 * without the flag), NL_EINVAL (no positive part), or the codes of nl_wk_sample_spectrum_half (a spectrum that is not
 * finite or not even; NL_ETOOBIG, NL_ENOMEM).  Not thread-safe (it may plan
 * FFTW). */
int nl_synth_lattice_check_grid(const nl_model *m, int dim, const size_t *n, unsigned flags, double *clamp_error);

/* The Wiener-interpolated noise lattice (Lewis 1987, "Comparison of
 * Stochastic Synthesis Methods": "a variation of the interpolated noise
 * lattice method [17] substitutes Wiener interpolation, which provides
 * greater spectral control (with some restrictions) and eliminates the
 * spectral summation"; [17] is unpublished, so the construction is our
 * reading).  One lattice of nodes every `cell` samples carries values with
 * the target's own covariance R at the node lags (periodic FFT synthesis
 * on the lattice, synth/fft.h, seed as given: exact there), and every
 * sample is the simple-kriging (Wiener) estimate from the
 * NL_LATTICE_WIENER_K nodes on each side (2K in 1D, (2K)^2 in 2D) of its
 * cell:  x(t) = w(u)^T L, w(u) = C^+ r(u), C the nodes' covariance, r(u)
 * their covariance with the sample at offset u in the cell (SVD
 * pseudo-inverse, singular values below 1e-13 of the largest dropped, as
 * for singular processes).  The weights depend on u only: c^dim solves at
 * plan time.  At the nodes x equals the lattice (w = delta), so the ACF is
 * exact at node lags; between nodes the estimate misses the error variance
 * e(u) = R(0) - w(u)^T r(u) (reported), the "restriction": the spectrum
 * above the lattice's Nyquist frequency 1 / (2 cell) is not synthesised. */
#define NL_LATTICE_WIENER_K 2
#define NL_LATTICE_WIENER_MAX_CELL 64

typedef struct nl_synth_lattice_wiener_plan nl_synth_lattice_wiener_plan;

typedef struct {
    int cell;              /* node spacing, samples */
    size_t nodes[2];       /* lattice nodes per axis (1 beyond dim) */
    double variance;       /* R(0) */
    double mean_error;     /* mean of e(u) / R(0) over the cell's offsets */
    double max_error;      /* largest e(u) / R(0) */
    int rank;              /* rank of C kept (of (2K)^dim) */
    size_t negatives;      /* lattice FFT eigenvalues clamped (synth/fft.h) */
} nl_synth_lattice_wiener_info;

/* Plan for model m (needs R: models given by R, and power:) on a dim-D
 * output grid n[] (1 or 2 axes, unit spacing in samples, each n[a] a
 * multiple of cell with at least 2K nodes), nodes every cell samples
 * (1..NL_LATTICE_WIENER_MAX_CELL).  flags: NL_SYNTH_LATTICE_CLAMP passes
 * NL_SYNTH_FFT_CLAMP to the lattice's FFT plan.  Free with
 * nl_synth_lattice_wiener_plan_free.  Errors: NL_EINVAL (dim, cell, sizes;
 * a model without R in closed form or with a nugget, R not finite at a
 * node lag), NL_ENOTPD (the lattice's FFT refuses the model, synth/fft.h),
 * NL_ETOOBIG, NL_ENOMEM, NL_EFAIL.  Not thread-safe (plans FFTW). */
int nl_synth_lattice_wiener_plan_alloc(const nl_model *m, int dim, const size_t *n, int cell, unsigned flags,
                                       nl_synth_lattice_wiener_plan **out);

void nl_synth_lattice_wiener_plan_info(const nl_synth_lattice_wiener_plan *p, nl_synth_lattice_wiener_info *info);

/* The weights of offset u (u[0..dim-1] in 0..cell-1) into w ((2K)^dim
 * doubles, node (d_x, d_y) at w[d_y 2K + d_x], node d at offset
 * (d - K + 1) cell from the cell's first node).  Thread-safe. */
void nl_synth_lattice_wiener_weights(const nl_synth_lattice_wiener_plan *p, const int *u, double *w);

/* The realization for seed into out (the plan's dim and n); *lattice (may
 * be NULL) receives a copy of the node values (nodes[0] x nodes[1],
 * row-major) for inspection, allocated with nl_alloc (caller frees with
 * nl_free).  NL_EINVAL (out does not match), NL_ENOMEM.  Executing one plan
 * concurrently into distinct fields is safe. */
int nl_synth_lattice_wiener_execute(const nl_synth_lattice_wiener_plan *p, uint64_t seed, nl_field *out,
                                    double **lattice);

void nl_synth_lattice_wiener_plan_free(nl_synth_lattice_wiener_plan *p);

/* What the lattice method's plan holds (nl_method_plan_impl of a "lattice"
 * plan, synth/method.h; owned by that plan). */
typedef struct {
    int wiener;                          /* 1: the Wiener lattice (plan); 0: Perlin octaves (perlin) */
    double cell0;                        /* Perlin: the largest cell; Wiener: the node spacing */
    int octaves;                         /* Perlin: the octaves */
    double grid_clamp_error;             /* Perlin: nl_synth_lattice_check_grid's clamp error */
    nl_synth_lattice_plan perlin;        /* Perlin: the plan */
    nl_synth_lattice_wiener_plan *plan;  /* Wiener: the plan, else NULL */
} nl_lattice_method_plan;

#ifdef __cplusplus
}
#endif

#endif
