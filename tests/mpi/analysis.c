/* The distributed estimators (mpi/analysis.h) against the one-process ones
 * on the same field, under mpirun -np 1..4 (tests/mpi/run.sh).
 *
 * Every process makes the whole field with the serial library (it is a
 * test: small fields), hands its nl_mpi_block slab to the distributed
 * functions, and compares their results with the serial estimators'.
 * Bound: |distributed - serial| <= TOL max |serial| over each estimate
 * (the transforms and sums run in another order, so rounding differs;
 * measured worst 6.3e-14 over np 1..4, in the unbiased radial ACF, whose
 * far lags divide sums of rounding size by few pairs); counts and histogram edges
 * and counts exactly; NaN where the serial one has NaN. */
#include "../../mpi/analysis.h"
#include "../../mpi/dist.h"
#include "../../analysis/acf.h"
#include "../../analysis/psd.h"
#include "../../analysis/slope.h"
#include "../../analysis/spectral.h"
#include "../../core/nl_error.h"
#include "../../synth/fft.h"

#include <fftw3-mpi.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define TOL 1e-12

static int rank, fails;
static double worst;  /* the largest relative difference seen */
static char worst_what[128];

static void fail(const char *what, const char *detail)
{
    fails++;
    if (rank == 0)
        fprintf(stderr, "FAIL %s: %s\n", what, detail);
}

/* a and b (n values) agree to TOL of max |b|, NaN where b is NaN. */
static void same(const char *what, const double *a, const double *b, size_t n)
{
    double scale = 0, d = 0;
    char msg[160];
    for (size_t i = 0; i < n; i++)
        scale = fmax(scale, isnan(b[i]) ? 0 : fabs(b[i]));
    for (size_t i = 0; i < n; i++) {
        if (isnan(a[i]) != isnan(b[i])) {
            snprintf(msg, sizeof msg, "entry %zu is %g, expected %g", i, a[i], b[i]);
            return fail(what, msg);
        }
        if (!isnan(b[i]))
            d = fmax(d, fabs(a[i] - b[i]));
    }
    if (scale > 0 && d / scale > worst)
        worst = d / scale, snprintf(worst_what, sizeof worst_what, "%s", what);
    if (!(d <= TOL * scale)) {
        snprintf(msg, sizeof msg, "differs by %.3g, bound %.3g (%.3g of max |value| %.3g)", d, TOL * scale,
                 d / scale, scale);
        fail(what, msg);
    }
}

static void same_counts(const char *what, const size_t *a, const size_t *b, size_t n)
{
    for (size_t i = 0; i < n; i++)
        if (a[i] != b[i]) {
            char msg[96];
            snprintf(msg, sizeof msg, "count %zu is %zu, expected %zu", i, a[i], b[i]);
            return fail(what, msg);
        }
}

static nl_field *make_field(int dim, const size_t *n, const double *h, double offset, uint64_t seed)
{
    nl_model *m;
    nl_synth_fft_plan *p;
    int st;
    nl_field *f = nl_field_alloc(dim, n, h, &st);
    if (!f || nl_model_parse("markov:scale=2", &m) ||
        nl_synth_fft_plan_alloc(m, dim, n, h, NL_SYNTH_FFT_CLAMP, &p) || nl_synth_fft_execute(p, seed, f)) {
        fprintf(stderr, "test field: %s\n", nl_errmsg());
        exit(1);
    }
    nl_synth_fft_plan_free(p), nl_model_free(m);
    /* plus a little white noise (an LCG), so that no periodogram ordinate
     * sits at rounding level, where its log (the slope's fit) is noise */
    uint64_t r = seed;
    for (size_t i = 0; i < f->count; i++) {
        r = r * 6364136223846793005u + 1442695040888963407u;
        f->data[i] += offset + 0.1 * ((double)(r >> 11) * 0x1p-53 - 0.5);
    }
    return f;
}

static nl_mpi_slab slab_of(const nl_field *f)
{
    int P;
    nl_mpi_slab s = {.comm = MPI_COMM_WORLD, .dim = f->dim};
    size_t row = f->count / f->n[f->dim - 1];
    MPI_Comm_size(MPI_COMM_WORLD, &P);
    for (int a = 0; a < 3; a++)
        s.n[a] = f->n[a], s.h[a] = f->h[a];
    nl_mpi_block(f->n[f->dim - 1], P, rank, &s.s0, &s.ns);
    s.data = s.ns ? f->data + s.s0 * row : NULL;
    return s;
}

