/* Rank-1 lattices (Keller 2001): wave vectors against brute force, the
 * one-FFT synthesis against its coefficients, reality, periodicity, the
 * Delaunay triangulation, and the realised covariance against the target. */
#include "../core/model.h"
#include "../core/nl_error.h"
#include "../synth/rank1.h"
#include "../synth/rank1_model.h"

#include <complex.h>
#include <criterion/criterion.h>
#include <fftw3.h>
#include <gsl/gsl_cdf.h>
#include <math.h>
#include <stdlib.h>

/* Brute force: the least squared norm over the box |k_a| <= B per residue. */
static void brute(const nl_rank1_lattice *L, long B, double *best)
{
    long k[4] = {0, 0, 0, 0};
    for (size_t m = 0; m < L->N; m++)
        best[m] = INFINITY;
    long span = 2 * B + 1, total = 1;
    for (int a = 0; a < L->s; a++)
        total *= span;
    for (long t = 0; t < total; t++) {
        long r = t, mm = 0;
        double n2 = 0;
        for (int a = 0; a < L->s; a++) {
            k[a] = r % span - B;
            r /= span;
            mm += k[a] * L->g[a];
            n2 += (double)(k[a] * k[a]);
        }
        mm %= (long)L->N;
        if (mm < 0)
            mm += (long)L->N;
        if (n2 < best[mm])
            best[mm] = n2;
    }
}

static void check_vectors(nl_rank1_lattice *L, long B)
{
    double *best = malloc(L->N * sizeof *best);
    brute(L, B, best);
    for (size_t m = 0; m < L->N; m++) {
        long dot = 0;
        double n2 = 0;
        for (int a = 0; a < L->s; a++)
            dot += L->k[m * L->s + a] * L->g[a], n2 += (double)(L->k[m * L->s + a] * L->k[m * L->s + a]);
        cr_assert_eq(((dot % (long)L->N) + (long)L->N) % (long)L->N, (long)m, "N=%zu m=%zu: k.g", L->N, m);
        cr_assert_eq(n2, best[m], "N=%zu m=%zu: norm^2 %g, brute force %g", L->N, m, n2, best[m]);
        for (int a = 0; a < L->s && m && 2 * m != L->N; a++)
            cr_assert_eq(L->k[(L->N - m) * L->s + a], -L->k[m * L->s + a], "symmetry at m=%zu", m);
    }
    free(best);
}

Test(rank1, wave_vectors_are_minimal)
{
    nl_rank1_lattice L;
    cr_assert_eq(nl_rank1_fibonacci(10, &L), 0);
    cr_assert_eq(L.N, 55);
    cr_assert_eq(L.g[1], 34);
    check_vectors(&L, 30), nl_rank1_free(&L);
    cr_assert_eq(nl_rank1_fibonacci(13, &L), 0);
    check_vectors(&L, 60), nl_rank1_free(&L);
    cr_assert_eq(nl_rank1_korobov(101, 2, 0, &L), 0);
    check_vectors(&L, 60), nl_rank1_free(&L);
    cr_assert_eq(nl_rank1_korobov(64, 3, 0, &L), 0);
    check_vectors(&L, 12), nl_rank1_free(&L);
    cr_assert_eq(nl_rank1_korobov(81, 4, 0, &L), 0);
    check_vectors(&L, 6), nl_rank1_free(&L);
}

static double s_gauss(const long *k, int s, void *ctx)
{
    double l = *(double *)ctx, k2 = 0;
    for (int a = 0; a < s; a++)
        k2 += (double)(k[a] * k[a]);
    /* the 2D spectrum of exp(-(r/l)^2) at wave vector k on the unit torus */
    return M_PI * l * l * exp(-M_PI * M_PI * l * l * k2);
}

