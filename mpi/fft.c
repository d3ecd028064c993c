/* Distributed periodic FFT synthesis on FFTW-MPI's transposed layouts. */
#include "fft.h"
#include "dist.h"
#include "../core/fftw_plan.h"
#include "../core/mem.h"
#include "../core/nl_error.h"
#include "../core/rng.h"
#include "../core/wk.h"
#include "../synth/fft_internal.h"

#include <complex.h>
#include <fftw3-mpi.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

struct nl_mpi_fft_plan {
    MPI_Comm comm;        /* the processes (not owned) */
    int dim;              /* 2 or 3 */
    size_t n[3];          /* samples per axis, x first; 1 beyond dim */
    double h[3];          /* spacing per axis */
    size_t count;         /* n[0] n[1] n[2] */
    size_t h0;            /* n[0] / 2 + 1: the half axis */
    ptrdiff_t N[3];       /* FFTW's real dims, slowest first */
    ptrdiff_t alloc;      /* complex elements of the local buffer */
    ptrdiff_t ln0, l0s;   /* real space: local rows of the slowest axis */
    ptrdiff_t ln1, l1s;   /* transposed frequency space: local rows of FFTW's second axis */
    size_t nloc;          /* local frequency elements: ln1 N0 (2D: x h0 rows... see freq_index) */
    double *amp;          /* sqrt(lambda / (2 N)) per local frequency element, in buffer order */
    fftw_complex *buf;    /* the plan's buffer (planned in place) */
    fftw_plan inv;        /* c2r, FFTW_MPI_TRANSPOSED_IN */
    nl_synth_fft_info info;
};

/* Global frequency (i, r) of local element e of the transposed layout:
 * 2D: (H, N0) with local rows of H: e = a N0 + j, i = l1s + a, r = j;
 * 3D: (N1, N0, H) with local rows of N1: e = (a N0 + k2) H + i,
 * r = (l1s + a) + n1 k2 (r = k1 + n1 k2 as synth/fft.h's row index). */
static void freq_index(const nl_mpi_fft_plan *p, size_t e, size_t *i, size_t *r)
{
    if (p->dim == 2) {
        *i = (size_t)p->l1s + e / p->n[1];
        *r = e % p->n[1];
    } else {
        size_t q = e / p->h0, k2 = q % p->n[2], a = q / p->n[2];
        *i = e % p->h0;
        *r = (size_t)p->l1s + a + p->n[1] * k2;
    }
}

/* The row of -k (synth/fft.h's hermitian_column). */
static size_t mirror(const nl_mpi_fft_plan *p, size_t r)
{
    size_t k1 = r % p->n[1], k2 = r / p->n[1];
    return (p->n[2] - k2) % p->n[2] * p->n[1] + (p->n[1] - k1) % p->n[1];
}

void nl_mpi_fft_plan_free(nl_mpi_fft_plan *p)
{
    if (!p)
        return;
    if (p->inv)
        fftw_destroy_plan(p->inv);
    fftw_free(p->buf);
    nl_free(p->amp);
    free(p);
}

static int setup(MPI_Comm comm, int dim, const size_t *n, const double *h, nl_mpi_fft_plan **out)
{
    nl_mpi_fft_plan *p = calloc(1, sizeof *p);
    ptrdiff_t C[3];
    *out = NULL;
    if (!p)
        return NL_ERROR(NL_ENOMEM, "out of memory");
    p->comm = comm, p->dim = dim, p->count = 1;
    for (int a = 0; a < 3; a++) {
        p->n[a] = a < dim ? n[a] : 1;
        p->h[a] = a < dim && h ? h[a] : 1;
        p->count *= p->n[a];
    }
    p->h0 = p->n[0] / 2 + 1;
    for (int a = 0; a < dim; a++)
        p->N[a] = C[a] = (ptrdiff_t)p->n[dim - 1 - a];
    C[dim - 1] = (ptrdiff_t)p->h0;
    p->alloc = fftw_mpi_local_size_transposed(dim, C, comm, &p->ln0, &p->l0s, &p->ln1, &p->l1s);
    p->nloc = (size_t)p->ln1 * (size_t)p->N[0] * (dim == 3 ? p->h0 : 1);
    *out = p;
    return NL_OK;
}

/* The model's spectrum S (as core/wk.h: cell R-hat for lag models) at each
 * local frequency element, into amp. */
