/* noiselab fit: fit a covariance model to scattered data or a field. */
#include "cli.h"
#include "opt.h"
#include "drift_terms.h"
#include "../analysis/fit.h"
#include "../analysis/variogram.h"
#include "../core/family.h"
#include "../core/model.h"
#include "../core/io_points.h"
#include "../core/io_table.h"
#include "../core/nl_error.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static const char help_usage[] =
    "usage: noiselab fit DATA.tsv|FIELD.exr --model FAMILY|SPEC [--nugget] [--fix NAME=VALUE]...\n"
    "                    [--method wls|ml|reml] [--drift TERMS]\n"
    "                    [--weights distance|pairs|reweighted|ols|cressie|7|1|2|6]\n"
    "                    [--width W] [--cutoff C] [--bins gstat|floor] [--json]\n"
    "       noiselab fit --variogram VARIO.tsv --model FAMILY|SPEC [...] [--weights ...]\n\n";

/* The first paragraph continues the sentence print_help makes; filled
 * with it to 80 columns. */
static const char help[] =
    "noiselab variogram, gstat's binning; --width, --cutoff, --bins), weights N/h^2 (distance, the "
    "default, gstat's default fit.method 7), N (pairs, fit.method 1), N/gamma^2 of the fitted model "
    "(reweighted: the weights held at the last fit and refitted to a fixed point, gstat's fit.method 2; "
    "cressie: Cressie's criterion) or none (ols, fit.method 6); --weights takes gstat's fit.method "
    "numbers 7, 1, 2, 6 too.  --variogram VARIO.tsv fits a variogram table instead of data (wls alone): "
    "the columns distance, gamma, pairs of noiselab variogram -o, or gstat's np, dist, gamma (any order; "
    "bins with 0 pairs, a negative gamma or a distance not above 0 are refused); its model is checked "
    "as in 2D.  "
    "--drift TERMS, krige's terms (comma-separated constant, linear, quadratic, x,y or names of covariate "
    "columns of DATA.tsv, read with x, y, value and any other columns: --drift sdist is gstat's "
    "log(zinc) ~ sqrt(dist) with a column sdist): wls fits the variogram of the drift's least-squares "
    "residuals (gstat's variogram(value ~ sdist), noiselab variogram --drift), ml and reml estimate the "
    "drift's coefficients by generalised least squares with the model.  "
    "ml, reml: the Gaussian likelihood of the data with an unknown mean (the drift; "
    "reml: Harville's restricted likelihood), O(n^3) per step "
    "(refused above a work budget: below), started from the wls fit (cressie weights unless --weights is "
    "given), searched over a box (scales up to 10 "
    "times the largest distance) by a profile grid over the scale and local optimisations until the "
    "projected gradient is small; a scale or variance that runs to the box's edge is \"at bound\" and the "
    "fit NOT converged.  Prints the fitted model as a spec for --acf, "
    "standard errors, the objective and AIC (compare models fitted by one method to one data set: "
    "lower is better).  ml and reml also print each free parameter's 95% profile-likelihood interval "
    "(the values within 3.841 of the minimum -2 log likelihood, the others re-optimised; \"unbounded\" "
    "when the data set no upper limit).  --json keys: model, parameters, standard_errors, objective, "
    "aic, method, n, converged, iterations, status (per parameter: ok, fixed, at bound, or not "
    "identifiable (singular information)), flags (singular-information, at-bound, not-converged), rcond "
    "(the information matrix's reciprocal condition number), and for ml and reml mean, intervals "
    "([lower, upper] per free parameter, upper null when unbounded), drift ([{term, value, se}]: 1, u, v, "
    "u^2, uv, v^2 in the coordinates centred on and scaled by the bounding box, then the covariates by "
    "column name; the text prints them as drift TERM lines), starts, restarts and "
    "gradient.";

