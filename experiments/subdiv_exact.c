/* Experiment: the exact covariance of subdivision fields against the target.
 *
 * usage: nl_subdiv_exact OUT.md OUT.tsv MAP.tsv CORR.tsv
 * For each model, the expected unbiased ACF (known mean 0) of a periodic
 * subdivision field, computed exactly by propagating the covariance through
 * the levels (analysis/subdiv_exact.h): the method's own error, free of
 * sampling error.  Then the diagonal bias of the 2D quadrilateral mesh for
 * the isotropic exp(-r/12): the ACF along the diagonal minus the ACF along
 * x at the same distance (linear interpolation), for N = 1..4, and for
 * N = 2 the whole map over lags |x|, |y| <= 20 (MAP.tsv: x, y, exact,
 * target, exact minus the exact x-axis profile at the same distance: the
 * anisotropy, zero for an isotropic field).  Each error is given for
 * independent and for correlated displacements (M = 2, 4, 8 taps; the
 * diagonal bias with M = 2), and CORR.tsv holds the Table 1 model's exact
 * ACF with N = 4 both ways.
 * Then Lewis's random quadrilateral neighbourhoods against the block
 * (random_table).
 * Verdict: exp(-|t|) is exact in 1D (error < 1e-10), and random
 * neighbourhoods leave at least half the block's diagonal excess (the
 * finding stated in the section); exit 1 otherwise. */
#include "../analysis/subdiv_exact.h"
#include "../core/model.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>

/* The largest |exact - R| / R(0) over lags 0..64 of a 1024-sample field in
 * 6 levels; taps > 0: correlated displacements with that many taps.  The
 * profile goes to tsv (NULL: not written). */
static double err_1d(const char *spec, double h, int N, int taps, FILE *tsv)
{
    nl_model *m;
    nl_subdiv_coeffs *c;
    long lags[2 * 65];
    double ex[65], e = 0;
    nl_model_parse(spec, &m);
    nl_subdiv_coeffs_alloc(m, 1, 6, ldexp(h, 6), N, 1e-4, 16, &c);
    if (taps)
        nl_subdiv_coeffs_correlate(c, m, taps, NL_SUBDIV_DISP_ERROR);
    for (int i = 0; i < 65; i++)
        lags[2 * i] = i, lags[2 * i + 1] = 0;
    nl_subdiv_exact_acf(c, m, 1024, 1, 65, lags, ex);
    for (int i = 0; i < 65; i++) {
        double lag = i * h, r = nl_model_acf(m, 1, &lag);
        e = fmax(e, fabs(ex[i] - r) / c->r0);
        if (tsv)
            fprintf(tsv, "%s\t%d\t%g\t%.8g\t%.8g\n", spec, N, lag, ex[i] / c->r0, r / c->r0);
    }
    if (tsv)
        fprintf(tsv, "\n\n");
    nl_subdiv_coeffs_free(c);
    nl_model_free(m);
    return e;
}

static double diag_bias(int N, int taps, double *axis_err)
{
    nl_model *m;
    nl_subdiv_coeffs *c;
    long lags[2 * 40];
    double ex[40], a = 0;
    nl_model_parse("markov:scale=12", &m);
    nl_subdiv_coeffs_alloc(m, 2, 4, 16.0, N, 1e-4, 8, &c);
    if (taps)
        nl_subdiv_coeffs_correlate(c, m, taps, NL_SUBDIV_DISP_ERROR);
    for (int k = 0; k < 20; k++)
        lags[2 * k] = k, lags[2 * k + 1] = 0, lags[2 * (20 + k)] = k, lags[2 * (20 + k) + 1] = k;
    nl_subdiv_exact_acf(c, m, 64, 64, 40, lags, ex);
    *axis_err = 0;
    for (int k = 1; k < 12; k++) {
        double d = k * sqrt(2.0), f = d - floor(d), lag[2] = {k, 0};
        int i = (int)d;
        double ax = (1 - f) * ex[i] + f * ex[i + 1];
        if (fabs(ex[20 + k] - ax) > fabs(a))
            a = ex[20 + k] - ax;
        *axis_err = fmax(*axis_err, fabs(ex[k] - nl_model_acf(m, 2, lag)));
    }
    nl_subdiv_coeffs_free(c);
    nl_model_free(m);
    return a;
}

/* The exact ACF of the N = 2 mesh over lags -L..L in x and y, in gnuplot's
 * grid format; returns the largest anisotropy (diagonal minus axis). */
