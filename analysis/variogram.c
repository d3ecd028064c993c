/* Empirical variogram: Matheron's and Cressie and Hawkins' (1980)
 * estimators over the pairs within the cutoff, binned as gstat's
 * variogram(). */
#include "variogram.h"
#include "variogram_internal.h"
#include "../core/nl_error.h"
#include "../core/spindex.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Pairs within the cutoff one variogram of points may visit: about half a
 * minute per core at the 3e7 pairs a second the pair walk runs. */
#define VG_MAX_PAIRS 1e9

void nl_variogram_options_default(nl_variogram_options *o)
{
    *o = (nl_variogram_options){.estimator = NL_VARIOGRAM_MATHERON};
}

void nl_variogram_free(nl_variogram *v)
{
    if (!v)
        return;
    free(v->distance), free(v->gamma), free(v->pairs), free(v);
}

int nl_vg_check_options(const nl_variogram_options *o)
{
    if (!(o->width >= 0) || !isfinite(o->width))
        return NL_ERROR(NL_EINVAL, "variogram: width: expected a finite number >= 0 (0: cutoff / 15), got %g", o->width);
    if (!(o->cutoff >= 0) || !isfinite(o->cutoff))
        return NL_ERROR(NL_EINVAL, "variogram: cutoff: expected a finite number >= 0 (0: a third of the diagonal), got %g",
                        o->cutoff);
    if (o->estimator != NL_VARIOGRAM_MATHERON && o->estimator != NL_VARIOGRAM_CRESSIE)
        return NL_ERROR(NL_EINVAL, "variogram: estimator: expected matheron or cressie, got %d", o->estimator);
    if (o->bins != NL_VARIOGRAM_BINS_GSTAT && o->bins != NL_VARIOGRAM_BINS_FLOOR)
        return NL_ERROR(NL_EINVAL, "variogram: bins: expected gstat or floor, got %d", o->bins);
    if (o->drift < NL_VARIOGRAM_DRIFT_CONSTANT || o->drift > NL_VARIOGRAM_DRIFT_QUADRATIC)
        return NL_ERROR(NL_EINVAL, "variogram: drift: expected constant, linear or quadratic, got %d", o->drift);
    if (o->directional && (!isfinite(o->direction) || !(o->tolerance >= 0 && o->tolerance <= 90)))
        return NL_ERROR(NL_EINVAL, "variogram: expected a finite direction and a tolerance in [0, 90] degrees, got %g and %g",
                        o->direction, o->tolerance);
    return NL_OK;
}

int nl_vg_check_values(const double *z, size_t n, const char *what)
{
    double lo = INFINITY, hi = -INFINITY, bound = sqrt(DBL_MAX / ((double)n * ((double)n - 1)));
    for (size_t i = 0; i < n; i++) {
        if (!isfinite(z[i]))
            return NL_ERROR(NL_EINVAL, "variogram: %s: number %zu is %g; expected finite numbers", what, i + 1, z[i]);
        lo = fmin(lo, z[i]), hi = fmax(hi, z[i]);
    }
    /* each bin sums up to n (n - 1) / 2 squared differences, each at most (hi - lo)^2 */
    if (!(hi - lo <= bound))
        return NL_ERROR(NL_EINVAL, "variogram: %s run from %g to %g: their squared differences summed over the pairs "
                        "overflow; expected max - min below %.3g (sqrt(DBL_MAX / (n (n - 1))), n = %zu)", what, lo, hi,
                        bound, n);
    return NL_OK;
}

/* The bins; the default cutoff is gstat's: 0.33333 (its DEF_fraction, not
 * 1/3) times the bounding-box diagonal diag, so that bins match to rounding. */
