/* Spectral slope: least-squares fit of log S = c + slope log f over a band
 * (GSL gsl_fit_linear), with the 95% confidence interval of the slope from
 * the fit's residual variance (Student's t, n - 2 degrees of freedom), and
 * the fractal dimension of Lewis 1987, eq. (16): D = E + (3 - d)/2 with
 * E the Euclidean dimension and d the exponent of a 1D profile's spectrum:
 * d = -slope in 1D, and d = -slope - (E - 1) when the slope is that of the
 * radial average of an E-D spectrum (an fBm surface, H = 0.8, has radial
 * slope -3.6, profile d = 2.6 and D = 2.2).  The residuals are treated as
 * independent, which holds for periodogram ordinates at distinct Fourier
 * frequencies of a long record. */
#ifndef NL_SLOPE_H
#define NL_SLOPE_H

#ifdef __cplusplus
extern "C" {
#endif

#include "../core/field.h"

#include <stddef.h>

typedef struct {
    double slope;     /* fitted exponent (negative for decaying spectra) */
    double ci95;      /* half-width of the 95% confidence interval */
    size_t points;    /* frequencies used */
    double fractal_dim; /* eq. (16) */
} nl_slope;

/* Frequencies f[i] (cycles per unit length, any positive unit) with
 * fmin <= f <= fmax and psd > 0 are used; E is the Euclidean dimension for
 * eq. (16).  Returns NL_OK, NL_EINVAL (fewer than 3 frequencies in the
 * band) or NL_ENOMEM; *out is untouched on failure.  Reentrant. */
int nl_psd_slope(const double *f, const double *psd, size_t n, double fmin, double fmax, int E, nl_slope *out);

/* The same fitted to every ordinate of a 2D or 3D periodogram P (wrapped
 * order, as nl_psd_periodogram makes it) with fmin <= |f| <= fmax, each
 * Hermitian pair once: log-periodogram regression.  The ordinates of a
 * Gaussian field's periodogram are close to independent with a log of
 * constant variance, so the least-squares interval holds; fitting the
 * radial average instead gives too narrow an interval (its low-frequency
 * rings hold few ordinates, over which a steep spectrum varies).  Returns
 * the codes of nl_psd_slope. */
int nl_psd_slope_grid(const nl_field *P, double fmin, double fmax, nl_slope *out);

/* Where the profile exponent d = -slope - (E - 1) of a fit s in E
 * dimensions lies against the range 1 < d < 3 in which eq. (16) gives a
 * fractal dimension (E <= D <= E + 1): 0 when its 95% interval
 * d +- ci95 meets [1, 3]; -1 when it lies wholly below 1 (a spectrum
 * flatter than 1/f in 1D: stationary noise, whose graph fills its space,
 * where eq. (16) would give D > E + 1); +1 when wholly above 3 (a graph
 * smooth enough to have D = E, where eq. (16) would give D < E); 0 for a
 * NULL s or E outside 1..3.  Reentrant. */
int nl_slope_fractal_range(const nl_slope *s, int E);

#ifdef __cplusplus
}
#endif

#endif
