/* noiselab synth: synthesise a field with a prescribed model. */
#include "synth.h"
#include "../core/field_sample.h"
#include "../core/nl_error.h"
#include "../core/provenance.h"
#include "../core/version.h"
#include "../synth/subdiv.h"

#include <errno.h>
#include <float.h>
#include <getopt.h>
#include <limits.h>
#include <inttypes.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Every method's options, each name once (the registry's rows, in its
 * order), with getopt codes CLI_MOPT + k. */
#define CLI_MOPT 1000
#define CLI_MAX_MOPTS 64

typedef struct {
    const nl_method_option *row; /* the first method's row of this name */
    const nl_method_type *type;  /* that method */
    int late;                    /* methods disagree on its values: checked once the method is known */
} cli_mopt;

/* What the command line gave, beyond the job itself. */
typedef struct {
    const char *acf, *spec, *size, *spacing, *out, *preview, *origin, *from; /* option values or NULL */
    const char *precision;                           /* --precision single|double (.h5 outputs) */
    int json;                                        /* --json */
    const char *mtext[CLI_MAX_MOPTS];                /* method options' values (flags: "") */
    int mgiven[CLI_MAX_MOPTS];                       /* given explicitly (or recorded for another method) */
    cli_synth_cond cond;                             /* --condition and its options */
    const char *other, *other_value;                 /* the first option --from takes from FILE, and its value */
    char other_label[96];                            /* (other points here) */
} cli_synth_args;

static cli_mopt mopts[CLI_MAX_MOPTS];
static int nmopts;

static int same_values(const nl_method_option *a, const nl_method_option *b)
{
    return a->type == b->type && a->flags == b->flags && a->min == b->min && a->max == b->max &&
           !a->words == !b->words && (!a->words || !strcmp(a->words, b->words)) && !a->expect == !b->expect &&
           (!a->expect || !strcmp(a->expect, b->expect));
}

/* The union of the methods' option tables (once). */
static void collect_mopts(void)
{
    static int done;
    for (int i = 0; i < nl_method_count() && !done; i++) {
        const nl_method_type *t = nl_method_at(i);
        for (int k = 0; k < t->noptions; k++) {
            int j = 0;
            while (j < nmopts && strcmp(mopts[j].row->name, t->options[k].name))
                j++;
            if (j < nmopts)
                mopts[j].late |= !same_values(mopts[j].row, &t->options[k]);
            else if (j < CLI_MAX_MOPTS)
                mopts[nmopts++] = (cli_mopt){&t->options[k], t, 0};
        }
    }
    done = 1;
}

static int mopt_index(const char *name)
{
    for (int j = 0; j < nmopts; j++)
        if (!strcmp(mopts[j].row->name, name))
            return j;
    return -1;
}

/* Window origins stay within +-2^30 samples: the 2D generators index
 * lattice points by 32-bit coordinates, and origin + size + reach must not
 * overflow a long. */
#define CLI_ORIGIN_MAX (1L << 30)

static void check_origin(const char *opt, const char *s, const long *o)
{
    for (int a = 0; a < 2; a++)
        if (o[a] < -CLI_ORIGIN_MAX || o[a] > CLI_ORIGIN_MAX)
            cli_die(2, "%s: expected window indices from -%ld to %ld, got \"%s\"", opt, CLI_ORIGIN_MAX,
                    CLI_ORIGIN_MAX, s);
}

static void parse_origin(const char *s, long *o)
{
    char *end, *p;
    int ok;
    errno = 0;
    o[0] = strtol(s, &end, 10);
    ok = end != s;
    if (ok && *end == ',') {
        p = end + 1;
        o[1] = strtol(p, &end, 10);
        ok = end != p;
    }
    if (!ok || *end)
        cli_die(2, "--origin: expected X or X,Y (integers), got \"%s\"", s);
    if (errno == ERANGE)
        o[0] = o[1] = LONG_MAX;
    check_origin("--origin", s, o);
}

/* Option `name` of the job's method from text, or exit 2 naming label. */
static void set_option(cli_synth_job *job, const char *name, const char *v, const char *label)
{
    cli_check(nl_method_options_set(&job->opts, name, v, label));
}

/* A record is data: a file it names (image:FILE, --seed-image FILE) is read
 * only when the command line names the same file. */