static double diag_map(FILE *out)
{
    enum { L = 20, NL = (L + 1) * (2 * L + 1) };
    nl_model *m;
    nl_subdiv_coeffs *c;
    static long lags[2 * NL];
    static double ex[NL];
    double top = 0;
    nl_model_parse("markov:scale=12", &m);
    nl_subdiv_coeffs_alloc(m, 2, 4, 16.0, 2, 1e-4, 8, &c);
    for (int x = 0; x <= L; x++)
        for (int y = -L; y <= L; y++) {
            int k = x * (2 * L + 1) + (y + L);
            lags[2 * k] = x, lags[2 * k + 1] = y;
        }
    nl_subdiv_exact_acf(c, m, 64, 64, NL, lags, ex);
    fprintf(out, "# x\ty\texact\ttarget\tanisotropy\n");
    for (int x = -L; x <= L; x++) {
        for (int y = -L; y <= L; y++) {
            /* C(-x, -y) = C(x, y) */
            int ax = x < 0 ? -x : x, ay = x < 0 ? -y : y, k = ax * (2 * L + 1) + (ay + L);
            double lag[2] = {x, y}, r = hypot(x, y), an = NAN;
            if (r <= L) {
                int i = (int)r;
                double f = r - i, axis = i < L ? (1 - f) * ex[i * (2 * L + 1) + L] + f * ex[(i + 1) * (2 * L + 1) + L]
                                               : ex[L * (2 * L + 1) + L];
                an = (ex[k] - axis) / c->r0;
                if (fabs(an) > fabs(top))
                    top = an;
            }
            fprintf(out, "%d\t%d\t%.8g\t%.8g\t%.8g\n", x, y, ex[k] / c->r0, nl_model_acf(m, 2, lag) / c->r0, an);
        }
        fprintf(out, "\n");
    }
    nl_subdiv_coeffs_free(c);
    nl_model_free(m);
    return top;
}

/* The Table 1 model's exact ACF with N = 4, independent and correlated
 * (4 taps) displacements, against the target (CORR.tsv, two blocks). */
static void table1_profiles(FILE *out)
{
    fprintf(out, "model\tN\tlag\texact\ttarget\n");
    err_1d("expr:100*cos(10*t)*exp(-abs(t))", 15.0 / 1024, 4, 0, out);
    err_1d("expr:100*cos(10*t)*exp(-abs(t))", 15.0 / 1024, 4, 4, out);
}

static void error_table(FILE *md, FILE *tsv, double *emk)
{
    static const struct {
        const char *spec;
        double h;
    } models[] = {{"markov:scale=8", 1},
                  {"markaussian:alpha=1.4,scale=8", 1},
                  {"expr:100*cos(10*t)*exp(-abs(t))", 15.0 / 1024},
                  {"gauss-osc:omega=10", 0.01171875}};
    fprintf(md, "| model | N = 2 | correlated M = 2 | M = 4 | M = 8 | N = 4 | correlated M = 2 | M = 4 | M = 8 "
                "| gain N = 4, M = 4 |\n|---|---|---|---|---|---|---|---|---|---|\n");
    for (size_t i = 0; i < sizeof models / sizeof *models; i++) {
        double e[2][4];
        for (int n = 0; n < 2; n++)
            for (int t = 0; t < 4; t++)
                e[n][t] = err_1d(models[i].spec, models[i].h, 2 + 2 * n, t ? 1 << t : 0, t ? NULL : tsv);
        if (i == 0)
            *emk = e[0][0];
        fprintf(md, "| `%s` (spacing %g) ", models[i].spec, models[i].h);
        for (int n = 0; n < 2; n++)
            for (int t = 0; t < 4; t++)
                fprintf(md, "| %.2g ", e[n][t]);
        fprintf(md, "| %.0fx |\n", e[1][2] > 0 ? e[1][0] / e[1][2] : 0.0);
    }
}

/* Lewis's "random quadrilateral" remedy (nl_subdiv_coeffs_randomize, as
 * synth subdiv --random-neighborhoods K): exp(-r/3), 64x64 from a 4x4
 * coarse grid of spacing 16 (R = 0.005 there: nearly white, so the torus
 * adds no anisotropy of its own) in 4 levels, N = 2, the exact ACF averaged
 * over the random choice.  k = 0: the standard 4x4 block.  *bias: the
 * largest diagonal-minus-axis excess over distances k sqrt 2, k = 1..7;
 * *aniso: the largest |ACF - its x-axis profile at the same distance| over
 * every lag within distance 10; *var: the variance (R(0) = 1). */
