/* noiselab synth --condition ... --at PTS.tsv -o OUT.tsv: conditional
 * realizations at the points of a table, the table's rows followed by the
 * columns sim1..simK (cli/synth_condition.c, analysis/condsim.h). */
#include "util.h"
#include "../analysis/condsim.h"
#include "../core/io_table.h"
#include "../core/nl_error.h"
#include "../synth/circulant.h"

#include <criterion/criterion.h>
#include <gsl/gsl_cdf.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The table at scratch path `name` (the test fails when it cannot be read). */
static nl_table *read_table(const char *name)
{
    char path[4096];
    nl_table *t;
    snprintf(path, sizeof path, "%s/%s", scratch_dir(), name);
    cr_assert_eq(nl_table_read(path, &t), 0, "%s", nl_errmsg());
    return t;
}

static const double *column(const nl_table *t, const char *name)
{
    long c = nl_table_column(t, name);
    cr_assert(c >= 0, "%s has no column %s", t->path, name);
    return t->cols[c];
}

/* Points on cell centres read the grid sample there: Z(at_j) = U(at_j) +
 * K[d - U(t)](at_j) with U(at_j) the sample itself and the same kriging
 * weights as the cell's, so the values agree to the rounding of the
 * outputs: the table prints 17 digits (exact), the 1D grid TSV 10
 * significant digits, a relative error of at most 5e-10 (1e-12 added for
 * the kriging sums evaluated at a point instead of a cell).  The table's
 * own columns (id, x) come back as read, and the points between centres
 * differ from both neighbours' values. */
Test(synth_at, points_on_cell_centres_are_the_grids_values)
{
    char out[256], err[4096];
    scratch_file("d.tsv", "x\tvalue\n2.3\t1.0\n5.5\t-0.5\n7.1\t0.3\n");
    /* cells of 0.125 on 0:8: centres 0.0625 + 0.125 i; rows 1, 3, 5 on centres 0, 20, 63 */
    scratch_file("p.tsv", "id\tx\n10\t0.0625\n11\t0.5\n12\t2.5625\n13\t4.00\n14\t7.9375\n");
    cr_assert_eq(run_noiselab("synth fft --acf markov:scale=1.5 --size 64 --condition d.tsv --extent 0:8 --at p.tsv "
                              "--realizations 3 --seed 5 --grid-out g.tsv -o o.tsv", out, sizeof out, err, sizeof err),
                 0, "%s", err);
    nl_table *t = read_table("o.tsv");
    cr_assert_eq(t->n, 5);
    cr_assert_str_eq(t->header, "id\tx\tsim1\tsim2\tsim3");
    cr_expect(strncmp(t->rows[3], "13\t4.00\t", 8) == 0, "the row as read, then the values: %s", t->rows[3]);
    static const size_t cell[3] = {0, 20, 63}, row[3] = {0, 2, 4};
    for (int k = 0; k < 3; k++) {
        char name[32], gname[32];
        snprintf(name, sizeof name, "sim%d", k + 1);
        snprintf(gname, sizeof gname, "g-%d.tsv", k + 1);
        const double *z = column(t, name);
        nl_table *g = read_table(gname);
        const double *v = column(g, "value");
        cr_assert_eq(g->n, 64);
        for (int i = 0; i < 3; i++)
            cr_expect(fabs(z[row[i]] - v[cell[i]]) <= 5e-10 * fabs(v[cell[i]]) + 1e-12,
                      "realization %d, cell %zu: %.17g at the point, %.17g in the grid", k + 1, cell[i], z[row[i]],
                      v[cell[i]]);
        cr_expect(z[1] != v[3] && z[1] != v[4], "x = 0.5 lies between cells 3 and 4: %.17g", z[1]);
        nl_table_free(g);
    }
    nl_table_free(t);
}

/* The same, bit for bit, in the library call behind it: a point on a cell
 * centre reads U at that sample (within NL_CONDSIM_ON_SAMPLE spacings) and
 * its kriging weights are computed as the cell's, so Z there is the grid's
 * double exactly; global and local (nmax 3) kriging, data between samples. */
Test(synth_at, points_on_cell_centres_are_the_grids_values_bit_for_bit)
{
    nl_model *m = test_model("markov:scale=0.8");
    const size_t g[2] = {20, 16};
    const double h[2] = {0.5, 0.5}, lo[2] = {0, 0};
    const double pts[] = {1.3, 2.2, 4.75, 6.1, 7.9, 1.05, 3.3, 7.6, 6.2, 4.4}, val[] = {0.4, -1.1, 0.9, 1.6, -0.2};
    const double at[] = {0.25, 0.25, 5.25, 4.75, 9.75, 7.75, 1.25, 2.25, 1.3, 2.2};
    const size_t cell[] = {0, 9 * 20 + 10, 15 * 20 + 19, 4 * 20 + 2};
    nl_field *f = nl_field_alloc(2, g, h, NULL);
    nl_synth_circulant_plan *cp;
    cr_assert_eq(nl_synth_circulant_plan_alloc(m, 2, g, h, 0, 16, &cp), 0, "%s", nl_errmsg());
    for (size_t nmax = 0; nmax <= 3; nmax += 3) {
        nl_condsim_plan *p;
        nl_condsim_options o = {.nmax = nmax};
        cr_assert_eq(nl_condsim_plan_alloc(m, 5, pts, val, lo, f, &o, 5, at, &p), 0, "%s", nl_errmsg());
        for (uint64_t s = 1; s <= 3; s++) {
            double z[5];
            cr_assert_eq(nl_synth_circulant_execute(cp, s, f), 0);
            cr_assert_eq(nl_condsim_execute(p, f, s, z), 0, "%s", nl_errmsg());
            for (int j = 0; j < 4; j++)
                cr_expect(z[j] == f->data[cell[j]], "nmax %zu, seed %d, point %d: %.17g, the cell %.17g", nmax,
                          (int)s, j + 1, z[j], f->data[cell[j]]);
            cr_expect(fabs(z[4] - val[0]) < 1e-12, "a point on datum 1: %.17g, the datum %.17g", z[4], val[0]);
        }
        nl_condsim_plan_free(p);
    }
    nl_synth_circulant_plan_free(cp), nl_field_free(f), nl_model_free(m);
}