static int sample_spectrum(nl_mpi_fft_plan *p, const nl_model *m)
{
    const int dim = p->dim;
    double cell = p->h[0] * p->h[1] * p->h[2];
    int st;
    if (nl_model_is_spectral(m)) {
        if ((st = nl_wk_check_even(m, dim, p->n, p->h, 1)))
            return st;
        for (size_t e = 0; e < p->nloc; e++) {
            size_t i, r, idx[3];
            freq_index(p, e, &i, &r);
            idx[0] = i, idx[1] = r % p->n[1], idx[2] = r / p->n[1];
            p->amp[e] = nl_wk_value(m, dim, p->n, p->h, idx, 1);
        }
        return NL_OK;
    }
    /* R at the wrapped lags of the local rows, then the forward transform */
    double *x = (double *)p->buf;
    fftw_plan fwd = fftw_mpi_plan_dft_r2c(dim, p->N, x, p->buf, p->comm,
                                          nl_fftw_flags(p->count) | FFTW_MPI_TRANSPOSED_OUT);
    if (!fwd)
        return NL_ERROR(NL_EFAIL, "FFTW-MPI could not plan a %d-D transform", dim);
    size_t per = dim == 3 ? p->n[1] : 1, r0 = (size_t)p->l0s * per;
    st = nl_wk_sample_rows(m, dim, p->n, p->h, r0, r0 + (size_t)p->ln0 * per, 0, x, 2 * p->h0);
    if (!st)
        fftw_execute(fwd);
    fftw_destroy_plan(fwd);
    for (size_t e = 0; !st && e < p->nloc; e++)
        p->amp[e] = cell * creal(p->buf[e]);
    return st;
}

/* Sums over the full grid (columns 0 < i < n0/2 count twice), the verdict
 * (synth/fft.h), then the amplitudes. */
static int judge(nl_mpi_fft_plan *p, const char *name, unsigned flags)
{
    double cell = p->h[0] * p->h[1] * p->h[2], s[2] = {0, 0}, mm[2] = {INFINITY, INFINITY}, S[2], M[2];
    unsigned long long negl = 0, neg;
    int st = NL_OK;
    for (size_t e = 0; e < p->nloc; e++) {
        size_t i, r;
        double l = p->amp[e] / cell, w;
        freq_index(p, e, &i, &r);
        w = i == 0 || 2 * i == p->n[0] ? 1 : 2;
        if (!isfinite(l)) {
            st = NL_ERROR(NL_EINVAL, "%s: the sampled spectrum is not finite (%g) at frequency index (%zu, %zu, "
                          "%zu): the model's values are too large for this grid", name, l, i, r % p->n[1],
                          r / p->n[1]);
            break;
        }
        mm[0] = fmin(mm[0], l), mm[1] = fmin(mm[1], -l);
        if (l < 0) {
            s[1] -= w * l;
            negl += (unsigned long long)w;
        } else {
            s[0] += w * l;
        }
    }
    if ((st = nl_mpi_agree(p->comm, st)))
        return st;
    MPI_Allreduce(s, S, 2, MPI_DOUBLE, MPI_SUM, p->comm);
    MPI_Allreduce(mm, M, 2, MPI_DOUBLE, MPI_MIN, p->comm);
    MPI_Allreduce(&negl, &neg, 1, MPI_UNSIGNED_LONG_LONG, MPI_SUM, p->comm);
    p->info.min_lambda = M[0] * cell;
    p->info.max_lambda = -M[1] * cell;
    p->info.negatives = (size_t)neg;
    if ((st = nl_synth_fft_verdict(name, p->count, S[0], S[1], flags, &p->info)))
        return st;
    for (size_t e = 0; e < p->nloc; e++) {
        double l = p->amp[e] / cell;
        p->amp[e] = l > 0 ? sqrt(l / (2 * (double)p->count)) : 0.0;
    }
    return NL_OK;
}

int nl_mpi_fft_plan_alloc(MPI_Comm comm, const nl_model *m, int dim, const size_t *n, const double *h,
                          unsigned flags, nl_mpi_fft_plan **out)
{
    nl_mpi_fft_plan *p = NULL;
    int st = NL_OK;
    *out = NULL;
    if (dim != 2 && dim != 3)
        st = NL_ERROR(NL_EINVAL, "size: distributed FFT synthesis needs a 2D or 3D field, got %dD (a 1D field fits "
                      "one process: run it without mpirun)", dim);
    for (int a = 0; !st && a < dim; a++)
        if (n[a] < 2 || n[a] > INT32_MAX)
            st = NL_ERROR(NL_EINVAL, "size: %zu samples along axis %d; expected 2 to 2^31 - 1", n[a], a);
    if (!st)
        st = nl_synth_check_cell(dim, h);
    if (!st)
        st = setup(comm, dim, n, h, &p);
    if (!st) {
        p->buf = fftw_alloc_complex((size_t)(p->alloc > 0 ? p->alloc : 1));
        p->amp = nl_alloc((p->nloc ? p->nloc : 1) * sizeof *p->amp);
        if (!p->buf || !p->amp)
            st = NL_ERROR(NL_ENOMEM, "out of memory for a %zu-sample slab of the spectrum", p->nloc);
    }
    if ((st = nl_mpi_agree(comm, st)))
        goto fail;
    /* planned before the buffer is filled: a measured plan overwrites it */
    p->inv = fftw_mpi_plan_dft_c2r(dim, p->N, p->buf, (double *)p->buf, comm,
                                   nl_fftw_flags(p->count) | FFTW_MPI_TRANSPOSED_IN);
    st = p->inv ? NL_OK : NL_ERROR(NL_EFAIL, "FFTW-MPI could not plan a %d-D transform", dim);
    if ((st = nl_mpi_agree(comm, st)) || (st = nl_mpi_agree(comm, sample_spectrum(p, m))) ||
        (st = judge(p, nl_model_spec(m), flags)))
        goto fail;
    *out = p;
    return NL_OK;
fail:
    nl_mpi_fft_plan_free(p);
    return st;
}

