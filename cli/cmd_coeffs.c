/* noiselab coeffs: midpoint estimation coefficients of generalized
 * stochastic subdivision, level by level. */
#include "cli.h"
#include "../core/model.h"
#include "../synth/subdiv.h"

#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

static const char help[] =
    "usage: noiselab coeffs --acf SPEC --dim 1|2 [--neighborhood N|auto] [--tol E] [--levels L]\n"
    "                       [--spacing0 S] [--json]\n\n"
    "Solves the orthogonality equations of generalized stochastic subdivision\n"
    "(Lewis 1987, eqs. 4, 10, 12) at every level, with the displacement variance\n"
    "(eq. 7), the condition number and the flags of each point class.\n\n"
    "  --neighborhood N  half-width: 2N points in 1D, a 2N x 2N block in 2D (default 2);\n"
    "                    auto grows N per level until eq. (7) improves by less than\n"
    "                    E R(0) (--tol, default 1e-4), up to 16 in 1D and 6 in 2D;\n"
    "                    in 2D, levels (2N)^6 at most 1.2e8 (N = 8: 7 levels)\n"
    "  --levels L        number of levels (default 10)\n"
    "  --spacing0 S      observation spacing at level 0, in lag units (default 1);\n"
    "                    level k uses S / 2^k\n"
    "  --json            {\"levels\": [{\"level\", \"spacing\", \"N\", \"classes\": [{\"class\",\n"
    "                    \"coefficients\", \"variance\", \"condition\", \"flags\"}]}]}\n"
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

int cli_cmd_coeffs(int argc, char **argv)
{
    static const struct option opts[] = {
        {"acf", required_argument, 0, 'a'},      {"dim", required_argument, 0, 'd'},
        {"neighborhood", required_argument, 0, 'N'}, {"tol", required_argument, 0, 't'},
        {"levels", required_argument, 0, 'L'},   {"spacing0", required_argument, 0, 's'},
        {"json", no_argument, 0, 'j'},           {"help", no_argument, 0, 'h'},
        {0}};
    const char *spec = NULL;
    int c, dim = 0, N = 2, levels = 10, json = 0;
    double tol = 1e-4, s0 = 1;
    nl_model *m;
    nl_subdiv_coeffs *co;
    while ((c = cli_getopt(argc, argv, ":h", opts, "coeffs")) != -1) {
        switch (c) {
        case 'a': spec = optarg; break;
        case 'd': dim = cli_parse_dim(optarg, 2); break;
        case 'N':
            N = strcmp(optarg, "auto") == 0 ? 0 : (int)cli_parse_count("--neighborhood", optarg, 1);
            break;
        case 't':
            tol = cli_parse_positive("--tol", optarg, "number");
            break;
        case 'L': levels = (int)cli_parse_count("--levels", optarg, 1); break;
        case 's':
            s0 = cli_parse_positive("--spacing0", optarg, "number");
            break;
        case 'j': json = 1; break;
        case 'h': fputs(help, stdout); return 0;
        }
    }
    cli_no_operands("coeffs", argc, argv);
    if (!spec)
        cli_die(2, "coeffs: --acf: expected an autocorrelation model (see noiselab models)");
    if (!dim)
        cli_die(2, "coeffs: --dim: expected 1 or 2");
    if (levels > 40)
        cli_die(2, "--levels: expected at most 40, got %d", levels);
    if (N > (dim == 1 ? 64 : 8))
        cli_die(2, "--neighborhood: expected at most %d in %dD, got %d", dim == 1 ? 64 : 8, dim, N);
    /* 2D: three (2N)^2 systems per level, O((2N)^6) each when singular (SVD):
     * N = 8 takes about 0.6 s a level, so levels (2N)^6 <= 1.2e8 keeps it to seconds */
    if (dim == 2 && (double)levels * pow(2.0 * N, 6) > 1.2e8)
        cli_die(2, "--neighborhood %d with --levels %d in 2D: expected levels (2N)^6 <= 1.2e8 (at most %d levels "
                "with N = %d)", N, levels, (int)(1.2e8 / pow(2.0 * N, 6)), N);
    cli_check(nl_model_parse(spec, &m));
    cli_check(nl_subdiv_coeffs_alloc(m, dim, levels, s0, N, tol, dim == 1 ? 16 : 6, &co));
    check_finite(m, co, spec);
    if (json) {
        json_t *lv = json_array();
        for (int k = 0; k < co->levels; k++) {
            const nl_subdiv_level *l = &co->level[k];
            json_t *cls = json_array();
            for (int j = 0; j < l->nclass; j++) {
                const nl_subdiv_class *cl = &l->cls[j];
                json_array_append_new(
                    cls, json_pack("{s:s,s:o,s:f,s:f,s:o,s:f,s:o}", "class", nl_subdiv_class_name(cl->cls),
                                   "coefficients", cli_json_array(cl->a, cl->n), "variance", cl->variance,
                                   "raw_variance", cl->raw_variance,
                                   "condition", isfinite(cl->condition) ? json_real(cl->condition) : json_null(),
                                   "min_eigenvalue", cl->min_eigenvalue, "flags", flags_json(cl->flags)));
            }
            json_array_append_new(lv, json_pack("{s:i,s:f,s:i,s:o}", "level", l->level, "spacing", l->spacing, "N",
                                                l->N, "classes", cls));
        }
        cli_json_print(json_pack("{s:s,s:i,s:f,s:o,s:o}", "model", spec, "dim", dim, "spacing0", s0, "flags",
                                 flags_json(co->flags), "levels", lv));
    } else {
        print_text(co, spec);
    }
    nl_subdiv_coeffs_free(co);
    nl_model_free(m);
    return 0;
}
