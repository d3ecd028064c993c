/* Empirical (semi)variogram of scattered points and of fields, binned as
 * gstat's variogram() (Pebesma 2004).
 *
 * Bins (nl_variogram_options.bins).  NL_VARIOGRAM_BINS_GSTAT (the default):
 * pairs (i, j), i < j, at distance h_ij = |x_i - x_j| with 0 <= h_ij <= cutoff
 * fall into bin k = ceil(h_ij / width) - 1, bins (k W, (k + 1) W] closed
 * above, a pair at distance 0 in the first bin and a pair at exactly the
 * cutoff kept: gstat's src/sem.c (get_index: q = h / W, k = floor(q), less 1
 * where h > 0 and q is an integer; valid_distance drops h > cutoff; a
 * variogram's zero distances are ZERO_INCLUDE, in the first bin).  It
 * matters where distances fall on multiples of W: on Meuse with W = 50 the
 * pair at exactly 200 m is in bin (150, 200].  NL_VARIOGRAM_BINS_FLOOR:
 * bins [k W, (k + 1) W), k = floor(h_ij / W), h_ij < cutoff.
 *
 * Drift (nl_variogram_options.drift).  NL_VARIOGRAM_DRIFT_LINEAR or
 * _QUADRATIC: the variogram of the residuals of the ordinary least-squares
 * fit of a polynomial in the coordinates to the values (1, x, y, z; the
 * quadratic adds the squares and cross products), gstat's variogram(z ~ x +
 * y) (src/sem.c alloc_exp_variogram, make_residuals_lm); points only.
 * nl_variogram_points_design adds external covariates to the drift's
 * columns (after 1, or after the polynomial's terms): gstat's
 * variogram(z ~ c1 + c2) (Meuse's variogram(log(zinc) ~ sqrt(dist)) to
 * 1e-9, tests/test_fit_cov.c).  The residuals do not depend on the
 * columns' units or centring (the same column space).
 *
 * Per bin, with N_k pairs and d_ij = z_i - z_j:
 *     Matheron:  gamma_k = sum d_ij^2 / (2 N_k)
 *     Cressie and Hawkins (1980):  gamma_k = (sum |d_ij|^(1/2) / N_k)^4
 *                / (2 (0.457 + 0.494 / N_k))
 * distance_k = mean h_ij of the bin's pairs.  Bins without a pair are left
 * out.  The default cutoff is gstat's: 0.33333 (gstat's constant, not
 * exactly 1/3) times the diagonal of the points' bounding box, where for 3D
 * points the box's z extent is, as in gstat, the first point's z minus the
 * smallest z (gstat reads the points without tracking the largest z), so
 * the default depends on the points' order in 3D; a field's default uses
 * its whole box.  Directional variograms keep the pairs whose direction lies within
 * `tolerance` degrees of `direction` (either sense): gstat's alpha (degrees
 * clockwise from the y axis, "north", towards x) and tol.hor, in the x-y
 * plane (for 3D points the pair's projection onto the x-y plane; a pair
 * with a zero projection is kept, as in gstat).
 *
 * Pairs are enumerated through a spatial index (core/spindex.h) with cells
 * of the cutoff: memory O(n), time O(n + pairs within the cutoff). */
#ifndef NL_VARIOGRAM_H
#define NL_VARIOGRAM_H

