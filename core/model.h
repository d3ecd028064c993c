/* The model layer: an autocorrelation R(lag) and, where known, its spectrum.
 *
 * A model is made from a spec string NAME[:key=value,...] (see `noiselab
 * models`), NAME a family of the registry (core/family.h), e.g.:
 *     markov:scale=8                  a named family with its parameters
 *     expr:EXPR                       R given by an expression, e.g. expr:besselj(0, r)
 *     spectrum:EXPR                   S given by an expression
 *     image:FILE                      R = empirical autocorrelation of an exemplar (Lewis 1987, eq. 15)
 * Every family's parameters, defaults and formula: nl_model_catalogue,
 * docs/models.md (generated from the registry).
 * Named models take var= (R(0)) and, in 2D and 3D, `sep` (separable:
 * R(x)R(y)R(z)/var^(dim-1)), `angle=` (degrees, rotation about z) and `ratio=`
 * (correlation length along the rotated y axis over that along x), `zratio=`
 * (same for z) for the ellipsoidal stretch of Stam and Fiume; default is
 * isotropic, R(|lag|).  The angle turns the major axis (scale's) from +x
 * towards +y; gstat's anis = c(p, s) measures p clockwise from +y, so it
 * is angle = 90 - p, ratio = s, and gstat's peer names (Sph:...) take p
 * itself as their angle= (core/families/peers.c).  For expr:, spectrum: and image: these keys may follow
 * a final ';', e.g. "expr:exp(-abs(t));ratio=0.5".
 *
 * Spherical.  Its `scale` is the range a, the lag at which R reaches 0
 * (as gstat's vgm(range = a) and GSTools' Spherical(len_scale = a); not a
 * decay length as for markov).  It is positive definite in 1, 2 and 3
 * dimensions only (its 4D Hankel transform is negative somewhere);
 * nl_model_check_dim accepts dim 1..3, and the methods that reach 4D
 * (rank-1 lattices) refuse it there.
 *
 * Nugget.  Every model defined by R (named, expr:, image:; not power: or
 * spectrum:) takes nugget=N >= 0 (default 0): white noise of variance N
 * independent of the rest, so R(0) = var + N and R(lag != 0) = var rho(lag)
 * (gstat's vgm(nugget = N), GSTools' nugget: the semivariogram jumps from 0
 * to N at the origin).  nl_model_acf adds N where every lag component is
 * exactly 0, so a covariance sampled on a grid holds N on its diagonal.  Its
 * spectrum on a grid of cell volume h_1...h_d is the constant N h_1...h_d
 * over the Nyquist band (nl_wk_sample_spectrum* include it, since they
 * transform the sampled R); nl_model_spectrum and nl_model_spectrum_iso
 * return the spectrum of the continuous part alone (the nugget's density
 * depends on the grid), so methods built on them refuse a nugget.
 *
 * Intrinsic models (powvar, the power variogram; NL_FAMILY_INTRINSIC).  A
 * field with stationary increments and no covariance: what it has is its
 * variogram gamma(h) = E (Z(x+h) - Z(x))^2 / 2, unbounded.  nl_model_acf
 * returns its generalized covariance K(h) = -gamma(h) (plus the nugget at
 * lag 0, so K(0) = nugget and K(0) - K(h) = gamma(h) for h != 0), which is
 * conditionally positive definite: sum_ij w_i w_j K(t_i - t_j) >= 0 for
 * every w with sum w_i = 0 (Matheron 1973).  Ordinary kriging uses only
 * such combinations (its weights sum to 1), so its predictions and
 * variances are those of the variogram and any constant added to K drops
 * out (analysis/krige.c adds one to make its matrix positive definite);
 * nl_model_variogram gives gamma directly.  Every consumer that needs a
 * covariance (R(0) as a variance, a positive definite matrix or spectrum:
 * the synthesis methods but `intrinsic`, simple kriging, ML fits,
 * conditional simulation) refuses it through nl_model_check_stationary.
 * nl_model_spectrum gives the generalized spectral density, not
 * integrable at f = 0.
 *
 * Sums and products.  A spec may join structures with '+' and '*', '*'
 * binding first (no parentheses: write A*B + A*C), blanks around either
 * optional:  nugget:var=0.05 + spherical:var=0.59,scale=897  or
 * markov:scale=3 * oscillatory:omega=2 + gauss:scale=0.5,var=0.1.  Each
 * structure is a spec of its own: its family, parameters, nugget and
 * anisotropy keys (angle, ratio, zratio, sep apply to it alone).  R of a
 * sum is the sum of its terms' R (R(0): every var and nugget added), of a
 * product the product of its factors' R (var: the product of the vars); a
 * nugget inside a product is refused (white noise times a structure is
 * white noise: write it as a term of the sum).  S of a sum is the sum of
 * the closed-form spectra, NAN where any term has none; of a product NAN
 * (no convolution).  Structures defined by their spectrum (power:,
 * spectrum:) and those that read a file (image:) are refused in sums and
 * products.  A sum with an intrinsic structure (powvar) is intrinsic
 * (nl_model_is_intrinsic; R its generalized covariance, the terms' added);
 * a product refuses one.  The nugget family (nugget:var=V) is white noise
 * in a sum: its V counts in nl_model_nugget.  Splitting: a '+' or '*' of
 * a named family's keys separates structures unless it is a number's sign
 * (after '=' or in an exponent: var=+2, scale=1e+3); an argument family's
 * argument (expr:) takes every character up to its first ';', or
 * up to the end of the spec without one, so an expression is either the
 * last structure or ends with ';' (its keys may follow):
 *     markov:scale=2 + expr:0.5*exp(-t^2)        expr: last
 *     expr:0.5*exp(-t^2); + markov:scale=2       expr: ended by ';'
 *     expr:0.5*exp(-t^2);ratio=2 * markov:scale=2
 * At most NL_MODEL_MAX_STRUCTURES structures.  Structures are numbered from
 * 1, left to right (nl_model_structure counts from 0), and a sum's
 * parameters are named NAME.I, e.g. var.2 (the var of the second
 * structure), scale.1, nugget.1 (nl_model_param; `noiselab fit` names the
 * fitted parameters so, as gstat's vgm rows).  nl_model_family of a sum or
 * product is a descriptor flagged NL_FAMILY_COMPOSITE.
 *
 * Expression variables.  ACF expressions: t (the signed lag in 1D; the
 * stretched lag norm in n-D), x, y, z (lag components), r (the stretched lag
 * norm).  Spectrum expressions: f (|frequency|; signed in 1D), fx, fy, fz,
 * k (|frequency|).  Frequencies are in cycles per unit length (cycles per
 * sample at unit spacing); spectra are two-sided densities, so the variance
 * is the integral of S over all frequencies.
 *
 * Expressions.  The syntax (libmatheval's, kept when noiselab moved to
 * muParser) and the functions, Bessel J, Y, K of real order, Gamma, the
 * incomplete gamma functions, erf, erfc, sinc among them, are listed in
 * core/expr_internal.h and docs/expressions.md.  Where an expression is
 * not finite (NaN or inf) at a lag or frequency, nl_model_acf and
 * nl_model_spectrum return its limit there when the limit exists
 * (sin(r)/r at 0 is 1, to 1e-10 relative or better: core/expr_limit.c),
 * else the value itself (1/r at 0 stays inf, sin(1/r) NaN); delta and
 * nandelta, whose point values are not limits, read 0 at 0 through this.
 *
 * Thread safety.  Expression evaluation is not reentrant: a compiled
 * muParser expression reads its variables from, and evaluates on a stack
 * inside, the one object, so nl_model_acf and nl_model_spectrum must not
 * be called on one expr: or spectrum: model from two threads
 * (nl_model_is_reentrant says which models may); two such models may be
 * evaluated concurrently, one per thread, and every other model from any
 * number of threads.  nl_model_parse is not thread-safe for expr: and
 * spectrum: specs (muParser's C interface keeps static buffers) nor for
 * image: (it plans FFTW, core/fftw_plan.h); other specs parse concurrently.  GSL: the Matern, power and Hankel paths reach GSL
 * under the library's guard (core/nl_error.h); where GSL fails they return
 * NAN (Matern: 0 where Bessel K fails), never abort. */