Test(rank1, synthesis_inverts_and_is_real_and_periodic)
{
    nl_rank1_lattice L;
    double l = 0.12, *c, *f, *g, imag, cmax = 0;
    cr_assert_eq(nl_rank1_fibonacci(15, &L), 0);
    size_t N = L.N;
    c = malloc(2 * N * sizeof *c), f = malloc(N * sizeof *f), g = malloc(2 * N * sizeof *g);
    cr_assert_eq(nl_rank1_coefficients(&L, s_gauss, &l, 3, c), 0);
    cr_assert_eq(nl_rank1_synthesize(&L, c, 1.0, f, g, &imag), 0);
    for (size_t m = 0; m < 2 * N; m++)
        cmax = fmax(cmax, fabs(c[m]));
    cr_expect_lt(imag, 1e-12 * cmax * (double)N, "max |imag| %g", imag);
    /* forward FFT / N returns the coefficients */
    fftw_complex *b = fftw_alloc_complex(N);
    fftw_plan p = fftw_plan_dft_1d((int)N, b, b, FFTW_FORWARD, FFTW_ESTIMATE);
    for (size_t n = 0; n < N; n++)
        b[n] = f[n];
    fftw_execute(p);
    for (size_t m = 0; m < N; m++) {
        cr_expect_leq(fabs(creal(b[m]) / (double)N - c[2 * m]), 1e-12 * cmax, "re c_%zu", m);
        cr_expect_leq(fabs(cimag(b[m]) / (double)N - c[2 * m + 1]), 1e-12 * cmax, "im c_%zu", m);
    }
    /* the Fourier series at any point: equal to the samples at lattice
     * points, and periodic (field and gradient) across the patch border */
    for (int t = 0; t < 5; t++) {
        double x[2] = {0.137 * t + 0.01, 0.731 - 0.11 * t}, v[2][3] = {{0}};
        for (int w = 0; w < 2; w++) {
            double px = x[0] + w, py = x[1] - w;  /* shifted by (1, -1) */
            for (size_t m = 0; m < N; m++) {
                double ph = 2 * M_PI * ((double)L.k[2 * m] * px + (double)L.k[2 * m + 1] * py);
                double re = c[2 * m] * cos(ph) - c[2 * m + 1] * sin(ph), im = c[2 * m] * sin(ph) + c[2 * m + 1] * cos(ph);
                v[w][0] += re;
                v[w][1] += -2 * M_PI * (double)L.k[2 * m] * im, v[w][2] += -2 * M_PI * (double)L.k[2 * m + 1] * im;
            }
        }
        for (int q = 0; q < 3; q++)
            cr_expect_float_eq(v[0][q], v[1][q], 1e-9 * (1 + fabs(v[0][q])), "component %d at point %d", q, t);
    }
    for (size_t n = 0; n < N; n += 97) {
        double x[2], v = 0;
        nl_rank1_point(&L, n, x);
        for (size_t m = 0; m < N; m++) {
            double ph = 2 * M_PI * ((double)L.k[2 * m] * x[0] + (double)L.k[2 * m + 1] * x[1]);
            v += c[2 * m] * cos(ph) - c[2 * m + 1] * sin(ph);
        }
        cr_expect_float_eq(v, f[n], 1e-9, "lattice point %zu", n);
    }
    fftw_destroy_plan(p), fftw_free(b), free(c), free(f), free(g), nl_rank1_free(&L);
}

/* The periodic Delaunay triangulation: 2N triangles of area 1/(2N) each,
 * tiling the unit square; the basis is reduced (acute, |v1| <= |v2|). */
Test(rank1, delaunay)
{
    nl_rank1_lattice L;
    size_t n1, n2;
    double v1[2], v2[2];
    cr_assert_eq(nl_rank1_fibonacci(10, &L), 0);
    cr_assert_eq(nl_rank1_delaunay(&L, &n1, &n2, v1, v2), 0);
    cr_expect_float_eq(fabs(v1[0] * v2[1] - v1[1] * v2[0]), 1.0 / 55, 1e-12);
    cr_expect_geq(v1[0] * v2[0] + v1[1] * v2[1], 0);
    cr_expect_leq(hypot(v1[0], v1[1]), hypot(v2[0], v2[1]) + 1e-15);
    cr_expect_float_eq(hypot(v1[0], v1[1]), L.min_dist, 1e-12);
    nl_rank1_free(&L);
}

/* Covariance over lattice point pairs binned by torus distance (bins of
 * 0.02 up to 0.3), ensembles of M = 64 fields (seeds 1..64), N = F_15 =
 * 610, against R(d) = exp(-(d/0.1)^2) averaged over each bin's pairs.
 * The wave vectors fill a disc of radius ~ sqrt(610/pi) = 14, where the
 * spectrum is exp(-(pi 14 0.1)^2) = 4e-9 of its peak, and R(0.5) = 1e-11:
 * band limit and period change R by less than 1e-8.  The bin means of one
 * realization are averaged over the ensemble; z = (mean - target) / (sd /
 * sqrt(M)) is t(63); 15 bins at a family-wise 1e-3 (Bonferroni). */
