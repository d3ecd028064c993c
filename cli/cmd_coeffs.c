/* noiselab coeffs: midpoint estimation coefficients of generalized
 * stochastic subdivision, level by level. */
#include "coeffs.h"
#include "opt.h"
#include "synth.h"

#include <math.h>
#include <stdio.h>

static const char help[] =
    "usage: noiselab coeffs --acf SPEC --dim 1|2 [--neighborhood N|auto] [--tol [variance:]E]\n"
    "                       [--levels L] [--spacing0 S] [--displacements independent|correlated [--taps M]]\n"
    "                       [--error --size N[xM]] [--json]\n\n"
    "Solves the orthogonality equations of generalized stochastic subdivision\n"
    "(Lewis 1987, eqs. 4, 10, 12) at every level, with the displacement variance\n"
    "(eq. 7), the condition number and the flags of each point class.\n\n"
    "  --neighborhood N  half-width: 2N points in 1D, a 2N x 2N block in 2D (default 2);\n"
    "                    auto grows N per level until eq. (7) improves by less than\n"
    "                    E R(0) (--tol, default 1e-4), up to 16 in 1D and 6 in 2D;\n"
    "                    in 2D, levels (2N)^6 at most 1.2e8 (N = 8: 7 levels)\n"
    "  --tol variance:E  auto by the paper's rule: the first N whose eq. (7) is below\n"
    "                    E R(0) (else the largest).  1D grows N by Levinson's\n"
    "                    recursion (O(N) a step), then solves the chosen N directly;\n"
    "                    2D solves every N directly (a ring is no Toeplitz bordering)\n"
    "  --levels L        number of levels (default 10)\n"
    "  --spacing0 S      observation spacing at level 0, in lag units (default 1);\n"
    "                    level k uses S / 2^k\n"
    "  --displacements correlated  the new points of a level displaced together (see synth\n"
    "                    subdiv): each level also gets its filter, taps g[a][b][p] (1D: g[p],\n"
    "                    p = -M..M; 2D: classes a, b, rows py = -M..M of columns px), and the\n"
    "                    displacement covariance it realises against the error covariance it\n"
    "                    approximates, at cell offsets 0..2M along x (and y, 2D)\n"
    "  --taps M          correlated: the filter's half-width in cells (default 4 in 1D, 2 in 2D)\n"
    "  --error           the exact expected ACF of a periodic field of --size samples made with\n"
    "                    these levels (covariance propagated level by level) against the target:\n"
    "                    per direction (x; 2D also y and the diagonal) \"lag\" (samples),\n"
    "                    \"exact_acf\", \"target_acf\", and \"method_error\", the largest\n"
    "                    |exact - R| / R(0); at most 4096 samples; --levels then defaults to a\n"
    "                    coarse grid of 8 samples and the output spacing is S / 2^levels\n"
    "  --json            {\"levels\": [{\"level\", \"spacing\", \"N\", \"classes\": [{\"class\",\n"
    "                    \"coefficients\", \"variance\", \"condition\", \"flags\"}]}]}; with auto,\n"
    "                    \"auto\" {\"stop\", \"tol\"} and, in 1D, each level's \"variance_by_N\"\n"
    "                    (eq. 7 for N = 1.. its N, from the recursion)\n"
    "Coefficients are in neighbourhood order: k = 1-N..N in 1D; row-major over\n"
    "(r, c) = 1-N..N in 2D, r along y.  Classes: mid (1D); face, edge-x, edge-y (2D).\n";

static json_t *flags_json(unsigned f)
{
    json_t *a = json_array();
    for (unsigned b = 0; b < 6; b++)
        if (f & (1u << b))
            json_array_append_new(a, json_string(nl_subdiv_flag_name(b)));
    return a;
}

static void print_text(const nl_subdiv_coeffs *c, const char *spec)
{
    printf("# %s, %dD, spacing0 %g, %d levels\n", spec, c->dim, c->spacing0, c->levels);
    for (int k = 0; k < c->levels; k++) {
        const nl_subdiv_level *l = &c->level[k];
        for (int j = 0; j < l->nclass; j++) {
            const nl_subdiv_class *cl = &l->cls[j];
            char fl[128];
            cli_subdiv_flags(cl->flags, fl, sizeof fl);
            char cond[32];
            if (isfinite(cl->condition))
                snprintf(cond, sizeof cond, "%-10.3g", cl->condition);
            else
                snprintf(cond, sizeof cond, "%-10s", "unbounded");
            printf("level %2d  spacing %-10.6g N %d  %-6s variance %-12.6f condition %s flags %s\n", l->level,
                   l->spacing, l->N, nl_subdiv_class_name(cl->cls), cl->variance, cond, fl[0] ? fl : "-");
            if (l->filt && j == l->nclass - 1)
                printf("    correlated displacements: %d taps, filter error %.3g R(0)\n", l->taps, l->filt_error);
            if (c->dim == 1) {
                /* the right half a_1..a_N, as in Lewis's Table 1 (a_k = a_{1-k}) */
                printf("    a_1..a_N:");
                for (int i = l->N; i < 2 * l->N; i++)
                    printf(" %10.6f", cl->a[i]);
                printf("\n");
            } else {
                int w = 2 * l->N;
                for (int r = 0; r < w; r++) {
                    printf("   ");
                    for (int s = 0; s < w; s++)
                        printf(" %10.6f", cl->a[r * w + s]);
                    printf("\n");
                }
            }
        }
    }
}

