/* The distributed periodogram (analysis/psd.h) and its summaries
 * (analysis/spectral.h): one FFTW-MPI r2c, transposed out, whose half
 * spectrum each process visits with its Hermitian mirrors. */
#include "analysis_internal.h"
#include "dist.h"
#include "../analysis/psd.h"
#include "../analysis/spectral.h"
#include "../analysis/verdict.h"
#include "../core/nl_error.h"
#include "../core/wk.h"

#include <math.h>
#include <stdlib.h>

size_t nl_mpi_psd_profile_size(int dim, const size_t *n, const double *h)
{
    nl_field P = {.dim = dim, .n = {1, 1, 1}, .h = {1, 1, 1}};
    for (int a = 0; a < dim && a < 3; a++)
        P.n[a] = n[a], P.h[a] = h[a];
    return nl_psd_profile_size(&P);
}

/* Per-process sums: the radial bins and the 2D sectors. */
typedef struct {
    const nl_mpi_slab *x;
    double unit[3], step;
    size_t nf, nsec;
    double *r, *v, flo, fhi, *sec;
    unsigned long long *c;  /* nf radial counts, then nsec sector counts */
    int slope;              /* the slope's points: log |f|, log P of this process's ordinates */
    double fmin, fmax, *lx, *ly;
    size_t m;
} psd_sums;

/* One ordinate of the full grid, as nl_radial and nl_psd_sectors see it. */
static void visit(psd_sums *s, const size_t *idx, double val)
{
    const size_t *n = s->x->n;
    double d2 = 0, d, q;
    for (int a = 0; a < s->x->dim; a++) {
        double e = nl_wrap(idx[a], n[a]) * s->unit[a];
        d2 += e * e;
    }
    d = sqrt(d2), q = floor(d / s->step + 0.5);
    if (q < (double)s->nf)
        s->r[(size_t)q] += d, s->v[(size_t)q] += val, s->c[(size_t)q]++;
    if (s->sec) {
        double fx = (double)nl_wrap(idx[0], n[0]) / (double)n[0], fy = (double)nl_wrap(idx[1], n[1]) / (double)n[1];
        double rr = hypot(fx, fy), a = atan2(fy, fx);
        if (rr < s->flo || rr > s->fhi)
            return;
        if (a < 0)
            a += M_PI;
        size_t b = (size_t)(a / M_PI * (double)s->nsec) % s->nsec;
        s->sec[b] += val, s->c[s->nf + b]++;
    }
}

/* A point of the log-periodogram regression, as nl_psd_slope_grid takes it. */
static void slope_point(psd_sums *s, const size_t *idx, double v)
{
    const size_t *n = s->x->n;
    const double *h = s->x->h;
    double fx = (double)nl_wrap(idx[0], n[0]) / ((double)n[0] * h[0]);
    double fy = (double)nl_wrap(idx[1], n[1]) / ((double)n[1] * h[1]);
    double fz = (double)nl_wrap(idx[2], n[2]) / ((double)n[2] * h[2]);
    double f = sqrt(fx * fx + fy * fy + fz * fz);
    if (f < s->fmin || f > s->fmax || f <= 0 || !(v > 0) || !isfinite(v))
        return;
    s->lx[s->m] = log(f), s->ly[s->m++] = log(v);
}

/* Least squares of ly on lx over every process's points, as gsl_fit_linear
 * (centred sums), with the 95% interval and eq. (16) of analysis/slope.c. */
static int slope_fit(const psd_sums *s, nl_slope *out)
{
    unsigned long long m = s->m;
    double a[3] = {0, 0, 0}, xm, ym, c0, c1, cov11;
    int E = s->x->dim, bad = MPI_Allreduce(MPI_IN_PLACE, &m, 1, MPI_UNSIGNED_LONG_LONG, MPI_SUM, s->x->comm);
    for (size_t i = 0; i < s->m; i++)
        a[0] += s->lx[i], a[1] += s->ly[i];
    bad |= MPI_Allreduce(MPI_IN_PLACE, a, 2, MPI_DOUBLE, MPI_SUM, s->x->comm);
    if (bad != MPI_SUCCESS)
        return NL_ERROR(NL_EFAIL, "MPI: summing the slope's points failed");
    if (m < 3)
        return NL_ERROR(NL_EINVAL, "slope: expected at least 3 frequencies in the band, got %llu", m);
    xm = a[0] / (double)m, ym = a[1] / (double)m, a[0] = a[1] = 0;
    for (size_t i = 0; i < s->m; i++)
        a[0] += (s->lx[i] - xm) * (s->lx[i] - xm), a[1] += (s->lx[i] - xm) * (s->ly[i] - ym);
    bad |= MPI_Allreduce(MPI_IN_PLACE, a, 2, MPI_DOUBLE, MPI_SUM, s->x->comm);
    c1 = a[1] / a[0], c0 = ym - c1 * xm;
    for (size_t i = 0; i < s->m; i++) {
        double r = s->ly[i] - (c0 + c1 * s->lx[i]);
        a[2] += r * r;
    }
    bad |= MPI_Allreduce(MPI_IN_PLACE, a + 2, 1, MPI_DOUBLE, MPI_SUM, s->x->comm);
    if (bad != MPI_SUCCESS)
        return NL_ERROR(NL_EFAIL, "MPI: summing the slope's points failed");
    cov11 = a[2] / (double)(m - 2) / a[0];
    out->slope = c1, out->points = (size_t)m;
    /* Student's t at 0.025 with m - 2 degrees of freedom, as analysis/slope.c */
    out->ci95 = nl_verdict_threshold(0.05, 1, (size_t)m - 2) * sqrt(cov11);
    out->fractal_dim = E + (3 - (-c1 - (E - 1))) / 2;
    return NL_OK;
}