Test(rank1, realised_covariance_matches_target)
{
    nl_rank1_lattice L;
    double l = 0.1, *c, *f;
    enum { B = 15, M = 64 };
    double s1[B] = {0}, s2[B] = {0}, tgt[B] = {0}, zmax = 0, zcrit = gsl_cdf_tdist_Qinv(1e-3 / (2 * B), M - 1);
    long cnt[B] = {0};
    cr_assert_eq(nl_rank1_fibonacci(15, &L), 0);
    size_t N = L.N;
    c = malloc(2 * N * sizeof *c), f = malloc(N * sizeof *f);
    /* pair bins and bin-averaged targets */
    int *bin = malloc(N * N * sizeof *bin);
    for (size_t a = 0; a < N; a++)
        for (size_t b = 0; b < N; b++) {
            double xa[2], xb[2], d2 = 0;
            nl_rank1_point(&L, a, xa), nl_rank1_point(&L, b, xb);
            for (int q = 0; q < 2; q++) {
                double d = fabs(xa[q] - xb[q]);
                d = fmin(d, 1 - d);
                d2 += d * d;
            }
            int k = (int)(sqrt(d2) / 0.02);
            bin[a * N + b] = k < B ? k : -1;
            if (k < B)
                tgt[k] += exp(-d2 / (l * l)), cnt[k]++;
        }
    for (int k = 0; k < B; k++)
        tgt[k] /= (double)cnt[k];
    for (uint64_t s = 1; s <= M; s++) {
        double acc[B] = {0}, imag;
        cr_assert_eq(nl_rank1_coefficients(&L, s_gauss, &l, s, c), 0);
        cr_assert_eq(nl_rank1_synthesize(&L, c, 1.0, f, NULL, &imag), 0);
        for (size_t a = 0; a < N; a++)
            for (size_t b = 0; b < N; b++)
                if (bin[a * N + b] >= 0)
                    acc[bin[a * N + b]] += f[a] * f[b];
        for (int k = 0; k < B; k++) {
            double v = acc[k] / (double)cnt[k];
            s1[k] += v, s2[k] += v * v;
        }
    }
    for (int k = 0; k < B; k++) {
        double mean = s1[k] / M, sd = sqrt((s2[k] - M * mean * mean) / (M - 1));
        zmax = fmax(zmax, fabs(mean - tgt[k]) / (sd / sqrt(M)));
    }
    cr_log_info("rank-1 covariance: max |z| = %.2f over %d distance bins (threshold %.2f)", zmax, B, zcrit);
    cr_expect_leq(zmax, zcrit);
    free(bin), free(c), free(f), nl_rank1_free(&L);
}

/* nl_rank1_fibonacci_index inverts F_k exactly for every index the 64-bit
 * recurrence reaches below the loop bound, and refuses the neighbours. */
Test(rank1, fibonacci_index)
{
    unsigned long long a = 1, b = 2;  /* F_2, F_3 */
    for (int k = 3; k < 60; k++) {
        cr_assert_eq(nl_rank1_fibonacci_index((size_t)b), k, "F_%d = %llu", k, b);
        if (k >= 5)
            cr_assert_eq(nl_rank1_fibonacci_index((size_t)b + 1), 0, "F_%d + 1", k);
        unsigned long long c = a + b;
        a = b, b = c;
    }
    cr_assert_eq(nl_rank1_fibonacci_index(0), 0);
    cr_assert_eq(nl_rank1_fibonacci_index(1), 0, "1 = F_1 = F_2 is below the smallest lattice");
    cr_assert_eq(nl_rank1_fibonacci_index(4), 0);
}

/* The mesh's 2N triangles tile the torus: each has area extent^2 / (2N)
 * with one orientation (so together they cover the side-extent square
 * once), and every vertex, wrapped, is a lattice point carrying its
 * height.  Tolerances: a few ulps of the coordinates, which are products
 * of two roundings. */
Test(rank1, mesh_tiles_the_torus)
{
    nl_rank1_lattice L;
    nl_rank1_mesh me;
    const double E = 2.385;
    cr_assert_eq(nl_rank1_fibonacci(11, &L), NL_OK);  /* N = 89 */
    size_t N = L.N;
    double *f = malloc(N * sizeof *f);
    for (size_t n = 0; n < N; n++)
        f[n] = 0.5 + (double)n;
    cr_assert_eq(nl_rank1_mesh_init(&L, E, f, &me), NL_OK);
    for (size_t t = 0; t < 2 * N; t++) {
        double v[9];
        nl_rank1_mesh_triangle(&me, t, v);
        double area = 0.5 * ((v[3] - v[0]) * (v[7] - v[1]) - (v[6] - v[0]) * (v[4] - v[1]));
        cr_assert_float_eq(area, E * E / (double)(2 * N), 1e-12, "triangle %zu: area %g", t, area);
        for (int k = 0; k < 3; k++) {
            size_t id = (size_t)(v[3 * k + 2] - 0.5 + 0.25);
            double x[2];
            cr_assert(id < N);
            nl_rank1_point(&L, id, x);
            for (int a = 0; a < 2; a++) {
                double w = fmod(v[3 * k + a], E);
                if (w < 0)
                    w += E;
                double d = fabs(w - x[a] * E);
                cr_assert(d < 1e-12 || fabs(d - E) < 1e-12, "triangle %zu vertex %d axis %d: %g vs %g", t, k, a, w,
                          x[a] * E);
            }
        }
    }
    free(f);
    nl_rank1_free(&L);
}