#ifndef NL_MODEL_H
#define NL_MODEL_H

#include "family.h"

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif


typedef struct nl_model nl_model;

/* Parse a spec.  Returns NL_OK and a new model in *out (release it with
 * nl_model_free), or, with *out = NULL and a message naming the bad part:
 * NL_EINVAL (unknown family or key, a value that is not a finite number or
 * out of range, a missing required parameter, a malformed expression, a 3D
 * or constant exemplar), NL_EINPUT (image: file missing or malformed),
 * NL_ETOOBIG (image: too large to tabulate) or NL_ENOMEM. */
int nl_model_parse(const char *spec, nl_model **out);

/* Release a model (NULL is a no-op). */
void nl_model_free(nl_model *m);

/* The spec as given by the user (owned by the model). */
const char *nl_model_spec(const nl_model *m);

/* Is the model defined by its spectrum (power, spectrum:) rather than by R? */
int nl_model_is_spectral(const nl_model *m);

/* Can R(lag) be evaluated (nl_model_acf): a model defined by R, or a
 * spectral family whose R is computed (power:)?  spectrum: cannot. */
int nl_model_has_acf(const nl_model *m);

/* May nl_model_acf and nl_model_spectrum be called on this model from
 * several threads at once?  True for every model but expressions
 * (a muParser object holds its variables and evaluation stack). */