/* The model finite and positive at lag 0, and every coefficient and
 * variance finite (a model singular at a lag the levels reach). */
static void check_finite(const nl_model *m, const nl_subdiv_coeffs *c, const char *spec)
{
    double zero[3] = {0, 0, 0}, r0 = nl_model_acf(m, c->dim, zero);
    if (!(isfinite(r0) && r0 > 0))
        cli_die(2, "--acf: %s: R(0) = %g; expected a finite positive variance", spec, r0);
    for (int k = 0; k < c->levels; k++)
        for (int j = 0; j < c->level[k].nclass; j++) {
            const nl_subdiv_class *cl = &c->level[k].cls[j];
            int ok = isfinite(cl->variance) && isfinite(cl->raw_variance) && isfinite(cl->min_eigenvalue);
            for (size_t i = 0; ok && i < cl->n; i++)
                ok = isfinite(cl->a[i]);
            if (!ok)
                cli_die(2, "--acf: %s gives non-finite coefficients at level %d (spacing %g); expected a model "
                        "finite at every lag", spec, k, c->level[k].spacing);
        }
}

typedef struct {
    const char *spec, *size;
    int dim, N, levels, json, disp, taps, error, stop;
    int N_given; /* --neighborhood given */
    double tol, s0;
    const char *tol_text; /* --tol as given, or NULL */
} coeffs_args;

static void tol_option(void *obj, const char *label, const char *arg)
{
    coeffs_args *a = obj;
    a->tol = cli_synth_parse_tol(label, arg, &a->stop);
    a->tol_text = arg;
}

static const char *const displacements[] = {"independent", "correlated", NULL};

static const cli_opt rows[] = {
    CLI_STRING("acf", coeffs_args, spec, .need = "an autocorrelation model (see noiselab models)"),
    CLI_OPT_DIMS(coeffs_args, dim, 2, .need = "1 or 2"),
    CLI_INT("neighborhood", coeffs_args, N, .lo = 1, .flags = CLI_AUTO, CLI_GIVEN(coeffs_args, N_given)),
    CLI_CALL("tol", tol_option),
    CLI_INT("levels", coeffs_args, levels, .lo = 1), CLI_POSITIVE("spacing0", coeffs_args, s0, .what = "number"),
    CLI_OPT_JSON(coeffs_args, json), CLI_CHOICE("displacements", coeffs_args, disp, .choices = displacements),
    CLI_INT("taps", coeffs_args, taps, CLI_FROM_TO(1, NL_SUBDIV_MAX_TAPS)), CLI_FLAG("error", coeffs_args, error),
    CLI_STRING("size", coeffs_args, size), {0}};

/* Returns 1 when --help was printed. */
static int parse(int argc, char **argv, coeffs_args *a)
{
    if (cli_opt_parse("coeffs", help, rows, a, argc, argv))
        return 1;
    cli_no_operands("coeffs", argc, argv);
    return 0;
}

/* The options against each other and the work they ask for. */
static void check_args(coeffs_args *a, size_t *n)
{
    cli_opt_need("coeffs", rows, a);
    if (a->tol_text && a->N)
        cli_die(2, "--tol \"%s\": expected --neighborhood auto (the tolerance stops its growth), got "
                "--neighborhood %d%s", a->tol_text, a->N, a->N_given ? "" : " (the default)");
    if (a->taps && !a->disp)
        cli_die(2, "--taps %d: expected --displacements correlated (independent displacements have no filter)",
                a->taps);
    if (a->size && !a->error)
        cli_die(2, "--size %s: expected --error (the size of the field whose exact ACF it computes)", a->size);
    if (a->error) {
        if (!a->size)
            cli_die(2, "--error: expected --size N%s", a->dim == 2 ? "xM" : "");
        if (cli_parse_size("--size", a->size, n, 2) != a->dim)
            cli_die(2, "--size %s: expected a %dD size like --dim", a->size, a->dim);
        if (n[0] * (a->dim == 2 ? n[1] : 1) > 4096)
            cli_die(2, "--size %s: expected at most 4096 samples for --error (the exact covariance is a "
                    "matrix of samples^2 doubles)", a->size);
        if (!a->levels && !(a->levels = nl_subdiv_default_levels(a->dim, n, 8)))
            cli_die(2, "--size %s: expected a size divisible by 2 with a coarse grid of at least 8 samples",
                    a->size);
    }
    if (!a->levels)
        a->levels = 10;
    if (a->levels > 40)
        cli_die(2, "--levels: expected at most 40, got %d", a->levels);
    if (a->N > (a->dim == 1 ? 64 : 8))
        cli_die(2, "--neighborhood: expected at most %d in %dD, got %d", a->dim == 1 ? 64 : 8, a->dim, a->N);
    /* 2D: three (2N)^2 systems per level, O((2N)^6) each when singular (SVD):
     * N = 8 takes about 0.6 s a level, so levels (2N)^6 <= 1.2e8 keeps it to seconds */
    if (a->dim == 2 && (double)a->levels * pow(2.0 * a->N, 6) > 1.2e8)
        cli_die(2, "--neighborhood %d with --levels %d in 2D: expected levels (2N)^6 <= 1.2e8 (at most %d levels "
                "with N = %d)", a->N, a->levels, (int)(1.2e8 / pow(2.0 * a->N, 6)), a->N);
}

