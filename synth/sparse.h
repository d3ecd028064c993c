/* Sparse convolution: a shaped Poisson point process (Lewis GI '86, eq. 2).
 *
 *     x(p) = sum_i a_i h(p - p_i)
 * with impulses p_i on the lattice of the output grid, amplitudes a_i ~
 * N(0, 1), and the kernel h tabulated on the same lattice within
 * |offset_a| <= radius samples.  The plane is split into cells of `cell`
 * samples per axis; cell c holds a Poisson(density) number of impulses
 * (count: nl_rng_uniform2(seed, NL_SPARSE_STREAM, c, 0) by inversion; impulse
 * k: position and amplitude from nl_rng_uniform2 / nl_rng_gauss2(seed,
 * NL_SPARSE_STREAM + 1..3, c, k)), c the cell index packed as in subdivision.
 * Any sample is a pure function of the seed and its position: it sums the
 * impulses of the cells within the radius, in cell order, so a sample
 * computed alone equals the same sample of any grid, bit for bit.
 *
 * Second-order theory: x is stationary with R(d) = lambda E[a^2] sum_q
 * h(q) h(q + d), lambda = density / cell^dim impulses per sample (eq. 1 of
 * GI '86: R is the kernel's autocorrelation).  Higher cumulants are
 * kappa_n = lambda E[a^n] sum h^n, so the excess kurtosis is
 *     3 sum h^4 / (lambda (sum h^2)^2),
 * which vanishes (the field becomes Gaussian) as the density grows.
 *
 * Kernels:
 *  - model: h = IDFT(sqrt(lambda_k)) / N on a periodic grid twice the radius
 *    (lambda_k the model's covariance eigenvalues, as in synth/fft.h), so that
 *    h * h = R at every grid lag, truncated at the radius (the energy lost
 *    is reported), then scaled so that the field variance is R(0);
 *  - expression in x, y (t and r as for models), scaled to unit variance;
 *  - an exemplar: the image minus its mean, times a Hann window, scaled to
 *    the exemplar's variance (texture resynthesis).
 * An optional angle expression theta(x, y) (radians, in grid samples)
 * rotates the kernel at each impulse: h(R(-theta(p_i)) (p - p_i)), bilinear
 * in the table, for non-stationary directional noise. */
#ifndef NL_SYNTH_SPARSE_H
#define NL_SYNTH_SPARSE_H

