/* Experiment: generalized subdivision on an equilateral triangular mesh
 * (Lewis 1987, eqs. (11), (12): "the subdivision topology enters only
 * through the arguments to the autocorrelation function") against the
 * quadrilateral mesh, for the diagonal bias.
 *
 * usage: lewis87_trimesh SUMMARY.tsv TRIMAP.tsv QUADMAP.tsv
 * The triangular lattice p = s (i a1 + j a2), a1 = (1, 0), a2 = (1/2,
 * sqrt 3 / 2), periodic with n x n points (a rhombic torus).  Refining
 * halves s: the old points keep their values and the three classes of new
 * points are the midpoints of the three edge directions (fine indices
 * (odd, even), (even, odd), (odd, odd)), each estimated by eq. (11) from
 * the M old points nearest to it (ties at the M-th distance included, so
 * each stencil has the mesh's symmetry) with coefficients from eq. (12)
 * (nl_subdiv_solve) and the variance of eq. (7).  The field's covariance
 * is propagated exactly, C' = A C A^T + diag(var), from the coarse 16 x 16
 * torus (spacing 4, the model's R periodised over the torus) to 64 x 64
 * (spacing 1) in 2 levels, for R = exp(-r/12).  Measured, as for the
 * quadrilateral mesh (experiments/subdiv_exact.c, same size and levels):
 * the ACF at every lag within distance 20 minus the ACF along a1 at the
 * same distance (linear interpolation): its largest magnitude
 * ("anisotropy") and, along a1 + a2 (30 degrees: halfway between two mesh
 * directions, as the diagonal is on the square mesh), its largest value
 * ("between-edges excess").  SUMMARY.tsv: mesh, M, points, excess,
 * anisotropy, variance. */
#include "../analysis/subdiv_exact.h"
#include "../core/model.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { NMAX = 64, LAGR = 10, MAXM = 64, LEVELS = 4 };

static const double A2X = 0.5, A2Y = 0.86602540378443865;

static long wrap(long i, long n) { return ((i % n) + n) % n; }

/* One class's stencil: offsets (di, dj) from the anchor (i, j) = (I/2,
 * J/2) of the fine index, coefficients and variance. */
typedef struct {
    int n, di[MAXM], dj[MAXM];
    double a[MAXM], var;
} tstencil;

/* The M nearest old points (ties included) of the class with target
 * offset (tx, ty) in lattice units, solved at spacing s. */
static int make_class(const nl_model *m, double tx, double ty, int M, double s, tstencil *t)
{
    double d[100], cut, pts[2 * MAXM], tgt[2];
    int di[100], dj[100], k = 0;
    nl_subdiv_class cl;
    for (int j = -4; j <= 5; j++)
        for (int i = -4; i <= 5; i++) {
            double x = (i - tx) + (j - ty) * A2X, y = (j - ty) * A2Y;
            di[k] = i, dj[k] = j, d[k++] = hypot(x, y);
        }
    {
        double sorted[100];
        memcpy(sorted, d, sizeof sorted);
        for (int a = 0; a < 100; a++)  /* selection of the M-th smallest */
            for (int b = a + 1; b < 100; b++)
                if (sorted[b] < sorted[a]) {
                    double tmp = sorted[a];
                    sorted[a] = sorted[b], sorted[b] = tmp;
                }
        cut = sorted[M - 1] + 1e-9;
    }
    t->n = 0;
    for (int q = 0; q < 100; q++)
        if (d[q] <= cut && t->n < MAXM) {
            t->di[t->n] = di[q], t->dj[t->n] = dj[q];
            pts[2 * t->n] = s * (di[q] + dj[q] * A2X), pts[2 * t->n + 1] = s * dj[q] * A2Y;
            t->n++;
        }
    tgt[0] = s * (tx + ty * A2X), tgt[1] = s * ty * A2Y;
    cl.a = t->a;
    if (nl_subdiv_solve(m, 2, (size_t)t->n, pts, tgt, NULL, &cl))
        return 1;
    t->var = cl.variance;
    return 0;
}

/* R between lattice points (di, dj) apart on an n-torus of spacing s,
 * periodised over the images within two periods. */
