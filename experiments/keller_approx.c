/* Keller 2001, section 3.2: "for the same number of points the rank-1
 * lattice method outperforms the standard tensor product approach".
 * Measured: a smooth periodic function of dimension s with an isotropic
 * band limit,
 *     f(x) = sum_k a_k exp(2 pi i k . x),  a_k = exp(-|k|^2 / (2 b^2)) u_k,
 * u_k unit complex numbers (seeded; u_{-k} = conj(u_k), so f is real), every
 * k with |a_k| >= 1e-17 kept, is interpolated from its values at N points:
 * on a Korobov rank-1 lattice (nl_rank1_korobov: one 1D FFT of length N,
 * coefficients on K_N, the wave vectors of minimal norm) and on the tensor
 * grid of M^s = N points (odd M, coefficients on the box |k_a| <= (M-1)/2).
 * Both interpolants alias: the coefficient they give wave vector k_m is the
 * sum of the a_k of its residue class (k . g = m mod N, or k = k_m mod M
 * per axis), which is what sampling and one FFT compute.  The relative L2
 * error is then exact by Parseval:
 *     e^2 = (sum_{k not in K} |a_k|^2 + sum_{m} |ghat_m - a_{k_m}|^2) / sum |a_k|^2.
 * The aliasing shortcut is itself checked against real sampling plus one FFT
 * at one N per dimension (equal to 1e-12).
 *
 * usage: keller_approx -> TSV on stdout: s, method, N, relative_error;
 * "# check" lines with the sampling comparison; exit 1 when the sampling
 * check fails, 2 on failure to build a lattice. */
#include "../core/nl_error.h"
#include "../core/rng.h"
#include "../synth/rank1.h"

#include <complex.h>
#include <fftw3.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    int s;             /* dimension */
    size_t T;          /* terms */
    long *k;           /* T * s wave vectors */
    double complex *a; /* T coefficients */
    double energy;     /* sum |a_k|^2 */
} target;

/* k as a key of a hash of the target's wave vectors: linear probing. */
typedef struct {
    size_t cap;
    long *key;   /* cap * s, LONG_MIN = empty */
    size_t *idx; /* term index */
} table;

static size_t hash(const long *k, int s, size_t cap)
{
    uint64_t h = 1469598103934665603ull;
    for (int a = 0; a < s; a++)
        h = (h ^ (uint64_t)(k[a] + 1000)) * 1099511628211ull;
    return (size_t)(h % cap);
}

static long find(const table *t, const long *k, int s)
{
    for (size_t i = hash(k, s, t->cap);; i = (i + 1) % t->cap) {
        if (t->key[i * (size_t)s] == -999999)
            return -1;
        if (!memcmp(t->key + i * (size_t)s, k, (size_t)s * sizeof *k))
            return (long)t->idx[i];
    }
}

static void make_target(int s, double b, target *f, table *t)
{
    double R = b * sqrt(2 * log(1e17));
    long r = (long)ceil(R), k[4], span = 2 * r + 1, total = 1;
    for (int a = 0; a < s; a++)
        total *= span;
    f->s = s, f->T = 0, f->energy = 0;
    f->k = malloc((size_t)total * (size_t)s * sizeof *f->k), f->a = malloc((size_t)total * sizeof *f->a);
    for (long q = 0; q < total; q++) {
        long u = q, n2 = 0, key = 0;
        for (int a = 0; a < s; a++)
            k[a] = u % span - r, u /= span, n2 += k[a] * k[a];
        if ((double)n2 > R * R)
            continue;
        /* u_k from the canonical sign of k (first non-zero component positive) */
        int sg = 0;
        for (int a = 0; a < s && !sg; a++)
            sg = k[a] > 0 ? 1 : k[a] < 0 ? -1 : 0;
        for (int a = 0; a < s; a++)
            key = key * span + (sg < 0 ? -k[a] : k[a]) + r;
        double ph = sg ? 2 * M_PI * nl_rng_uniform(3, (uint32_t)s, (uint64_t)key) : 0;
        memcpy(f->k + f->T * (size_t)s, k, (size_t)s * sizeof *k);
        f->a[f->T] = exp(-(double)n2 / (2 * b * b)) * cexp(I * (sg < 0 ? -ph : ph));
        f->energy += exp(-(double)n2 / (b * b));
        f->T++;
    }
    t->cap = 2 * f->T + 1;
    t->key = malloc(t->cap * (size_t)s * sizeof *t->key), t->idx = malloc(t->cap * sizeof *t->idx);
    for (size_t i = 0; i < t->cap * (size_t)s; i++)
        t->key[i] = -999999;
    for (size_t q = 0; q < f->T; q++) {
        size_t i = hash(f->k + q * (size_t)s, s, t->cap);
        while (t->key[i * (size_t)s] != -999999)
            i = (i + 1) % t->cap;
        memcpy(t->key + i * (size_t)s, f->k + q * (size_t)s, (size_t)s * sizeof(long));
        t->idx[i] = q;
    }
}

/* The error of an interpolant whose N coefficients ghat are the aliasing
 * sums and whose wave vectors are kw (N * s). */