static void confirm_file(const char *path, const char *opt, const char *v, const char *given)
{
    if (!given || strcmp(given, v))
        cli_die(2, "--from: %s records %s %s; give %s %s on the command line to read that file", path, opt, v,
                opt, v);
}

/* One recorded key: the method's option, the window origin, or (a key of
 * another method's) marked given for the checks; others are ignored. */
static void apply_key(char *kv, int suffix, cli_synth_job *job, cli_synth_args *g)
{
    char label[96], *eq = strchr(kv, '=');
    const char *v = eq ? eq + 1 : "";
    int k, j;
    if (eq)
        *eq = 0;
    if (!suffix && !strcmp(kv, "origin")) {
        errno = 0;
        if (sscanf(v, "%ld:%ld", &job->origin[0], &job->origin[1]) != 2 || errno == ERANGE)
            job->origin[0] = LONG_MAX;
        check_origin("--from: origin", v, job->origin);
        return;
    }
    k = nl_method_option_index(job->type, kv);
    if (k >= 0 && !(job->type->options[k].flags & NL_METHOD_SUFFIX) == !suffix) {
        if (job->type->options[k].flags & NL_METHOD_FILE) {
            snprintf(label, sizeof label, "--%s", kv);
            j = mopt_index(kv);
            confirm_file(g->from, label, v, j >= 0 && g->mgiven[j] ? g->mtext[j] : NULL);
        }
        snprintf(label, sizeof label, "--from: %s", kv);
        set_option(job, kv, job->type->options[k].type == NL_METHOD_FLAG ? NULL : v, label);
    } else if (k < 0 && !suffix && (j = mopt_index(kv)) >= 0) {
        g->mgiven[j] = 1;
    }
}

/* The method's recorded options: "k=v,...|k=v|..." (what follows "name:"
 * in the method string its describe wrote). */
static void apply_keys(char *rest, cli_synth_job *job, cli_synth_args *g)
{
    char *part, *save = NULL;
    for (part = strtok_r(rest, "|", &save); part; part = strtok_r(NULL, "|", &save)) {
        if (part != rest) {  /* an expression-valued key: the rest of the part */
            if (strchr(part, '='))
                apply_key(part, 1, job, g);
            continue;
        }
        char *kv, *s2 = NULL;
        for (kv = strtok_r(part, ",", &s2); kv; kv = strtok_r(NULL, ",", &s2))
            apply_key(kv, 0, job, g);
    }
}

/* Regenerate from a field's provenance: the method string "name:k=v,...|k=v|..."
 * written by the methods, the model, seed, size and spacing. */
static void apply_from(const char *path, cli_synth_job *job, cli_synth_args *g)
{
    static char mbuf[1100], sizebuf[64], spbuf[128], methbuf[256];
    const nl_family *fam;
    nl_meta meta;
    nl_provenance prov;
    char *rest;
    if (cli_is_h5(path))
        cli_check(cli_h5_read_meta(path, &meta));
    else
        nl_field_free(cli_read_field(path, &meta));
    if (!meta.method[0] || !meta.seed[0] || !meta.size[0])
        cli_die(2, "--from: %s does not record how it was made (noiselab.method, seed, size)", path);
    snprintf(methbuf, sizeof methbuf, "%s", meta.method);
    rest = strchr(methbuf, ':');
    if (rest)
        *rest++ = 0;
    if (strchr(methbuf, ' '))
        cli_die(2, "--from: %s was post-processed (\"%s\"); only synthesised fields regenerate", path, meta.method);
    job->method = methbuf;
    /* size and spacing are read as --size and --spacing are, with their checks */
    cli_check(nl_provenance_parse(&meta, NL_PROV_SEED | NL_PROV_MODEL | NL_PROV_METHOD, &prov));
    job->seed = prov.seed;
    fam = nl_family_find(prov.model, strcspn(prov.model, ":"));
    if (prov.model[0] && fam && (fam->flags & NL_FAMILY_FILE))
        confirm_file(path, fam->flags & NL_FAMILY_SPECTRAL ? "--spectrum" : "--acf", prov.model,
                     g->acf ? g->acf : g->spec);
    else if (g->acf || g->spec)
        cli_die(2, "--from: %s records %s%s%s; with --from, --acf and --spectrum only name a file the record reads "
                "(image:FILE)", path, prov.model[0] ? "the model \"" : "no model", prov.model,
                prov.model[0] ? "\"" : "");
    snprintf(sizebuf, sizeof sizebuf, "%s", meta.size), g->size = sizebuf;
    snprintf(spbuf, sizeof spbuf, "%s", meta.spacing), g->spacing = spbuf[0] ? spbuf : NULL;
    if (prov.model[0]) {
        nl_model *m;
        cli_check(nl_model_parse(prov.model, &m));
        snprintf(mbuf, sizeof mbuf, "%s", prov.model);
        *(nl_model_is_spectral(m) ? &g->spec : &g->acf) = mbuf;
        nl_model_free(m);
    }
    if (strstr(meta.flags, "clamped") || strstr(meta.flags, "not-positive-definite"))
        job->clamp = 1;
    if ((job->type = nl_method_find(methbuf)))
        nl_method_options_default(job->type, &job->opts);
    if (rest && job->type)
        apply_keys(rest, job, g);
}