static void random_quad(int k, uint64_t seed, double *bias, double *aniso, double *var)
{
    enum { L = 10, NL = (L + 1) * (2 * L + 1) };
    nl_model *m;
    nl_subdiv_coeffs *c;
    static long lags[2 * NL];
    static double ex[NL];
    nl_model_parse("markov:scale=3", &m);
    nl_subdiv_coeffs_alloc(m, 2, 4, 16.0, 2, 1e-4, 8, &c);
    if (k)
        nl_subdiv_coeffs_randomize(c, m, k, seed);
    for (int x = 0; x <= L; x++)
        for (int y = -L; y <= L; y++)
            lags[2 * (x * (2 * L + 1) + y + L)] = x, lags[2 * (x * (2 * L + 1) + y + L) + 1] = y;
    nl_subdiv_exact_acf(c, m, 64, 64, NL, lags, ex);
    *bias = 0, *aniso = 0, *var = ex[L];
    for (int x = 0; x <= L; x++)
        for (int y = -L; y <= L; y++) {
            double r = hypot(x, y), f, axis, an;
            int i = (int)r;
            if (r > L || r == 0)
                continue;
            f = r - i;
            axis = i < L ? (1 - f) * ex[i * (2 * L + 1) + L] + f * ex[(i + 1) * (2 * L + 1) + L] : ex[L * (2 * L + 1) + L];
            an = ex[x * (2 * L + 1) + y + L] - axis;
            if (fabs(an) > fabs(*aniso))
                *aniso = an;
            if ((x == y || x == -y) && x >= 1 && x <= 7 && fabs(an) > fabs(*bias))
                *bias = an;
        }
    nl_subdiv_coeffs_free(c);
    nl_model_free(m);
}

/* The random-quadrilateral rows of the diagonal-bias section.  Returns 1
 * when the finding stated holds: no row with K >= 4 cuts the diagonal
 * excess below half the block's (the remedy would, if the excess came from
 * the block's shape); 0 otherwise. */
static int random_table(FILE *md)
{
    static const struct {
        int k;
        uint64_t seed;
    } rows[] = {{0, 1}, {1, 1}, {4, 1}, {16, 1}, {16, 2}};
    double b0 = 0, bmin = INFINITY;
    fprintf(md, "\n### Random quadrilateral neighbourhoods (Lewis's remedy, measured)\n\n"
                "> The author has employed a \"random quadrilateral\" subdivision scheme, in which several random "
                "neighborhoods are preselected using a non-biased random walk from the nearest neighbors of the "
                "point to be estimated, and one of these neighborhoods is chosen at random for each estimation.\n\n"
                "exp(-r/3), N = 2 (16 points), a 64x64 periodic field refined in 4 levels from a 4x4 coarse grid "
                "of spacing 16 (R = 0.005 there: the levels refine through the whole correlation scale, and "
                "the torus adds no anisotropy of its own; on the two coarsest levels the random neighbourhoods "
                "wrap on the 4- and 8-point grids, where `synth subdiv --random-neighborhoods` would refuse so "
                "small a field, but their coefficients there are small), its exact ACF averaged over the random "
                "choice "
                "(analysis/subdiv_exact.c: a new point enters every covariance through the mean of its "
                "alternatives and its own variance through their second moment; tests/test_lewis87.c). "
                "\"Diagonal excess\": the largest ACF along the diagonal minus the x-axis ACF at the same "
                "distance (the paper's bias, 0 if isotropic); \"anisotropy\": the same over every direction "
                "within distance 10. The triangular mesh on the same field is in the next section.\n\n| neighbourhoods | plan seed | diagonal excess | anisotropy (any "
                "direction) | variance |\n|---|---|---|---|---|\n");
    for (size_t i = 0; i < sizeof rows / sizeof *rows; i++) {
        double b, a, v;
        random_quad(rows[i].k, rows[i].seed, &b, &a, &v);
        if (rows[i].k == 0)
            b0 = b;
        if (rows[i].k >= 4)
            bmin = fmin(bmin, fabs(b));
        if (rows[i].k)
            fprintf(md, "| K = %d random | %llu | %+.4f | %+.4f | %.4f |\n", rows[i].k,
                    (unsigned long long)rows[i].seed, b, a, v);
        else
            fprintf(md, "| the 4x4 block | - | %+.4f | %+.4f | %.4f |\n", b, a, v);
    }
    fprintf(md, "\nVerdict %s: the remedy does not remove the diagonal excess here; the smallest |excess| with "
                "K >= 4 random neighbourhoods is %.4f against the block's %.4f, and another plan seed moves it "
                "either way (the verdict fails if any K >= 4 row cuts it below half the block's, i.e. if the "
                "remedy worked). The reason is the one the table above gives for growing N: this excess does "
                "not come from the block's square support, which random neighbourhoods break, but from the "
                "independent displacements of neighbouring new points, which they keep. A single random "
                "neighbourhood per class (K = 1) trades the diagonal bias for one along its own walk "
                "(anisotropy column).\n\n",
            bmin >= 0.5 * fabs(b0) ? "**pass**" : "**FAIL**", bmin, fabs(b0));
    return bmin >= 0.5 * fabs(b0);
}