static const char help_errors[] =
    "Standard errors: ml and reml's describe the spread of the estimates for\n"
    "regular models (markov with a nugget); the spherical range's understate it by\n"
    "about 2x (its likelihood is not smooth in the range): quote the profile\n"
    "intervals, which need no curvature (experiments/fit_coverage.c measures both).\n"
    "wls's treat correlated variogram bins as independent and understate the spread.\n"
    "A parameter the data cannot resolve (the information matrix singular in its\n"
    "direction: reciprocal condition number below %.2g) is \"not identifiable\",\n"
    "one that ends at an end of its fit range (above) or a nugget at 0 \"at bound\":\n"
    "neither has a standard error (null in JSON).  Two data at one place need\n"
    "--nugget; data without variation are refused.  ml and reml refuse more than\n"
    "%.2g operations of work (n^3/3 per likelihood evaluation: about 1000 data with\n"
    "a nugget; the message gives the most): fit the variogram (wls) or a subsample.\n";

/* "; fit ranges: FAMILY's NAME LO to HI, ..." from the registry. */
static void fit_ranges(char *buf, size_t size)
{
    size_t len = 0;
    for (size_t i = 0; i < nl_family_count(); i++) {
        const nl_family *f = nl_family_get(i);
        for (size_t k = 0; (f->flags & NL_FAMILY_FIT) && k < f->nparams && len < size; k++)
            if (f->params[k].fit_hi > 0)
                len += (size_t)snprintf(buf + len, size - len, "%s%s's %s %g to %g", len ? ", " : "; fit ranges: ",
                                        f->name, f->params[k].name, f->params[k].fit_lo, f->params[k].fit_hi);
    }
}

/* The usage, then the families `fit` accepts and their shape parameters,
 * from the registry, then the rest. */
static void print_help(void)
{
    char families[512], shapes[512] = "", text[6144];
    size_t len = 0;
    nl_family_names(NL_FAMILY_FIT, 0, ", ", families, sizeof families);
    for (size_t i = 0; i < nl_family_count(); i++) {
        const nl_family *f = nl_family_get(i);
        for (size_t k = 0; (f->flags & NL_FAMILY_FIT) && k < f->nparams; k++) {
            const char *name = f->params[k].name;
            char word[40];
            snprintf(word, sizeof word, "%s,", name);
            if (f->params[k].role == NL_ROLE_SHAPE && !strstr(shapes, word) && len < sizeof shapes)
                len += (size_t)snprintf(shapes + len, sizeof shapes - len, "%s%s", len ? " " : "", word);
        }
    }
    if (len)
        shapes[len - 1] = 0;  /* the last comma */
    fit_ranges(shapes + strlen(shapes), sizeof shapes - strlen(shapes));
    snprintf(text, sizeof text, "Fits a model family (%s) to data: its var, scale (the spherical model's range), "
             "the nugget with --nugget, and its shape parameters (%s), each unless fixed by --fix.  A SPEC with values "
             "(spherical:var=0.59,scale=897,nugget=0.05) starts the fit there, as gstat's vgm; a nested SPEC "
             "(spherical:var=0.5,scale=12,nugget=0.1 + markov:var=0.6,scale=40, or spherical + markov) fits every "
             "structure's parameters, named NAME.I for structure I from 1 (var.2, scale.1; --fix scale.2=40), "
             "--nugget adding one to structure 1.  wls (default): "
             "weighted least squares on the empirical variogram (as %s", families, shapes, help);
    fputs(help_usage, stdout);
    cli_fill(stdout, text, 80);
    printf(help_errors, NL_FIT_RCOND_MIN, NL_FIT_ML_WORK_MAX);
}

/* The command's options. */
typedef struct {
    const char *in;             /* input */
    const char *vario;          /* --variogram: a variogram table to fit (no data) */
    int weights_given;          /* --weights given */
    int json;                   /* --json */
    int method;                 /* 0 wls, 1 ml, 2 reml */
    const char *drift;          /* --drift TERMS as given, or NULL */
    cli_drift terms;            /* its terms */
    double *cov;                /* the covariates of --drift at the data (n x terms.ncov), or NULL */
    int dim;                    /* the data's dimension */
    nl_fit_options o;           /* the library's options */
    nl_variogram_options vo;    /* binning */
    char names[NL_FIT_MAX_FIX][32]; /* --fix names */
} opts_t;

