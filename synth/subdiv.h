/* Generalized stochastic subdivision (Lewis 1987).
 *
 * Geometry.  Level k refines a grid of observation spacing s_k = s_0 / 2^k
 * (s_0 = spacing0, in the model's lag units; eq. (6) is this scaling of R).
 * Old points keep their values; each new point is
 *     x_p = u_p + sum_k a_k x_{p_k}                         eq. (3), (9), (11)
 * with the a_k from the orthogonality principle
 *     R(p - p_j) = sum_k a_k R(p_k - p_j),  all j            eq. (4), (10), (12)
 * and u_p independent Gaussian with the variance of eq. (7)
 *     E{u^2} = R(0) - sum_k a_k R(p - p_k).
 *
 * Point classes and neighbourhood order:
 *   1D "mid":  observations at k = 1-N..N (times s_k), target 0.5 s_k;
 *              coefficient i is for k = i + 1 - N.
 *   2D, observations at (r, c) = 1-N..N squared (r along y, c along x),
 *              coefficient i = (r + N - 1) 2N + (c + N - 1) (row-major):
 *      "face"   target (y, x) = (0.5, 0.5)  the mid-face vertex
 *      "edge-x" target (0, 0.5)             mid-edge between (0,0) and (0,1)
 *      "edge-y" target (0.5, 0)             mid-edge between (0,0) and (1,0)
 *   (the edges use the 2N x 2N block of the face below/right of them, as in
 *   Lewis's Fig. 3, so their neighbourhood is one row (column) heavier on
 *   the far side).
 *
 * Solving.  The symmetric matrix of eq. (4)/(10) is factorised by Cholesky
 * when it is positive definite and its condition number is at most
 * NL_SUBDIV_COND_MAX.  Past that it is "singular": the solution is the SVD
 * pseudo-inverse with singular values below sigma_max / NL_SUBDIV_COND_MAX
 * dropped, and a pseudo-inverse that comes out uniform (every a = 1/n to
 * within 1e-3/n, Lewis: "the generalized inverse sets the coefficients to
 * 1/2N") is reset to the equivalent nearest-neighbour interpolant before the
 * variance is computed.  A matrix with an eigenvalue below
 * -n eps lambda_max is "not positive definite" (solved by the pseudo-inverse
 * and flagged); a negative variance (7) is clamped to 0 and flagged. */
#ifndef NL_SYNTH_SUBDIV_H
#define NL_SYNTH_SUBDIV_H

