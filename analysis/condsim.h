/* Conditional simulation by kriging (Journel 1974; Journel and Huijbregts
 * 1978, section VI.A.2): a field with the model's covariance that honours
 * data d_i at points t_i.  From an unconditional realization U of the
 * model (any exact method: fft, circulant, subdivision) on a grid,
 *     Z(x) = U(x) + K[d - U(t)](x),
 * where K[v](x) is the kriging estimate (analysis/krige.h) at x from values
 * v_i at the t_i.  Over realizations of U, Z has the kriging estimate
 * K[d](x) as its mean and the kriging variance as its variance (the
 * estimation error U(x) - K[U(t)](x) is that of kriging and, for Gaussian
 * U, independent of the data's values), with ordinary kriging (unknown
 * mean) or simple kriging with a known mean.
 *
 * Grid.  Sample i of axis a sits at the cell centre lo[a] + (i + 0.5) h[a]
 * (as nl_krige_eval_grid), so the grid covers [lo[a], lo[a] + n[a] h[a]].
 * Data on samples (within NL_CONDSIM_ON_SAMPLE spacings of one on every
 * axis: taken as on it) read U there, and are honoured to rounding (Z(t_i)
 * = d_i: kriging interpolates).  Data between samples ("sites") need U(t)
 * with its joint law with the grid: it is drawn from its conditional law
 * given the grid samples around it (Davis 1987, "Production of conditional
 * simulations via the LU triangular decomposition of the covariance
 * matrix"; the same Gaussian conditioning):
 *     U(T) ~ N(C_TG C_GG^-1 U(G), C_TT - C_TG C_GG^-1 C_GT),
 * T the sites of one group, G the union of their neighbourhoods (the
 * hood^dim nearest samples of each, a block of hood samples per axis),
 * sites being grouped when their blocks overlap (up to
 * NL_CONDSIM_JOINT_MAX samples in a group).  The plan factors each group
 * once; a realization costs one product by C_TG C_GG^-1 and one by the
 * conditional covariance's Cholesky factor applied to N(0, 1) numbers
 * nl_rng_gauss(seed, NL_STREAM_CONDSIM, site), site the datum's index
 * from 0 (the points `at` follow the data: n + j), so a realization is a
 * function of its seed alone, whatever the thread count.  The law is exact
 * when the grid beyond the neighbourhood tells nothing more about U(T)
 * (screening: exact for the 1D exponential with hood >= 2, Markov); the
 * plan states the error as the standard deviation, over realizations, of
 * the change in the conditional mean of a site between hood and hood + 2
 * (the largest over the first NL_CONDSIM_SCREEN_SITES sites, in units of
 * sqrt(R(0))).  The default hood, 4, measured on Meuse (155 data between
 * the samples of a 40 m grid, spherical range 897 m with a nugget;
 * experiments/fig-condsim.sh): over 200 realizations the ensemble
 * variance averages 1.003 of the kriging variance with hood 4 and with
 * hood 6, 1.038 with hood 2 (screening errors 0.0097, 0.0068, 0.10).
 * Sites whose blocks overlap but whose group would exceed
 * NL_CONDSIM_JOINT_MAX are drawn apart (counted in the info's unlinked).
 *
 * Kriging weights.  K[r](x) = c(x) + sum_k w_k(x) r_{idx_k(x)} with
 * weights that depend on the geometry alone (analysis/krige_weights_internal.h):
 * the plan computes them once per grid cell and point, and a realization
 * costs cells x (nmax, or n) multiply-adds, in parallel over cells above
 * 2^22 of them (each cell's sum in a fixed order: the bits do not depend
 * on the thread count).  When the weights would take more than
 * NL_CONDSIM_WEIGHTS_MAX bytes, or global kriging has more than
 * NL_KRIGE_LOCAL_MAX data or a singular system, or the options ask for
 * it (rekrige), each realization kriges its residual anew (analysis/krige.h
 * or krige_local.h): the same field to rounding, at O(n^3) per realization.
 *
 * Points.  Points `at` (np of them, anywhere in the extent) between
 * samples are sites too, drawn jointly with the data given the grid (on a
 * sample, U is the sample's), then
 * Z(at_j) = U(at_j) + K[d - U(t)](at_j), so the realizations at the points
 * have the kriging estimate and variance there, jointly with the grid's.
 *
 * Ownership and threads: the plan copies the data and borrows the model,
 * which must outlive it; nl_condsim_plan_free releases it (NULL is a
 * no-op).  nl_condsim_execute may run concurrently on one plan (with
 * different fields) for models that are thread-safe (every kind but
 * expr:). */