/* Options that only some methods take: those with caps, or taking opt. */
static void only_for(const char *opt, int given, const cli_synth_job *job, unsigned caps, const char *name)
{
    char list[256];
    if (!given || (caps ? (job->type->caps & caps) == caps : nl_method_option_index(job->type, name) >= 0))
        return;
    nl_method_names(caps, name, " ", " ", list, sizeof list);
    cli_die(2, "synth %s: %s applies to %s only", job->method, opt, list);
}

static void job_defaults(cli_synth_job *job)
{
    memset(job, 0, sizeof *job);
    job->seed = 1;
    for (int a = 0; a < 3; a++)
        job->n[a] = 1, job->h[a] = 1;
}

/* A method option on the command line: its value kept, and checked now
 * unless the methods taking it disagree on its values. */
static void method_option(int j, const char *arg, cli_synth_args *g)
{
    char label[96];
    nl_method_options o;
    g->mtext[j] = mopts[j].row->type == NL_METHOD_FLAG ? NULL : arg;
    g->mgiven[j] = 1;
    if (mopts[j].late)
        return;
    snprintf(label, sizeof label, "--%s", mopts[j].row->name);
    nl_method_options_default(mopts[j].type, &o);
    cli_check(nl_method_options_set(&o, mopts[j].row->name, g->mtext[j], label));
}

/* The common options, then every method's (CLI_MOPT + k). */
static const struct option *options_table(void)
{
    static const struct option common[] = {
        {"acf", required_argument, 0, 'a'},        {"spectrum", required_argument, 0, 'S'},
        {"size", required_argument, 0, 'n'},       {"seed", required_argument, 0, 's'},
        {"spacing", required_argument, 0, 'H'},    {"clamp", no_argument, 0, 'c'},
        {"preview", required_argument, 0, 'p'},    {"json", no_argument, 0, 'j'},
        {"output", required_argument, 0, 'o'},     {"help", no_argument, 0, 'h'},
        {"origin", required_argument, 0, 'O'},     {"from", required_argument, 0, 'F'},
        {"condition", required_argument, 0, 'Y'}, {"extent", required_argument, 0, 'Z'},
        {"realizations", required_argument, 0, 'k'}, {"mean", required_argument, 0, 'M'},
        {"interpolation", required_argument, 0, 'Q'}, {"ensemble-mean", required_argument, 0, 'g'},
        {"ensemble-variance", required_argument, 0, 'J'}, {"nmax", required_argument, 0, 'q'},
        {"precision", required_argument, 0, 'G'}, {"at", required_argument, 0, 'T'},
        {"grid-out", required_argument, 0, 'W'},  {"format", required_argument, 0, 'X'},
        {"range", required_argument, 0, 'R'},     {"crs", required_argument, 0, 'E'},
        {"cog", no_argument, 0, 'U'}};
    static struct option opts[sizeof common / sizeof *common + CLI_MAX_MOPTS + 1];
    size_t n = sizeof common / sizeof *common;
    collect_mopts();
    memcpy(opts, common, sizeof common);
    for (int j = 0; j < nmopts; j++)
        opts[n + (size_t)j] = (struct option){mopts[j].row->name,
                                              mopts[j].row->type == NL_METHOD_FLAG ? no_argument : required_argument,
                                              0, CLI_MOPT + j};
    return opts;
}