/* Property: over K realizations the values at a point x are Gaussian with
 * the kriging estimate K[d](x) as mean and the kriging variance s2(x) as
 * variance (analysis/condsim.h), the reference being krige --at on the same
 * table.  Bands, derived: the realizations are independent (seeds S..S+K-1)
 * and exact (circulant embedding, covariance R exactly; the point between
 * two samples drawn given its 4 neighbours, exact for the 1D exponential,
 * a Markov process), so z = (mean - K[d]) / sqrt(s2 / K) ~ N(0, 1) and
 * K v / s2 ~ chi2_K, v the mean square about K[d].  m points, family-wise
 * false-alarm rate 1e-3 (Bonferroni, valid under any dependence; the 1e-3
 * split between the two tests): |z| <= Phi^-1(1 - 1e-3 / (4 m)), chi2_K
 * quantiles 1e-3 / (4 m) and 1 - 1e-3 / (4 m) (0.72 .. 1.33 for K = 400,
 * m = 12).  Power: the points lie midway between cell centres, where a
 * field read from the grid (linear interpolation of the two centres) has
 * variance 0.5 (1 + e^-2) = 0.57 of the model's far from the data
 * (markov:scale=0.125, cells of 0.25): outside the band. */
Test(synth_at, ensemble_mean_and_variance_are_kriging_at_the_points)
{
    enum { K = 400, M = 12 };
    char out[256], err[4096], buf[1024];
    scratch_file("d2.tsv", "x\tvalue\n1.1\t0.8\n2.3\t1.0\n5.55\t-0.5\n9.2\t0.3\n13.9\t1.4\n");
    size_t len = (size_t)snprintf(buf, sizeof buf, "x\n");
    for (int j = 0; j < M; j++) /* cell boundaries j + 0.25 and j + 0.5 (1.25: 0.15 from a datum) */
        len += (size_t)snprintf(buf + len, sizeof buf - len, "%.2f\n", j + (j % 2 ? 0.5 : 0.25) + 1);
    scratch_file("p2.tsv", buf);
    cr_assert_eq(run_noiselab("synth circulant --acf markov:scale=0.125 --size 64 --condition d2.tsv --extent 0:16 "
                              "--at p2.tsv --realizations 400 --seed 11 -o o2.tsv", out, sizeof out, err, sizeof err),
                 0, "%s", err);
    cr_assert_eq(run_noiselab("krige --data d2.tsv --acf markov:scale=0.125 --at p2.tsv -o k2.tsv", out, sizeof out,
                              err, sizeof err), 0, "%s", err);
    nl_table *t = read_table("o2.tsv"), *kt = read_table("k2.tsv");
    const double *est = column(kt, "estimate"), *var = column(kt, "variance"), *x = column(t, "x");
    double a = 1e-3 / (4.0 * M), zc = gsl_cdf_ugaussian_Qinv(a), clo = gsl_cdf_chisq_Pinv(a, K) / K,
           chi = gsl_cdf_chisq_Qinv(a, K) / K;
    cr_assert_eq(t->n, M);
    double zmax = 0, rlo = INFINITY, rhi = 0;
    for (size_t j = 0; j < M; j++) {
        double s1 = 0, s2 = 0;
        for (int k = 0; k < K; k++) {
            char name[32];
            snprintf(name, sizeof name, "sim%d", k + 1);
            double e = column(t, name)[j] - est[j];
            s1 += e, s2 += e * e;
        }
        double z = s1 / K / sqrt(var[j] / K), r = s2 / K / var[j];
        zmax = fmax(zmax, fabs(z)), rlo = fmin(rlo, r), rhi = fmax(rhi, r);
        cr_expect(fabs(z) <= zc, "point %zu (x = %g): ensemble mean %.3g sd of the mean from the kriging estimate "
                  "(band %.2f)", j + 1, x[j], z, zc);
        cr_expect(r >= clo && r <= chi, "point %zu (x = %g): ensemble variance / kriging variance %.3f outside "
                  "%.3f..%.3f", j + 1, x[j], r, clo, chi);
    }
    cr_log_info("K = %d, %d points: max |z| of the mean %.2f (band %.2f); variance ratio %.3f..%.3f (band "
                "%.3f..%.3f)", K, M, zmax, zc, rlo, rhi, clo, chi);
    nl_table_free(t), nl_table_free(kt);
}
