/* Experiment: conditional simulation with data between grid samples has
 * the kriging mean and variance (analysis/condsim.h).
 *
 * usage: condsim_meuse OUT.md DATA.tsv CELLS.tsv MODEL NX NY LOX LOY H K LABEL [METHODS [HOODS]]
 * DATA.tsv: x, y, value (the conditioning data, anywhere in the extent);
 * CELLS.tsv: x, y of the cells where the ensemble is checked (cell centres
 * of the NX x NY grid of spacing H whose extent starts at LOX, LOY).  For
 * each method of METHODS (default fft,circulant,subdiv) and global and
 * nmax 40 ordinary kriging, K realizations (seeds 1..K) give the ensemble
 * mean and variance (divisor K - 1) at the cells, against the kriging
 * estimate and variance there: z = (mean - est) / sqrt(var / K) (N(0, 1)
 * for an exact simulation, the realizations being independent) and the
 * ratio of the ensemble variance to the kriging variance (mean 1; each
 * cell's ratio has sd sqrt(2 / (K - 1)), the average over correlated cells
 * less).  HOODS (default 4) lists the neighbourhood sizes to compare.
 * Rows append to OUT.md.  Verdict: for hood 4, rms z <= 1.2 and the mean
 * ratio within 0.97..1.03 for every row; exit 1 otherwise. */
#include "../analysis/condsim.h"
#include "../analysis/krige.h"
#include "../analysis/krige_local.h"
#include "../core/io_points.h"
#include "../core/model.h"
#include "../core/nl_error.h"
#include "../synth/method.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static void die(const char *what)
{
    fprintf(stderr, "condsim_meuse: %s: %s\n", what, nl_errmsg());
    exit(2);
}

typedef struct {
    const nl_model *m;
    const nl_points *d, *cells;
    nl_field *f;
    double lo[2];
    size_t *cell;   /* grid index of each check cell */
    double *est, *var; /* kriging at the check cells */
    size_t K;
} setup_t;

/* Kriging estimate and variance at the check cells. */
static void kriging(setup_t *s, size_t nmax)
{
    if (nmax) {
        nl_krige_local *kl;
        nl_krige_local_options o = {.nmax = nmax, .drift = NL_DRIFT_CONSTANT};
        if (nl_krige_local_alloc(s->m, 2, s->d->n, s->d->pts, s->d->val, &o, &kl) ||
            nl_krige_local_eval(kl, s->cells->n, s->cells->pts, s->est, s->var))
            die("local kriging");
        nl_krige_local_free(kl);
        return;
    }
    nl_krige_plan *kp;
    if (nl_krige_plan_alloc(s->m, 2, s->d->n, s->d->pts, s->d->val, 0, 0, 0, &kp) ||
        nl_krige_eval_block(kp, s->cells->n, s->cells->pts, s->est, s->var))
        die("kriging");
    nl_krige_plan_free(kp);
}