int nl_model_is_reentrant(const nl_model *m);

/* R at the lag vector lag[0..dim-1] (lengths, in the units of scale), for models defined by R,
 * and for power:, whose R is computed by quadrature (the Fourier or Hankel
 * transform of its band-limited spectrum, Lewis 1987 eq. (13)).  For
 * spectrum: models returns NAN (use the sampled conversion in wk.h).  NAN
 * too where power:'s quadrature fails (e.g. at lags of 1e6 in 2D: GSL runs
 * out of subdivisions).  dim is 1..3 (checked by nl_model_check_dim, not
 * here); R is in the model's variance units, R(0) = var + nugget. */
double nl_model_acf(const nl_model *m, int dim, const double *lag);

/* The semivariogram gamma(lag) = (E (Z(x+lag) - Z(x))^2) / 2 at the lag
 * vector lag[0..dim-1]: R(0) - R(lag) for every model with R (nugget
 * included: gamma jumps to nugget just off lag 0), c |lag|^alpha (plus the
 * nugget) for the intrinsic powvar (on its stretched lag when anisotropic).
 * NAN where R is NAN (spectrum:).  Same units and threads as nl_model_acf. */
double nl_model_variogram(const nl_model *m, int dim, const double *lag);

/* Is the model intrinsic (a variogram without covariance: powvar)? */
int nl_model_is_intrinsic(const nl_model *m);

/* The intrinsic structure of m: m itself when intrinsic (powvar), the
 * intrinsic term of a sum of it and white noise (nugget:, e.g.
 * "nugget:var=0.1 + powvar:alpha=1.5"), NULL otherwise (a model with a
 * covariance, or a sum of an intrinsic model and other structures, which
 * only ordinary kriging takes).  Its parameters are the intrinsic part's;
 * nl_model_nugget(m) has every nugget. */
const nl_model *nl_model_intrinsic_structure(const nl_model *m);

/* NL_OK for a model with a covariance; for an intrinsic one NL_EINVAL with
 * the message "SPEC: <what> needs a covariance; powvar is intrinsic (no
 * covariance): use synth intrinsic or ordinary kriging (krige)".  what:
 * e.g. "synth fft", "fit --ml". */
int nl_model_check_stationary(const nl_model *m, const char *what);

/* S at the frequency vector f[0..dim-1] (cycles per unit length) for spectral
 * models, and for the 1D analytic spectra of markov, gauss, oscillatory and
 * gauss-osc; NAN where no closed form is implemented.  The continuous part
 * only: a nugget is not included (see Nugget above). */
double nl_model_spectrum(const nl_model *m, int dim, const double *f);

/* The spectrum of an isotropic autocorrelation in dim = 1..4 dimensions at
 * radial frequency w (cycles per unit), by the Hankel transform of Lewis
 * 1987 eq. (13) with GSL quadrature and Bessel functions (4D uses the model's
 * 3D profile, which is the same function of |lag|).  NAN on failure (dim
 * outside 1..4, R(0) not positive, quadrature not converged, |R| still
 * above 1e-12 R(0) at lag 1e7, where no transform exists).  Slow: up to
 * thousands of evaluations of R per frequency.  The continuous part only
 * (the nugget, a value at one lag, has no weight in the integral). */
double nl_model_spectrum_iso(const nl_model *m, int dim, double w);