int main(int argc, char **argv)
{
    FILE *md, *tsv, *map, *corr;
    double emk = 1, top;
    int remedy;
    if (argc != 5 || !(md = fopen(argv[1], "w")) || !(tsv = fopen(argv[2], "w")) || !(map = fopen(argv[3], "w")) ||
        !(corr = fopen(argv[4], "w")))
        return 2;
    fprintf(tsv, "model\tN\tlag\texact\ttarget\n");
    fprintf(md, "## The method's own error: exact covariance of subdivision fields, and the diagonal bias\n\n"
                "Not a figure of the papers. Lewis's construction estimates each new point from earlier levels "
                "only; new points of one level get independent displacements although their estimation errors "
                "are correlated, so the field's covariance differs from R (eq. (5) holds only for lags to the "
                "point's own neighbourhood). The expected ACF of a periodic 1024-sample field made in 6 levels "
                "is computed exactly by propagating the covariance through the levels; the ensemble tests in "
                "`tests/test_subdiv_stat.c` confirm the synthesis matches it.\n\n"
                "![exact](subdiv-exact.png)\n\n"
                "Correlated displacements (`--displacements correlated --taps M`) draw the new points of a level "
                "together, with the covariance of their estimation errors, through a filter of M taps either "
                "side (synth/subdiv_disp.c). The largest |exact − R| / R(0) over lags 0..64:\n\n");
    error_table(md, tsv, &emk);
    table1_profiles(corr);
    fclose(corr);
    fprintf(md, "\n![correlated](subdiv-corr.png)\n\nThe Table 1 model with N = 4: independent displacements "
                "(left) against correlated ones with 4 taps (right). What remains with correlated "
                "displacements is the part of the error that comes from the finite neighbourhood: new points "
                "correlate with old points outside their own neighbourhood, which no choice of displacements "
                "independent of the old points can reproduce; it shrinks with N (the N = 2 and N = 4 columns).\n\n");
    fprintf(md, "Diagonal bias of the 2D quadrilateral mesh (isotropic exp(-r/12), 64x64, 4 levels): the "
                "exact ACF along the diagonal minus that along x at the same distance (0 for an isotropic "
                "field), and the largest error along x, with independent and correlated (M = 2) "
                "displacements:\n\n| N | diagonal − axis | axis error | correlated: diagonal − axis | axis error "
                "|\n|---|---|---|---|---|\n");
    for (int N = 1; N <= 4; N++) {
        double ae, ac, d = diag_bias(N, 0, &ae), dc = diag_bias(N, 2, &ac);
        fprintf(md, "| %d | %+.4f | %.4f | %+.4f | %.4f |\n", N, d, ae, dc, ac);
    }
    top = diag_map(map);
    fclose(map);
    fprintf(md, "\n![diagonal bias](subdiv-diagonal.png)\n\nThe map for N = 2 (left: contours of the exact ACF, "
                "solid, against the isotropic target, dashed; right: the exact ACF minus its own x-axis profile "
                "at the same distance, which an isotropic field would make zero everywhere): the mesh's ACF "
                "is not isotropic; the largest departure is %+.4f R(0).\n",
            top);
    fprintf(md, "\nVerdict: exp(-|t|) is exact in 1D (max error %.1e, bound 1e-10): %s. The other models keep "
                "an error that a larger neighbourhood removes only in part, or not at all (table above): it "
                "comes mostly from the independent displacements of sibling points, not from truncating the "
                "neighbourhood. Likewise the "
                "diagonal excess of the 2D mesh is a few thousandths and does not shrink with N, so the "
                "paper's remedy (a larger neighbourhood) does not apply to it; the larger error is the loss "
                "of variance along the axes, shared by the separable model.\n\n",
            emk, emk < 1e-10 ? "pass" : "FAIL");
    remedy = random_table(md);
    fclose(md);
    fclose(tsv);
    printf("subdiv exact: markov error %.1e, random quadrilaterals finding %s\n", emk, remedy ? "pass" : "FAIL");
    return emk < 1e-10 && remedy ? 0 : 1;
}