static void parse_fix(void *obj, const char *label, const char *s)
{
    opts_t *a = obj;
    const char *eq = strchr(s, '=');
    size_t k = a->o.nfix;
    if (!eq || eq == s || (size_t)(eq - s) >= sizeof a->names[0])
        cli_die(2, "%s: expected NAME=VALUE, got \"%s\"", label, s);
    if (k >= NL_FIT_MAX_FIX)
        cli_die(2, "%s: expected at most %d, got \"%s\" beyond them", label, NL_FIT_MAX_FIX, s);
    memcpy(a->names[k], s, (size_t)(eq - s));
    a->names[k][eq - s] = 0;
    for (size_t j = 0; j < k; j++)
        if (!strcmp(a->names[j], a->names[k]))
            cli_die(2, "%s: %s given twice (\"%s\"); expected each parameter fixed once", label, a->names[k], s);
    a->o.fix_name[k] = a->names[k];
    a->o.fix_value[k] = cli_parse_double(label, eq + 1);
    a->o.nfix++;
}

static const char *const methods[] = {"wls", "ml", "reml", NULL};
/* --weights: the names, then gstat's fit.method numbers */
static const char *const weights[] = {"cressie", "pairs", "reweighted", "distance", "ols", "1", "2", "6", "7", NULL};
static const int weight_vals[] = {NL_FIT_CRESSIE, NL_FIT_PAIRS, NL_FIT_REWEIGHTED, NL_FIT_DISTANCE, NL_FIT_OLS,
                                  NL_FIT_PAIRS,   NL_FIT_REWEIGHTED, NL_FIT_OLS, NL_FIT_DISTANCE};

static const cli_opt rows[] = {
    CLI_STRING("model", opts_t, o.family), CLI_FLAG("nugget", opts_t, o.nugget),
    CLI_CALL("fix", parse_fix, .flags = CLI_REPEAT),
    CLI_CHOICE("method", opts_t, method, .choices = methods),
    CLI_STRING("drift", opts_t, drift),
    CLI_CHOICE("weights", opts_t, o.weights, CLI_GIVEN(opts_t, weights_given), .choices = weights,
               .vals = weight_vals), CLI_OPT_BINS(opts_t, vo),
    CLI_STRING("variogram", opts_t, vario),
    CLI_OPT_JSON(opts_t, json), {0}};

/* --variogram: the table is the input; the data's options do not apply. */
static void parse_vario(opts_t *a, int argc)
{
    if (optind != argc)
        cli_die(2, "--variogram: expected no data operand with a variogram table, got %d", argc - optind);
    if (a->method)
        cli_die(2, "--method: expected wls with --variogram (a likelihood needs the data), got %s",
                a->method == 2 ? "reml" : "ml");
    if (a->drift)
        cli_die(2, "--drift: expected no drift with --variogram (the table's bins are fitted as they are)");
    if (a->vo.width > 0 || a->vo.cutoff > 0 || a->vo.bins)
        cli_die(2, "--variogram: expected no --width, --cutoff or --bins (the table's bins are fitted as they are)");
    a->in = a->vario;
}

static void parse(int argc, char **argv, opts_t *a)
{
    nl_variogram_options_default(&a->vo);
    a->o.weights = NL_FIT_DISTANCE; /* gstat's default */
    if (cli_opt_parse("fit", NULL, rows, a, argc, argv)) {
        print_help();
        exit(0);
    }
    if (a->vario)
        parse_vario(a, argc);
    else
        a->in = cli_one_operand("fit", "input (points .tsv or field .exr)", argc, argv);
    if (!a->o.family)
        cli_die(2, "--model: expected a family such as markov or spherical, or a nested spec, got none");
    a->o.likelihood = a->method == 2 ? NL_FIT_REML : NL_FIT_ML;
    /* ml, reml start from Cressie's wls fit unless --weights says: its
     * relative residuals keep the start near the data's sill where N/h^2
     * can run off on degenerate data (tests/bad/fit_hostile.cases) */
    if (a->method && !a->weights_given)
        a->o.weights = NL_FIT_CRESSIE;
    if (a->drift)
        cli_drift_parse(a->drift, "the data", &a->terms);
    if (a->terms.ncov && !cli_has_ext(a->in, ".tsv"))
        cli_die(2, "--drift: covariates (\"%s\") are columns of a points table; expected DATA.tsv, got \"%s\"",
                a->terms.cov[0], a->in);
}

