/* noiselab validate: DIR/index.md, its tables, plots and data. */
#include "validate_report.h"

#include <fcntl.h>
#include <math.h>
#include <spawn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#define NM NL_VALIDATE_METHODS
#define ND NL_VALIDATE_DIRS

static const char *const colour[NM] = {"#1f4e99", "#2e8b57", "#b22222", "#d2691e", "#8b6914"};

/* Every file of the report is written to a temporary beside its name and
 * renamed at the end of a successful run (cli_out_begin): a failure or a
 * signal removes only what this run made. */
static const char *report_tmp(const cli_validate *v, const char *name)
{
    char path[4096];
    if (snprintf(path, sizeof path, "%s/%s", v->dir, name) >= (int)sizeof path)
        cli_die(2, "-o: path too long: \"%s\"", v->dir);
    return cli_out_begin(path);
}

static void report_commit(const cli_validate *v, const char *name)
{
    char path[4096];
    snprintf(path, sizeof path, "%s/%s", v->dir, name);
    cli_out_commit(path);
}

static FILE *open_in(const cli_validate *v, const char *name)
{
    const char *tmp = report_tmp(v, name);
    FILE *fp = fopen(tmp, "w");
    if (!fp)
        cli_die(1, "-o: cannot write %s/%s", v->dir, name);
    return fp;
}

static void close_in(FILE *fp, const cli_validate *v, const char *name)
{
    if (ferror(fp) | fclose(fp))
        cli_die(1, "-o: cannot write %s/%s", v->dir, name);
    report_commit(v, name);
}

/* The folder as a gnuplot string (single quotes, a quote doubled). */
static const char *gp_dir(const cli_validate *v)
{
    static char buf[8200];
    size_t k = 0;
    for (const char *p = v->dir; *p && k + 3 < sizeof buf; p++) {
        if (*p == '\'')
            buf[k++] = '\'';
        buf[k++] = *p;
    }
    buf[k] = 0;
    return buf;
}

/* One TSV cell: the number, or "-" where there is none (no nan in files). */
static void cell(FILE *fp, int have, double x)
{
    if (have && isfinite(x))
        fprintf(fp, "\t%.8g", x);
    else
        fprintf(fp, "\t-");
}

/* Lag length of lag l along direction d, in samples. */
static double lag_length(const cli_validate *v, int d, size_t l)
{
    return (double)l * (d == NL_VALIDATE_DIAG ? sqrt((double)v->dim) : 1.0);
}

/* DIR/acf.tsv: one block per direction (gnuplot index 0, 1, ...). */
static void write_acf_tsv(const cli_validate *v)
{
    const nl_validate_result *r = &v->r;
    FILE *fp = open_in(v, "acf.tsv");
    int block = 0;
    for (int d = 0; d < ND; d++) {
        if (!r->nlag[d])
            continue;
        fprintf(fp, "%sdirection\tlag\tlength\ttarget\tsubdiv_exact", block++ ? "\n\n" : "");
        for (int meth = 0; meth < NM; meth++)
            fprintf(fp, "\t%s\t%s_se", nl_validate_method_name(meth), nl_validate_method_name(meth));
        fprintf(fp, "\n");
        for (size_t l = 0; l < r->nlag[d]; l++) {
            fprintf(fp, "%s\t%zu\t%.8g", nl_validate_dir_name(d), l, lag_length(v, d, l));
            cell(fp, 1, r->target[d][l]);
            cell(fp, r->have_exact, r->exact[d][l]);
            for (int meth = 0; meth < NM; meth++) {
                cell(fp, r->method[meth].ran, r->method[meth].mean[d][l]);
                cell(fp, r->method[meth].ran, r->method[meth].se[d][l]);
            }
            fprintf(fp, "\n");
        }
    }
    close_in(fp, v, "acf.tsv");
}