/* The options a run with --from takes: where the output goes, what it
 * prints, and the files its record names (--acf image:F, a file option),
 * checked against the record by apply_from. */
static int with_from(int c)
{
    return c == 'o' || c == 'p' || c == 'j' || c == 'F' || c == 'G' || c == 'X' || c == 'R' || c == 'E' || c == 'U' || c == 'h' ||
           c == 'a' || c == 'S' ||
           (c >= CLI_MOPT && c < CLI_MOPT + nmopts && (mopts[c - CLI_MOPT].row->flags & NL_METHOD_FILE));
}

/* Option c given with value arg (NULL: a flag): refused when given before,
 * as the last would silently win; the first that --from would not use kept
 * in g.  seen and first: by code, whether given and the first value. */
static void note_option(const struct option *opts, int c, const char *arg, int *seen, const char **first,
                        cli_synth_args *g)
{
    char label[96] = "-o";
    for (const struct option *o = opts; c != 'o' && o->name; o++)
        if (o->val == c)
            snprintf(label, sizeof label, "--%s", o->name);
    if (seen[c] && !arg)
        cli_die(2, "synth: %s: given twice; expected it once", label);
    if (seen[c])
        cli_die(2, "synth: %s: given twice (\"%s\", then \"%s\"); expected it once", label, first[c], arg);
    seen[c] = 1, first[c] = arg;
    if (!with_from(c) && !g->other) {
        snprintf(g->other_label, sizeof g->other_label, "%s", label);
        g->other = g->other_label, g->other_value = arg;
    }
}

/* getopt over argv into job and g; returns 1 when --help was printed. */
static int parse_options(int argc, char **argv, cli_synth_job *job, cli_synth_args *g)
{
    const struct option *opts = options_table();
    int c, seen[CLI_MOPT + CLI_MAX_MOPTS] = {0};
    const char *first[CLI_MOPT + CLI_MAX_MOPTS];
    while ((c = cli_getopt(argc, argv, ":ho:", opts, "synth")) != -1) {
        if (c >= 0 && c < CLI_MOPT + nmopts)
            note_option(opts, c, optarg, seen, first, g);
        switch (c) {
        case 'a': g->acf = optarg; break;
        case 'S': g->spec = optarg; break;
        case 'n': g->size = optarg; break;
        case 's': job->seed = cli_parse_u64("--seed", optarg); break;
        case 'H': g->spacing = optarg; break;
        case 'c': job->clamp = 1; break;
        case 'p': g->preview = optarg; break;
        case 'j': g->json = 1; break;
        case 'o': g->out = optarg; break;
        case 'O': g->origin = optarg; break;
        case 'F': g->from = optarg; break;
        case 'G': g->precision = optarg; break;
        case 'X': cli_opt_format(NULL, "--format", optarg); break;
        case 'R': cli_opt_range(NULL, "--range", optarg); break;
        case 'E': cli_opt_crs(NULL, "--crs", optarg); break;
        case 'U': cli_opt_cog(NULL, "--cog", NULL); break;
        case 'Y': case 'Z': case 'k': case 'M': case 'Q': case 'g': case 'J': case 'q': case 'T': case 'W':
            cli_synth_cond_option(&g->cond, c, optarg); break;
        case 'h': cli_synth_print_help(); return 1;
        default:
            if (c >= CLI_MOPT && c < CLI_MOPT + nmopts)
                method_option(c - CLI_MOPT, optarg, g);
        }
    }
    return 0;
}