/* The data with --drift: a table (core/io_table.h) of x [y [z]], value,
 * the covariates' columns and any others. */
static nl_points *read_table(opts_t *a)
{
    nl_table *t;
    nl_points *p = cli_malloc(sizeof *p);
    int st;
    if ((st = nl_table_read(a->in, &t)) || (st = nl_table_points(t, "value", &p->dim, &p->pts, &p->val)))
        cli_die(nl_error_is_input(st) ? 2 : 1, "%s", nl_errmsg());
    p->n = t->n;
    a->cov = cli_drift_columns(t, a->terms.ncov, a->terms.cov);
    nl_table_free(t);
    return p;
}

/* The data as points: a TSV as read, a field as its samples at i * h. */
static nl_points *read_points(opts_t *a)
{
    const char *path = a->in;
    nl_points *p;
    int st;
    if (a->drift && cli_has_ext(path, ".tsv"))
        return read_table(a);
    if (cli_has_ext(path, ".tsv")) {
        if ((st = nl_points_read(path, &p)))
            cli_die(nl_error_is_input(st) ? 2 : 1, "%s", nl_errmsg());
        return p;
    }
    nl_field *f = cli_read_field(path, NULL);
    p = calloc(1, sizeof *p);
    if (!p || !(p->pts = malloc(f->count * (size_t)f->dim * sizeof(double))) ||
        !(p->val = malloc(f->count * sizeof(double))))
        cli_die(1, "out of memory for %zu samples", f->count);
    p->dim = f->dim;
    p->n = f->count;
    for (size_t i = 0; i < f->count; i++) {
        size_t r = i;
        for (int a = 0; a < f->dim; a++) {
            p->pts[i * (size_t)f->dim + (size_t)a] = (double)(r % f->n[a]) * f->h[a];
            r /= f->n[a];
        }
        p->val[i] = f->data[i];
    }
    nl_field_free(f);
    return p;
}

/* wls: the fit to the variogram of the data, of the drift's OLS residuals
 * with --drift.  ml, reml: the likelihood's fit started from the wls fit
 * to the data's variogram (a constant mean, as the Python package's fit
 * starts, so that the two give one optimum to the last digit). */
static int fit(const opts_t *a, const nl_points *p, nl_fit_result *r)
{
    nl_variogram *v;
    nl_variogram_options vo = a->vo;
    int st = nl_fit_check_options(&a->o, p->dim);
    vo.drift = a->method ? NL_VARIOGRAM_DRIFT_CONSTANT : a->o.drift;
    if (!st)
        st = nl_variogram_points_design(p, a->cov, a->method ? 0 : a->terms.ncov, &vo, &v);
    if (st)
        return st;
    st = nl_fit_variogram(v->distance, v->gamma, v->pairs, v->nbins, p->dim, &a->o, r);
    nl_variogram_free(v);
    if (!st && a->method) {
        nl_fit_options ml = a->o;
        double *start = cli_malloc(r->np * sizeof *start);
        for (size_t k = 0; k < r->np; k++)
            start[k] = r->param[k].value;
        nl_fit_result_free(r);
        ml.start = start;
        ml.intervals = NL_FIT_INTERVALS_ALL;
        cli_phase("fit", a->method == 2 ? "restricted maximum likelihood" : "maximum likelihood");
        st = nl_fit_ml_design(p->pts, p->val, p->n, p->dim, a->cov, a->terms.ncov, &ml, r);
        cli_progress_done();
        free(start);
    }
    return st;
}

/* --variogram: WLS on the table's bins, the model checked in 2D (gstat's
 * variograms are of 2D data, and the table does not say). */