/* DIR/spectrum.tsv: one row per band, low frequencies first. */
static void write_spectrum_tsv(const cli_validate *v)
{
    const nl_validate_result *r = &v->r;
    FILE *fp = open_in(v, "spectrum.tsv");
    fprintf(fp, "band\tf_lo\tf_hi\tf_centre\texpected_periodic\texpected_fejer");
    for (int meth = 0; meth < NM; meth++)
        fprintf(fp, "\t%s_error\t%s_lo\t%s_hi", r->method[meth].name, r->method[meth].name, r->method[meth].name);
    fprintf(fp, "\n");
    for (size_t i = r->nbands; i-- > 0;) {
        double c = r->band_lo[i] > 0 ? sqrt(r->band_lo[i] * r->band_hi[i]) : r->band_hi[i] / M_SQRT2;
        fprintf(fp, "%zu\t%.8g\t%.8g\t%.8g", i, r->band_lo[i], r->band_hi[i], c);
        cell(fp, 1, r->band_periodic[i]);
        cell(fp, 1, r->band_fejer[i]);
        for (int meth = 0; meth < NM; meth++) {
            const nl_validate_method_result *m = &r->method[meth];
            cell(fp, m->ran, m->band_error[i].est);
            cell(fp, m->ran, m->band_error[i].lo);
            cell(fp, m->ran, m->band_error[i].hi);
        }
        fprintf(fp, "\n");
    }
    close_in(fp, v, "spectrum.tsv");
}

/* DIR/map.tsv (2D and 3D): the lag map's plane lz = 0, both l and its
 * mirror -l (the same estimate), as (mean - R) / R(0) per method; rows of
 * one ly, blank lines between (gnuplot's grid order).  Returns the largest
 * |error| over the methods that ran (the colour range). */
static double write_map_tsv(const cli_validate *v)
{
    const nl_validate_result *r = &v->r;
    double r0 = r->target[NL_VALIDATE_X][0], top = 0;
    long W = 0;
    FILE *fp;
    for (size_t i = 0; i < r->nmap; i++)
        W = r->map[i][0] > W ? r->map[i][0] : W;
    fp = open_in(v, "map.tsv");
    fprintf(fp, "lx\tly\ttarget");
    for (int meth = 0; meth < NM; meth++)
        fprintf(fp, "\t%s_error", r->method[meth].name);
    for (long y = -W; y <= W; y++) {
        fprintf(fp, "\n");
        for (long x = -W; x <= W; x++)
            for (size_t i = 0; i < r->nmap; i++) {
                const long *l = r->map[i];
                if (l[2] != 0 || !((l[0] == x && l[1] == y) || (l[0] == -x && l[1] == -y)))
                    continue;
                fprintf(fp, "%ld\t%ld", x, y);
                cell(fp, 1, r->map_target[i]);
                for (int meth = 0; meth < NM; meth++) {
                    double e = (r->method[meth].map_mean[i] - r->map_target[i]) / r0;
                    cell(fp, r->method[meth].ran, e);
                    if (r->method[meth].ran && isfinite(e))
                        top = fmax(top, fabs(e));
                }
                fprintf(fp, "\n");
                break;
            }
    }
    close_in(fp, v, "map.tsv");
    return top > 0 ? top : 1;
}