int nl_vg_bins(const nl_variogram_options *o, double diag, nl_vg_acc *acc)
{
    memset(acc, 0, sizeof *acc);
    acc->cutoff = o->cutoff > 0 ? o->cutoff : NL_VG_FRACTION * diag;
    acc->width = o->width > 0 ? o->width : acc->cutoff / 15;
    if (!(acc->cutoff > 0) || !(acc->width > 0))
        return NL_ERROR(NL_EINVAL, "variogram: expected points at more than one place (the bounding-box diagonal is %g)",
                        diag);
    acc->gstat = o->bins == NL_VARIOGRAM_BINS_GSTAT;
    /* gstat's count (src/sem.c alloc_exp_variogram): the bin of h = cutoff
     * exists even where rounding puts cutoff / width just above an integer */
    double nb = acc->gstat ? floor(acc->cutoff / acc->width) + 1 : ceil(acc->cutoff / acc->width);
    acc->reach = acc->gstat ? acc->cutoff * (1 + 1e-12) : acc->cutoff;
    if (!(nb <= NL_VG_MAXBINS))
        return NL_ERROR(NL_EINVAL, "variogram: cutoff / width = %g / %g gives %g bins; expected at most %d", acc->cutoff,
                        acc->width, nb, NL_VG_MAXBINS);
    acc->nb = (size_t)nb;
    acc->cressie = o->estimator == NL_VARIOGRAM_CRESSIE;
    acc->directional = o->directional && o->tolerance < 90;
    if (acc->directional) { /* gstat: the unit vector alpha degrees clockwise from +y */
        double a = o->direction * M_PI / 180;
        acc->ux = sin(a), acc->uy = cos(a), acc->costol = cos(o->tolerance * M_PI / 180);
    }
    return NL_OK;
}

int nl_vg_sums_alloc(size_t nb, double **s)
{
    *s = calloc(3 * nb, sizeof **s);
    return *s ? NL_OK : NL_ERROR(NL_ENOMEM, "variogram: out of memory for %zu bins", nb);
}

/* Is the pair's direction (dx, dy) within the tolerance?  A pair with no
 * horizontal extent counts, as in gstat. */
static int in_direction(const nl_vg_acc *a, double dx, double dy)
{
    double h = sqrt(dx * dx + dy * dy);
    return h == 0 || fabs(dx * a->ux + dy * a->uy) >= a->costol * h;
}

long nl_vg_bin(const nl_vg_acc *a, double d, const double *dx)
{
    if (a->directional && !in_direction(a, dx[0], dx[1]))
        return -1;
    double q = d / a->width, k = floor(q);
    if (a->gstat) { /* gstat's src/sem.c get_index and valid_distance */
        if (!(d <= a->cutoff))
            return -1;
        if (d > 0 && q == k)
            k -= 1;
    } else if (!(d < a->cutoff))
        return -1;
    return k < (double)a->nb ? (long)k : -1;
}

void nl_vg_add(const nl_vg_acc *a, double *sums, double d, const double *dx, double dz)
{
    long k = nl_vg_bin(a, d, dx);
    if (k < 0)
        return;
    double *s = sums + 3 * (size_t)k;
    s[0] += d, s[1] += a->cressie ? sqrt(fabs(dz)) : dz * dz, s[2] += 1;
}

int nl_vg_finish(const nl_vg_acc *a, const double *sums, nl_variogram **out)
{
    size_t m = 0;
    for (size_t k = 0; k < a->nb; k++)
        m += sums[3 * k + 2] > 0;
    if (!m)
        return NL_ERROR(NL_EINVAL, "variogram: no pair of points within the cutoff %g%s; expected at least one", a->cutoff,
                        a->directional ? " and the direction's tolerance" : "");
    nl_variogram *v = calloc(1, sizeof *v);
    if (!v || !(v->distance = malloc(m * sizeof(double))) || !(v->gamma = malloc(m * sizeof(double))) ||
        !(v->pairs = malloc(m * sizeof(double)))) {
        nl_variogram_free(v);
        return NL_ERROR(NL_ENOMEM, "variogram: out of memory");
    }
    for (size_t k = 0; k < a->nb; k++) {
        const double *s = sums + 3 * k;
        if (!(s[2] > 0))
            continue;
        size_t i = v->nbins++;
        v->distance[i] = s[0] / s[2], v->pairs[i] = s[2];
        if (a->cressie) { /* Cressie and Hawkins 1980, eq. (2.4) */
            double q = s[1] / s[2];
            v->gamma[i] = 0.5 * q * q * q * q / (0.457 + 0.494 / s[2]);
        } else
            v->gamma[i] = s[1] / (2 * s[2]);
    }
    *out = v;
    return NL_OK;
}