/* 1D auto: eq. (7) for N = 1 .. the level's N from Levinson's recursion
 * (shorter where the recursion stops: singular from there on). */
static json_t *variance_by_n(const nl_subdiv_level *l, const nl_model *m)
{
    double a[128], var[64];
    int nout = 0;
    cli_check(nl_subdiv_levinson(m, l->spacing, l->N, NL_SUBDIV_STOP_NONE, 0, a, var, &nout));
    return cli_json_array(var, (size_t)nout);
}

static json_t *levels_json(const nl_subdiv_coeffs *co, const nl_model *m, int autoN)
{
    json_t *lv = json_array();
    for (int k = 0; k < co->levels; k++) {
        const nl_subdiv_level *l = &co->level[k];
        json_t *cls = json_array(), *o;
        for (int j = 0; j < l->nclass; j++) {
            const nl_subdiv_class *cl = &l->cls[j];
            json_array_append_new(
                cls, json_pack("{s:s,s:o,s:f,s:f,s:o,s:f,s:o}", "class", nl_subdiv_class_name(cl->cls),
                               "coefficients", cli_json_array(cl->a, cl->n), "variance", cl->variance,
                               "raw_variance", cl->raw_variance,
                               "condition", isfinite(cl->condition) ? json_real(cl->condition) : json_null(),
                               "min_eigenvalue", cl->min_eigenvalue, "flags", flags_json(cl->flags)));
        }
        o = json_pack("{s:i,s:f,s:i,s:o}", "level", l->level, "spacing", l->spacing, "N", l->N, "classes", cls);
        if (autoN && co->dim == 1)
            json_object_set_new(o, "variance_by_N", variance_by_n(l, m));
        if (l->filt)
            json_object_set_new(o, "displacements", cli_coeffs_filter_json(l, m, co->dim));
        json_array_append_new(lv, o);
    }
    return lv;
}

int cli_cmd_coeffs(int argc, char **argv)
{
    coeffs_args a = {.N = 2, .stop = NL_SUBDIV_STOP_IMPROVEMENT, .tol = 1e-4, .s0 = 1};
    size_t n[3] = {0, 0, 0};
    nl_model *m;
    nl_subdiv_coeffs *co;
    json_t *err = NULL;
    double e = 0;
    if (parse(argc, argv, &a))
        return 0;
    check_args(&a, n);
    cli_check(nl_model_parse(a.spec, &m));
    cli_check(nl_subdiv_coeffs_alloc_rule(m, a.dim, a.levels, a.s0, a.N, a.stop, a.tol, a.dim == 1 ? 16 : 6, &co));
    check_finite(m, co, a.spec);
    if (a.disp)
        cli_check(nl_subdiv_coeffs_correlate(co, m, a.taps ? a.taps : a.dim == 1 ? 4 : 2, NL_SUBDIV_DISP_ERROR));
    if (a.error)
        err = cli_coeffs_error_json(co, m, n, &e);
    if (a.json) {
        json_t *o = json_pack("{s:s,s:i,s:f,s:s,s:o,s:o}", "model", a.spec, "dim", a.dim, "spacing0", a.s0,
                              "displacements", a.disp ? "correlated" : "independent", "flags",
                              flags_json(co->flags), "levels", levels_json(co, m, !a.N));
        if (!a.N)  /* auto: the rule that chose each level's N */
            json_object_set_new(o, "auto", json_pack("{s:s,s:f}", "stop", a.stop ? "variance" : "improvement",
                                                     "tol", a.tol));
        if (err) {
            json_object_set_new(o, "error", json_pack("{s:s,s:f,s:o,s:f}", "size", a.size, "spacing",
                                                      ldexp(a.s0, -co->levels), "directions", err,
                                                      "method_error", e));
        }
        cli_json_print(o);
    } else {
        print_text(co, a.spec);
        if (err) {
            printf("# exact expected ACF of a periodic %s field: method error max |exact - R| / R(0) = %.3g\n",
                   a.size, e);
            json_decref(err);
        }
    }
    nl_subdiv_coeffs_free(co);
    nl_model_free(m);
    return 0;
}