/* Every ordinate of the transposed half spectrum here, and its mirror
 * P(-k) = P(k) where that lies in the other half. */
static void visit_half(psd_sums *s, const nl_mpi_grid *G)
{
    const size_t *n = s->x->n;
    size_t h0 = n[0] / 2 + 1, inner = s->x->dim == 3 ? n[2] * h0 : n[1];
    double scale = s->x->h[0] * s->x->h[1] * s->x->h[2] / (double)(n[0] * n[1] * n[2]);
    for (size_t a = 0; a < (size_t)G->ln1; a++)
        for (size_t e = 0; e < inner; e++) {
            const double *c = G->buf + 2 * (a * inner + e);
            size_t idx[3], mir[3];
            if (s->x->dim == 2)
                idx[0] = (size_t)G->l1s + a, idx[1] = e, idx[2] = 0;
            else
                idx[0] = e % h0, idx[1] = (size_t)G->l1s + a, idx[2] = e / h0;
            double v = scale * (c[0] * c[0] + c[1] * c[1]);
            visit(s, idx, v);
            mir[0] = (n[0] - idx[0]) % n[0], mir[1] = (n[1] - idx[1]) % n[1], mir[2] = (n[2] - idx[2]) % n[2];
            if (mir[0] != idx[0])
                visit(s, mir, v);
            /* the slope takes each pair once: the half's ordinate, or of a
             * pair inside the half (x frequency 0 or Nyquist) the first */
            if (s->slope && (mir[0] != idx[0] || idx[2] * n[1] + idx[1] <= mir[2] * n[1] + mir[1]))
                slope_point(s, idx, v);
        }
}

/* The sums over every process, then the means (NAN when empty). */
static int finish(psd_sums *s, double *freq, double *val, size_t *cnt, double *aniso)
{
    int st = NL_OK, k = (int)(s->nf + s->nsec);
    if (MPI_Allreduce(MPI_IN_PLACE, s->r, (int)s->nf, MPI_DOUBLE, MPI_SUM, s->x->comm) != MPI_SUCCESS ||
        MPI_Allreduce(MPI_IN_PLACE, s->v, (int)s->nf, MPI_DOUBLE, MPI_SUM, s->x->comm) != MPI_SUCCESS ||
        (s->sec && MPI_Allreduce(MPI_IN_PLACE, s->sec, (int)s->nsec, MPI_DOUBLE, MPI_SUM, s->x->comm) != MPI_SUCCESS) ||
        MPI_Allreduce(MPI_IN_PLACE, s->c, k, MPI_UNSIGNED_LONG_LONG, MPI_SUM, s->x->comm) != MPI_SUCCESS)
        st = NL_ERROR(NL_EFAIL, "MPI: summing the spectrum's bins failed");
    for (size_t b = 0; b < s->nf; b++) {
        cnt[b] = (size_t)s->c[b];
        freq[b] = cnt[b] ? s->r[b] / (double)cnt[b] : NAN;
        val[b] = cnt[b] ? s->v[b] / (double)cnt[b] : NAN;
    }
    if (s->sec) {
        double mn = INFINITY, mx = 0;
        for (size_t b = 0; b < s->nsec; b++) {
            s->sec[b] = s->c[s->nf + b] ? s->sec[b] / (double)s->c[s->nf + b] : NAN;
            mn = fmin(mn, s->sec[b]), mx = fmax(mx, s->sec[b]);
        }
        *aniso = mx / mn;
    }
    return nl_mpi_agree(s->x->comm, st);
}