typedef struct {
    const nl_vg_acc *a;  /* binning */
    const nl_points *p;  /* the data */
    double *sums;        /* this block's sums */
} pair_ctx;

static int on_pair(void *ctx, size_t i, size_t j, double d2)
{
    pair_ctx *c = ctx;
    int dim = c->p->dim;
    double dx[3] = {0, 0, 0};
    for (int k = 0; k < dim && k < 2; k++)
        dx[k] = c->p->pts[i * dim + k] - c->p->pts[j * dim + k];
    nl_vg_add(c->a, c->sums, sqrt(d2), dx, c->p->val[i] - c->p->val[j]);
    return 0;
}

/* The diagonal for gstat's default cutoff: its bounding box, except that in
 * 3D gstat takes the z extent as the first point's z minus the smallest z
 * (gstat's src/s.c updates minZ twice and never maxZ while it reads the
 * points); followed so that default bins agree with gstat's.  Where that
 * gives 0 (gstat then uses a cutoff of 1), the true diagonal. */
static double gstat_diagonal(const nl_points *p, const double *lo, const double *hi, double diag)
{
    double s = 0;
    for (int k = 0; k < p->dim; k++) {
        double e = k == 2 ? p->pts[2] - lo[2] : hi[k] - lo[k];
        s += e * e;
    }
    return s > 0 ? sqrt(s) : diag;
}

static int check_points(const nl_points *p, double *diag, double *gdiag)
{
    double lo[3], hi[3], s = 0;
    *diag = 0;
    if (!p || p->n < 2)
        return NL_ERROR(NL_EINVAL, "variogram: expected at least 2 points, got %zu", p ? p->n : 0);
    int dim = p->dim;
    for (int k = 0; k < dim; k++)
        lo[k] = INFINITY, hi[k] = -INFINITY;
    for (size_t i = 0; i < p->n; i++) {
        if (!isfinite(p->val[i]))
            return NL_ERROR(NL_EINVAL, "variogram: the value of point %zu is %g; expected a finite number", i + 1, p->val[i]);
        for (int k = 0; k < dim; k++)
            lo[k] = fmin(lo[k], p->pts[i * dim + k]), hi[k] = fmax(hi[k], p->pts[i * dim + k]);
    }
    for (int k = 0; k < dim; k++)
        s += (hi[k] - lo[k]) * (hi[k] - lo[k]);
    *diag = sqrt(s);
    if (!isfinite(*diag))
        return NL_ERROR(NL_EINVAL, "variogram: the points span a distance that is not finite; expected finite coordinates");
    if (!(*diag > 0) || s < DBL_MIN) {
        int k = 0;
        for (int a = 1; a < dim; a++)
            if (hi[a] - lo[a] > hi[k] - lo[k])
                k = a;
        if (hi[k] == lo[k])
            return NL_ERROR(NL_EINVAL, "variogram: all %zu points are at one place; expected points at two places at "
                            "least", p->n);
        /* distinct, but their squared distances underflow */
        return NL_ERROR(NL_EINVAL, "variogram: the %zu points span only %g (coordinate %d, %g to %g), below what "
                        "double precision resolves in squared distances; expected a span of at least %.3g "
                        "(rescale the coordinates)", p->n, hi[k] - lo[k], k + 1, lo[k], hi[k], sqrt(DBL_MIN));
    }
    *gdiag = gstat_diagonal(p, lo, hi, *diag);
    return nl_vg_check_values(p->val, p->n, "the points' values");
}

static int count_pair(void *ctx, size_t i, size_t j, double d2)
{
    (void)i, (void)j, (void)d2;
    ++*(double *)ctx;
    return 0;
}

/* The work before it is done: the pairs within the cutoff, estimated from
 * the pairs of VG_SAMPLE positions spread over the index's order (each
 * position's share of the pair walk), refused above VG_MAX_PAIRS. */