static void check_acf(const char *name, const nl_field *f, double mean, int unbiased)
{
    nl_mpi_slab s = slab_of(f);
    nl_field *full;
    size_t nb = f->n[0] + f->n[1] + f->n[2], *c1 = malloc(nb * sizeof *c1), *c2 = malloc(nb * sizeof *c2);
    double *l1 = malloc(4 * nb * sizeof *l1), *v1 = l1 + nb, *l2 = v1 + nb, *v2 = l2 + nb;
    char what[128];
    if (nl_acf_full(f, mean, unbiased, &full))
        exit(1);
    for (int a = 0; a < f->dim; a++) {
        size_t maxlag = f->n[a] - 1;
        snprintf(what, sizeof what, "%s acf axis %d %s mean %g", name, a, unbiased ? "unbiased" : "biased", mean);
        if (nl_mpi_acf_axis(&s, mean, unbiased, a, maxlag, l1, v1) || nl_acf_axis(full, a, maxlag, l2, v2)) {
            fail(what, nl_errmsg());
            continue;
        }
        same(what, l1, l2, maxlag + 1), same(what, v1, v2, maxlag + 1);
    }
    snprintf(what, sizeof what, "%s acf radial %s", name, unbiased ? "unbiased" : "biased");
    if (nl_mpi_acf_radial(&s, mean, unbiased, nb, l1, v1, c1) || nl_acf_radial(full, nb, l2, v2, c2))
        fail(what, nl_errmsg());
    else
        same(what, l1, l2, nb), same(what, v1, v2, nb), same_counts(what, c1, c2, nb);
    nl_field_free(full), free(l1), free(c1), free(c2);
}

static void check_psd(const char *name, const nl_field *f, double mean)
{
    nl_mpi_slab s = slab_of(f);
    nl_field *P;
    size_t nb = f->n[0] + f->n[1] + f->n[2], *c1 = malloc(nb * sizeof *c1), *c2 = malloc(nb * sizeof *c2), nf1, nf2;
    double *f1 = malloc(4 * nb * sizeof *f1), *v1 = f1 + nb, *f2 = v1 + nb, *v2 = f2 + nb, s1[18], s2[18], a1 = 0,
           a2 = 0;
    int two = f->dim == 2;
    char what[96];
    snprintf(what, sizeof what, "%s psd mean %g", name, mean);
    if (nl_psd_periodogram(f, mean, &P) || nl_psd_profile(P, f2, v2, c2, &nf2) ||
        (two && nl_psd_sectors(P, 18, 0.05, 0.45, s2, &a2)))
        exit(1);
    nl_mpi_psd_more more = {.nsec = 18, .flo = 0.05, .fhi = 0.45, .sector = two ? s1 : NULL, .slope = 1,
                            .fmin = 0.02, .fmax = 0.4 / f->h[0]};
    nl_slope sl;
    if (f->dim == 1 ? nl_psd_slope(f2, v2, nf2, more.fmin, more.fmax, 1, &sl)
                    : nl_psd_slope_grid(P, more.fmin, more.fmax, &sl))
        exit(1);
    if (nl_mpi_psd(&s, mean, f1, v1, c1, &nf1, &more))
        fail(what, nl_errmsg());
    else if (nf1 != nf2 || nf1 != nl_mpi_psd_profile_size(f->dim, f->n, f->h))
        fail(what, "a profile of another length");
    else {
        same(what, f1, f2, nf1), same(what, v1, v2, nf1);
        if (f->dim > 1)
            same_counts(what, c1, c2, nf1);
        if (two)
            a1 = more.aniso, same(what, s1, s2, 18), same(what, &a1, &a2, 1);
        double x1[3] = {more.sl.slope, more.sl.ci95, more.sl.fractal_dim}, x2[3] = {sl.slope, sl.ci95, sl.fractal_dim};
        for (int k = 0; k < 3; k++) /* each on its own scale */
            same(what, x1 + k, x2 + k, 1);
        if (more.sl.points != sl.points)
            fail(what, "the slope's fit took another number of ordinates");
    }
    nl_field_free(P), free(f1), free(c1), free(c2);
}