static double torus_r(const nl_model *m, long di, long dj, long n, double s)
{
    double v = 0;
    for (int u = -2; u <= 2; u++)
        for (int w = -2; w <= 2; w++) {
            double i = (double)(wrap(di, n) + u * n), j = (double)(wrap(dj, n) + w * n);
            double lag[2] = {s * (i + j * A2X), s * j * A2Y};
            v += nl_model_acf(m, 2, lag);
        }
    return v;
}

/* One level on the triangular torus: C (n x n points) -> C2 (2n x 2n). */
static double *refine(const tstencil *cls, const double *C, long n)
{
    long n1 = n * n, N2 = 2 * n, n2 = N2 * N2;
    double *T = calloc((size_t)(n2 * n1), sizeof *T), *C2 = malloc((size_t)(n2 * n2) * sizeof *C2);
    long *idx = malloc((size_t)n2 * MAXM * sizeof *idx);
    double *w = malloc((size_t)n2 * MAXM * sizeof *w), *var = calloc((size_t)n2, sizeof *var);
    int *cnt = malloc((size_t)n2 * sizeof *cnt);
    if (!T || !C2 || !idx || !w || !var || !cnt)
        return NULL;
    for (long P = 0; P < n2; P++) {
        long I = P % N2, J = P / N2, i = I / 2, j = J / 2;
        int c = (I % 2) + 2 * (J % 2) - 1;  /* 0: (odd, even), 1: (even, odd), 2: (odd, odd) */
        if (c < 0) {
            cnt[P] = 1, idx[P * MAXM] = j * n + i, w[P * MAXM] = 1;
            continue;
        }
        cnt[P] = cls[c].n, var[P] = cls[c].var;
        for (int q = 0; q < cls[c].n; q++)
            idx[P * MAXM + q] = wrap(j + cls[c].dj[q], n) * n + wrap(i + cls[c].di[q], n), w[P * MAXM + q] = cls[c].a[q];
    }
    for (long P = 0; P < n2; P++)
        for (int q = 0; q < cnt[P]; q++)
            for (long k = 0; k < n1; k++)
                T[P * n1 + k] += w[P * MAXM + q] * C[idx[P * MAXM + q] * n1 + k];
    for (long P = 0; P < n2; P++)
        for (long Q = 0; Q < n2; Q++) {
            double v = P == Q ? var[P] : 0;
            for (int q = 0; q < cnt[Q]; q++)
                v += w[Q * MAXM + q] * T[P * n1 + idx[Q * MAXM + q]];
            C2[P * n2 + Q] = v;
        }
    free(T), free(idx), free(w), free(var), free(cnt);
    return C2;
}

/* The torus ACF at lattice lag (u, v), averaged over every point. */
static double tacf(const double *C, long n, long u, long v)
{
    double s = 0;
    for (long j = 0; j < n; j++)
        for (long i = 0; i < n; i++)
            s += C[(j * n + i) * n * n + wrap(j + v, n) * n + wrap(i + u, n)];
    return s / (double)(n * n);
}

/* Anisotropy of the triangular mesh's exact ACF (map to out). */
static void tri_measure(const double *C, long n, FILE *out, double *excess, double *aniso)
{
    double axis[LAGR + 2];
    for (int u = 0; u <= LAGR + 1; u++)
        axis[u] = tacf(C, n, u, 0);
    *excess = 0, *aniso = 0;
    for (int v = -LAGR; v <= LAGR; v++)
        for (int u = -2 * LAGR; u <= 2 * LAGR; u++) {
            double x = u + v * A2X, y = v * A2Y, r = hypot(x, y), f, ax, an;
            int i = (int)r;
            if (r > LAGR || r == 0)
                continue;
            f = r - i, ax = (1 - f) * axis[i] + f * axis[i + 1];
            an = tacf(C, n, u, v) - ax;
            fprintf(out, "%.6f\t%.6f\t%.8g\n", x, y, an);
            if (fabs(an) > fabs(*aniso))
                *aniso = an;
            if (u == v && u >= 1 && u <= LAGR / 1.7320508 && fabs(an) > fabs(*excess))
                *excess = an;
        }
}