/* 1D: the series on every process, the one-process periodogram. */
static int psd_1d(const nl_mpi_slab *x, double mean, double *freq, double *val, size_t *cnt, size_t *nf,
                  nl_mpi_psd_more *more)
{
    nl_field *f, *P = NULL;
    int st = nl_mpi_gather_1d(x, &f);
    if (st)
        return st;
    if (!(st = nl_psd_periodogram(f, mean, &P)))
        st = nl_psd_profile(P, freq, val, cnt, nf);
    if (!st && more && more->slope) /* as noiselab psd fits a 1D spectrum */
        st = nl_psd_slope(freq, val, *nf, more->fmin, more->fmax, 1, &more->sl);
    nl_field_free(P), nl_field_free(f);
    return nl_mpi_agree(x->comm, st);
}

static int check_args(const nl_mpi_slab *x, const nl_mpi_psd_more *o)
{
    int st = nl_mpi_slab_check(x);
    if (st)
        return st;
    if (o && o->sector && (x->dim != 2 || o->nsec == 0 || o->nsec > 1u << 20 || !(o->flo >= 0 && o->fhi >= o->flo)))
        st = NL_ERROR(NL_EINVAL, "sectors: expected a 2D spectrum, 1 to 2^20 sectors and 0 <= fmin <= fmax, got "
                      "%dD, %zu, %g, %g", x->dim, o->nsec, o->flo, o->fhi);
    return nl_mpi_agree(x->comm, st);
}

/* The transform, the visit of its half spectrum, and the sums. */
static int transform(psd_sums *s, double m, double *freq, double *val, size_t *cnt, nl_mpi_psd_more *more)
{
    nl_mpi_grid G;
    size_t pts;
    int st = nl_mpi_grid_alloc(s->x->comm, s->x->dim, s->x->n, 0, &G);
    if (st)
        return st;
    /* the ordinates here: ln1 lines of the transposed half spectrum (visit_half) */
    pts = s->slope ? (size_t)G.ln1 * (s->x->dim == 3 ? s->x->n[2] * (s->x->n[0] / 2 + 1) : s->x->n[1]) + 1 : 1;
    s->lx = malloc(pts * sizeof *s->lx), s->ly = malloc(pts * sizeof *s->ly);
    st = s->lx && s->ly ? NL_OK : NL_ERROR(NL_ENOMEM, "out of memory for the slope's %zu points", pts);
    if (!(st = nl_mpi_agree(s->x->comm, st)) && !(st = nl_mpi_grid_fill(s->x, m, &G))) {
        fftw_execute(G.fwd);
        visit_half(s, &G);
        st = finish(s, freq, val, cnt, more ? &more->aniso : NULL);
        if (!st && s->slope)
            st = nl_mpi_agree(s->x->comm, slope_fit(s, &more->sl));
    }
    free(s->lx), free(s->ly);
    nl_mpi_grid_free(&G);
    return st;
}

int nl_mpi_psd(const nl_mpi_slab *x, double mean, double *freq, double *val, size_t *cnt, size_t *nf,
               nl_mpi_psd_more *more)
{
    psd_sums s = {.x = x, .step = INFINITY};
    double m;
    int st = check_args(x, more);
    if (st)
        return st;
    if (x->dim == 1)
        return psd_1d(x, mean, freq, val, cnt, nf, more);
    if ((st = nl_mpi_agree(x->comm, nl_mpi_check_range(x, mean, 1, &m))))
        return st;
    if (more && more->sector)
        s.nsec = more->nsec, s.flo = more->flo, s.fhi = more->fhi, s.sec = more->sector;
    if (more && more->slope)
        s.slope = 1, s.fmin = more->fmin, s.fmax = more->fmax;
    for (int a = 0; a < x->dim; a++) { /* the bins of analysis/spectral.c */
        s.unit[a] = 1.0 / ((double)x->n[a] * x->h[a]);
        s.step = fmin(s.step, s.unit[a]);
    }
    *nf = s.nf = nl_mpi_psd_profile_size(x->dim, x->n, x->h);
    s.r = freq, s.v = val;
    for (size_t b = 0; b < s.nf; b++)
        freq[b] = val[b] = 0;
    for (size_t b = 0; b < s.nsec; b++)
        s.sec[b] = 0;
    s.c = calloc(s.nf + s.nsec, sizeof *s.c);
    if (!(st = nl_mpi_agree(x->comm, s.c ? NL_OK : NL_ERROR(NL_ENOMEM, "out of memory for %zu bins", s.nf))))
        st = transform(&s, m, freq, val, cnt, more);
    free(s.c);
    return st;
}
