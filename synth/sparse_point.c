/* Solid sparse-convolution noise evaluated at any point (see sparse_point.h). */
#include "sparse_point.h"
#include "../core/field.h"
#include "../core/nl_error.h"
#include "../core/rng.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

struct nl_synth_sparse_point {
    uint64_t seed;          /* the impulses' seed */
    double r, w, inv2s2, c; /* cut radius, cube side r / 2, 1 / (2 s^2), normalisation */
    double mean;            /* Poisson mean per cube, lambda w^3 */
    long lo[3], n[3];       /* cached cube range: first cube, count per axis */
    size_t *start;          /* n0 n1 n2 + 1 offsets into q (cube order: i slowest) */
    double *q;              /* 4 per impulse: x y z amplitude */
    nl_synth_sparse_point_stats info;
};

void nl_synth_sparse_point_free(nl_synth_sparse_point *p)
{
    if (!p)
        return;
    free(p->start), free(p->q), free(p);
}

void nl_synth_sparse_point_info(const nl_synth_sparse_point *p, nl_synth_sparse_point_stats *info) { *info = p->info; }

static uint64_t cube_id(const long *i)
{
    uint64_t id = 0;
    for (int a = 0; a < 3; a++)
        id = id << 21 | (uint64_t)(i[a] + NL_SPARSE_POINT_CELLS_MAX);
    return id;
}

/* Impulse k of cube i into q (x y z amplitude). */
static void impulse(const nl_synth_sparse_point *p, const long *i, uint64_t id, uint32_t k, double *q)
{
    for (int a = 0; a < 3; a++)
        q[a] = ((double)i[a] + nl_rng_uniform2(p->seed, NL_SPARSE_POINT_STREAM + 1 + (uint32_t)a, id, k)) * p->w;
    q[3] = nl_rng_gauss2(p->seed, NL_SPARSE_POINT_STREAM + 4, id, k);
}

static unsigned long cube_count(const nl_synth_sparse_point *p, uint64_t id)
{
    return nl_rng_poisson(p->seed, NL_SPARSE_POINT_STREAM, id, 0, p->mean);
}

/* Draw the cached cubes' impulses. */
static int fill_cache(nl_synth_sparse_point *p)
{
    size_t cubes = (size_t)p->n[0] * (size_t)p->n[1] * (size_t)p->n[2], total = 0, c = 0;
    double want = p->mean * (double)cubes * 1.2 + 64;
    if (want > 1e8)
        return NL_ERROR(NL_ETOOBIG, "sparse point noise: about %.3g impulses to cache (limit 1e8): expected a smaller "
                        "box or density", want);
    size_t nw = (size_t)want, ns = cubes + 1;
    int st;
    if ((st = nl_size_check(1, &nw, 4 * sizeof(double), 1, NULL)) || (st = nl_size_check(1, &ns, sizeof(size_t), 1, NULL)))
        return st;
    p->start = malloc(ns * sizeof *p->start);
    p->q = malloc(nw * 4 * sizeof *p->q);
    if (!p->start || !p->q)
        return NL_ERROR(NL_ENOMEM, "out of memory for %zu cubes of impulses", cubes);
    long i[3];
    for (i[0] = p->lo[0]; i[0] < p->lo[0] + p->n[0]; i[0]++)
        for (i[1] = p->lo[1]; i[1] < p->lo[1] + p->n[1]; i[1]++)
            for (i[2] = p->lo[2]; i[2] < p->lo[2] + p->n[2]; i[2]++, c++) {
                uint64_t id = cube_id(i);
                unsigned long K = cube_count(p, id);
                p->start[c] = total;
                for (unsigned long k = 0; k < K; k++, total++) {
                    if (total == nw) {
                        double *g = (nw *= 2, realloc(p->q, nw * 4 * sizeof *p->q));
                        if (!g)
                            return NL_ERROR(NL_ENOMEM, "out of memory for impulses");
                        p->q = g;
                    }
                    impulse(p, i, id, (uint32_t)k, p->q + 4 * total);
                }
            }
    p->start[cubes] = total;
    p->info.cached = total;
    return NL_OK;
}

/* The model's scale and variance, checked. */
static int model_numbers(const nl_model *m, double *L, double *V)
{
    if (!m || nl_model_family(m) != &nl_family_gauss || !nl_model_is_isotropic(m) || nl_model_nugget(m) != 0 ||
        nl_model_param(m, "scale", L) || nl_model_param(m, "var", V))
        return NL_ERROR(NL_EINVAL, "sparse point noise: expected an isotropic gauss: model without a nugget (its "
                        "kernel is a Gaussian in closed form), got \"%s\"", m ? nl_model_spec(m) : "(none)");
    if (!(*L > 0) || !isfinite(*L) || !(*V > 0) || !isfinite(*V))
        return NL_ERROR(NL_EINVAL, "sparse point noise: expected a positive finite scale and variance, got %g and %g",
                        *L, *V);
    return NL_OK;
}

