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
 * 1..NL_LATTICE_MAX_OCTAVES, cells below 2 samples, or a model without a
 * closed-form spectrum in dim dimensions or with a nugget (lattice noise is
 * smooth between nodes: white noise has no closed form there); NL_ENOMEM.  (GSL's weighted
 * least squares, an SVD of finite values, does not fail; it would give
 * NL_EFAIL.) */
int nl_synth_lattice_plan_init(const nl_model *m, int dim, double cell0, int octaves, nl_synth_lattice_plan *p);

/* As nl_synth_lattice_plan_init (which is this with flags 0), with the
 * positive-definiteness rule of the other methods on the target at the 96
 * fit frequencies: a target that is not finite there is NL_EINVAL; one that
 * is negative there is NL_ENOTPD, or with NL_SYNTH_LATTICE_CLAMP fitted
 * without those values, p->negatives and p->clamp_error (their power,
 * weighted by f^dim on the log-spaced frequencies, relative to the positive
 * power) saying so. */
int nl_synth_lattice_plan_init_flags(const nl_model *m, int dim, double cell0, int octaves, unsigned flags,
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
 * the positive must stay within NL_SYNTH_FFT_CLAMP_TOL, or clamp accepts it
 * and *clamp_error receives that ratio (0 when within, and for models that
 * are not spectrum: models, which are not checked here).  Returns NL_OK,
 * NL_ENOTPD (beyond the tolerance without clamp), NL_EINVAL (no positive
 * part), or the codes of nl_wk_sample_spectrum_half (a spectrum that is not
 * finite or not even; NL_ETOOBIG, NL_ENOMEM).  Not thread-safe (it may plan
 * FFTW). */
int nl_synth_lattice_check_grid(const nl_model *m, int dim, const size_t *n, int clamp, double *clamp_error);

#endif