#define VG_SAMPLE 128
static int check_work(const nl_spindex *s, const nl_points *p, const nl_vg_acc *a)
{
    double n = (double)p->n, found = 0, est;
    if (n * (n - 1) / 2 <= VG_MAX_PAIRS)
        return NL_OK;
    for (size_t t = 0; t < VG_SAMPLE; t++)
        nl_spindex_pairs_at(s, (size_t)((double)t * n / VG_SAMPLE), a->reach, count_pair, &found);
    est = found * n / VG_SAMPLE;
    if (est > VG_MAX_PAIRS)
        return NL_ERROR(NL_ETOOBIG, "variogram: %zu points have about %.3g pairs within the cutoff %g; expected at "
                        "most %.0e (about half a minute of work): set a smaller cutoff, thin the points, or grid them "
                        "(the variogram of a field costs samples x offsets)", p->n, est, a->cutoff, VG_MAX_PAIRS);
    return NL_OK;
}

/* Blocks of positions run in parallel; their sums are added in block order,
 * so the result does not depend on the number of threads. */
#define VG_BLOCK 256
static int accumulate(const nl_spindex *s, const nl_points *p, const nl_vg_acc *a, double *sums)
{
    size_t n = p->n, nblk = (n + VG_BLOCK - 1) / VG_BLOCK;
    int fail = 0;
#pragma omp parallel if (n > 4 * VG_BLOCK)
    {
        double *loc = calloc(3 * a->nb, sizeof *loc);
        if (!loc) {
#pragma omp atomic write
            fail = 1;
        }
#pragma omp for ordered schedule(dynamic, 1)
        for (size_t b = 0; b < nblk; b++) {
            pair_ctx c = {a, p, loc};
            if (loc) {
                memset(loc, 0, 3 * a->nb * sizeof *loc);
                for (size_t k = b * VG_BLOCK; k < n && k < (b + 1) * VG_BLOCK; k++)
                    nl_spindex_pairs_at(s, k, a->reach, on_pair, &c);
            }
#pragma omp ordered
            if (loc)
                for (size_t k = 0; k < 3 * a->nb; k++)
                    sums[k] += loc[k];
        }
        free(loc);
    }
    return fail ? NL_ERROR(NL_ENOMEM, "variogram: out of memory for %zu bins per thread", a->nb) : NL_OK;
}

/* The points with their values less the drift's least-squares fit (a
 * copy sharing the coordinates; its values in *res, to be freed). */
static int detrend(const nl_points *p, int drift, const double *cov, size_t nc, nl_points *q, double **res)
{
    *q = *p;
    *res = NULL;
    if (drift == NL_VARIOGRAM_DRIFT_CONSTANT && !nc)
        return NL_OK;
    if (!(*res = malloc(p->n * sizeof **res)))
        return NL_ERROR(NL_ENOMEM, "variogram: out of memory for %zu residuals", p->n);
    q->val = *res;
    return nl_vg_residuals(p->dim, p->n, p->pts, p->val, drift, cov, nc, *res);
}

int nl_variogram_points(const nl_points *p, const nl_variogram_options *o, nl_variogram **out)
{
    return nl_variogram_points_design(p, NULL, 0, o, out);
}

int nl_variogram_points_design(const nl_points *p, const double *design, size_t q, const nl_variogram_options *o,
                               nl_variogram **out)
{
    double diag = 0, gdiag = 0, *sums = NULL, *res = NULL;
    nl_vg_acc a;
    nl_spindex *s = NULL;
    nl_points pq;
    int st;
    *out = NULL;
    if ((st = check_points(p, &diag, &gdiag)) || (st = nl_vg_check_options(o)) || (st = nl_vg_bins(o, gdiag, &a)))
        return st;
    if (q && !design)
        return NL_ERROR(NL_EINVAL, "variogram: drift: %zu covariates and no design; expected n x %zu numbers", q, q);
    if ((st = detrend(p, o->drift, design, q, &pq, &res)) || (st = nl_spindex_alloc(p->dim, p->n, p->pts, &s))) {
        free(res);
        return st;
    }
    if (!(st = check_work(s, &pq, &a)) && !(st = nl_vg_sums_alloc(a.nb, &sums)) && !(st = accumulate(s, &pq, &a, sums)))
        st = nl_vg_finish(&a, sums, out);
    free(sums);
    free(res);
    nl_spindex_free(s);
    return st;
}