void nl_mpi_fft_local(const nl_mpi_fft_plan *p, size_t *s0, size_t *ns)
{
    *s0 = (size_t)p->l0s;
    *ns = (size_t)p->ln0;
}

void nl_mpi_fft_plan_info(const nl_mpi_fft_plan *p, nl_synth_fft_info *info) { *info = p->info; }

/* The Hermitian columns k0 = 0 and n0/2 (synth/fft.h): element e at
 * frequency (i, r) holds G of its own index; make it the conjugate of its
 * mirror's when that comes first, real (sqrt(2) Re G) when self-conjugate. */
static void hermitian_fix(const nl_mpi_fft_plan *p, uint64_t seed, size_t e, size_t i, size_t r, fftw_complex *c)
{
    size_t m = mirror(p, r);
    double g[2];
    if (m < r) {
        nl_rng_gauss_pair(seed, NL_STREAM_WHITE, m * p->h0 + i, g);
        c[e] = g[0] - I * g[1];
    } else if (m == r) {
        c[e] = M_SQRT2 * creal(c[e]);
    }
}

/* G times the amplitude at every local frequency (synth/fft.h's white
 * spectrum, drawn by global index: runs of consecutive indices by the
 * vectorised fill). */
static int fill_noise(const nl_mpi_fft_plan *p, uint64_t seed, fftw_complex *c)
{
    const size_t h0 = p->h0, n0 = p->n[0], ln1 = (size_t)p->ln1, l1s = (size_t)p->l1s;
    int fail = 0;
    if (p->dim == 3) {
        /* (a, k2, i): each row of i is a run */
        size_t rows = p->nloc / h0;
#pragma omp parallel for schedule(static) if (p->nloc > 65536)
        for (size_t q = 0; q < rows; q++) {
            size_t r = l1s + q / p->n[2] + p->n[1] * (q % p->n[2]);
            nl_rng_gauss_fill(seed, NL_STREAM_WHITE, r * h0, 2 * h0, (double *)(c + q * h0));
            hermitian_fix(p, seed, q * h0, 0, r, c);
            if (n0 % 2 == 0)
                hermitian_fix(p, seed, q * h0 + h0 - 1, h0 - 1, r, c);
        }
    } else {
        /* (a, j): for each j the run of i = l1s .. l1s + ln1 - 1, scattered */
        const size_t N0 = p->n[1];
#pragma omp parallel if (p->nloc > 65536)
        {
            double *g = malloc(2 * (ln1 ? ln1 : 1) * sizeof *g);
            if (!g) {
#pragma omp atomic write
                fail = 1;
            }
#pragma omp for schedule(static)
            for (size_t j = 0; j < N0; j++) {
                if (!g || !ln1)
                    continue;
                nl_rng_gauss_fill(seed, NL_STREAM_WHITE, j * h0 + l1s, 2 * ln1, g);
                for (size_t a = 0; a < ln1; a++)
                    c[a * N0 + j] = g[2 * a] + I * g[2 * a + 1];
                if (l1s == 0)
                    hermitian_fix(p, seed, j, 0, j, c);
                if (n0 % 2 == 0 && l1s + ln1 == h0)
                    hermitian_fix(p, seed, (ln1 - 1) * N0 + j, h0 - 1, j, c);
            }
            free(g);
        }
    }
#pragma omp parallel for schedule(static) if (p->nloc > 65536)
    for (size_t e = 0; e < p->nloc; e++)
        c[e] *= p->amp[e];
    return fail ? NL_ERROR(NL_ENOMEM, "out of memory for the white noise's rows") : NL_OK;
}

int nl_mpi_fft_execute(const nl_mpi_fft_plan *p, uint64_t seed, double *out)
{
    const size_t rowlen = p->n[0], rows = (size_t)p->ln0 * (p->dim == 3 ? p->n[1] : 1);
    const double *x = (const double *)p->buf;
    int st = nl_mpi_agree(p->comm, fill_noise(p, seed, p->buf));
    if (st)
        return st;
    fftw_execute(p->inv);
    for (size_t q = 0; q < rows; q++)
        memcpy(out + q * rowlen, x + q * 2 * p->h0, rowlen * sizeof *out);
    return nl_mpi_agree(p->comm, NL_OK);
}

size_t nl_mpi_fft_bytes(int dim, const size_t *n, int P)
{
    size_t slow = n[dim - 1], rest = 1, b = (slow + (size_t)P - 1) / (size_t)P;
    for (int a = 0; a + 1 < dim; a++)
        rest *= n[a];
    /* the complex buffer (padded rows), the amplitudes (half) and the output */
    return (size_t)(2.5 * (double)b * (double)rest * sizeof(double)) + 2 * b * sizeof(double) * (n[0] / 2 + 1);
}
