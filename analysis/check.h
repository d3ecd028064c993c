/* Model checks: is R a valid autocorrelation, how smooth is it, and where
 * does it become numerically singular?  (Lewis 1987, "Singular Processes",
 * "Multi-dimensional Autocorrelation and Spectrum".)
 *
 * Two paths, by what the model gives exactly.
 *
 * Models defined by R (named, expr:, image:).  Scales: L0 is the first lag
 * where R departs from R(0+) by half of it (core/taper.c), L8 the smallest
 * lag (searched by factors of 1.25, along x, up to 2^20) beyond which
 * |R| < 1e-8 R(0) for good.  R decays fast when L8 <= 64 L0; otherwise
 * (power-law tails, cos r, exp(-r^0.3)) it is slow and L, the scale of the
 * tests below, is 16 L0 instead of L8, so that they look near the origin.
 *
 * Positive definiteness (Bochner) is judged on:
 *   - for models isotropic in dim (any in 1D; not exemplars), the spectrum
 *     of R times a Gaussian taper exp(-(r/T)^2) on a periodic lattice
 *     (core/taper.c: 65536 points of spacing L0 / 16 in 1D, 1024^2 of
 *     L0 / 8 in 2D, 128^3 of L0 / 4 in 3D, T = 1/12 of the lattice's
 *     extent, then 8 and 64 times coarser while T < L8): a product of
 *     positive definite functions, whose sampled spectrum is a sum of
 *     non-negative aliases for every valid R however slowly it decays, so
 *     a value below the rounding bound (1e-11 of the sum of |samples|)
 *     proves the model invalid (NL_CHECK_NEG_TAPERED);
 *   - when R decays fast, the spectrum of R sampled on a periodic grid of
 *     extent 8 L (spacing L / 512 in 1D, L / 32 in 2D, L / 8 in 3D) and,
 *     for isotropic models in 2D and 3D, the radial spectrum by Hankel
 *     quadrature (nl_model_spectrum_iso) at k = 0 and 128 frequencies from
 *     0.01 / L to 64 / L (the grid's Riemann sums are off by a few percent
 *     of the peak where R has a kink; the quadrature resolves the boundary
 *     of validity, e.g. omega = 1 for cos(omega r) e^-r in 2D): values
 *     below -1e-6 of the largest magnitude make the model not positive
 *     definite (this grid's truncation is what misjudged slow R);
 *   - the smallest eigenvalue of the covariance matrix of a small grid (64
 *     samples in 1D, 16x16 in 2D, 6x6x6 in 3D) spaced L / 16;
 *   - isotropic models: R >= R(0) inf Omega_d (Schoenberg 1938: -0.40276,
 *     min J0, in 2D; -0.21723, min sin(x)/x, in 3D) over lags 0..L, and in
 *     3D a non-increasing line spectrum (the spectrum of R along a line,
 *     S1(f) = 2 pi int_f^inf S(k) k dk; of the tapered R when slow);
 *   - slow R with a negative power-law tail R ~ -c r^-b, b <= d (fitted
 *     from 1e2 L0 to 1e5 L0): the integral of R diverges to -infinity
 *     (NL_CHECK_NEG_INTEGRAL); a positive tail r^-b, b < d, is an
 *     integrable singularity ~ k^(b-d) of S at 0 that the taper smooths;
 *   - compactly supported isotropic R: the asymptotics of S at high |k|
 *     from R's exponents at the origin and at the edge of its support
 *     (core/model_edge.c, NL_CHECK_EDGE: Askey's (1-r)_+^nu below
 *     nu = (d+1)/2, whose negative lobes lie far beyond any sampling).
 * Smoothness: the line spectrum of the profile R(t) along x (times the
 * taper when slow) falls as f^-b between 16/L and 128/L; the order m of
 * mean-square differentiability is the largest m with a finite moment of
 * order 2m, m = ceil((b - 1)/2) - 1 (with 0.05 of slack for the fit), -1
 * meaning infinitely differentiable when the spectrum falls faster than
 * any power, and 0 whenever R has a kink at the origin (R(0) - R(d) ~ d^a,
 * a < 1.9, at d = 1e-5 L); the d-dimensional density of an isotropic or
 * ellipsoidal model falls as k^-(b + d - 1); R''(0) is an extrapolated
 * difference (core/expr_limit.c) for expressions, a finite difference
 * otherwise.
 *
 * A nugget (core/model.h) is white noise: its sampled spectra gain a
 * constant, so the model is positive definite whenever its continuous part
 * is; R jumps at 0, so the kink test gives differentiable_order 0 and
 * R''(0) = -inf, and the fitted spectral decay flattens towards the
 * constant (read it as a bound).  The spherical model is judged by the same
 * tests: positive definite in 1, 2 and 3 dimensions (dim is at most 3 here;
 * its 4D spectrum is negative, synth/rank1_model.h refuses it there).
 *
 * Spectral models (power:, spectrum:).  The d-dimensional density S is
 * known in closed form and is the evidence: it is scanned along the radius
 * (isotropic) or sampled on a d-dimensional grid over the band that holds
 * it (anisotropic spectrum: expressions) for its sign; the variance
 * R(0) = int S and R''(0) = -4 pi^2 int fx^2 S are radial integrals of S
 * (GSL adaptive quadrature, relative error 1e-10, and beyond the scanned
 * band the tail of the fitted power law; anisotropic spectra: Riemann sums
 * on the grid); the decay k^-b of S is fitted along x where S has fallen
 * below 1e-6 of its peak (power: the band's exponent d, and S vanishes
 * above fmax: band-limited, so infinitely differentiable), the line
 * spectrum's is b - (d - 1) (exact for isotropic tails); b <= d (an
 * infinite variance) is refused.  The smallest eigenvalue is that of the covariance of an
 * infinite grid of unit spacing (the one synthesis samples), the smallest
 * value over the Brillouin zone of the aliased spectrum sum_m S(f + m),
 * aliases |m_i| <= 64 (1D), 16 (2D), 4 (3D): a lower bound for every finite
 * grid of unit spacing, exact as the grid grows (Szego); zero when S
 * vanishes on part of the zone, as a band-limited power spectrum does in
 * the zone's corners.
 *
 * singular_below_spacing is the largest spacing s = L / 2^k, k <= 24, at
 * which the N = 2 subdivision matrix of 4 points on the x axis (in dim
 * dimensions) has condition number above NL_SUBDIV_COND_MAX (0 when it
 * never does): within 24 octaves below the correlation length, smooth
 * (singular) processes lose rank while rough ones such as exp(-|t|) keep it
 * (their matrices lose rank too, but only at spacings near 1e-10 L, below
 * any sampling that resolves them).  It is computed for models defined by
 * R and for power: (whose R is a quadrature), not for spectrum: models
 * (singular_checked = 0). */