#ifdef __cplusplus
extern "C" {
#endif

#include "../core/field.h"
#include "../core/model.h"

#include <stdint.h>

#define NL_SPARSE_STREAM 400u

/* Automatic radius: the kernel energy left outside is below this fraction;
 * by Cauchy-Schwarz the ACF then changes by at most sqrt(1e-6) = 1e-3 R(0). */
#define NL_SPARSE_ENERGY_TOL 1e-6

/* Work bound of one execution: impulses drawn plus impulses gathered over
 * all samples (some 10 ns each: under a minute on one core at the bound). */
#define NL_SPARSE_WORK_MAX 4e9

/* Windows keep within +-2^30 samples of the origin: cells are indexed by
 * 32-bit coordinates (farther windows would repeat the field). */
#define NL_SPARSE_ORIGIN_MAX (1L << 30)

/* At most this many band-limited versions of a kernel (sigma up to 2^5). */
#define NL_SPARSE_BANDS_MAX 6

typedef struct nl_synth_sparse_plan nl_synth_sparse_plan;

typedef struct {
    int radius;             /* kernel half-width, samples */
    int cell;               /* cell size, samples */
    double density;         /* mean impulses per cell */
    double kernel_energy;   /* sum h^2 after scaling */
    double truncated;       /* model kernels: energy fraction beyond the radius */
    double kurtosis;        /* predicted excess kurtosis */
    double variance;        /* predicted variance */
    double mean;            /* added to every sample: the exemplar's mean (plan_exemplar), else 0 */
    double clamp_error;     /* model kernels: negative mass / positive mass of the sampled spectrum */
    size_t negatives;       /* model kernels: negative spectrum samples zeroed */
} nl_synth_sparse_info;

/* Executes: the field is a periodic tile of the grid's size (else a window
 * of the infinite field). */
#define NL_SYNTH_SPARSE_WRAP 1u
/* nl_synth_sparse_check_work: the kernel rotates with position (an angle
 * expression, nl_synth_sparse_set_angle). */
#define NL_SYNTH_SPARSE_ANGLE 2u

/* How a plan is made (nl_synth_sparse_options_default: radius 0, cell 0,
 * density 1, flags 0). */
typedef struct {
    int radius;      /* kernel half-width, samples; 0: automatic (below) */
    int cell;        /* cell size, samples; 0: automatic (below) */
    double density;  /* mean impulses per cell */
    unsigned flags;  /* model kernels: NL_SYNTH_FFT_CLAMP, or 0 (refuse what is not positive definite) */
} nl_synth_sparse_options;

void nl_synth_sparse_options_default(nl_synth_sparse_options *o);

/* Plans own their kernel table (and angle expression); free with
 * nl_synth_sparse_plan_free.  Making a plan evaluates the model or an
 * expression (muParser) and plans FFTW (model kernels): NOT thread-safe.
 * Radius and cell (of the options) are in grid samples; h[] (NULL: unit) is
 * the spacing in the model's lag units.
 * radius <= 0: the smallest radius keeping all but NL_SPARSE_ENERGY_TOL of the kernel's
 * energy (model kernels) or the image's half-size.  cell <= 0: the
 * smallest power of two >= max(4, radius).
 * Each returns NL_OK and *out, or (*out = NULL)
 *   NL_EINVAL  dim not 1 or 2, density outside (0, 1e6], radius or cell
 *              above 4096, a zero kernel, a malformed expression or one
 *              with unknown variables or non-finite values, an image not 2D
 *              or constant, a model unusable in dim or not finite on the
 *              kernel's grid, a model with a nugget (shot noise of finite
 *              density cannot carry white noise);
 *   NL_ENOTPD  a model not positive definite on the kernel's grid: the
 *              rule of FFT synthesis (synth/fft.h), the negative mass of
 *              the sampled spectrum above NL_SYNTH_FFT_CLAMP_TOL of its
 *              positive mass; with the options' flags NL_SYNTH_FFT_CLAMP
 *              the negative part is zeroed instead and info.clamp_error
 *              bounds the change;
 *   NL_ETOOBIG the kernel table, or a model kernel's FFT grid (up to
 *              4 radius + 4 samples per axis), exceeds this machine's
 *              memory (nl_mem_available), checked before allocating;
 *   NL_ENOMEM  out of memory.
 * info.truncated is the kernel energy left beyond the radius: the field's
 * variance is R(0) times (1 - truncated), its ACF that of the truncated
 * kernel (callers flag it).  A spectrum model with no closed-form R(0) is
 * scaled to the kernel's own energy, R(0) as sampled. */
int nl_synth_sparse_plan_model(const nl_model *m, int dim, const double *h, const nl_synth_sparse_options *o,
                               nl_synth_sparse_plan **out);
int nl_synth_sparse_plan_expr(const char *expr, int dim, const nl_synth_sparse_options *o,
                              nl_synth_sparse_plan **out);
/* (the image's own radius: o->radius is not read) */
int nl_synth_sparse_plan_image(const nl_field *img, const nl_synth_sparse_options *o, nl_synth_sparse_plan **out);

/* Texture resynthesis from an exemplar: with the options' radius > 0 the
 * central 2 radius x 2 radius window of img (2D) is the exemplar, else all
 * of it; planned as nl_synth_sparse_plan_image, and the exemplar's mean (info.mean)
 * is added to every sample the plan synthesises.  NL_EINVAL (img not 2D,
 * window larger than img, constant exemplar, cell/density), NL_ENOMEM. */
int nl_synth_sparse_plan_exemplar(const nl_field *img, const nl_synth_sparse_options *o, nl_synth_sparse_plan **out);

/* Rotate the kernel by the angle expression theta(x, y) (radians, x and y
 * in grid samples); the plan keeps the compiled expression.  NL_EINVAL (a 1D
 * plan, a malformed expression or unknown variables), NL_ENOMEM. */
int nl_synth_sparse_set_angle(nl_synth_sparse_plan *p, const char *expr);

void nl_synth_sparse_plan_info(const nl_synth_sparse_plan *p, nl_synth_sparse_info *info);

/* The window of samples origin[a] .. origin[a] + n[a] - 1 (NULL: 0) into
 * out (the plan's dim, row-major, x fastest).  With flags
 * NL_SYNTH_SPARSE_WRAP (wrap; else 0), the field is
 * periodic with the grid's size (each a multiple of the cell size) and
 * origin must be NULL.  Bit-identical for equal arguments; a plan without
 * an angle is only read (thread-safe); with an angle the muParser
 * expression is evaluated, so one such plan serves one thread at a time.
 * NL_OK, or NL_EINVAL (dims differ, wrap with an origin, a tile not a
 * multiple of the cell or smaller than the kernel, a window beyond
 * +-NL_SPARSE_ORIGIN_MAX, an angle that is not finite at some impulse),
 * NL_ETOOBIG (the impulses of the window's cells exceed the memory
 * available, checked before allocating, or the work exceeds
 * NL_SPARSE_WORK_MAX), NL_ENOMEM. */
int nl_synth_sparse_execute(const nl_synth_sparse_plan *p, uint64_t seed, unsigned flags, const long *origin,
                            nl_field *out);

/* A slab along the slowest axis (y in 2D, x in 1D), for synthesis
 * distributed by rows: the samples of slowest-axis indices s0 .. s0 + ns - 1
 * (every index of the other axis) of the field of n_global[0..dim-1]
 * samples, bit for bit those of nl_synth_sparse_execute(p, seed, flags,
 * NULL, field) (each sample sums the same impulses in the same order).
 * out: the plan's dim, n[dim - 1] = ns >= 1, the other axis n_global's; its
 * first sample is the global (0, s0).  flags 0: the window at origin (0, s0)
 * (1D: s0), of any n_global; NL_SYNTH_SPARSE_WRAP: the periodic tile of n_global (each a
 * multiple of the cell size, the kernel within it): the impulses of the
 * cells the slab's kernels reach, wrapped round the tile, are drawn in
 * unwrapped cell coordinates (the slab's cells plus the reach, whatever
 * the tile).  Angle plans are supported (the angle is evaluated at the same
 * impulses); band-limited kernels are not used by lattice executes.  The
 * work bound is the slab's.  Thread safety as nl_synth_sparse_execute.
 * NL_OK, or NL_EINVAL (dims, a row length not n_global[0], a slab not within
 * n_global, wrap with a tile not a multiple of the cell or smaller than the
 * kernel, an angle not finite at an impulse), NL_ETOOBIG, NL_ENOMEM. */
int nl_synth_sparse_execute_slab(const nl_synth_sparse_plan *p, uint64_t seed, unsigned flags, const size_t *n_global,
                                 size_t s0, nl_field *out);

/* The bytes nl_synth_sparse_execute_slab allocates (the impulses of the
 * cells the slab reaches, as first reserved: 1.5 times their expected count
 * plus 64; a slab whose cells draw more impulses grows them by doubling), for
 * a slab of ns rows (1D: samples) of n_global, whatever s0 and flags; not
 * out itself.  O((ns + 2 reach) (n[0] + 2 reach) density / cell^2) in 2D.
 * SIZE_MAX when it overflows.  Pure. */
size_t nl_synth_sparse_slab_bytes(const nl_synth_sparse_plan *p, unsigned flags, const size_t *n_global, size_t ns);

/* The work bound of nl_synth_sparse_execute for an output of n[0..dim-1]
 * samples, a kernel of this radius (rotated: NL_SYNTH_SPARSE_ANGLE in
 * flags, else 0), cell (<= 0: the default) and density, checkable before a plan is made: NL_OK, or
 * NL_ETOOBIG naming the values when the impulses drawn and gathered exceed
 * NL_SPARSE_WORK_MAX.  Thread-safe. */
int nl_synth_sparse_check_work(int dim, const size_t *n, int radius, int cell, double density, unsigned flags);

/* Depth band-limiting (GI '86, sec. 3.1: "the noise can be accurately and
 * efficiently anti-aliased by selecting appropriate precomputed bandlimited
 * versions of the kernel as a function of depth").  Precomputes `levels`
 * band-limited kernels of a 2D plan: level l = 1..levels is the kernel table
 * convolved with the separable discrete Gaussian g(q) ~ exp(-q^2 / (2
 * sigma_l^2)), |q| <= 4 sigma_l per axis, normalised to sum 1, sigma_l =
 * 2^(l-1) samples; its table has half-width radius + 4 sigma_l.  Level 0 is
 * the kernel itself.  Level l suits a footprint (the sample spacing on the
 * field at that pixel) of 2^l samples: sigma = footprint / 2.  Replaces any
 * earlier bands; levels 0 drops them.  NL_OK, or NL_EINVAL (a 1D plan,
 * levels outside 0..NL_SPARSE_BANDS_MAX), NL_ETOOBIG (the tables exceed the
 * memory available, checked before allocating), NL_ENOMEM (the plan then
 * has no bands).  Not thread-safe (modifies the plan). */
int nl_synth_sparse_set_bands(nl_synth_sparse_plan *p, int levels);

/* The variance of the level-l band-limited field, lambda sum h_l^2 in the
 * plan's units (level 0: info.variance); NAN for a level the plan lacks. */
double nl_synth_sparse_band_variance(const nl_synth_sparse_plan *p, int level);

/* The non-periodic field at n arbitrary points xy[2 i], xy[2 i + 1] (grid
 * samples, any real values within +-NL_SPARSE_ORIGIN_MAX) into out[i].
 * footprint NULL: the kernel itself, bilinear between table entries (at
 * integer points equal to nl_synth_sparse_execute's samples without wrap,
 * bit for bit); else footprint[i] >= 0 (samples) selects the band-limited
 * kernels: level lambda = log2(footprint) clamped to 0..nbands, linear
 * between the two nearest levels (footprint <= 1: level 0).  Requires a 2D
 * plan.  NL_OK, or NL_EINVAL (a 1D plan, a point or footprint not finite or
 * out of range, an angle not finite at an impulse), NL_ETOOBIG (the
 * impulses of the points' bounding box exceed the memory available, or the
 * work exceeds NL_SPARSE_WORK_MAX), NL_ENOMEM.  Thread safety as
 * nl_synth_sparse_execute. */
int nl_synth_sparse_execute_points(const nl_synth_sparse_plan *p, uint64_t seed, size_t n, const double *xy,
                                   const double *footprint, double *out);

/* Frees the plan (NULL: no-op). */
void nl_synth_sparse_plan_free(nl_synth_sparse_plan *p);

#ifdef __cplusplus
}
#endif

#endif