#ifndef NL_CONDSIM_H
#define NL_CONDSIM_H

#ifdef __cplusplus
extern "C" {
#endif

#include "../core/field.h"
#include "../core/model.h"

#include <stddef.h>
#include <stdint.h>

#define NL_CONDSIM_ON_SAMPLE 1e-9
#define NL_CONDSIM_HOOD 4                          /* default samples per axis around a site */
#define NL_CONDSIM_JOINT_MAX 600                   /* grid samples in one jointly drawn group, at most */
#define NL_CONDSIM_SCREEN_SITES 16                 /* sites whose screening error is measured */
#define NL_CONDSIM_WEIGHTS_MAX ((size_t)1 << 30)   /* bytes of kriging weights kept, at most */
#define NL_STREAM_CONDSIM 0x434f4e44u              /* "COND": the draws at the sites */

typedef struct nl_condsim_plan nl_condsim_plan;

typedef struct {
    int simple;    /* simple kriging with the known mean `mean`, else ordinary */
    double mean;   /* the known mean (simple) */
    size_t nmax;   /* local kriging from the nmax nearest data (analysis/krige_local.h); 0: every datum */
    size_t hood;   /* samples per axis in a site's neighbourhood, 1..16; 0: NL_CONDSIM_HOOD */
    int rekrige;   /* krige each realization's residual anew instead of keeping weights */
} nl_condsim_options;

typedef struct {
    size_t n;          /* data */
    size_t on_samples; /* data read from one grid sample (honoured exactly) */
    size_t sites;      /* data and points between samples, drawn given the grid */
    size_t hood;       /* samples per axis in a site's neighbourhood */
    size_t groups;     /* groups of sites drawn jointly */
    size_t largest;    /* grid samples in the largest group */
    size_t unlinked;   /* pairs of overlapping sites drawn in separate groups (NL_CONDSIM_JOINT_MAX) */
    double screening;  /* the screening error (see above; 0 without sites) */
    size_t worst;      /* the site (datum index from 0; n + j for point j) with it */
    double max_move;   /* largest distance from a datum to its nearest sample, in units of the coordinates */
    int reuse;         /* 1: kriging weights kept; 0: each realization kriges anew */
    size_t weight_bytes; /* bytes of the kept weights */
} nl_condsim_info;

/* The plan for data pts (n points of grid->dim coordinates, row-major) and
 * values val, on a grid of grid->n samples of spacing grid->h (grid->data
 * is not read) whose cell centres start at lo + h / 2, with the options o
 * (NULL: ordinary global kriging, default hood), and np points at (np *
 * dim coordinates; at may be NULL when np = 0) whose realizations
 * nl_condsim_execute returns.  With nmax > 0 (local kriging from the nmax
 * nearest data) the ensemble's mean and variance are that kriging's.
 * *out is NULL on failure.
 * Errors: NL_EINVAL for n = 0, a datum or point outside [lo, lo + n h]
 * (the message names the first: its row from 1 and coordinates), a
 * non-finite lo, datum or point, hood above 16, or what
 * nl_krige_plan_alloc refuses in the model or data (checked here, once, on
 * the data's values); NL_ETOOBIG, NL_ENOMEM. */
int nl_condsim_plan_alloc(const nl_model *m, size_t n, const double *pts, const double *val, const double *lo,
                          const nl_field *grid, const nl_condsim_options *o, size_t np, const double *at,
                          nl_condsim_plan **out);

/* Replace the unconditional realization in f (the plan's grid: same dim, n
 * and h) by the conditional one, Z = U + K[d - U(t)], the draws at the
 * sites from `seed` (use the realization's own); z_at (np values; may be
 * NULL) receives Z at the plan's points.  Cost: the sites' draws, and
 * (count + np) x (nmax or n) multiply-adds (or, without kept weights, one
 * kriging set-up and one kriging of the grid).
 * Errors: NL_EINVAL for a field of another shape or non-finite samples
 * near the data; NL_ETOOBIG, NL_ENOMEM; those of nl_krige_plan_alloc. */
int nl_condsim_execute(const nl_condsim_plan *p, nl_field *f, uint64_t seed, double *z_at);

void nl_condsim_plan_info(const nl_condsim_plan *p, nl_condsim_info *info);
void nl_condsim_plan_free(nl_condsim_plan *p);

#ifdef __cplusplus
}
#endif

#endif