static int fit_table(const opts_t *a, nl_fit_result *r)
{
    nl_variogram *v;
    int st = nl_fit_check_options(&a->o, 2);
    if (!st)
        st = nl_variogram_read(a->vario, &v);
    if (st)
        return st;
    st = nl_fit_variogram(v->distance, v->gamma, v->pairs, v->nbins, 2, &a->o, r);
    nl_variogram_free(v);
    return st;
}

/* The name of drift term k, in the order of analysis/fit.h's Drift: the
 * polynomial's (coordinates u, v, w centred on and scaled by the bounding
 * box), then the covariates' column names. */
static const char *drift_term(const opts_t *a, size_t k, char *buf, size_t size)
{
    static const char ax[] = "uvw";
    int dim = a->dim;
    size_t t = 1, npoly = a->o.drift == NL_DRIFT_NONE ? 0 : a->o.drift == NL_DRIFT_CONSTANT ? 1
                       : a->o.drift == NL_DRIFT_LINEAR ? 1 + (size_t)dim : 1 + (size_t)dim * (size_t)(dim + 3) / 2;
    if (k >= npoly && k - npoly < a->terms.ncov)
        return snprintf(buf, size, "%s", a->terms.cov[k - npoly]), buf;
    if (k == 0)
        return snprintf(buf, size, "1"), buf;
    for (int i = 0; i < dim; i++, t++)
        if (k == t)
            return snprintf(buf, size, "%c", ax[i]), buf;
    for (int i = 0; i < dim; i++)
        for (int j = i; j < dim; j++, t++)
            if (k == t) {
                if (i == j)
                    snprintf(buf, size, "%c^2", ax[i]);
                else
                    snprintf(buf, size, "%c%c", ax[i], ax[j]);
                return buf;
            }
    return snprintf(buf, size, "c%zu", k + 1), buf;
}

/* An interval's end for the text output ("unbounded" for +infinity). */
static const char *end_text(double v, char *buf, size_t size)
{
    if (isfinite(v))
        snprintf(buf, size, "%.4g", v);
    else
        snprintf(buf, size, "unbounded");
    return buf;
}

/* A parameter's status word for JSON and the notes below the table. */
static const char *status_word(const nl_fit_param *q)
{
    if (q->fixed)
        return "fixed";
    if (q->flags & NL_FIT_PARAM_AT_BOUND)
        return "at bound";
    return q->flags & NL_FIT_PARAM_SINGULAR ? "not identifiable (singular information)" : "ok";
}

/* The fit range of a shape parameter, from the registry (0, 0: none);
 * NAME.I of a nested model: structure I's family. */
static void fit_range(const char *family, const char *name, double *lo, double *hi)
{
    const nl_family *f = nl_family_find(family, strlen(family));
    const char *dot = strchr(name, '.');
    char key[32];
    nl_model *m = NULL;
    int k;
    snprintf(key, sizeof key, "%.*s", (int)(dot ? (size_t)(dot - name) : strlen(name)), name);
    if (!f && nl_model_parse(family, &m) == NL_OK) {
        const nl_model *s = nl_model_structure(m, dot ? strtoul(dot + 1, NULL, 10) - 1 : 0);
        f = s ? nl_model_family(s) : NULL;
    }
    k = f ? nl_family_param_index(f, key) : -1;
    *lo = k >= 0 ? f->params[k].fit_lo : 0;
    *hi = k >= 0 ? f->params[k].fit_hi : 0;
    nl_model_free(m);
}

/* Is name the nugget (nugget, or nugget.I of a nested model)? */
static int is_nugget(const char *name) { return strncmp(name, "nugget", 6) == 0 && (!name[6] || name[6] == '.'); }