#ifdef __cplusplus
extern "C" {
#endif

#include "../core/field.h"
#include "../core/model.h"

#include <stdint.h>

/* Condition number past which the matrix is treated as singular: the
 * solution's relative error bound eps * cond is then above 2e-6. */
#define NL_SUBDIV_COND_MAX 1e10

/* Largest half-width N of a 2D neighbourhood (1D: 64). */
#define NL_SUBDIV_MAX_N 8

/* diagonal-bias: a corner coefficient of the 2N x 2N block exceeds this
 * fraction of the largest coefficient. */
#define NL_SUBDIV_DIAG_BIAS_FRAC 0.01

enum { NL_SUBDIV_MID = 0, NL_SUBDIV_FACE = 1, NL_SUBDIV_EDGE_X = 2, NL_SUBDIV_EDGE_Y = 3 };

enum {
    NL_SUBDIV_SINGULAR = 1u << 0,  /* condition number > NL_SUBDIV_COND_MAX */
    NL_SUBDIV_PINV = 1u << 1,      /* solved by the pseudo-inverse */
    NL_SUBDIV_NOT_PD = 1u << 2,    /* negative eigenvalue */
    NL_SUBDIV_NEG_VAR = 1u << 3,   /* eq. (7) came out negative; clamped to 0 */
    NL_SUBDIV_DIAG_BIAS = 1u << 4, /* corner coefficients not negligible */
    NL_SUBDIV_NN_RESET = 1u << 5   /* uniform pseudo-inverse reset to nearest neighbours */
};

/* Names of the flags, in bit order ("singular", "pseudo-inverse", ...). */
const char *nl_subdiv_flag_name(unsigned bit);
/* The names of the flags set in `flags`, comma-separated, into buf (len
 * bytes, NUL-terminated, truncated if short; "" when none). */
void nl_subdiv_flag_names(unsigned flags, char *buf, size_t len);
const char *nl_subdiv_class_name(int cls);

typedef struct {
    int cls;              /* NL_SUBDIV_MID, _FACE, _EDGE_X, _EDGE_Y */
    size_t n;             /* coefficients: 2N in 1D, (2N)^2 in 2D */
    double *a;            /* n coefficients in neighbourhood order */
    double variance;      /* displacement variance, eq. (7), clamped at 0 */
    double raw_variance;  /* eq. (7) as computed */
    double condition;     /* 2-norm condition number of the matrix */
    double min_eigenvalue;/* smallest eigenvalue of the matrix */
    unsigned flags;       /* NL_SUBDIV_* */
    /* random quadrilateral neighbourhoods (2D, optional): nalt alternative
     * observation sets, each of n points at offsets (offx, offy) from the
     * anchor (i, j) of the new point, with their own coefficients and
     * variance; empty for the standard 2N x 2N block */
    int nalt;             /* 0, or the number of alternatives */
    int *offx, *offy;     /* nalt * n offsets, alternative-major */
    double *alt_a;        /* nalt * n coefficients */
    double *alt_var;      /* nalt variances (clamped at 0) */
} nl_subdiv_class;

typedef struct {
    int level;            /* 0 = coarsest */
    double spacing;       /* observation spacing s_k */
    int N;                /* neighbourhood half-width: 2N points per axis */
    int reach;            /* largest |offset| of an observation from the anchor */
    int nclass;           /* 1 in 1D; 3 in 2D (face, edge-x, edge-y) */
    nl_subdiv_class cls[3];
    /* correlated displacements (nl_subdiv_coeffs_correlate); filt NULL:
     * independent, each of variance cls[a].variance */
    int taps;             /* M: filter offsets -M..M per axis */
    double *filt;         /* nclass^2 (2M+1)^dim taps g^{ab}(p): index
                             ((a nclass + b) (2M+1) + py + M) (2M+1) + px + M (1D: py absent) */
    double filt_error;    /* max |realised - target| displacement covariance / R(0) */
} nl_subdiv_level;

typedef struct {
    int dim;              /* 1 or 2 */
    int levels;           /* number of levels */
    double spacing0;      /* s_0 */
    double r0;            /* R(0) */
    unsigned flags;       /* union of all class flags */
    nl_subdiv_level *level;  /* levels entries */
} nl_subdiv_coeffs;

/* Compute the coefficients of `levels` levels.  N > 0 fixes the
 * half-width; N = 0 chooses it per level ("auto"): N grows from 1 until the
 * displacement variance (7) of the mid (1D) or face (2D) class improves by
 * less than tol * R(0), up to nmax (nl_subdiv_coeffs_alloc_rule below for
 * the paper's rule).  spacing0 in the model's lag units.
 * *out is owned by the caller: free with nl_subdiv_coeffs_free.  Evaluates
 * the model (not thread-safe for expression models).  Returns NL_OK, or
 * (*out = NULL) NL_EINVAL (dim not 1 or 2, levels outside 1..40, spacing0
 * or tol not positive, N outside 0..64 (1D) / 0..8 (2D), a spectral model
 * without R, R(0) <= 0, a model with a nugget: subdivision keeps the coarse
 * nodes' values, so white noise would have to be added at every level and
 * the finest-level-only alternative changes the coarse nodes' covariance;
 * use a method with NL_METHOD_NUGGET), NL_EFAIL (an eigenvalue or SVD solve did not
 * converge), NL_ENOMEM.  Non-positive-definite levels are not errors here:
 * they are flagged (NL_SUBDIV_NOT_PD) and refused by synthesis. */
int nl_subdiv_coeffs_alloc(const nl_model *m, int dim, int levels, double spacing0, int N, double tol, int nmax,
                        nl_subdiv_coeffs **out);

/* nl_subdiv_coeffs_alloc with the stopping rule of "auto" (N = 0) chosen:
 *   NL_SUBDIV_STOP_IMPROVEMENT  N grows until (7) improves by < tol R(0)
 *                               (nl_subdiv_coeffs_alloc's rule);
 *   NL_SUBDIV_STOP_VARIANCE     Lewis 1987 ("increase the size until the
 *                               expected error variance (7) is reduced below
 *                               a specified threshold"): the first N whose
 *                               (7) is below tol R(0), else nmax;
 *   NL_SUBDIV_STOP_NONE         N = nmax.
 * 1D: the sizes are grown by Levinson's recursion (nl_subdiv_levinson,
 * O(N) per step); the chosen N's system is then solved once directly,
 * which gives the condition number and flags reported and keeps the
 * pseudo-inverse path.  Where the recursion breaks down before the rule
 * stops it (singular or not positive definite from some N on), the growth
 * continues from there by direct solves, pseudo-inverted, so the N chosen
 * is the one the direct re-solve of every N would choose.  2D: the (2N)^2
 * block grows by a ring, not a Toeplitz bordering; every N is solved
 * directly.  Same codes as nl_subdiv_coeffs_alloc, and NL_EINVAL for an
 * unknown rule. */
int nl_subdiv_coeffs_alloc_rule(const nl_model *m, int dim, int levels, double spacing0, int N, int rule, double tol,
                                int nmax, nl_subdiv_coeffs **out);

/* Frees the coefficients (NULL: no-op). */
void nl_subdiv_coeffs_free(nl_subdiv_coeffs *c);

/* Replace every 2D class's block by `k` random neighbourhoods of the same
 * size (Lewis 1987's remedy for diagonal bias): each grows from the nearest
 * observation points (the face corners, the edge ends) by adding, (2N)^2 - m
 * times, a point chosen uniformly among the grid points 4-adjacent to the
 * set (an unbiased random walk of the frontier); eq. (12) is solved for
 * each.  The walk draws from nl_rng_uniform(plan_seed, level * 4 + class,
 * step).  During synthesis each new point uses alternative
 * nl_rng_uniform(seed, NL_SUBDIV_STREAM + 64 + level, position) * k.
 * The alternatives are owned by c.  NL_OK, or NL_EINVAL (c not 2D, k
 * outside 1..256), NL_EFAIL, NL_ENOMEM (c is then still valid and freeable). */
int nl_subdiv_coeffs_randomize(nl_subdiv_coeffs *c, const nl_model *m, int k, uint64_t plan_seed);

/* Correlated displacements (synth/subdiv_disp.c has the derivation): the
 * new points of a level, grouped by cell (1D: cell i holds the midpoint
 * 2i + 1; 2D: cell (i, j) holds face (2i+1, 2j+1), edge-x (2i+1, 2j) and
 * edge-y (2i, 2j+1), in cls[] order), get displacements
 *     d_a(i) = sum_b sum_{|p| <= M} g^{ab}(p) w_b(i + p),
 * w_b(i) the N(0, 1) number the independent construction with the standard
 * neighbourhoods draws for class b's point of cell i (1D: nl_rng_gauss at
 * the point's fine index; 2D: the pairs described under NL_SUBDIV_STREAM
 * below), and
 * g a filter whose covariance approximates, over cell offsets m,
 *   NL_SUBDIV_DISP_ERROR   the covariance of the true estimation errors,
 *   NL_SUBDIV_DISP_NEWNEW  R_nn - A R_oo A^T, which makes the new points'
 *                          covariance exact when the old level is;
 * both keep eq. (7) as the variance.  taps = M, 0 .. NL_SUBDIV_MAX_TAPS.
 * Sets every level's taps, filt and filt_error.  NL_OK, or NL_EINVAL (taps
 * or target out of range, random neighbourhoods, R not finite at a lag it
 * needs), NL_EFAIL, NL_ENOMEM (c is then still valid, with every level
 * independent or correlated).  Evaluates the model: not thread-safe for
 * expression models. */
enum { NL_SUBDIV_DISP_INDEPENDENT = 0, NL_SUBDIV_DISP_ERROR = 1, NL_SUBDIV_DISP_NEWNEW = 2 };
#define NL_SUBDIV_MAX_TAPS 16
int nl_subdiv_coeffs_correlate(nl_subdiv_coeffs *c, const nl_model *m, int taps, int target);

/* The displacement covariance a level realises, Cov(d_a(i), d_b(i + m)),
 * m = (mx, my) in cells (my = 0 in 1D): from its filter, or the diagonal
 * eq. (7) variances when independent.  Pure. */
double nl_subdiv_disp_realised(const nl_subdiv_level *l, int dim, int a, int b, int mx, int my);

/* The covariance the displacements of a level are meant to have, for
 * target NL_SUBDIV_DISP_ERROR or _NEWNEW (above), classes a, b, cell offset
 * (mx, my), evaluated from m: what nl_subdiv_disp_realised approximates.
 * NAN when out of memory.  As thread-safe as the model. */
double nl_subdiv_disp_target(const nl_subdiv_level *l, const nl_model *m, int dim, int target, int a, int b, int mx,
                             int my);

/* Levinson's recursion for the 1D midpoint equations (synth/subdiv_levinson.c,
 * Lewis 1987: "the Levinson algorithm would need to be modified ... since
 * only even neighborhood sizes are used"): at spacing s, for N = 1, 2, ...
 * up to nmax (1..64), the 2N coefficients of eq. (4) in O(N) per step, and
 * var[N-1] the error variance (7).  rule: NL_SUBDIV_STOP_NONE (every N to
 * nmax), NL_SUBDIV_STOP_VARIANCE (the paper's: stop at the first N whose
 * variance is below tol R(0)), NL_SUBDIV_STOP_IMPROVEMENT (stop when
 * growing N improves the variance by less than tol R(0); *nout is then the
 * smaller N).  *nout is the N whose coefficients are in a (2 nmax doubles,
 * neighbourhood order) and whose variance is var[*nout - 1]; the recursion
 * also stops, short of nmax, where the system stops being positive definite
 * or its prediction error power falls below 1 / NL_SUBDIV_COND_MAX (then
 * the condition number is above NL_SUBDIV_COND_MAX): the caller then solves directly (nl_subdiv_solve), which flags and
 * pseudo-inverts.  *nout = 0 when even N = 1 fails.  NL_OK, NL_EINVAL (nmax
 * out of range, R(0) not positive), NL_ENOMEM.  As thread-safe as m. */
enum { NL_SUBDIV_STOP_IMPROVEMENT = 0, NL_SUBDIV_STOP_VARIANCE = 1, NL_SUBDIV_STOP_NONE = 2 };
int nl_subdiv_levinson(const nl_model *m, double s, int nmax, int rule, double tol, double *a, double *var,
                       int *nout);

/* Eq. (12) for any observation set: n points pts[i*dim..] and the target,
 * in lag units.  Fills cls (a must hold n doubles); `reset` gives the
 * nearest-neighbour coefficients to use when the pseudo-inverse is uniform
 * (NULL: no reset).  NL_OK, NL_EFAIL (solver), NL_ENOMEM. */
int nl_subdiv_solve(const nl_model *m, int dim, size_t n, const double *pts, const double *target,
                 const double *reset, nl_subdiv_class *cls);

/* Synthesis.  Random numbers: the displacement of the point with index
 * (i, j) on the grid of level k + 1 (and the seed values at level 0) is
 * nl_rng_gauss(seed, NL_SUBDIV_STREAM + level, j * 2^32 + i) with the signed
 * indices taken modulo 2^32, except on a 2D level with the standard
 * neighbourhoods, where the draws come in pairs, nl_rng_gauss_pair(seed,
 * NL_SUBDIV_STREAM + level, j * 2^32 + k): on odd rows j points 2k and 2k + 1,
 * on even rows (which draw at odd i only) points 4k + 1 and 4k + 3.  So
 * every number is a pure function of (seed, level, integer position). */
#define NL_SUBDIV_STREAM 100u

/* Midpoint displacement (Fournier, Fussell and Carpenter 1982) as a
 * subdivision plan: nearest-neighbour averages (1D: the two ends; 2D: the
 * four face corners, the two edge ends) with the displacement variance
 * that makes the increments those of fractional Brownian motion with
 * variogram 2 gamma(h) = sigma2 |h|^(2H):
 *     v = 2 sum_k a_k gamma(p - p_k) - sum_jk a_j a_k gamma(p_j - p_k),
 * (1D: sigma2 s^(2H) (2^(-2H) - 1/4)), times vscale^k at level k
 * (vscale = 1: the fractal schedule; otherwise the altered variances of
 * Haruyama and Barsky).  r0 is set to sigma2 s_0^(2H) / 2, the variance of
 * the independent coarse values.  Caller frees *out with
 * nl_subdiv_coeffs_free.  NL_EINVAL (dim, H outside (0, 1), levels outside
 * 1..40, spacing0, sigma2 or vscale not positive), NL_ENOMEM.  Pure. */
int nl_subdiv_coeffs_midpoint(int dim, int levels, double spacing0, double H, double sigma2, double vscale,
                           nl_subdiv_coeffs **out);

/* Plans: plan once, execute many seeds.  A plan owns its coefficients
 * (nl_subdiv_coeffs) and, for periodic synthesis from a model, the FFT plan
 * of its coarse level, so executing another seed re-plans nothing.
 * nl_subdiv_plan_alloc and _alloc_midpoint plan FFTW and evaluate the model:
 * not thread-safe.  The executes only read the plan: one plan may serve
 * several threads at once; each call allocates its own level grids
 * (NL_ENOMEM when they do not fit).  Free with nl_subdiv_plan_free. */
typedef struct nl_subdiv_plan nl_subdiv_plan;

typedef struct {
    int levels;           /* levels of refinement; 0 = the default policy (see nl_subdiv_plan_alloc) */
    int N;                /* neighbourhood half-width (2N points per axis); 0 = auto (see tol) */
    double tol;           /* auto: the stopping rule's threshold, relative to R(0) */
    int nmax;             /* auto: largest N; 0 = 16 in 1D, 6 in 2D */
    int nonperiodic;      /* a window of the infinite field (nl_subdiv_plan_execute_window) */
    int allow_not_pd;     /* --clamp: negative variances become 0 instead of NL_ENOTPD (periodic) */
    int image;            /* the coarse level is given (nl_subdiv_plan_execute_image): no coarse FFT plan */
    int random_nb;        /* 2D: random neighbourhoods per class (nl_subdiv_coeffs_randomize); 0 = none */
    uint64_t random_seed; /* plan seed of the random neighbourhoods */
    int displacements;    /* NL_SUBDIV_DISP_INDEPENDENT (Lewis), _ERROR (correlated) or _NEWNEW */
    int taps;             /* correlated: filter half-width M, 1..NL_SUBDIV_MAX_TAPS; 0 = 4 in 1D, 2 in 2D */
    int stop;             /* auto: NL_SUBDIV_STOP_IMPROVEMENT (0: eq. (7) improves by < tol R(0)) or
                             _VARIANCE (the paper's: (7) below tol R(0)); nl_subdiv_coeffs_alloc_rule */
} nl_subdiv_options;

typedef struct {
    int levels;           /* levels of refinement */
    double spacing0;      /* s_0 = h 2^levels, the coarse spacing */
    double variance;      /* R(0) (midpoint: variance of the independent coarse values) */
    double coarse_correlation; /* nonperiodic: R(s_0)/R(0), the neglected correlation of level 0; else NAN */
} nl_subdiv_info;

/* The defaults: levels 0 (policy), N = 2, tol 1e-4, nmax 0, periodic, no
 * clamp, no image, no random neighbourhoods, random_seed 1, independent
 * displacements. */
void nl_subdiv_options_default(nl_subdiv_options *o);

/* The default number of levels for an output of n[0..dim-1] samples: the
 * number of halvings k = 1, 2, ... (at most 30) for which every n[a] is a
 * multiple of 2^k with n[a] / 2^k >= min; 0 when n[0] is odd or below
 * 2 min.  Pure. */
int nl_subdiv_default_levels(int dim, const size_t *n, long min);

/* The levels a seed image of image_n samples needs to refine to n (both
 * dim-D): image_n[a] 2^L = n[a].  `levels` is the caller's request (0 = none).
 * Returns NL_OK with *out = L >= 1, or NL_EINVAL when n is not a
 * power-of-two multiple of image_n, when levels is nonzero and differs
 * from L, or when L = 0.  Pure. */
int nl_subdiv_image_levels(int dim, const size_t *image_n, const size_t *n, int levels, int *out);

/* Plan subdivision of model m (defined by R) to an output of n[0..dim-1]
 * samples (dim 1 or 2) at spacing h on every axis (lag units of m).
 * Levels: o->levels, or by default 6 with o->nonperiodic, else
 * nl_subdiv_default_levels(dim, n, 8) (a coarse grid of >= 8 samples);
 * s_0 = h 2^levels.  Periodic plans (neither nonperiodic nor image) check
 * here that every n[a] is a multiple of 2^levels with >= 2 coarse samples,
 * that every level is positive definite (unless allow_not_pd) and plan the
 * coarse FFT synthesis (synth/fft.h).  o is read, not kept; m is not kept.
 * Returns NL_OK and *out, or (*out = NULL)
 *   NL_EINVAL  dim not 1 or 2, fewer than 1 level, bad N/tol, random_nb in
 *              1D, sizes not refinable, a model without R;
 *   NL_ENOTPD  a level or the coarse spectrum not positive definite;
 *   NL_EFAIL   a solve failed; NL_ENOMEM, NL_ETOOBIG  out of memory. */
int nl_subdiv_plan_alloc(const nl_model *m, int dim, const size_t *n, double h, const nl_subdiv_options *o,
                         nl_subdiv_plan **out);

/* Midpoint displacement as a plan (nl_subdiv_coeffs_midpoint below):
 * `levels` (0 = nl_subdiv_default_levels(dim, n, 2)), s_0 = h 2^levels,
 * independent coarse values of variance sigma2 s_0^(2H) / 2.  Returns NL_OK,
 * NL_EINVAL (dim, H, levels, sizes) or NL_ENOMEM. */
int nl_subdiv_plan_alloc_midpoint(int dim, const size_t *n, double h, int levels, double H, double sigma2,
                                  double vscale, nl_subdiv_plan **out);

/* The Hurst exponent of a power:d=D model for midpoint displacement:
 * H = (d - dim) / 2 (the spectrum f^-d, d = 2H + E).  Returns NL_OK, or
 * NL_EINVAL when m is not a power model or H is outside (0, 1). */
int nl_subdiv_midpoint_hurst(const nl_model *m, int dim, double *H);

/* The plan's coefficients (owned by the plan, valid until _free) and summary. */
const nl_subdiv_coeffs *nl_subdiv_plan_coeffs(const nl_subdiv_plan *p);
void nl_subdiv_plan_info(const nl_subdiv_plan *p, nl_subdiv_info *info);

/* Synthesise the field for `seed` into f (allocated with the plan's dim and
 * n): periodic plans as nl_subdiv_synth_periodic, nonperiodic ones as the
 * window at origin 0.  f->h is set to s_0 / 2^levels.  Bit-identical for
 * equal seeds.  NL_EINVAL (f does not match; an image plan; a level smaller
 * than its neighbourhood), NL_ENOTPD (nonperiodic plans), NL_ENOMEM. */
int nl_subdiv_plan_execute(const nl_subdiv_plan *p, uint64_t seed, nl_field *f);

/* The window at finest-grid indices origin[a] .. origin[a] + n[a] - 1 of a
 * nonperiodic plan (nl_subdiv_synth_window); origin NULL is origin 0, as
 * for sparse windows.  NL_EINVAL for a periodic
 * plan or a mismatched f; NL_ENOTPD; NL_ENOMEM. */
int nl_subdiv_plan_execute_window(const nl_subdiv_plan *p, uint64_t seed, const long *origin, nl_field *f);

/* Refine a seed image (Lewis 1987 Fig. 5, external consistency): image has
 * the plan's dim and n / 2^levels samples; its mean is subtracted, the
 * rest refined (nl_subdiv_refine_periodic), the mean added back, and the
 * image's samples restored bit for bit at every 2^levels-th point.  NL_EINVAL
 * (nonperiodic plan, dims or sizes), NL_ENOTPD, NL_ENOMEM. */
int nl_subdiv_plan_execute_image(const nl_subdiv_plan *p, const nl_field *image, uint64_t seed, nl_field *f);

/* Slabs, for synthesis distributed along the slowest axis (axis dim - 1: y
 * in 2D, x in 1D): the samples of slowest-axis indices s0 .. s0 + ns - 1
 * and every index of the other axis, bit for bit those of
 * nl_subdiv_plan_execute's field (nonperiodic plans: of its window at
 * origin 0), computed from O(slab + halo) samples per level, never the
 * whole field.  f has the plan's dim and size except n[dim - 1] = ns >= 1
 * (row-major as the field, its first sample the global (0, s0)); s0 + ns
 * must not pass the plan's n[dim - 1].  Periodic plans synthesise the whole
 * coarse level (n / 2^levels samples: small) on every call and refine only
 * the rows the slab needs at each level, with their wrapped neighbours;
 * nonperiodic plans are the window at origin (0, s0) (1D: s0).  Random and
 * correlated displacements, every N, midpoint plans and --clamp are
 * supported.  f->h is set as by nl_subdiv_plan_execute.  Thread-safe as
 * the executes.  NL_OK, or NL_EINVAL (f's dim or row length, a slab not
 * within the field, an image plan: use nl_subdiv_plan_execute_image_slab;
 * a level smaller than its neighbourhood), NL_ENOTPD, NL_ETOOBIG, NL_ENOMEM. */
int nl_subdiv_plan_execute_slab(const nl_subdiv_plan *p, uint64_t seed, size_t s0, nl_field *f);

/* nl_subdiv_plan_execute_image's samples of the slab s0 .. s0 + ns - 1 (as
 * above; the whole seed image is read).  NL_EINVAL (a plan not made with
 * the image option, dims or sizes), NL_ENOTPD, NL_ENOMEM. */
int nl_subdiv_plan_execute_image_slab(const nl_subdiv_plan *p, const nl_field *image, uint64_t seed, size_t s0,
                                      nl_field *f);

/* An upper bound of the peak bytes nl_subdiv_plan_execute_slab (and
 * _image_slab) allocate for a slab of ns rows (1D: samples), whatever s0:
 * the level grids, the correlated displacements and their white numbers,
 * the coarse level and its FFT's scratch (periodic plans; the image copy
 * for image plans), the window's final level (nonperiodic plans).  Not
 * counted: f itself (ns times the row length doubles, the caller's), and
 * blocks below 1 KiB.  Grows as ns + the halo (a few neighbourhood reaches
 * per level) times the row length, plus the coarse level's size.  SIZE_MAX
 * when it overflows.  Pure. */
size_t nl_subdiv_plan_slab_bytes(const nl_subdiv_plan *p, size_t ns);

void nl_subdiv_plan_free(nl_subdiv_plan *p);

/* One-shot forms, kept for callers holding their own coefficients. */

/* Periodic synthesis into f (dim 1 or 2, each n divisible by 2^levels and
 * the coarse grid n / 2^levels at least 2): the coarse grid is synthesised
 * exactly by periodic FFT synthesis of m at spacing s_0 (its white noise is
 * the FFT stream of `seed`), or, when m is NULL, as independent values of
 * variance c->r0; then it is refined with wrapped neighbourhoods.  f->h is
 * set to s_0 / 2^levels.  NL_ENOTPD when the coarse grid or any level is not
 * positive definite (unless allow_not_pd: negative variances are then 0).
 * Equivalent to a plan borrowing c, executed once (nl_subdiv_plan_execute
 * gives the same field bit for bit): it re-plans the coarse FFT on every
 * call, so prefer a plan for several seeds.  NL_EINVAL (dims or sizes),
 * NL_ENOTPD, NL_ETOOBIG, NL_ENOMEM, NL_EFAIL.  Not thread-safe (plans FFTW). */
int nl_subdiv_synth_periodic(const nl_subdiv_coeffs *c, const nl_model *m, uint64_t seed, int allow_not_pd,
                          nl_field *f);

/* Refine a given coarse level (kept exactly: external consistency, Lewis
 * 1987 Fig. 5) into f, whose size must be the coarse size times 2^levels;
 * coarse is read, not kept (f->h set to s_0 / 2^levels).  NL_EINVAL (dims,
 * sizes, a level smaller than its neighbourhood), NL_ENOTPD, NL_ENOMEM.
 * Thread-safe: c and coarse are only read. */
int nl_subdiv_refine_periodic(const nl_subdiv_coeffs *c, const nl_field *coarse, uint64_t seed, int allow_not_pd,
                           nl_field *f);

/* Windows keep within +-2^30 finest-grid samples: 2D lattice points are
 * drawn by 32-bit coordinates (farther windows would repeat the field). */
#define NL_SUBDIV_ORIGIN_MAX (1L << 30)

/* Non-periodic window: the samples of an infinite field at finest-grid
 * indices origin[a] .. origin[a] + n[a] - 1.  Level 0 is white noise of
 * variance R(0) at spacing s_0 (exact when R(s_0) is negligible; the
 * residual correlation R(s_0)/R(0) is the caller's to report).  Two windows
 * agree bit for bit where they overlap.  f->h is set to s_0 / 2^levels.
 * NL_EINVAL (f's dim), NL_ENOTPD (a level not positive definite: windows
 * never clamp), NL_EINVAL (a window beyond +-NL_SUBDIV_ORIGIN_MAX),
 * NL_ENOMEM.  Thread-safe: c is only read. */
int nl_subdiv_synth_window(const nl_subdiv_coeffs *c, uint64_t seed, const long *origin, nl_field *f);

#ifdef __cplusplus
}
#endif

#endif