/* The triangular mesh with M nearest points: returns 0 on success. */
static int tri_run(const nl_model *m, int M, FILE *sum, FILE *map)
{
    static const double tx[3] = {0.5, 0, 0.5}, ty[3] = {0, 0.5, 0.5};
    long n = 64 >> LEVELS;
    double s = 1 << LEVELS, *C = malloc((size_t)(n * n * n * n) * sizeof *C), ex, an;
    tstencil cls[3];
    if (!C)
        return 1;
    for (long p = 0; p < n * n; p++)
        for (long q = 0; q < n * n; q++)
            C[p * n * n + q] = torus_r(m, q % n - p % n, q / n - p / n, n, s);
    for (int lv = 0; lv < LEVELS; lv++, n *= 2, s /= 2) {
        double *C2;
        for (int c = 0; c < 3; c++)
            if (make_class(m, tx[c], ty[c], M, s, &cls[c]))
                return 1;
        if (!(C2 = refine(cls, C, n)))
            return 1;
        free(C);
        C = C2;
    }
    tri_measure(C, n, map, &ex, &an);
    fprintf(sum, "triangular\t%d\t%d\t%+.4f\t%+.4f\t%.4f\n", M, cls[0].n, ex, an, tacf(C, n, 0, 0));
    fprintf(map, "\n\n");
    free(C);
    return 0;
}

/* The quadrilateral mesh, N = 1, 2 (4, 16 points), the same size and
 * levels (analysis/subdiv_exact.h), measured the same way. */
static int quad_run(const nl_model *m, int N, FILE *sum, FILE *map)
{
    enum { NL = (LAGR + 1) * (2 * LAGR + 1) };
    static long lags[2 * NL];
    static double ex[NL];
    nl_subdiv_coeffs *c;
    double excess = 0, aniso = 0;
    if (nl_subdiv_coeffs_alloc(m, 2, LEVELS, 1 << LEVELS, N, 1e-4, 8, &c))
        return 1;
    for (int x = 0; x <= LAGR; x++)
        for (int y = -LAGR; y <= LAGR; y++)
            lags[2 * (x * (2 * LAGR + 1) + y + LAGR)] = x, lags[2 * (x * (2 * LAGR + 1) + y + LAGR) + 1] = y;
    if (nl_subdiv_exact_acf(c, m, 64, 64, NL, lags, ex))
        return 1;
    for (int x = 0; x <= LAGR; x++)
        for (int y = -LAGR; y <= LAGR; y++) {
            double r = hypot(x, y), f, axis, an;
            int i = (int)r;
            if (r > LAGR || r == 0)
                continue;
            f = r - i;
            axis = i < LAGR ? (1 - f) * ex[i * (2 * LAGR + 1) + LAGR] + f * ex[(i + 1) * (2 * LAGR + 1) + LAGR]
                            : ex[LAGR * (2 * LAGR + 1) + LAGR];
            an = ex[x * (2 * LAGR + 1) + y + LAGR] - axis;
            fprintf(map, "%d\t%d\t%.8g\n%d\t%d\t%.8g\n", x, y, an, -x, -y, an);
            if (fabs(an) > fabs(aniso))
                aniso = an;
            if ((x == y || x == -y) && x >= 1 && x <= LAGR / 1.4142136 && fabs(an) > fabs(excess))
                excess = an;
        }
    fprintf(map, "\n\n");
    fprintf(sum, "quadrilateral\t%d\t%d\t%+.4f\t%+.4f\t%.4f\n", N, 4 * N * N, excess, aniso, ex[LAGR]);
    nl_subdiv_coeffs_free(c);
    return 0;
}

int main(int argc, char **argv)
{
    FILE *sum, *tmap, *qmap;
    nl_model *m;
    if (argc != 4) {
        fprintf(stderr, "usage: lewis87_trimesh SUMMARY.tsv TRIMAP.tsv QUADMAP.tsv\n");
        return 2;
    }
    if (!(sum = fopen(argv[1], "w")) || !(tmap = fopen(argv[2], "w")) || !(qmap = fopen(argv[3], "w")) ||
        nl_model_parse("markov:scale=3", &m))
        return 1;
    if (quad_run(m, 1, sum, qmap) || quad_run(m, 2, sum, qmap) || tri_run(m, 2, sum, tmap) ||
        tri_run(m, 6, sum, tmap) || tri_run(m, 16, sum, tmap))
        return 1;
    nl_model_free(m);
    fclose(sum), fclose(tmap), fclose(qmap);
    return 0;
}