/* The continuous spectral density S at the frequency vector f[0..dim-1]
 * (cycles per unit length; dim 1..3): two-sided, in variance per (cycles
 * per unit)^dim, so that R(lag) = int S(f) exp(2 pi i f.lag) df and the
 * integral of S over all frequencies is R(0) less the nugget.  The
 * family's closed form (nl_model_spectrum) where it has one; otherwise,
 * for a model defined by a radial profile, its d-dimensional transform by
 * nl_model_spectrum_iso (slow: quadrature per frequency), carried through
 * the anisotropy: with angle, ratio, zratio, S(f) = ratio zratio
 * S_iso(|(u, ratio v, zratio w)|) where (u, v, w) is f turned by the
 * angle (Stam and Fiume's ellipsoid, the linear map of the lag); with
 * sep, the product of the axes' 1D spectra over R(0)^(dim-1).  A sum
 * adds its terms' densities (nugget: 0).  NAN for a product (a
 * convolution), an image: model, an expression of x, y, z, dim outside
 * 1..3, a non-finite f, and where the quadrature fails (see
 * nl_model_spectrum_iso).  Intrinsic models: their generalized density
 * (nl_model_spectrum).  Thread safety as nl_model_spectrum (core/model.h,
 * "Thread safety"); GSL runs under the library's guard. */
double nl_model_spectral_density(const nl_model *m, int dim, const double *f);

/* The band of radial frequencies fmin <= |f| <= fmax (cycles per unit
 * length, as the spectrum's) outside which the model's spectrum in dim
 * dimensions is zero, so that a field made from it holds no power there
 * (but for the estimator's leakage and rounding).  A family's band is its
 * NL_ROLE_BAND parameters (core/family.h; power: fmin, fmax, defaults
 * included); a family without is the whole axis, *fmin = 0 and *fmax =
 * INFINITY.  A sum: the smallest band holding every term's (its spectrum
 * is positive wherever a term's is; a gap between the terms' bands is not
 * reported).  A product: 0 to the sum of the factors' fmax (its spectrum
 * is the convolution of theirs).  The nugget is not counted (its white
 * spectrum depends on the grid).  Returns NL_OK, or NL_EINVAL (dim not 1,
 * 2 or 3, a NULL argument) with *fmin, *fmax untouched.  Thread-safe. */
int nl_model_band(const nl_model *m, int dim, double *fmin, double *fmax);

/* Is R a function of |lag| alone in dim > 1 (no sep, angle or ratio, and
 * for expressions no x, y, z)? */
int nl_model_is_isotropic(const nl_model *m);

/* d^2 R / dt^2 of the 1D profile at t by extrapolated central differences
 * (Ridders; within 1e-9 relative on smooth profiles, e.g. -2 for
 * exp(-t^2) at 0) (expr: models only; NAN otherwise or where they do not
 * converge, as at a kink). */
double nl_model_acf_d2(const nl_model *m, double t);

/* Check that the model can be used in `dim` dimensions (e.g. an image model
 * has no 3D table, spectral models take no anisotropy keys).  NL_OK,
 * NL_ENOTPD with a message where the family is known not to be positive
 * definite in dim with these parameters (askey, wendland, dampedcos,
 * jbessel, lgd, bohman, hyperspherical, superspherical: core/family.h's
 * check_dim), or NL_EINVAL with a message. */
int nl_model_check_dim(const nl_model *m, int dim);

/* One entry of the model catalogue printed by `noiselab models`, made from
 * the family registry (core/family.h): the name, the parameters with their
 * defaults (required ones first; an argument family's argument and the
 * keys after its ';'), the formula. */
typedef struct {
    const char *name;     /* as written in a spec */
    const char *params;   /* parameters with defaults; required ones first */
    const char *formula;  /* R or S */
} nl_model_info;

/* The catalogue (static storage: do not free); *count receives its length. */
const nl_model_info *nl_model_catalogue(size_t *count);

/* The value in effect of the parameter `name` (a parameter of the model's
 * family, core/family.h, or ratio, zratio of a model defined by R: defaults
 * included, in the spec's units; nugget is 0 unless given; of a sum or
 * product, NAME.I: structure I's, see "Sums and products") into
 * *value.  Returns NL_OK, or NL_EINVAL when the model's family has no such
 * parameter (*value untouched).  Thread-safe (core/model_param.c). */
int nl_model_param(const nl_model *m, const char *name, double *value);

/* The nugget (0 for spectral models and when not given; of a sum, its
 * terms' nuggets added).  Thread-safe. */
double nl_model_nugget(const nl_model *m);

/* The most structures of a sum or product. */
#define NL_MODEL_MAX_STRUCTURES 64

/* How many structures the model joins (1 for a model of one family). */
size_t nl_model_structures(const nl_model *m);

/* The i-th structure (from 0, left to right; m itself for a model of one
 * family and i = 0), owned by m; NULL when i is out of range. */
const nl_model *nl_model_structure(const nl_model *m, size_t i);

/* The operator after the i-th structure: '+', '*', or 0 after the last. */
char nl_model_operator(const nl_model *m, size_t i);

#ifdef __cplusplus
}
#endif

#endif