/* One heat map of the error over the lag map per method that ran. */
static void map_plot(FILE *fp, const cli_validate *v, double top)
{
    int np = 0, k = 0;
    for (int meth = 0; meth < NM; meth++)
        np += v->r.method[meth].ran;
    if (!np)
        return;
    fprintf(fp, "set terminal pngcairo size %d,470 font 'DejaVu Sans,10'\nset output D.'/map.png'.S\nunset logscale\n"
                "unset key\nunset grid\nset autoscale fix\nset size ratio -1\nset palette defined (-1 '#2166ac', 0 'white', 1 '#b2182b')\n"
                "set cbrange [%g:%g]\nset cblabel '(mean - R) / R(0)'\nset xlabel 'lag x (samples)'\n"
                "set ylabel 'lag y (samples)'\nset multiplot layout 1,%d title "
                "'%s, %dD: (ensemble mean - R) / R(0) over the lag map%s'\n",
            60 + 420 * np, -top, top, np, v->spec, v->dim, v->dim > 2 ? " (plane lz = 0)" : "");
    for (int meth = 0; meth < NM; meth++)
        if (v->r.method[meth].ran)
            fprintf(fp, "set title '%s'\n%splot D.'/map.tsv'.S using 1:2:%d with image\n", v->r.method[meth].name,
                    ++k == np ? "set colorbox\n" : "unset colorbox\n", 4 + meth);
    fprintf(fp, "unset multiplot\n");
}

/* One panel per direction: the ACF (kind 0) or its error over R(0) with
 * the simultaneous 95% half-width and the tolerance (kind 1). */
static void panels(FILE *fp, const cli_validate *v, int kind)
{
    const nl_validate_result *r = &v->r;
    double r0 = r->target[NL_VALIDATE_X][0];
    int np = 0, block = 0;
    for (int d = 0; d < ND; d++)
        np += r->nlag[d] > 0;
    fprintf(fp, "set multiplot layout 1,%d title '%s, %dD, %zu realizations of %zu%s%.0d: %s'\n", np, v->spec, v->dim,
            v->M, v->N, v->dim > 1 ? "^" : "", v->dim > 1 ? v->dim : 0,
            kind ? "(ensemble mean - R) / R(0), 95% simultaneous intervals" : "ensemble ACF");
    for (int d = 0; d < ND; d++) {
        if (!r->nlag[d])
            continue;
        fprintf(fp, "set title 'along %s%s'\nset xlabel '%s'\nset ylabel '%s'\nset grid\n"
                    "set key below horizontal width 1 samplen 2 height 1.5\n",
                d == NL_VALIDATE_DIAG ? "the " : "", nl_validate_dir_name(d),
                d == NL_VALIDATE_DIAG ? "lag length (sample spacings)" : "lag (samples)",
                kind ? "(ensemble mean - R) / R(0)" : "ensemble mean ACF (value^2)");
        if (kind)
            fprintf(fp, "plot %g with lines dt 2 lc rgb 'black' title 'tolerance', %g with lines dt 2 lc rgb 'black' notitle, "
                        "0 with lines lc rgb 'gray' notitle", r->tolerance, -r->tolerance);
        else
            fprintf(fp, "plot D.'/acf.tsv'.S index %d using 3:4 with lines lw 3 lc rgb 'black' title 'target'", block);
        for (int meth = 0; meth < NM; meth++)
            if (r->method[meth].ran && kind)
                fprintf(fp, ", D.'/acf.tsv'.S index %d using ($3+%g):(($%d-$4)/%g):(%g*$%d/%g) with yerrorbars pt 7 ps 0.4 "
                            "lc rgb '%s' title '%s'", block, 0.15 * (meth - 1.5), 6 + 2 * meth, r0, r->ci_factor,
                        7 + 2 * meth, r0, colour[meth], r->method[meth].name);
            else if (r->method[meth].ran)
                fprintf(fp, ", '' index %d using 3:%d:%d with yerrorlines pt 7 ps 0.4 lc rgb '%s' title '%s'", block,
                        6 + 2 * meth, 7 + 2 * meth, colour[meth], r->method[meth].name);
        if (r->have_exact)
            fprintf(fp, kind ? ", D.'/acf.tsv'.S index %d using 3:(($5-$4)/%g) with lines dt 2 lw 2 lc rgb '#b22222' title 'subdiv exact'"
                             : ", D.'/acf.tsv'.S index %d using 3:5 with lines dt 2 lw 2 lc rgb '#b22222' title 'subdiv exact'",
                    block, r0);
        fprintf(fp, "\n");
        block++;
    }
    fprintf(fp, "unset multiplot\n");
}