static double error(const target *f, const table *t, size_t N, const double complex *ghat, const long *kw)
{
    double e = 0;
    char *in = calloc(f->T, 1);
    for (size_t m = 0; m < N; m++) {
        long q = find(t, kw + m * (size_t)f->s, f->s);
        double complex am = q < 0 ? 0 : f->a[q];
        if (q >= 0)
            in[q] = 1;
        e += cabs(ghat[m] - am) * cabs(ghat[m] - am);
    }
    /* the target's terms the interpolant has no wave vector for (summed
     * apart, not subtracted from the energy: no cancellation) */
    for (size_t q = 0; q < f->T; q++)
        if (!in[q])
            e += cabs(f->a[q]) * cabs(f->a[q]);
    free(in);
    return sqrt(e / f->energy);
}

static double lattice_error(const target *f, const table *t, const nl_rank1_lattice *L, double complex *ghat)
{
    size_t N = L->N;
    memset(ghat, 0, N * sizeof *ghat);
    for (size_t q = 0; q < f->T; q++) {
        long m = 0;
        for (int a = 0; a < f->s; a++)
            m = (m + (f->k[q * (size_t)f->s + (size_t)a] % (long)N + (long)N) % (long)N * L->g[a]) % (long)N;
        ghat[m] += f->a[q];
    }
    return error(f, t, N, ghat, L->k);
}

static double grid_error(const target *f, const table *t, long M, double complex *ghat, long *kw)
{
    size_t N = 1;
    for (int a = 0; a < f->s; a++)
        N *= (size_t)M;
    memset(ghat, 0, N * sizeof *ghat);
    for (size_t m = 0; m < N; m++) {
        size_t u = m;
        for (int a = 0; a < f->s; a++)
            kw[m * (size_t)f->s + (size_t)a] = (long)(u % (size_t)M) - (M - 1) / 2, u /= (size_t)M;
    }
    for (size_t q = 0; q < f->T; q++) {
        size_t m = 0;
        for (int a = f->s - 1; a >= 0; a--) {
            long r = ((f->k[q * (size_t)f->s + (size_t)a] + (M - 1) / 2) % M + M) % M;
            m = m * (size_t)M + (size_t)r;
        }
        ghat[m] += f->a[q];
    }
    return error(f, t, N, ghat, kw);
}

/* Sampling at the lattice points and one FFT give the aliasing sums. */
static double sampling_check(const target *f, const nl_rank1_lattice *L, const double complex *ghat)
{
    size_t N = L->N;
    fftw_complex *b = fftw_alloc_complex(N);
    fftw_plan p = fftw_plan_dft_1d((int)N, b, b, FFTW_FORWARD, FFTW_ESTIMATE);
    double x[4], err = 0, top = 0;
    for (size_t n = 0; n < N; n++) {
        double complex v = 0;
        nl_rank1_point(L, n, x);
        for (size_t q = 0; q < f->T; q++) {
            double ph = 0;
            for (int a = 0; a < f->s; a++)
                ph += (double)f->k[q * (size_t)f->s + (size_t)a] * x[a];
            v += f->a[q] * cexp(2 * M_PI * I * (ph - floor(ph)));
        }
        b[n] = v;
    }
    fftw_execute(p);
    for (size_t m = 0; m < N; m++)
        err = fmax(err, cabs(b[m] / (double)N - ghat[m])), top = fmax(top, cabs(ghat[m]));
    fftw_destroy_plan(p), fftw_free(b);
    return err / top;
}

int main(void)
{
    static const struct { int s; double b; long M0, M1, Mcheck; } dims[] = {{2, 3, 5, 61, 21}, {3, 1.6, 5, 19, 9},
                                                                            {4, 1.1, 3, 11, 5}};
    int bad = 0;
    printf("s\tmethod\tN\trelative_error\n");
    for (size_t d = 0; d < sizeof dims / sizeof *dims; d++) {
        target f;
        table t;
        int s = dims[d].s;
        make_target(s, dims[d].b, &f, &t);
        size_t Nmax = (size_t)pow((double)dims[d].M1, s) + 1;
        double complex *ghat = malloc(Nmax * sizeof *ghat);
        long *kw = malloc(Nmax * (size_t)s * sizeof *kw);
        for (long M = dims[d].M0; M <= dims[d].M1; M += 2) {
            size_t N = (size_t)pow((double)M, s);
            nl_rank1_lattice L;
            if (nl_rank1_korobov(N, s, 0, &L)) {
                fprintf(stderr, "keller_approx: %s\n", nl_errmsg());
                return 2;
            }
            printf("%d\tlattice\t%zu\t%.3e\n", s, N, lattice_error(&f, &t, &L, ghat));
            if (M == dims[d].Mcheck) {
                double c = sampling_check(&f, &L, ghat);
                printf("# check s %d N %zu: sampling + FFT vs aliasing sums, max difference %.1e of the largest\n", s, N,
                       c);
                bad += !(c <= 1e-12);
            }
            nl_rank1_free(&L);
            printf("%d\tgrid\t%zu\t%.3e\n", s, N, grid_error(&f, &t, M, ghat, kw));
        }
        free(ghat), free(kw), free(f.k), free(f.a), free(t.key), free(t.idx);
    }
    return bad ? 1 : 0;
}