#ifdef __cplusplus
extern "C" {
#endif

#include "../core/field.h"
#include "../core/io_points.h"

#include <stddef.h>

enum { NL_VARIOGRAM_MATHERON, NL_VARIOGRAM_CRESSIE };
/* nl_variogram_options.bins */
enum { NL_VARIOGRAM_BINS_GSTAT = 0, NL_VARIOGRAM_BINS_FLOOR = 1 };
/* nl_variogram_options.drift (the values of krige_local.h's NL_DRIFT_*) */
enum { NL_VARIOGRAM_DRIFT_CONSTANT = 0, NL_VARIOGRAM_DRIFT_LINEAR = 1, NL_VARIOGRAM_DRIFT_QUADRATIC = 2 };

typedef struct {
    double width;     /* bin width; 0 = cutoff / 15 */
    double cutoff;    /* 0 = a third of the bounding-box diagonal, gstat's default */
    int estimator;    /* NL_VARIOGRAM_MATHERON or NL_VARIOGRAM_CRESSIE */
    int directional;  /* 0 = omnidirectional */
    double direction; /* degrees, gstat's alpha convention */
    double tolerance; /* degrees, gstat's tol.hor */
    int bins;         /* NL_VARIOGRAM_BINS_GSTAT (default, (lo, hi]) or _FLOOR ([lo, hi)) */
    int drift;        /* NL_VARIOGRAM_DRIFT_*: the variogram of the OLS residuals (points) */
} nl_variogram_options;

/* Omnidirectional Matheron with gstat's default width, cutoff and bins, no drift. */
void nl_variogram_options_default(nl_variogram_options *o);

typedef struct {
    size_t nbins;     /* bins holding at least one pair */
    double *distance; /* mean pair distance */
    double *gamma;    /* semivariance */
    double *pairs;    /* pair counts */
} nl_variogram;

/* The variogram of the points p (nl_points from core/io_points.h, 1 to 3
 * coordinates).  *out (NULL on failure) is released by nl_variogram_free.
 * Errors: NL_EINVAL for fewer than 2 points, a coordinate or value that is
 * not finite, all points at one place (no positive distance), a width or
 * cutoff that is negative or not finite, more than 10^6 bins, an unknown
 * estimator, a direction or tolerance that is not finite (tolerance must lie
 * in [0, 90]), an unknown bins or drift, a drift with no more points than
 * its terms or whose terms are collinear at the points (rank-deficient
 * least squares), values whose max - min exceeds sqrt(DBL_MAX / (n (n - 1)))
 * (their squared differences summed over the pairs would overflow), or no
 * pair within the cutoff; NL_ETOOBIG when the pairs within the cutoff,
 * estimated from a sample of the points before any is walked, exceed 1e9
 * (about half a minute of work per core: a smaller cutoff, fewer points,
 * or the variogram of a gridded field), or when the index outgrows
 * memory; NL_ENOMEM.  Thread-safe. */
int nl_variogram_points(const nl_points *p, const nl_variogram_options *o, nl_variogram **out);

/* The same with q covariates in the drift: design[i * q + c] the c-th
 * covariate at point i (row-major n x q; any units), columns after the
 * terms of o->drift (NL_VARIOGRAM_DRIFT_CONSTANT: 1 and the covariates, as
 * gstat's z ~ c1 + c2).  q = 0 (design may be NULL) is
 * nl_variogram_points.  Errors as nl_variogram_points, and NL_EINVAL for
 * design NULL with q > 0, a non-finite covariate, no more points than the
 * drift's terms, or terms of rank below their count (a constant covariate,
 * a combination of the others).  Thread-safe. */
int nl_variogram_points_design(const nl_points *p, const double *design, size_t q, const nl_variogram_options *o,
                               nl_variogram **out);

/* The variogram of a field: sample (i, j, k) at (i h[0], j h[1], k h[2]),
 * all pairs of samples (same binning and errors as nl_variogram_points;
 * non-finite samples and samples whose max - min exceeds
 * sqrt(DBL_MAX / (count (count - 1))) are refused; a drift is refused:
 * NL_EINVAL).  Time O(count x offsets within the
 * cutoff).  Thread-safe. */
int nl_variogram_field(const nl_field *f, const nl_variogram_options *o, nl_variogram **out);

/* A variogram table (a TSV: a header of the three column names in any
 * order, distance, gamma, pairs as `noiselab variogram -o` writes them or
 * gstat's np, dist, gamma; then a row per bin of three finite numbers;
 * '#' lines and empty lines skipped) into *out (NULL on failure), released
 * by nl_variogram_free; the rows are kept in the file's order.  Errors:
 * NL_EINPUT naming file and line for a file that cannot be read, another or
 * a repeated column name, no header or no row, a row that is not three
 * finite numbers, a distance not > 0, a gamma below 0, pairs that are not
 * a whole number >= 1, more than 10^6 rows; NL_ENOMEM.  Thread-safe. */
int nl_variogram_read(const char *path, nl_variogram **out);

/* Release v and its arrays (NULL is a no-op). */
void nl_variogram_free(nl_variogram *v);

#ifdef __cplusplus
}
#endif

#endif
