/* Binning shared by the variograms of points and of fields. */
#ifndef NL_VARIOGRAM_INTERNAL_H
#define NL_VARIOGRAM_INTERNAL_H

#include "variogram.h"

#define NL_VG_MAXBINS 1000000
#define NL_VG_FRACTION 0.33333 /* gstat's default cutoff over the diagonal */

typedef struct {
    double cutoff, width; /* as resolved from the options */
    double reach;         /* the pair search's radius: the cutoff, a hair beyond for gstat's bins
                             (the search keeps distances below it) */
    size_t nb;            /* bins: ceil(cutoff / width), gstat's floor(cutoff / width) + 1 */
    int gstat;            /* gstat's (lo, hi] bins, h <= cutoff */
    int cressie;          /* estimator */
    int directional;      /* direction test on */
    double ux, uy;        /* unit vector of the direction */
    double costol;        /* cos(tolerance) */
} nl_vg_acc;

int nl_vg_check_options(const nl_variogram_options *o);
/* The n values z, all finite, whose squared differences summed over every
 * pair stay finite: max - min at most sqrt(DBL_MAX / (n (n - 1))).  `what`
 * names them ("the points' values", "the field's samples"). */
int nl_vg_check_values(const double *z, size_t n, const char *what);
int nl_vg_bins(const nl_variogram_options *o, double diag, nl_vg_acc *acc);
/* 3 sums per bin: distances, squared (or root) differences, pairs. */
int nl_vg_sums_alloc(size_t nb, double **s);
/* The bin of a pair at distance d, horizontal offset dx[0..1]; -1 when
 * the pair is beyond the cutoff or outside the direction. */
long nl_vg_bin(const nl_vg_acc *a, double d, const double *dx);
/* Add a pair at distance d, horizontal offset dx[0..1], value difference dz. */
void nl_vg_add(const nl_vg_acc *a, double *sums, double d, const double *dx, double dz);
int nl_vg_finish(const nl_vg_acc *a, const double *sums, nl_variogram **out);
/* The n values z at the points pts (n x dim) less their ordinary
 * least-squares drift (drift NL_VARIOGRAM_DRIFT_*, then the q covariates
 * cov, n x q row-major) into r (n values): analysis/variogram_drift.c.
 * NL_EINVAL (too few points, a non-finite covariate, rank-deficient
 * terms), NL_ENOMEM. */
int nl_vg_residuals(int dim, size_t n, const double *pts, const double *z, int drift, const double *cov, size_t q,
                    double *r);

#endif