int nl_synth_sparse_point_alloc(const nl_model *m, double density, uint64_t seed, const double *lo, const double *hi,
                                nl_synth_sparse_point **out)
{
    double L, V;
    int st;
    *out = NULL;
    if ((st = model_numbers(m, &L, &V)))
        return st;
    if (!(density >= 0.01 && density <= 1e4))
        return NL_ERROR(NL_EINVAL, "sparse point noise: density: expected 0.01 to 1e4 impulses per scale^3, got %g",
                        density);
    nl_synth_sparse_point *p = calloc(1, sizeof *p);
    if (!p)
        return NL_ERROR(NL_ENOMEM, "out of memory");
    double s = L / 2, lambda = density / (L * L * L);
    p->seed = seed, p->r = 3.5 * s, p->w = p->r / 2, p->inv2s2 = 1 / (2 * s * s), p->mean = lambda * pow(p->w, 3);
    /* the energy of h^2 (a normal of sd s/sqrt(2)) within r: 1 - tail */
    double R = p->r / (s / M_SQRT2), tail = erfc(R / M_SQRT2) + sqrt(2 / M_PI) * R * exp(-R * R / 2);
    p->c = sqrt(V / (lambda * pow(M_PI * s * s, 1.5) * (1 - tail)));
    p->info = (nl_synth_sparse_point_stats){L, V, p->r, lambda, 6 * M_SQRT2 / (density * pow(M_PI, 1.5)), 0};
    if (lo && hi) {
        for (int a = 0; a < 3; a++) {
            double u0 = floor((lo[a] - p->r) / p->w), u1 = floor((hi[a] + p->r) / p->w);
            if (!(lo[a] <= hi[a]) || !(fabs(u0) < NL_SPARSE_POINT_CELLS_MAX - 2) || !(fabs(u1) < NL_SPARSE_POINT_CELLS_MAX - 2)) {
                double r = p->r;
                nl_synth_sparse_point_free(p);
                return NL_ERROR(NL_EINVAL, "sparse point noise: box: expected finite lo <= hi within %ld cubes of %g "
                                "of the origin, got %g to %g on axis %d", NL_SPARSE_POINT_CELLS_MAX - 2, r, lo[a],
                                hi[a], a + 1);
            }
            p->lo[a] = (long)u0, p->n[a] = (long)(u1 - u0) + 1;
        }
        if ((st = fill_cache(p))) {
            nl_synth_sparse_point_free(p);
            return st;
        }
    }
    *out = p;
    return NL_OK;
}

/* The sum over one cube's impulses at x: from the cache, or drawn now. */
static double cube_sum(const nl_synth_sparse_point *p, const long *i, const double *x)
{
    double s = 0, r2 = p->r * p->r, qb[4];
    int cached = p->start != NULL;
    for (int a = 0; a < 3; a++)
        cached = cached && i[a] >= p->lo[a] && i[a] < p->lo[a] + p->n[a];
    size_t k0 = 0, k1;
    uint64_t id = cube_id(i);
    if (cached) {
        size_t c = ((size_t)(i[0] - p->lo[0]) * (size_t)p->n[1] + (size_t)(i[1] - p->lo[1])) * (size_t)p->n[2] +
                   (size_t)(i[2] - p->lo[2]);
        k0 = p->start[c], k1 = p->start[c + 1];
    } else
        k1 = cube_count(p, id);
    for (size_t k = k0; k < k1; k++) {
        const double *q = cached ? p->q + 4 * k : (impulse(p, i, id, (uint32_t)k, qb), qb);
        double dx = x[0] - q[0], dy = x[1] - q[1], dz = x[2] - q[2], d2 = dx * dx + dy * dy + dz * dz;
        if (d2 < r2)
            s += q[3] * exp(-d2 * p->inv2s2);
    }
    return s;
}

/* The squared distance from x to the cube [i w, (i + 1) w) on one axis. */
static double gap2(double x, long i, double w)
{
    double a = (double)i * w, b = a + w, g = x < a ? a - x : x > b ? x - b : 0;
    return g * g;
}

int nl_synth_sparse_point_eval(const nl_synth_sparse_point *p, size_t count, const double *x, double *out)
{
    double r2 = p->r * p->r;
    for (size_t n = 0; n < count; n++) {
        const double *xp = x + 3 * n;
        long i0[3], i1[3], i[3];
        for (int a = 0; a < 3; a++) {
            double u0 = floor((xp[a] - p->r) / p->w), u1 = floor((xp[a] + p->r) / p->w);
            if (!(fabs(u0) < NL_SPARSE_POINT_CELLS_MAX - 2) || !(fabs(u1) < NL_SPARSE_POINT_CELLS_MAX - 2))
                return NL_ERROR(NL_EINVAL, "sparse point noise: point %zu: expected finite coordinates within %ld "
                                "cubes of %g of the origin, got %g on axis %d", n, NL_SPARSE_POINT_CELLS_MAX - 2, p->w,
                                xp[a], a + 1);
            i0[a] = (long)u0, i1[a] = (long)u1;
        }
        double s = 0;
        /* only the cubes that come within r of x can hold a contributing impulse */
        for (i[0] = i0[0]; i[0] <= i1[0]; i[0]++) {
            double g0 = gap2(xp[0], i[0], p->w);
            for (i[1] = i0[1]; i[1] <= i1[1]; i[1]++) {
                double g1 = g0 + gap2(xp[1], i[1], p->w);
                if (g1 >= r2)
                    continue;
                for (i[2] = i0[2]; i[2] <= i1[2]; i[2]++)
                    if (g1 + gap2(xp[2], i[2], p->w) < r2)
                        s += cube_sum(p, i, xp);
            }
        }
        out[n] = p->c * s;
    }
    return NL_OK;
}