/* |k_m| from the stored wave vectors. */
Test(rank1, wave_norm)
{
    nl_rank1_lattice L;
    long g[3] = {1, 7, 49};
    cr_assert_eq(nl_rank1_generator(101, 3, g, &L), NL_OK);
    for (size_t m = 0; m < L.N; m++) {
        const long *k = L.k + 3 * m;
        cr_assert_eq(nl_rank1_wave_norm(&L, m), sqrt((double)(k[0] * k[0] + k[1] * k[1] + k[2] * k[2])));
    }
    nl_rank1_free(&L);
}

/* f from the per-wave-vector spectrum (one quadrature per wave vector, the
 * reference the faster paths must reproduce). */
static void field_per_wave_vector(const nl_rank1_lattice *L, const nl_model *m, double *f)
{
    nl_rank1_model_ctx ctx = {m, L->s, 1};
    double *c = malloc(2 * L->N * sizeof *c);
    cr_assert_not_null(c);
    cr_assert_eq(nl_rank1_coefficients(L, nl_rank1_model_spectrum, &ctx, 5, c), NL_OK, "%s", nl_errmsg());
    cr_assert_eq(nl_rank1_synthesize(L, c, 1, f, NULL, NULL), NL_OK);
    free(c);
}

/* Few distinct radii (N = 610): one quadrature per radius gives the very
 * same field, bit for bit, as one per wave vector. */
Test(rank1, spectrum_once_per_radius_is_bit_identical)
{
    nl_rank1_lattice L;
    nl_model *m;
    nl_rank1_model_info info;
    cr_assert_eq(nl_model_parse("markov:scale=0.1", &m), NL_OK);
    cr_assert_eq(nl_rank1_fibonacci(15, &L), NL_OK);
    double *a = malloc(L.N * sizeof *a), *b = malloc(L.N * sizeof *b);
    field_per_wave_vector(&L, m, a);
    cr_assert_eq(nl_rank1_model_synthesize_info(&L, m, 1, 5, 0, b, NULL, NULL, &info), NL_OK, "%s", nl_errmsg());
    cr_assert_eq(info.nodes, 0, "exact per radius at N = 610");
    cr_assert(memcmp(a, b, L.N * sizeof *a) == 0, "the fields differ");
    free(a), free(b), nl_rank1_free(&L), nl_model_free(m);
}

/* Many radii (N = 10946): the radial table.  Its measured interpolation
 * error is at most 1e-6 of S(0) per value, so a coefficient moves by at
 * most sqrt(1e-6 S(0)) |xi| (sqrt is 1/2-Hoelder); over the 5473 wave
 * vectors with S(0) = pi 0.05^2 that bounds the rms change of the field by
 * 6.5e-3 of its unit sd: checked at 1e-2. */
Test(rank1, radial_table_matches_the_quadrature)
{
    nl_rank1_lattice L;
    nl_model *m;
    nl_rank1_model_info info;
    cr_assert_eq(nl_model_parse("gauss:scale=0.05", &m), NL_OK);
    cr_assert_eq(nl_rank1_fibonacci(21, &L), NL_OK);
    double *a = malloc(L.N * sizeof *a), *b = malloc(L.N * sizeof *b), d = 0, v = 0;
    field_per_wave_vector(&L, m, a);
    cr_assert_eq(nl_rank1_model_synthesize_info(&L, m, 1, 5, 0, b, NULL, NULL, &info), NL_OK, "%s", nl_errmsg());
    cr_assert(info.nodes > 0 && info.interp_error <= 1e-6, "nodes %zu, error %g", info.nodes, info.interp_error);
    for (size_t n = 0; n < L.N; n++)
        d += (a[n] - b[n]) * (a[n] - b[n]), v += a[n] * a[n];
    cr_assert(sqrt(d / v) < 1e-2, "rms change %g of the field's rms", sqrt(d / v));
    free(a), free(b), nl_rank1_free(&L), nl_model_free(m);
}