/* The method and its options from --from FILE or from the command line. */
static void method_source(int argc, char **argv, cli_synth_job *job, cli_synth_args *g)
{
    if (g->from) {
        int file[CLI_MAX_MOPTS];
        /* --from regenerates FILE bit for bit: an option that would change it is refused, not ignored */
        if (g->other)
            cli_die(2, "synth: %s%s%s%s: expected no option but -o, --format, --range, --preview, --json, --precision and the files "
                    "the record names with --from %s, which takes the method, its options, model, seed, size and "
                    "spacing from it", g->other, g->other_value ? " \"" : "", g->other_value ? g->other_value : "",
                    g->other_value ? "\"" : "", g->from);
        if (optind < argc)
            cli_die(2, "synth: \"%s\": expected no METHOD with --from %s, which takes the method from it",
                    argv[optind], g->from);
        for (int j = 0; j < nmopts; j++)
            file[j] = g->mgiven[j] && (mopts[j].row->flags & NL_METHOD_FILE);
        apply_from(g->from, job, g);
        for (int j = 0; j < nmopts; j++) {
            int k = file[j] && job->type ? nl_method_option_index(job->type, mopts[j].row->name) : -1;
            if (file[j] && (k < 0 || !job->opts.v[k].set))
                cli_die(2, "--from: %s records no --%s; with --from give only -o, --preview, --json and the files "
                        "FILE records", g->from, mopts[j].row->name);
        }
        job->from = 1;
        return;
    }
    if (optind >= argc) {
        char list[256];
        nl_method_names(0, NULL, ", ", " or ", list, sizeof list);
        cli_die(2, "synth: expected a METHOD (%s), see noiselab synth --help", list);
    }
    job->method = argv[optind];
    if (optind + 1 < argc)
        cli_die(2, "synth: unexpected argument \"%s\"", argv[optind + 1]);
}


static const nl_method_type *find_method(const char *method)
{
    const nl_method_type *t = nl_method_find(method);
    char list[256];
    if (t)
        return t;
    if (nl_method_planned(method)) {
        nl_method_names(0, NULL, ", ", ", ", list, sizeof list);
        cli_die(2, "synth: method \"%s\" is not available in this version (available: %s)", method, list);
    }
    nl_method_names(0, NULL, ", ", " or ", list, sizeof list);
    cli_die(2, "synth: unknown method \"%s\" (expected %s)", method, list);
    return NULL;
}

/* --origin against the options that make a window (needed) or unmake it
 * (excluded). */
static void check_window(const cli_synth_job *job, const cli_synth_args *g)
{
    const nl_method_type *t = job->type;
    for (int k = 0; k < t->noptions && g->origin; k++) {
        int given = nl_method_options_given(&job->opts, t->options[k].name);
        if ((t->options[k].flags & NL_METHOD_NO_WINDOW) && given)
            cli_die(2, "synth %s: --origin \"%s\" and --%s exclude each other (a periodic tile has no origin)",
                    job->method, g->origin, t->options[k].name);
        if ((t->options[k].flags & NL_METHOD_MAKES_WINDOW) && !given)
            cli_die(2, "synth %s: --origin needs --%s (a periodic field has no origin)", job->method,
                    t->options[k].name);
    }
}

/* --tol and --max-neighborhood stop and bound the growth of --neighborhood
 * auto; with a fixed neighbourhood they would do nothing. */
static void check_auto_only(const cli_synth_job *job, const cli_synth_args *g)
{
    static const char *const only_auto[] = {"tol", "max-neighborhood"};
    int n = mopt_index("neighborhood");
    if (g->from || nl_method_option_index(job->type, "neighborhood") < 0 ||
        nl_method_options_get(&job->opts, "neighborhood")->i == 0)
        return;
    for (size_t k = 0; k < sizeof only_auto / sizeof *only_auto; k++) {
        int j = mopt_index(only_auto[k]);
        if (j >= 0 && g->mgiven[j])
            cli_die(2, "synth %s: --%s \"%s\": expected --neighborhood auto (it %s its growth), got --neighborhood %s",
                    job->method, only_auto[k], g->mtext[j], k ? "bounds" : "stops",
                    g->mgiven[n] ? g->mtext[n] : "2 (the default)");
    }
}

/* Each method option against the method it was given with, then their
 * values into the job's options. */
static void check_method_options(cli_synth_job *job, const cli_synth_args *g)
{
    char label[96];
    for (int j = 0; j < nmopts; j++) {
        snprintf(label, sizeof label, "--%s", mopts[j].row->name);
        only_for(label, g->mgiven[j], job, 0, mopts[j].row->name);
    }
    only_for("--origin", g->origin != NULL, job, NL_METHOD_WINDOW, NULL);
    if (!g->from) {
        nl_method_options_default(job->type, &job->opts);
        for (int j = 0; j < nmopts; j++)
            if (g->mgiven[j]) {
                snprintf(label, sizeof label, "--%s", mopts[j].row->name);
                set_option(job, mopts[j].row->name, g->mtext[j], label);
            }
    }
    check_window(job, g);
    check_auto_only(job, g);
    for (int k = 0; k < job->type->noptions; k++) {
        unsigned fl = job->type->options[k].flags;
        int set = nl_method_options_given(&job->opts, job->type->options[k].name);
        job->nonperiodic |= (fl & NL_METHOD_MAKES_WINDOW) && set;
        job->wrap |= (fl & NL_METHOD_NO_WINDOW) && set;
    }
    job->opts.flags = (job->clamp ? NL_METHOD_OPT_CLAMP : 0) | (job->from ? NL_METHOD_OPT_RECORDED : 0);
}