#ifndef NL_CHECK_H
#define NL_CHECK_H

#ifdef __cplusplus
extern "C" {
#endif

#include "../core/model.h"

#include <stddef.h>

/* Why a model is not positive definite (the first that applies). */
typedef enum {
    NL_CHECK_VALID = 0,       /* it is */
    NL_CHECK_NEG_INTEGRAL,    /* S(0) < 0: the integral of R over R^d is negative */
    NL_CHECK_NEG_SPECTRUM,    /* S < 0 at |k| = why_k */
    NL_CHECK_BOUND,           /* isotropic R below R(0) nl_check_isotropic_bound(d) at lag min_r_lag */
    NL_CHECK_NEG_EIGENVALUE,  /* the grid's covariance matrix has a negative eigenvalue */
    NL_CHECK_LINE_RISES,      /* 3D isotropic: the line spectrum rises at f = why_k */
    NL_CHECK_EDGE,            /* compactly supported isotropic R whose edge singularity makes S
                                 negative at high |k| (core/model_edge.c) */
    NL_CHECK_NEG_TAPERED,     /* the spectrum of R times a Gaussian taper, >= 0 for every valid R,
                                 is negative at |k| = min_spectrum_k (core/taper.c) */
    NL_CHECK_KNOWN            /* the family (or a structure's) is known not to be positive definite
                                 in dim (nl_model_check_dim's NL_ENOTPD): nothing was measured, the
                                 other fields are NAN or 0, and nl_errmsg() holds the reason until
                                 the thread's next failing call */
} nl_check_reason;

typedef struct {
    int dim;
    int spectral;            /* the spectral path (power:, spectrum:) was taken */
    double scale;            /* L (spectral models: 16, the matrix's reach in unit spacings) */
    double variance;         /* R(0) */
    double min_spectrum;     /* smallest sampled d-dimensional spectrum value / largest magnitude */
    double min_spectrum_k;   /* |k| (cycles per unit) where it is reached */
    double spectrum_kmax;    /* the sampled frequencies reach |k| = this along each axis */
    double min_eigenvalue;   /* smallest covariance eigenvalue / R(0) */
    size_t eig_side;         /* the matrix's grid: eig_side^dim points; 0 = infinite grid */
    double eig_spacing;      /* the grid's spacing */
    int positive_definite;   /* every test below passed */
    nl_check_reason why;     /* the first failure, NL_CHECK_VALID if none */
    int isotropic;           /* the model is isotropic in dim */
    double min_r;            /* min R / R(0) over lags 0..L along x (NAN: not sampled, spectral models) */
    double min_r_lag;        /* the lag where it is reached */
    int isotropic_bound_ok;  /* min_r >= nl_check_isotropic_bound(dim) (always 1 if not isotropic) */
    int monotone_3d;         /* 3D isotropic: line spectrum non-increasing (1 if not applicable) */
    double line_rise_f;      /* where it rises (0 if it does not) */
    double spectral_decay;   /* b in S1 ~ f^-b, the line spectrum of R along x (INFINITY: faster) */
    double density_decay;    /* b in S ~ |k|^-b, the d-dimensional density (INFINITY: faster; NAN: not
                                estimated, anisotropic models other than ellipsoids) */
    int band_limited;        /* S = 0 above |k| = band_edge */
    double band_edge;        /* cycles per unit */
    int differentiable_order;/* m; -1 infinitely */
    double r2;               /* R''(0) along x (-INFINITY when it does not exist) */
    int singular_checked;    /* singular_below was computed */
    double singular_below;   /* spacing, or 0 */
} nl_check;

/* All checks of m in dim (1..3) dimensions into *out (zeroed first).
 * Returns NL_OK, NL_EINVAL (m not defined in dim, nl_model_check_dim, or
 * R(0) not a positive finite variance or outside [1e-200, 1e200], or a
 * spectrum without a measurable decay), NL_ENOMEM, NL_EFAIL (the
 * eigenvalues or an integral of the spectrum did not converge), or the
 * codes of nl_wk_sample_spectrum and nl_wk_acf_to_spectrum (core/wk.h).
 * "Not positive definite" is a result (out->positive_definite = 0, the
 * reason in out->why), not an error; so is a family known not to be in dim
 * (NL_CHECK_KNOWN).  Thread safety: as the model
 * (core/model.h: expression models are not thread-safe); the FFTs it runs
 * plan FFTW, so not concurrently with other planning. */
int nl_check_model(const nl_model *m, int dim, nl_check *out);

/* The bound an isotropic correlation R / R(0) keeps in dim dimensions:
 * the infimum of Schoenberg's Omega_dim, -1 (1D), min J0 = -0.40276 (2D),
 * min sin(x)/x = -0.21723 (3D). */
double nl_check_isotropic_bound(int dim);

/* Valid neighbours of a model m whose check c (nl_check_model of m) found
 * it not positive definite, as specs separated by '\n' into buf (size
 * bytes, NUL-terminated; "" when there is no obvious one: valid models,
 * spectral, anisotropic and exemplar models), each verified positive
 * definite in c->dim by nl_check_model: for oscillatory and gauss-osc the
 * largest omega (3 significant digits, rounded down) valid in c->dim; for
 * an isotropic expr: that vanishes beyond a lag a, the spherical model of
 * range a (valid up to 3D); for an isotropic model valid in 1D, its
 * separable product (",sep" or ";sep"), valid in every dimension.  Runs up
 * to 16 checks.  Returns NL_OK (a candidate that cannot be checked is left
 * out).  Thread safety: as nl_check_model. */
int nl_check_neighbours(const nl_model *m, const nl_check *c, char *buf, size_t size);

/* Lewis 1987, eq. (14) (Matheron 1973): the isotropic 2D correlation made
 * by sweeping m's 1D profile C_1 = R over every direction (turning bands),
 *     C_2(r) = (2/pi) int_0^1 C_1(v r) (1 - v^2)^(-1/2) dv,
 * at the n lags r[i] >= 0 (m's lag units) into c2[i] (variance units;
 * C_2(0) = R(0), a nugget included only there).  Valid in 2D whenever m is
 * valid in 1D.  Adaptive quadrature to 1e-12 relative, 1e-13 R(0)
 * absolute (analysis/check_matheron.c), at most 1000 subintervals per
 * lag and 1e7 evaluations of R in all.  NL_OK, NL_EINVAL (a spectral
 * model or one not defined in 1D, R(0) not positive, a negative or
 * non-finite lag), NL_ETOOBIG (a lag where the profile oscillates more
 * often than the subintervals resolve, or the evaluations spent: the
 * message names the lag), NL_EFAIL (the quadrature did not converge
 * otherwise), NL_ENOMEM.
 * Thread safety: as the model. */
int nl_check_matheron_2d(const nl_model *m, size_t n, const double *r, double *c2);

#ifdef __cplusplus
}
#endif

#endif