static void spectrum_plot(FILE *fp, const cli_validate *v)
{
    fprintf(fp, "set output D.'/spectrum.png'.S\nset title '%s, %dD: periodogram / its expectation - 1, by octave band "
                "(95%% simultaneous)'\nset xlabel 'radial frequency (cycles per sample)'\n"
                "set ylabel 'periodogram / its expectation - 1'\nset logscale x\nset grid\n"
                "set key below horizontal width 1 samplen 2 height 1.5\nset offsets 0, 0, graph 0.06, graph 0.06\n"
                "plot 0 with lines lc rgb 'gray' notitle",
            v->spec, v->dim);
    for (int meth = 0; meth < NM; meth++)
        if (v->r.method[meth].ran)
            fprintf(fp, ", D.'/spectrum.tsv'.S using ($4*%g):%d:%d:%d with yerrorbars pt 7 ps 0.6 lc rgb '%s' title '%s'",
                    pow(1.06, meth - 1.5), 7 + 3 * meth, 8 + 3 * meth, 9 + 3 * meth, colour[meth],
                    v->r.method[meth].name);
    fprintf(fp, "\n");
}

/* gnuplot on the script's temporary, without a shell, the suffix of the
 * temporaries in S (the script names its files D.'/name'.S); 1 when it
 * succeeded. */