/* One row: K realizations of method `name`, hood, nmax; returns 1 when the verdict fails. */
static int row(setup_t *s, FILE *md, const char *label, const char *name, size_t hood, size_t nmax)
{
    const nl_method_type *t = nl_method_find(name);
    nl_method_options mo;
    nl_method_plan *mp;
    nl_condsim_plan *cp;
    nl_condsim_info info;
    nl_method_grid g = {2, {s->f->n[0], s->f->n[1], 1}, {s->f->h[0], s->f->h[1], 1}, {0, 0}};
    size_t C = s->cells->n;
    double *s1 = calloc(C, sizeof *s1), *s2 = calloc(C, sizeof *s2), t0 = now();
    nl_method_options_default(t, &mo);
    if (nl_method_plan_alloc(t, s->m, &g, &mo, &mp))
        die(name);
    nl_condsim_options o = {.nmax = nmax, .hood = hood};
    if (nl_condsim_plan_alloc(s->m, s->d->n, s->d->pts, s->d->val, s->lo, s->f, &o, 0, NULL, &cp))
        die("condsim plan");
    double t1 = now();
    for (uint64_t k = 1; k <= s->K; k++) {
        if (nl_method_execute(mp, k, s->f) || nl_condsim_execute(cp, s->f, k, NULL))
            die("realization");
        for (size_t c = 0; c < C; c++) {
            double e = s->f->data[s->cell[c]] - s->est[c];
            s1[c] += e, s2[c] += e * e;
        }
    }
    double t2 = now(), zz = 0, rsum = 0, rmin = INFINITY, rmax = 0, Kd = (double)s->K;
    size_t used = 0;
    for (size_t c = 0; c < C; c++) {
        if (!(s->var[c] > 1e-9))
            continue;
        double mean = s1[c] / Kd, v = (s2[c] - Kd * mean * mean) / (Kd - 1), z = mean / sqrt(s->var[c] / Kd);
        double r = v / s->var[c];
        zz += z * z, rsum += r, rmin = fmin(rmin, r), rmax = fmax(rmax, r), used++;
    }
    nl_condsim_plan_info(cp, &info);
    double rms = sqrt(zz / (double)used), ratio = rsum / (double)used;
    int fail = hood == 4 && !(rms <= 1.2 && ratio >= 0.97 && ratio <= 1.03);
    fprintf(md, "| %s | %s | %zu | %s | %zu | %.3f | %.4f | %.3f..%.3f | %.3g | %.2f | %.2f | %s |\n", label, name,
            hood, nmax ? "40" : "all", s->K, rms, ratio, rmin, rmax, info.screening, t1 - t0, t2 - t1,
            fail ? "FAIL" : hood == 4 ? "pass" : "-");
    fflush(md);
    printf("%s %s hood %zu nmax %zu: rms z %.3f, variance ratio %.4f (%.3f..%.3f), screening %.3g, groups %zu "
           "(largest %zu samples), plan %.2f s, %zu realizations %.2f s\n", label, name, hood, nmax, rms, ratio, rmin,
           rmax, info.screening, info.groups, info.largest, t1 - t0, s->K, t2 - t1);
    nl_condsim_plan_free(cp), nl_method_plan_free(mp), free(s1), free(s2);
    return fail;
}

int main(int argc, char **argv)
{
    if (argc < 12) {
        fprintf(stderr, "usage: condsim_meuse OUT.md DATA.tsv CELLS.tsv MODEL NX NY LOX LOY H K LABEL [METHODS [HOODS]]\n");
        return 2;
    }
    nl_points *d, *cells;
    nl_model *m;
    if (nl_points_read(argv[2], &d) || nl_points_read(argv[3], &cells))
        die("points");
    if (nl_model_parse(argv[4], &m))
        die(argv[4]);
    size_t n[2] = {strtoul(argv[5], NULL, 10), strtoul(argv[6], NULL, 10)};
    double h = atof(argv[9]), hh[2] = {h, h};
    setup_t s = {m, d, cells, nl_field_alloc(2, n, hh, NULL), {atof(argv[7]), atof(argv[8])}, NULL, NULL, NULL,
                 strtoul(argv[10], NULL, 10)};
    const char *label = argv[11], *methods = argc > 12 ? argv[12] : "fft,circulant,subdiv";
    const char *hoods = argc > 13 ? argv[13] : "4";
    s.cell = malloc(cells->n * sizeof *s.cell), s.est = malloc(cells->n * sizeof *s.est);
    s.var = malloc(cells->n * sizeof *s.var);
    for (size_t c = 0; c < cells->n; c++) {
        size_t i = (size_t)floor((cells->pts[2 * c] - s.lo[0]) / h), j = (size_t)floor((cells->pts[2 * c + 1] - s.lo[1]) / h);
        s.cell[c] = j * n[0] + i;
    }
    FILE *md = fopen(argv[1], "a");
    if (!md)
        return 2;
    int fail = 0;
    for (size_t nmax = 0; nmax <= 40; nmax += 40) {
        kriging(&s, nmax);
        char ms[256], hs[64];
        snprintf(ms, sizeof ms, "%s", methods);
        for (char *sv, *name = strtok_r(ms, ",", &sv); name; name = strtok_r(NULL, ",", &sv)) {
            snprintf(hs, sizeof hs, "%s", hoods);
            for (char *sh, *hd = strtok_r(hs, ",", &sh); hd; hd = strtok_r(NULL, ",", &sh))
                fail |= row(&s, md, label, name, strtoul(hd, NULL, 10), nmax);
        }
    }
    fclose(md);
    nl_field_free(s.f), nl_points_free(d), nl_points_free(cells), nl_model_free(m);
    free(s.cell), free(s.est), free(s.var);
    return fail;
}