/* Notes on flagged parameters: which, and why there are no numbers. */
static void print_status(const opts_t *a, const nl_fit_result *r)
{
    char names[128] = "";
    for (size_t k = 0; k < r->np; k++) {
        const nl_fit_param *q = &r->param[k];
        double lo, hi;
        if (q->flags & NL_FIT_PARAM_SINGULAR)
            snprintf(names + strlen(names), sizeof names - strlen(names), "%s%s", *names ? ", " : "", q->name);
        else if ((q->flags & NL_FIT_PARAM_AT_BOUND) && is_nugget(q->name))
            printf("at bound    %s = %.3g: at 0 (below %.2g var: no nugget in the data)\n", q->name, q->value,
                   NL_FIT_RCOND_MIN);
        else if (q->flags & NL_FIT_PARAM_AT_BOUND) {
            fit_range(a->o.family, q->name, &lo, &hi);
            if (!(hi > 0)) {
                printf("at bound    %s = %g: at the edge of the search box (scales from a tenth of the smallest "
                       "to %g times the largest distance between data, variances up to %g times the sample "
                       "variance): the likelihood still rises beyond it, no optimum inside\n", q->name, q->value,
                       NL_FIT_SCALE_REACH, NL_FIT_VAR_REACH);
                continue;
            }
            printf("at bound    %s = %g: at an end of its fit range %g to %g (the data ask for a value beyond)\n",
                   q->name, q->value, lo, hi);
        }
    }
    if (*names)
        printf("not identifiable  %s: the information matrix is singular in their direction (reciprocal condition "
               "number %.2g, below %.2g%s): no standard error or interval\n", names, r->rcond, NL_FIT_RCOND_MIN,
               r->rcond > 0 ? "" : "; 0: not positive definite, or the likelihood undefined a step away");
}

static void print_text(const opts_t *a, const nl_fit_result *r)
{
    static const char *const mname[] = {"wls", "ml", "reml"};
    static const char *const wname[] = {" (cressie weights)", " (pairs weights)", " (reweighted weights)",
                                        " (distance weights)", " (ols weights)"};
    printf("model       %s\n", r->spec);
    printf("method      %s%s on %zu %s, %s after %d steps", mname[a->method], a->method ? "" : wname[a->o.weights],
           r->nobs, a->method ? "data"
           : a->o.drift != NL_DRIFT_CONSTANT || a->terms.ncov ? "variogram bins of the drift's residuals"
                                                               : "variogram bins",
           r->converged ? "converged" : "NOT converged", r->iterations);
    if (a->method)
        printf(" (%d local optimisation%s%s, projected gradient %.2g)", r->starts, r->starts == 1 ? "" : "s",
               r->restarts ? ", restarted from a profile point below the optimum" : "", r->gradient);
    printf("\n");
    printf("parameter   value         standard error%s\n", a->method ? "   95% profile-likelihood interval" : "");
    for (size_t k = 0; k < r->np; k++) {
        char se[32], lo[32], hi[32];
        const nl_fit_param *q = &r->param[k];
        if (q->fixed)
            snprintf(se, sizeof se, "fixed");
        else if (q->flags & NL_FIT_PARAM_AT_BOUND)
            snprintf(se, sizeof se, "n/a (at bound)");
        else if (q->flags & NL_FIT_PARAM_SINGULAR)
            snprintf(se, sizeof se, "n/a (not identifiable)");
        else if (isfinite(q->se))
            snprintf(se, sizeof se, "%.4g", q->se);
        else
            snprintf(se, sizeof se, "n/a (singular information)");
        if (isnan(q->lower) || isnan(q->upper))
            printf("%-11s %-13.6g %s\n", q->name, q->value, se);
        else
            printf("%-11s %-13.6g %-16s %s to %s\n", q->name, q->value, se, end_text(q->lower, lo, sizeof lo),
                   end_text(q->upper, hi, sizeof hi));
    }
    print_status(a, r);
    if (a->method && a->o.drift == NL_DRIFT_CONSTANT && !a->terms.ncov)
        printf("mean        %.6g\n", r->mean);
    else if (a->method)
        for (size_t k = 0; k < r->ndrift; k++) {
            char name[16];
            printf("drift %-5s %-13.6g %.4g\n", drift_term(a, k, name, sizeof name), r->drift[k], r->drift_se[k]);
        }
    printf("objective   %.8g (%s)\n", r->objective, a->method ? "-2 log likelihood" : "weighted sum of squares");
    printf("AIC         %.8g\n", r->aic);
}