/* Whether the method needs a model, and whether exactly one was given. */
static void check_model_given(const cli_synth_job *job, const cli_synth_args *g)
{
    const nl_method_type *t = job->type;
    int alt = 0, model = g->acf || g->spec;
    for (int k = 0; k < t->noptions; k++)
        alt |= (t->options[k].flags & NL_METHOD_REPLACES_MODEL) &&
               nl_method_options_given(&job->opts, t->options[k].name);
    if (model && t->model_conflict && (alt || (t->caps & NL_METHOD_NO_MODEL)))
        cli_die(2, "synth %s: %s", job->method, t->model_conflict);
    if ((t->caps & NL_METHOD_MODEL) && !alt && !g->acf == !g->spec) {
        if (t->model_missing)
            cli_die(2, "synth %s: %s", job->method, t->model_missing);
        cli_die(2, "synth: expected exactly one of --acf SPEC or --spectrum SPEC");
    }
}

/* Size, spacing, output names and the model. */
static void check_outputs_and_model(cli_synth_job *job, const cli_synth_args *g)
{
    char sbuf[1200];
    if (!g->size)
        cli_die(2, "synth: --size: expected N, NxM or NxMxK");
    if (!g->out)
        cli_die(2, "synth: -o: expected an output file (noiselab formats lists them)");
    job->dim = cli_parse_size("--size", g->size, job->n, 2);
    if (g->spacing)
        cli_parse_spacing("--spacing", g->spacing, job->dim, job->h);
    int at = cli_synth_cond_check_out(&g->cond, g->out, job->dim); /* -o the table of --at */
    if (g->precision && strcmp(g->precision, "single") && strcmp(g->precision, "double"))
        cli_die(2, "--precision: expected single or double, got \"%s\"", g->precision);
    cli_h5_double = g->precision && !strcmp(g->precision, "double");
    cli_field_single = g->precision && !strcmp(g->precision, "single");
    if (!at)
        cli_field_out_check("-o", g->out, job->dim);
    if (g->preview && job->dim == 1)
        cli_die(2, "--preview: expected a 2D or 3D field, got --size \"%s\"", g->size);
    if (g->preview && !cli_has_ext(g->preview, ".png"))
        cli_die(2, "--preview: expected a file name ending in .png, got \"%s\"", g->preview);
    if (g->acf || g->spec) {
        cli_check(nl_model_parse(g->acf ? g->acf : cli_spectrum_spec(g->spec, sbuf, sizeof sbuf), &job->m));
        if (g->acf && nl_model_is_spectral(job->m))
            cli_die(2, "--acf: \"%s\" is a spectrum model; pass it with --spectrum", g->acf);
        if (g->spec && !nl_model_is_spectral(job->m))
            cli_die(2, "--spectrum: \"%s\" is an autocorrelation model; pass it with --acf", g->spec);
    }
}

static void print_json(const cli_synth_job *job, const nl_meta *meta, const cli_synth_result *res,
                       const cli_synth_cond *cond)
{
    json_t *o = cli_synth_json(job, meta, res);
    cli_synth_cond_report(cond, o);
    cli_json_print(o);
}

/* Nothing non-finite is written, and an EXR (float32) holds every sample. */
static void check_output(const cli_synth_job *job, const cli_synth_args *g, const nl_field *f)
{
    const char *out = cli_synth_cond_grid(&g->cond, g->out);
    int exr = out && cli_field_is_float32(out);
    size_t k;
    if (nl_field_check_finite(f, exr ? FLT_MAX : INFINITY, &k))
        cli_die(2, "synth %s%s%s: %s%s; %s not written", job->method, job->m ? " " : "",
                job->m ? nl_model_spec(job->m) : "", nl_errmsg(),
                isfinite(f->data[k]) ? " of float32 (lower the variance)" : "", g->out);
}