static void check_hist(const char *name, const nl_field *f, size_t bins)
{
    nl_mpi_slab s = slab_of(f);
    nl_moments m1, m2;
    double *e1 = malloc(4 * (bins + 1) * sizeof *e1), *c1 = e1 + bins + 1, *e2 = c1 + bins + 1, *c2 = e2 + bins + 1;
    char what[96];
    snprintf(what, sizeof what, "%s moments", name);
    if (nl_moments_compute(f, &m2) || nl_hist(f, bins, e2, c2))
        exit(1);
    if (nl_mpi_moments(&s, &m1))
        fail(what, nl_errmsg());
    else {
        double a[4] = {m1.mean, m1.variance, m1.min, m1.max}, b[4] = {m2.mean, m2.variance, m2.min, m2.max};
        double a2[2] = {m1.skewness, m1.kurtosis}, b2[2] = {m2.skewness, m2.kurtosis};
        same(what, a, b, 2), same(what, a + 2, b + 2, 2);
        same(what, a2, b2, 2); /* standardised: of order 1 */
        if (m1.n != m2.n)
            fail(what, "another sample count");
    }
    snprintf(what, sizeof what, "%s histogram of %zu bins", name, bins);
    if (nl_mpi_hist(&s, bins, e1, c1))
        fail(what, nl_errmsg());
    else if (memcmp(e1, e2, (bins + 1) * sizeof *e1) || memcmp(c1, c2, bins * sizeof *c1))
        fail(what, "edges or counts differ");
    free(e1);
}

/* Bad arguments fail on every process with the same status, without a hang. */
static void check_errors(const nl_field *f)
{
    nl_mpi_slab s = slab_of(f);
    double l[16], v[16];
    int st = nl_mpi_acf_axis(&s, NAN, 0, 5, 2, l, v), all;
    MPI_Allreduce(&st, &all, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
    if (st != NL_EINVAL || all != NL_EINVAL)
        fail("bad axis", "expected NL_EINVAL on every process");
    if (rank == 1)
        s.s0 += 1; /* slabs that do not tile: refused everywhere */
    st = nl_mpi_hist(&s, 10, l, v);
    MPI_Allreduce(&st, &all, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
    int P;
    MPI_Comm_size(MPI_COMM_WORLD, &P);
    if (P > 1 && s.ns && (st != NL_EINVAL || all != NL_EINVAL))
        fail("slabs that do not tile", "expected NL_EINVAL on every process");
}

static void check_field(const char *name, int dim, const size_t *n, const double *h, double offset)
{
    nl_field *f = make_field(dim, n, h, offset, 7);
    check_acf(name, f, NAN, 0);
    check_acf(name, f, NAN, 1);
    check_acf(name, f, 0.25, 0);
    check_psd(name, f, NAN);
    check_psd(name, f, 0.25);
    check_hist(name, f, 1);
    check_hist(name, f, 37);
    nl_field_free(f);
}

int main(int argc, char **argv)
{
    MPI_Init(&argc, &argv);
    fftw_mpi_init();
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    check_field("2D 48x40", 2, (size_t[]){48, 40}, (double[]){1, 1}, 0);
    check_field("2D 37x29 h 0.5x0.25", 2, (size_t[]){37, 29}, (double[]){0.5, 0.25}, 3);
    check_field("2D 16x3", 2, (size_t[]){16, 3}, (double[]){1, 1}, 0);
    check_field("3D 12x10x9", 3, (size_t[]){12, 10, 9}, (double[]){1, 1, 1}, -2);
    check_field("3D 7x6x5 h 1x2x0.5", 3, (size_t[]){7, 6, 5}, (double[]){1, 2, 0.5}, 0);
    check_field("3D 6x5x2", 3, (size_t[]){6, 5, 2}, (double[]){1, 1, 1}, 0);
    check_field("2D 9x1", 2, (size_t[]){9, 1}, (double[]){1, 1}, 0);
    check_field("1D 101", 1, (size_t[]){101}, (double[]){0.5}, 1);
    {
        nl_field *f = make_field(2, (size_t[]){16, 16}, NULL, 0, 1);
        check_errors(f);
        nl_field_free(f);
    }
    MPI_Allreduce(MPI_IN_PLACE, &fails, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
    if (rank == 0) /* every process compares the same results: rank 0's worst is the run's */
        printf("analysis: %s, largest difference %.3g of the largest |value| (%s)\n", fails ? "FAILED" : "passed",
               worst, worst_what);
    fftw_mpi_cleanup();
    MPI_Finalize();
    return fails ? 1 : 0;
}