static void print_json(const opts_t *a, const nl_fit_result *r)
{
    static const char *const mname[] = {"wls", "ml", "reml"};
    json_t *par = json_object(), *se = json_object(), *status = json_object(), *flags = json_array(), *j;
    for (size_t k = 0; k < r->np; k++) {
        const nl_fit_param *q = &r->param[k];
        json_object_set_new(par, q->name, json_real(q->value));
        json_object_set_new(se, q->name, isfinite(q->se) ? json_real(q->se) : json_null());
        json_object_set_new(status, q->name, json_string(status_word(q)));
    }
    if (r->flags & NL_FIT_PARAM_SINGULAR)
        json_array_append_new(flags, json_string("singular-information"));
    if (r->flags & NL_FIT_PARAM_AT_BOUND)
        json_array_append_new(flags, json_string("at-bound"));
    if (!r->converged)
        json_array_append_new(flags, json_string("not-converged"));
    j = json_pack("{s:s,s:o,s:o,s:f,s:f,s:s,s:I,s:b,s:i}", "model", r->spec, "parameters", par, "standard_errors", se,
                  "objective", r->objective, "aic", r->aic, "method", mname[a->method], "n", (json_int_t)r->nobs,
                  "converged", r->converged, "iterations", r->iterations);
    json_object_set_new(j, "status", status);
    json_object_set_new(j, "flags", flags);
    json_object_set_new(j, "rcond", json_real(r->rcond));
    if (a->method) {
        json_t *iv = json_object();
        for (size_t k = 0; k < r->np; k++) {
            const nl_fit_param *q = &r->param[k];
            if (!isnan(q->lower) && !isnan(q->upper))
                json_object_set_new(iv, q->name, json_pack("[f,o]", q->lower,
                                                           isfinite(q->upper) ? json_real(q->upper) : json_null()));
        }
        json_t *dr = json_array();
        for (size_t k = 0; k < r->ndrift; k++) {
            char name[16];
            json_array_append_new(dr, json_pack("{s:s,s:f,s:f}", "term", drift_term(a, k, name, sizeof name),
                                                "value", r->drift[k], "se", r->drift_se[k]));
        }
        json_object_set_new(j, "mean", json_real(r->mean));
        json_object_set_new(j, "intervals", iv);
        json_object_set_new(j, "drift", dr);
        json_object_set_new(j, "starts", json_integer(r->starts));
        json_object_set_new(j, "restarts", json_integer(r->restarts));
        json_object_set_new(j, "gradient", json_real(r->gradient));
    }
    cli_json_print(j);
}

int cli_cmd_fit(int argc, char **argv)
{
    opts_t a = {0};
    nl_fit_result r;
    nl_points *p;
    int st;
    parse(argc, argv, &a);
    if (a.vario)
        st = fit_table(&a, &r);
    else {
        p = read_points(&a);
        a.dim = p->dim;
        if (a.drift)
            a.o.drift = cli_drift_poly(&a.terms, a.drift, a.dim);
        st = fit(&a, p, &r);
        nl_points_free(p);
        free(a.cov);
    }
    if (st) {
        const char *msg = nl_errmsg();
        int code = st == NL_EINVAL || st == NL_ETOOBIG || nl_error_is_input(st) ? 2 : 1;
        /* the options' own errors name the option, the data's name the file */
        if (strncmp(msg, "model:", 6) == 0 || strncmp(msg, "fix:", 4) == 0)
            cli_die(code, "--%s", msg);
        if (strncmp(msg, a.in, strlen(a.in)) == 0 && msg[strlen(a.in)] == ':') /* names the file already */
            cli_die(code, "%s", msg);
        cli_die(code, "%s: %s", a.in, msg);
    }
    if (!isfinite(r.objective) || !isfinite(r.aic))
        cli_die(1, "%s: the fit's objective is not finite", a.in);
    if (a.json)
        print_json(&a, &r);
    else
        print_text(&a, &r);
    nl_fit_result_free(&r);
    return 0;
}