/* Realization k: the method's field, conditioned when asked, written with its preview. */
static void realization(cli_synth_job *job, cli_synth_args *g, nl_field *f,
                        cli_synth_result *res, size_t k, const char *const *tmps)
{
    char obuf[4096], pbuf[4096];
    const char *out = cli_synth_cond_name(&g->cond, cli_synth_cond_grid(&g->cond, g->out), k, obuf, sizeof obuf);
    const char *prev = cli_synth_cond_name(&g->cond, g->preview, k, pbuf, sizeof pbuf);
    const char *tmp = tmps[0], *ptmp = tmps[1];
    nl_meta meta;
    int st;
    json_decref(res->report);
    memset(res, 0, sizeof *res);
    cli_synth_run(job, f, res);
    cli_synth_cond_apply(&g->cond, job, f, res, k);
    cli_synth_cond_accumulate(&g->cond, f, k);
    cli_synth_fill_meta(job, f, res, &meta);
    check_output(job, g, f);
    cli_phase("synth", "writing");
    cli_synth_cond_write(&g->cond, out, tmp, f, &meta);
    if (prev && (st = nl_png_write_field(ptmp, f, res->offset - 3 * res->sd, res->offset + 3 * res->sd)))
        cli_die_status(st);
    cli_out_commit(out);
    cli_out_commit(prev);
    if (k + 1 == g->cond.K)
        cli_synth_cond_finish(&g->cond, &meta);
    if (g->json && k + 1 == g->cond.K)
        print_json(job, &meta, res, &g->cond);
}

int cli_cmd_synth(int argc, char **argv)
{
    cli_synth_job job;
    cli_synth_args g;
    cli_synth_result res;
    nl_field *f;

    job_defaults(&job);
    memset(&g, 0, sizeof g);
    memset(&res, 0, sizeof res);
    g.cond.K = 1, g.cond.interp = NL_INTERP_LINEAR;
    if (parse_options(argc, argv, &job, &g))
        return 0;
    method_source(argc, argv, &job, &g);
    job.type = find_method(job.method);
    check_method_options(&job, &g);
    if (g.origin && !g.from)
        parse_origin(g.origin, job.origin);
    check_model_given(&job, &g);
    check_outputs_and_model(&job, &g);
    if (cli_is_h5(g.out) && (g.cond.data || g.cond.K > 1 || g.preview) && cli_h5 && cli_h5->launched)
        cli_die(2, "synth: --condition, --realizations and --preview run on one process; without mpirun, "
                "or with an .exr output");
    if (cli_h5 && cli_h5->launched && cli_is_h5(g.out))
        return cli_h5->synth(&job, g.out, cli_synth_run, g.json);
    if (cli_h5 && cli_h5->size > 1)
        cli_die(2, "-o: a run on %d processes writes one HDF5 file; expected OUT.h5, got \"%s\"", cli_h5->size,
                g.out);
    if (cli_is_h5(g.out))
        cli_h5->check_memory(&job, cli_synth_run);
    cli_synth_cond_prepare(&g.cond, &job, g.from != NULL, g.spacing != NULL);
    const char **tmps = cli_malloc(2 * g.cond.K * sizeof *tmps);
    for (size_t k = 0; k < g.cond.K; k++) { /* every output can be written, before the work */
        char ob[4096], pb[4096];
        const char *grid = cli_synth_cond_grid(&g.cond, g.out); /* -o, or --grid-out with --at */
        tmps[2 * k] = cli_out_begin(cli_synth_cond_name(&g.cond, grid, k, ob, sizeof ob));
        tmps[2 * k + 1] = cli_out_begin(cli_synth_cond_name(&g.cond, g.preview, k, pb, sizeof pb));
    }
    cli_synth_cond_begin(&g.cond, g.out);
    f = cli_field_alloc(job.dim, job.n, job.h);
    uint64_t seed0 = job.seed;
    for (size_t k = 0; k < g.cond.K; k++) {
        cli_phase("synth", job.method);
        job.seed = seed0 + k;
        realization(&job, &g, f, &res, k, tmps + 2 * k);
    }
    free(tmps);
    cli_progress_done();
    cli_synth_cond_note(&g.cond);
    json_decref(res.report);
    cli_synth_cond_free(&g.cond);
    nl_field_free(f);
    nl_model_free(job.m);
    return 0;
}