static int run_gnuplot(const char *script, const char *suffix)
{
    extern char **environ;
    char s[64];
    char *argv[] = {"gnuplot", "-e", s, (char *)script, NULL};
    posix_spawn_file_actions_t fa;
    pid_t pid;
    int status = -1, ok;
    snprintf(s, sizeof s, "S='%s'", suffix);
    if (posix_spawn_file_actions_init(&fa))
        return 0;
    posix_spawn_file_actions_addopen(&fa, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&fa, 2, "/dev/null", O_WRONLY, 0);
    ok = posix_spawnp(&pid, "gnuplot", &fa, NULL, argv, environ) == 0;
    posix_spawn_file_actions_destroy(&fa);
    while (ok && waitpid(pid, &status, 0) < 0)
        ;
    return ok && WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

/* The gnuplot script and its plots; returns whether they were made.  The
 * plots are written by gnuplot to their temporaries and kept only when it
 * succeeds. */
static int write_plots(const cli_validate *v)
{
    static const char *const png[] = {"acf.png", "error.png", "spectrum.png", "map.png"};
    char path[4200];
    int ndir = 0, nran = 0, npng, ok;
    const char *script = report_tmp(v, "plots.gp");
    FILE *fp = fopen(script, "w");
    if (!fp)
        cli_die(1, "-o: cannot write %s/plots.gp", v->dir);
    for (int d = 0; d < ND; d++)
        ndir += v->r.nlag[d] > 0;
    for (int meth = 0; meth < NM; meth++)
        nran += v->r.method[meth].ran;
    npng = v->r.nmap && nran ? 4 : 3;
    fprintf(fp, "# the report's plots: gnuplot DIR/plots.gp where validate ran, or gnuplot -e \"D='.'\" plots.gp in DIR\n"
                "# (D: the report's folder; S: a suffix of the file names)\nif (!exists(\"D\")) D = '%s'\n"
                "if (!exists(\"S\")) S = ''\n",
            gp_dir(v));
    fprintf(fp, "set terminal pngcairo size %d,600 font 'DejaVu Sans,10'\nset datafile missing '-'\n"
                "set output D.'/acf.png'.S\n", 420 + 380 * ndir);
    panels(fp, v, 0);
    fprintf(fp, "set output D.'/error.png'.S\n");
    panels(fp, v, 1);
    fprintf(fp, "set terminal pngcairo size 900,620 font 'DejaVu Sans,11'\n");
    spectrum_plot(fp, v);
    if (v->r.nmap)
        map_plot(fp, v, write_map_tsv(v));
    close_in(fp, v, "plots.gp");
    for (int k = 0; k < npng; k++)
        report_tmp(v, png[k]);
    snprintf(path, sizeof path, "%s/plots.gp", v->dir);
    ok = run_gnuplot(script, script + strlen(path));
    for (int k = 0; ok && k < npng; k++)
        report_commit(v, png[k]);
    return ok;
}

/* "%.*g", or what an undefined (NaN) or unbounded figure means. */
static const char *figure(char *buf, size_t size, int digits, double x, const char *nan_means)
{
    if (isfinite(x))
        snprintf(buf, size, "%.*g", digits, x);
    else
        snprintf(buf, size, "%s", isnan(x) ? nan_means : x < 0 ? "unbounded below (a kink at lag 0)" : "unbounded");
    return buf;
}

static void write_model_md(FILE *fp, const cli_validate *v)
{
    const nl_check *k = &v->k;
    char b1[64], b2[64], b3[64];
    fprintf(fp, "## The model\n\n%s. Smallest sampled spectrum / largest: %s; smallest covariance eigenvalue / R(0): "
                "%s%s. Mean-square differentiable %s; R''(0) = %s; %s",
            k->positive_definite ? "**Positive definite**" : "**Not positive definite**",
            figure(b1, sizeof b1, 3, k->min_spectrum, "not computed"),
            figure(b2, sizeof b2, 3, k->min_eigenvalue, "not computed (a spectrum: model)"),
            k->isotropic ? (k->isotropic_bound_ok ? "; isotropic, above the -1/n bound" : "; isotropic, BELOW the -1/n bound") : "",
            k->differentiable_order < 0 ? "infinitely often" : k->differentiable_order == 0 ? "nowhere (rough)" : "a finite number of times",
            figure(b3, sizeof b3, 4, k->r2, "not computed (a spectrum: model)"),
            k->singular_below > 0 ? "numerically singular for subdivision below spacing" : "never numerically singular for subdivision");
    if (k->singular_below > 0)
        fprintf(fp, " %.3g", k->singular_below);
    fprintf(fp, " (`noiselab check`).\n\n");
}

static void interval_md(FILE *fp, const nl_validate_interval *i)
{
    if (isfinite(i->est))
        fprintf(fp, "%.3g [%.3g, %.3g]", i->est, i->lo, i->hi);
    else
        fprintf(fp, "-");
}

static const char *verdict_words(int verdict)
{
    return verdict == NL_VALIDATE_WITHIN ? "**within** the tolerance"
           : verdict == NL_VALIDATE_OFF  ? "**off**: beyond the tolerance"
                                         : "**unresolved**: the interval straddles the tolerance";
}

/* What each method is judged against for the exit status (nl_validate_claim). */
static void claims_md(FILE *fp, const cli_validate *v)
{
    fprintf(fp, "\nJudged for the exit status (%d), each method against its own claim:", cli_validate_status(v));
    for (int meth = 0; meth < NM; meth++) {
        const nl_validate_method_result *r = &v->r.method[meth];
        int verdict, claim = nl_validate_claim(&v->r, meth, &verdict);
        if (!r->ran)
            continue;
        if (claim == NL_VALIDATE_CLAIM_NONE)
            fprintf(fp, " %s approximate, nothing to compare at this size (reported, not judged);", r->name);
        else
            fprintf(fp, " %s %s %s;", r->name, nl_validate_verdict_name(verdict),
                    claim == NL_VALIDATE_CLAIM_MODEL ? "R (exact method)" : "its own exact expected ACF");
    }
    fprintf(fp, "\n");
}

/* The leading table: method, verdict, effect size, detectable error, time. */
static void summary_md(FILE *fp, const cli_validate *v)
{
    const nl_validate_result *res = &v->r;
    fprintf(fp, "| method | verdict | effect size [95%% CI] | detectable error | max \\|z\\| | variance ratio [95%% CI] "
                "| spectrum: largest band error [95%% CI] | time |\n|---|---|---|---|---|---|---|---|\n");
    for (int meth = 0; meth < NM; meth++) {
        const nl_validate_method_result *r = &res->method[meth];
        if (!r->ran) {
            fprintf(fp, "| %s | refused: %s | - | - | - | - | - | %.2f s |\n", r->name,
                    v->k.positive_definite ? r->why : "the model is not positive definite", r->seconds);
            continue;
        }
        fprintf(fp, "| %s | %s", r->name, verdict_words(r->verdict));
        if (cli_validate_to_resolve(res, r) > 0)
            fprintf(fp, " (about %.0f realizations would resolve it)", cli_validate_to_resolve(res, r));
        fprintf(fp, " | ");
        interval_md(fp, &r->all.effect);
        fprintf(fp, " | %.3g | %.2f%s | ", r->all.detectable, r->all.zmax, r->pass ? "" : " (detected)");
        interval_md(fp, &r->variance);
        fprintf(fp, " | ");
        interval_md(fp, &r->spectrum_error);
        fprintf(fp, " | %.2f s |\n", r->seconds);
    }
    claims_md(fp, v);
    fprintf(fp, "\nEffect size: the largest |ensemble mean ACF - R| / R(0) over all %zu lags tested, with a conservative "
                "95%% interval (each lag's mean +- %.2f se, simultaneous over the lags). Tolerance %.3g: *within* when "
                "the whole interval is at most the tolerance, *off* when all of it is above, *unresolved* otherwise. "
                "Detectable error: an error this large at any tested lag is found by the z test with about 80%% power. "
                "max |z| = |mean - R| / se against %.2f (Student's t(%zu), Bonferroni over the lags, family-wise %g). "
                "The verdict uses the model's R for every method.\n\n",
            res->ntests, res->ci_factor, res->tolerance, res->threshold, res->realizations - 1, res->alpha);
}

static void directions_md(FILE *fp, const cli_validate *v)
{
    const nl_validate_result *res = &v->r;
    fprintf(fp, "## By direction\n\n%zu realizations of %zu", res->realizations, res->n[0]);
    for (int a = 1; a < v->dim; a++)
        fprintf(fp, " x %zu", res->n[a]);
    fprintf(fp, " samples (seeds %llu..+%zu), unbiased ACF with known mean 0. Lags:", (unsigned long long)res->seed,
            res->realizations - 1);
    for (int d = 0; d < ND; d++)
        if (res->nlag[d])
            fprintf(fp, " %s 0..%zu,", nl_validate_dir_name(d), res->nlag[d] - 1);
    fprintf(fp, " and %zu lags of the map.\n\n| method | direction | effect size [95%% CI] | worst lag | detectable "
                "| max \\|z\\| |\n|---|---|---|---|---|---|\n", res->nmap);
    for (int meth = 0; meth < NM; meth++) {
        const nl_validate_method_result *r = &res->method[meth];
        for (int d = 0; d <= ND && r->ran; d++) {
            const nl_validate_effect *e = d < ND ? &r->dir[d] : &r->map;
            if ((d < ND && !res->nlag[d]) || (d == ND && !res->nmap))
                continue;
            fprintf(fp, "| %s | %s | ", r->name, d < ND ? nl_validate_dir_name(d) : "map");
            interval_md(fp, &e->effect);
            fprintf(fp, " | (%ld, %ld, %ld) | %.3g | %.2f |\n", e->worst[0], e->worst[1], e->worst[2], e->detectable,
                    e->zmax);
        }
    }
    fprintf(fp, "\n![acf](acf.png)\n\n![error](error.png)\n\n");
    if (res->nmap)
        fprintf(fp, "The lag map (map.tsv, the plane of lag z = 0 in 3D):\n\n![map](map.png)\n\n");
}

static void subdiv_md(FILE *fp, const cli_validate *v)
{
    const nl_validate_result *res = &v->r;
    const nl_validate_method_result *r = NULL;
    for (int meth = 0; meth < NM && !r; meth++) /* the method compared with its exact ACF */
        r = res->method[meth].have_exact ? &res->method[meth] : NULL;
    fprintf(fp, "## Subdivision against its own exact ACF\n\nSubdivision estimates new points from earlier levels "
                "only, so its covariance differs from R except for Markovian models in 1D. ");
    if (!res->have_exact) {
        fprintf(fp, "Its exact expected ACF is computed for grids up to 64 x 64 (2D) or 2048 (1D) with at most 4 "
                    "neighbours per side; not available here.\n\n");
        return;
    }
    fprintf(fp, "Its exact expected ACF differs from R by up to %.3g R(0) (at lag (%ld, %ld)): the method's error "
                "by construction.", res->exact_effect, res->exact_worst[0], res->exact_worst[1]);
    if (r && r->ran) {
        fprintf(fp, " The ensemble against that exact ACF: effect size ");
        interval_md(fp, &r->vs_exact.effect);
        fprintf(fp, ", max |z| %.2f (an implementation that works as designed stays within noise of it). The "
                    "verdict above is against R.", r->vs_exact.zmax);
    }
    fprintf(fp, "\n\n");
}

static void spectrum_md(FILE *fp, const cli_validate *v)
{
    const nl_validate_result *res = &v->r;
    fprintf(fp, "## Spectrum by octave band\n\nRelative error of the ensemble's mean periodogram (known mean 0) against "
                "its expectation for the method: the model's spectrum sampled on the periodic grid (fft, subdiv, sparse "
                "wrapped), or smoothed by the Fejer kernel (circulant embedding, a non-periodic field); 95%% intervals "
                "simultaneous over the bands; `-` where the expectation is below 1e-6 of the largest band. Not part of "
                "the verdict.\n\n| band (cycles/sample) |");
    for (int meth = 0; meth < NM; meth++)
        if (res->method[meth].ran)
            fprintf(fp, " %s |", res->method[meth].name);
    fprintf(fp, "\n|---|");
    for (int meth = 0; meth < NM; meth++)
        if (res->method[meth].ran)
            fprintf(fp, "---|");
    for (size_t b = res->nbands; b-- > 0;) {
        fprintf(fp, "\n| %.4g - %.4g |", res->band_lo[b], res->band_hi[b]);
        for (int meth = 0; meth < NM; meth++)
            if (res->method[meth].ran) {
                fprintf(fp, " ");
                interval_md(fp, &res->method[meth].band_error[b]);
                fprintf(fp, " |");
            }
    }
    fprintf(fp, "\n\n![spectrum](spectrum.png)\n\n");
}

void cli_validate_write(const cli_validate *v)
{
    FILE *fp;
    json_t *j = cli_validate_json(v);
    char path[4096];
    int plotted;
    write_acf_tsv(v);
    write_spectrum_tsv(v);
    plotted = write_plots(v);
    fp = open_in(v, "index.md");
    fprintf(fp, "# noiselab validate: `%s` in %dD\n\n", v->spec, v->dim);
    summary_md(fp, v);
    write_model_md(fp, v);
    directions_md(fp, v);
    subdiv_md(fp, v);
    spectrum_md(fp, v);
    if (!plotted)
        fprintf(fp, "(gnuplot failed: no plots.)\n");
    close_in(fp, v, "index.md");
    snprintf(path, sizeof path, "%s/verdict.json", v->dir);
    if (json_dump_file(j, report_tmp(v, "verdict.json"), JSON_INDENT(2) | JSON_PRESERVE_ORDER))
        cli_die(1, "-o: cannot write %s", path);
    report_commit(v, "verdict.json");
    json_decref(j);
}
