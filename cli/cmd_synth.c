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

static const char help[] =
    "usage: noiselab synth METHOD (--acf SPEC | --spectrum SPEC) --size N[xM[xK]]\n"
    "                      [--seed S] [--spacing H[,H...]] [--clamp] [--preview P.png]\n"
    "                      [--json] [method options] -o OUT.exr|OUT.tsv|OUT.h5\n"
    "                      [--precision single|double]\n\n"
    "METHOD\n"
    "  fft       periodic Fourier synthesis: white noise filtered by the square root of\n"
    "            the model's spectrum on the periodic grid; Gaussian, zero ensemble mean,\n"
    "            variance R(0), covariance exactly the model's R sampled on the torus.\n"
    "            The same seed and size give the same white noise for every model.\n"
    "  subdiv    generalized stochastic subdivision (Lewis 1987), 1D or 2D:\n"
    "            --levels L          levels of refinement (default: down to a coarse grid\n"
    "                                of 8 samples, or 6 levels with --nonperiodic)\n"
    "            --neighborhood N|auto  half-width of the neighbourhood (default 2: 4 or 4x4)\n"
    "            --tol [variance:]E  auto: grow N until (7) improves by < E R(0) (1e-4), or is < E R(0)\n"
    "            --nonperiodic       a window of an infinite, spatially consistent field\n"
    "            --origin X[,Y]      the window's first sample, in output samples (default 0)\n"
    "            --seed-image FILE   start from this image as the coarse level (kept exactly)\n"
    "            --random-neighborhoods K  2D: K random quadrilateral neighbourhoods per\n"
    "                                point class, one drawn per point (against diagonal bias)\n"
    "            --displacements independent|correlated  independent: Lewis's, each new\n"
    "                                point displaced on its own (eq. 7); correlated: the new\n"
    "                                points of a level displaced together, with the covariance\n"
    "                                of their estimation errors, by a filter of white noise\n"
    "                                (default independent)\n"
    "            --taps M            correlated: the filter's half-width in cells (default 4 in\n"
    "                                1D, 2 in 2D; at most 16)\n"
    "  circulant exact stationary field on a NON-periodic grid by circulant embedding\n"
    "            (Dietrich-Newsam, Wood-Chan): the embedding doubles until its eigenvalues\n"
    "            are non-negative, up to 16x the size; the report gives the embedding and\n"
    "            the smallest eigenvalue\n"
    "  cholesky  direct simulation by the Cholesky factor of the covariance matrix; exact,\n"
    "            O(N^3), at most 8192 samples: the ground truth for small grids\n"
    "  faulting  Poisson faulting (Mandelbrot): random steps in 1D, random lines in 2D;\n"
    "            --density D faults per sample (1D) or lines per (nx + ny) (2D); no model:\n"
    "            the spectrum is f^-2 (1D), k^-3 radially (2D)\n"
    "  sparse    sparse convolution (Lewis GI '86): Poisson impulses in cells, convolved with\n"
    "            a kernel: the model's (R = h * h), --kernel EXPR in x, y (t, r), or --exemplar\n"
    "            FILE (Hann-windowed, for texture resynthesis); --density D impulses per\n"
    "            cell (default 1), --cell C and --radius R in samples, --wrap for a periodic\n"
    "            tile, --origin X[,Y] for a window of the infinite field, --angle EXPR in\n"
    "            x, y rotating the kernel with position; the report predicts the excess\n"
    "            kurtosis 3 sum h^4 / (lambda (sum h^2)^2); a kernel losing more than 1e-3\n"
    "            of its energy at the radius is flagged truncated=FRACTION\n"
    "  lattice   interpolated noise lattice (Perlin gradient noise) summed over octaves,\n"
    "            weighted to the target spectrum's power in each octave's band; --cell C\n"
    "            largest lattice cell (default size/4), --octaves O (default: down to cell\n"
    "            2); the report gives each octave's weight and its low-frequency leakage;\n"
    "            --interpolant wiener: one lattice of the target's own covariance (FFT on\n"
    "            the lattice), every sample its simple-kriging (Wiener) estimate from the\n"
    "            4 (1D) or 4x4 nearest nodes; --cell C the node spacing (default 4)\n"
    "  midpoint  midpoint displacement (Fournier, Fussell and Carpenter), nearest neighbours\n"
    "            only; --H h (Hurst exponent) or --acf/--spectrum power:d=D with d = 2H + 1\n"
    "            (1D), --levels L, --variance-scale Q multiplies the variance of each level\n"
    "            by an extra Q (Haruyama-Barsky-style altered variances); --interpolant\n"
    "            miller: Miller's square-square subdivision (each level a new grid of\n"
    "            half the spacing, weights 9/16 3/16 3/16 1/16 of the parent square;\n"
    "            1D 3/4 1/4) instead of the nearest-neighbour midpoint (fournier)\n\n"
    "  --acf SPEC       autocorrelation model (see noiselab models)\n"
    "  --spectrum SPEC  spectrum model: power:d=..., spectrum:EXPR, or a bare EXPR in f/fx/fy/k\n"
    "  --size           samples per axis, each >= 2 (fft: 1D, 2D or 3D; subdiv: 1D or 2D)\n"
    "  --seed           64-bit seed (default 1)\n"
    "  --spacing        output grid spacing, one value or one per axis (default 1)\n"
    "  --clamp          synthesise a model that is not positive definite by zeroing its\n"
    "                   negative spectrum (fft, circulant, sparse, lattice) or variances\n"
    "                   (subdiv); flagged \"clamped\" in the output, the change in the report\n"
    "  --preview        8-bit PNG of a 2D field (the first slice of 3D), mean +- 3 sd\n"
    "  --json           print the synthesis report as JSON\n"
    "  --condition DATA.tsv --extent a:b[,c:d[,e:f]]  fft, circulant, subdiv: honour the\n"
    "                   data (conditional simulation, Journel: the field plus the ordinary\n"
    "                   kriging of data minus field; --mean M: simple); sample i at\n"
    "                   a + (i + 0.5)(b - a)/N; --interpolation bilinear|nearest reads the field\n"
    "                   between samples; --realizations K: OUT-1.exr ... OUT-K.exr, seeds S..;\n"
    "                   --ensemble-mean M.exr, --ensemble-variance V.exr (divisor K - 1);\n"
    "                   --nmax K: local kriging from the K nearest data (as krige)\n"
    "  --from FILE      regenerate FILE from what it records (method, options, model,\n"
    "                   seed, size, spacing): bit for bit for every method\n"
    "  -o               EXR (any dimension; attributes noiselab.model, .method, .seed,\n"
    "                   .size, .spacing, .origin, .version, .flags) or TSV (1D: the same as\n"
    "                   \"# key: value\" lines, then columns t, value, t = (origin + i) h);\n"
    "                   or HDF5 (.h5: dataset /field, float32, attributes model, method, seed,\n"
    "                   size, spacing, origin, version, flags, processes; read by noiselab-mpi,\n"
    "                   which noiselab hands .h5 runs to); nothing is written unless every\n"
    "                   sample is finite (and, in float32, within its range)\n"
    "  --precision single|double  .h5 outputs: float32 (default) or float64\n"
    "Under an MPI launcher (mpirun -np P noiselab synth ... -o OUT.h5) fft, circulant,\n"
    "subdiv and sparse run distributed, each process holding 1/P of the field\n"
    "(docs/scale-out.md).\n";

/* What the command line gave, beyond the job itself. */
typedef struct {
    const char *acf, *spec, *size, *spacing, *out, *preview, *origin, *from; /* option values or NULL */
    const char *precision;                           /* --precision single|double (.h5 outputs) */
    int json;                                        /* --json */
    int given_L, given_N, given_tol, given_vs, given_density, given_disp; /* explicitly given */
    cli_synth_cond cond;                             /* --condition and its options */
} cli_synth_args;

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

/* An integer option in min..max, checked before it is narrowed to int. */
static int parse_int(const char *opt, const char *s, int min, int max)
{
    return cli_synth_parse_int(opt, s, min, max);
}

static int parse_displacements(const char *opt, const char *s)
{
    if (!strcmp(s, "independent"))
        return NL_SUBDIV_DISP_INDEPENDENT;
    if (!strcmp(s, "correlated"))
        return NL_SUBDIV_DISP_ERROR;
    cli_die(2, "%s: expected independent or correlated, got \"%s\"", opt, s);
    return 0;
}

/* The method's recorded options: "k=v,...|k=v|..." (what follows "name:"
 * in the method string written by the methods). */
static void apply_keys(char *rest, cli_synth_job *job)
{
    char *part, *save = NULL;
    for (part = strtok_r(rest, "|", &save); part; part = strtok_r(NULL, "|", &save)) {
        if (part != rest) {  /* an expression-valued key: the rest of the part */
            char *eq = strchr(part, '=');
            if (!eq)
                continue;
            *eq = 0;
            if (!strcmp(part, "kernel")) job->kernel = eq + 1;
            else if (!strcmp(part, "exemplar")) job->exemplar = eq + 1;
            else if (!strcmp(part, "angle")) job->angle = eq + 1;
            else if (!strcmp(part, "seed-image")) job->seed_image = eq + 1;
            continue;
        }
        char *kv, *s2 = NULL;
        for (kv = strtok_r(part, ",", &s2); kv; kv = strtok_r(NULL, ",", &s2)) {
            char *eq = strchr(kv, '=');
            const char *v = eq ? eq + 1 : "";
            if (eq)
                *eq = 0;
            if (!strcmp(kv, "levels")) job->levels = parse_int("--from: levels", v, 0, 40);
            else if (!strcmp(kv, "neighborhood"))
                job->N = strcmp(v, "auto") ? parse_int("--from: neighborhood", v, 1, INT_MAX) : 0;
            else if (!strcmp(kv, "tol")) job->tol = cli_synth_parse_tol("--from: tol", v, &job->stop);
            else if (!strcmp(kv, "nonperiodic")) job->nonperiodic = 1;
            else if (!strcmp(kv, "origin")) {
                errno = 0;
                if (sscanf(v, "%ld:%ld", &job->origin[0], &job->origin[1]) != 2 || errno == ERANGE)
                    job->origin[0] = LONG_MAX;
                check_origin("--from: origin", v, job->origin);
            }
            else if (!strcmp(kv, "random-neighborhoods"))
                job->random_nb = parse_int("--from: random-neighborhoods", v, 1, 256);
            else if (!strcmp(kv, "displacements"))
                job->displacements = parse_displacements("--from: displacements", v);
            else if (!strcmp(kv, "taps")) job->taps = parse_int("--from: taps", v, 1, NL_SUBDIV_MAX_TAPS);
            else if (!strcmp(kv, "H")) job->H = cli_parse_double("--from: H", v);
            else if (!strcmp(kv, "variance-scale"))
                job->vscale = cli_parse_positive("--from: variance-scale", v, "factor");
            else if (!strcmp(kv, "density")) job->density = cli_parse_positive("--from: density", v, "number");
            else if (!strcmp(kv, "radius")) job->radius = parse_int("--from: radius", v, 1, 4096);
            else if (!strcmp(kv, "cell")) {
                job->cell0 = cli_parse_positive("--from: cell", v, "number");
                job->cell = job->cell0 < INT_MAX ? (int)job->cell0 : INT_MAX;
            }
            else if (!strcmp(kv, "wrap")) job->wrap = 1;
            else if (!strcmp(kv, "octaves")) job->octaves = parse_int("--from: octaves", v, 1, 16);
            else if (!strcmp(kv, "interpolant")) job->interpolant = v;
        }
    }
}

/* Regenerate from a field's provenance: the method string "name:k=v,...|k=v|..."
 * written by the methods, the model, seed, size and spacing. */
static void apply_from(const char *path, cli_synth_job *job, cli_synth_args *g)
{
    static char mbuf[1100], sizebuf[64], spbuf[128], methbuf[256];
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
    cli_check(nl_provenance_parse(&meta, NL_PROV_SEED | NL_PROV_MODEL, &prov));
    job->seed = prov.seed;
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
    if (rest)
        apply_keys(rest, job);
}

/* Options that only some methods take. */
static void only_for(const char *opt, int given, const char *method, const char *allowed)
{
    char list[64];
    snprintf(list, sizeof list, " %s ", allowed);
    char word[32];
    snprintf(word, sizeof word, " %s ", method);
    if (given && !strstr(list, word))
        cli_die(2, "synth %s: %s applies to %s only", method, opt, allowed);
}

static void job_defaults(cli_synth_job *job)
{
    memset(job, 0, sizeof *job);
    job->seed = 1;
    job->N = -1;
    job->tol = 1e-4;
    job->H = NAN;
    job->vscale = 1;
    job->density = 1;
    for (int a = 0; a < 3; a++)
        job->n[a] = 1, job->h[a] = 1;
}

/* The options with a numeric range of their own. */
static void parse_numeric(int c, cli_synth_job *job, cli_synth_args *g)
{
    switch (c) {
    case 'L':
        job->levels = parse_int("--levels", optarg, 1, 30);
        g->given_L = 1;
        break;
    case 'N':
        job->N = cli_synth_parse_neighborhood(optarg);
        g->given_N = 1;
        break;
    case 't':
        job->tol = cli_synth_parse_tol("--tol", optarg, &job->stop);
        g->given_tol = 1;
        break;
    case 'R':
        job->random_nb = parse_int("--random-neighborhoods", optarg, 1, 256);
        break;
    case 'X':
        job->displacements = parse_displacements("--displacements", optarg);
        g->given_disp = 1;
        break;
    case 'T':
        job->taps = parse_int("--taps", optarg, 1, NL_SUBDIV_MAX_TAPS);
        break;
    case 'u':
        job->H = cli_parse_double("--H", optarg);
        if (!(job->H > 0 && job->H < 1))
            cli_die(2, "--H: expected a Hurst exponent between 0 and 1, got \"%s\"", optarg);
        break;
    case 'v':
        job->vscale = cli_parse_positive("--variance-scale", optarg, "factor");
        g->given_vs = 1;
        break;
    case 'D':
        job->density = cli_parse_positive("--density", optarg, "number");
        g->given_density = 1;
        break;
    case 'V':
        job->octaves = parse_int("--octaves", optarg, 1, 16);
        break;
    }
}

/* getopt over argv into job and g; returns 1 when --help was printed. */
static int parse_options(int argc, char **argv, cli_synth_job *job, cli_synth_args *g)
{
    static const struct option opts[] = {
        {"acf", required_argument, 0, 'a'},        {"spectrum", required_argument, 0, 'S'},
        {"size", required_argument, 0, 'n'},       {"seed", required_argument, 0, 's'},
        {"spacing", required_argument, 0, 'H'},    {"clamp", no_argument, 0, 'c'},
        {"preview", required_argument, 0, 'p'},    {"json", no_argument, 0, 'j'},
        {"output", required_argument, 0, 'o'},     {"help", no_argument, 0, 'h'},
        {"levels", required_argument, 0, 'L'},     {"neighborhood", required_argument, 0, 'N'},
        {"tol", required_argument, 0, 't'},        {"nonperiodic", no_argument, 0, 'P'},
        {"origin", required_argument, 0, 'O'},     {"seed-image", required_argument, 0, 'I'},
        {"H", required_argument, 0, 'u'},          {"variance-scale", required_argument, 0, 'v'},
        {"random-neighborhoods", required_argument, 0, 'R'}, {"density", required_argument, 0, 'D'},
        {"kernel", required_argument, 0, 'K'},     {"exemplar", required_argument, 0, 'E'},
        {"angle", required_argument, 0, 'A'},      {"radius", required_argument, 0, 'r'},
        {"cell", required_argument, 0, 'C'},       {"wrap", no_argument, 0, 'W'},
        {"from", required_argument, 0, 'F'},
        {"octaves", required_argument, 0, 'V'},    {"interpolant", required_argument, 0, 'i'},
        {"displacements", required_argument, 0, 'X'}, {"taps", required_argument, 0, 'T'},
        {"condition", required_argument, 0, 'Y'}, {"extent", required_argument, 0, 'Z'},
        {"realizations", required_argument, 0, 'k'}, {"mean", required_argument, 0, 'M'},
        {"interpolation", required_argument, 0, 'Q'}, {"ensemble-mean", required_argument, 0, 'g'},
        {"ensemble-variance", required_argument, 0, 'J'}, {"nmax", required_argument, 0, 'q'},
        {"precision", required_argument, 0, 'G'},
        {0}};
    int c;
    while ((c = cli_getopt(argc, argv, ":ho:", opts, "synth")) != -1) {
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
        case 'L': case 'N': case 't': case 'R': case 'u': case 'v': case 'D': case 'V': case 'X': case 'T':
            parse_numeric(c, job, g);
            break;
        case 'P': job->nonperiodic = 1; break;
        case 'O': g->origin = optarg; break;
        case 'I': job->seed_image = optarg; break;
        case 'K': job->kernel = optarg; break;
        case 'E': job->exemplar = optarg; break;
        case 'A': job->angle = optarg; break;
        case 'r': job->radius = parse_int("--radius", optarg, 1, 4096); break;
        case 'C': job->cell = parse_int("--cell", optarg, 1, INT_MAX); break;
        case 'W': job->wrap = 1; break;
        case 'i': job->interpolant = optarg; break;
        case 'F': g->from = optarg; break;
        case 'G': g->precision = optarg; break;
        case 'Y': case 'Z': case 'k': case 'M': case 'Q': case 'g': case 'J': case 'q':
            cli_synth_cond_option(&g->cond, c, optarg); break;
        case 'h': fputs(help, stdout); return 1;
        }
    }
    return 0;
}

/* The method and its options from --from FILE or from the command line. */
static void method_source(int argc, char **argv, cli_synth_job *job, cli_synth_args *g)
{
    if (g->from) {
        if (optind < argc || g->acf || g->spec || g->size || g->spacing || g->given_L || g->given_N ||
            g->given_tol || g->given_vs || g->given_density || g->origin || job->nonperiodic || job->kernel ||
            job->exemplar || job->angle || job->radius || job->cell || job->wrap || job->octaves ||
            job->seed_image || job->random_nb || !isnan(job->H) || g->given_disp || job->taps || job->interpolant)
            cli_die(2, "synth: --from FILE takes the method and every option from FILE; give only -o, --preview "
                    "and --json");
        apply_from(g->from, job, g);
        job->from = 1;
        g->given_L = job->levels != 0;
        g->given_density = strcmp(job->method, "faulting") == 0 || strcmp(job->method, "sparse") == 0;
        g->given_N = strcmp(job->method, "subdiv") == 0;
        g->given_tol = g->given_N;
        g->given_vs = strcmp(job->method, "midpoint") == 0;
        if (job->nonperiodic && (job->origin[0] || job->origin[1]))
            g->origin = "recorded";
        return;
    }
    if (optind >= argc)
        cli_die(2, "synth: expected a METHOD (fft, subdiv, midpoint, circulant, cholesky, faulting, sparse or lattice), "
                "see noiselab synth --help");
    job->method = argv[optind];
    if (optind + 1 < argc)
        cli_die(2, "synth: unexpected argument \"%s\"", argv[optind + 1]);
}


static cli_synth_run_fn find_method(const char *method)
{
    static const struct {
        const char *name;
        cli_synth_run_fn run;
    } methods[] = {{"fft", cli_synth_fft_run},         {"subdiv", cli_synth_subdiv_run},
                   {"midpoint", cli_synth_midpoint_run}, {"circulant", cli_synth_circulant_run},
                   {"cholesky", cli_synth_cholesky_run}, {"faulting", cli_synth_faulting_run},
                   {"sparse", cli_synth_sparse_run}, {"lattice", cli_synth_lattice_run}};
    static const char *const planned[] = {"rank1"};
    for (size_t i = 0; i < sizeof methods / sizeof *methods; i++)
        if (strcmp(method, methods[i].name) == 0)
            return methods[i].run;
    for (size_t i = 0; i < sizeof planned / sizeof *planned; i++)
        if (strcmp(method, planned[i]) == 0)
            cli_die(2, "synth: method \"%s\" is not available in this version (available: fft, subdiv, "
                    "midpoint, circulant, cholesky, faulting, sparse, lattice)", method);
    cli_die(2, "synth: unknown method \"%s\" (expected fft, subdiv, midpoint, circulant, cholesky, faulting, "
            "sparse or lattice)",
            method);
    return NULL;
}

/* Each method-specific option against the method it was given with. */
static void check_method_options(const cli_synth_job *job, const cli_synth_args *g)
{
    only_for("--levels", g->given_L, job->method, "subdiv midpoint");
    only_for("--neighborhood", g->given_N, job->method, "subdiv");
    only_for("--tol", g->given_tol, job->method, "subdiv");
    only_for("--nonperiodic", job->nonperiodic, job->method, "subdiv");
    only_for("--origin", g->origin != NULL, job->method, "subdiv sparse");
    only_for("--kernel", job->kernel != NULL, job->method, "sparse");
    only_for("--exemplar", job->exemplar != NULL, job->method, "sparse");
    only_for("--angle", job->angle != NULL, job->method, "sparse");
    only_for("--radius", job->radius != 0, job->method, "sparse");
    only_for("--cell", job->cell != 0, job->method, "sparse lattice");
    only_for("--octaves", job->octaves != 0, job->method, "lattice");
    only_for("--interpolant", job->interpolant != NULL, job->method, "midpoint lattice");
    only_for("--wrap", job->wrap, job->method, "sparse");
    only_for("--seed-image", job->seed_image != NULL, job->method, "subdiv");
    only_for("--random-neighborhoods", job->random_nb != 0, job->method, "subdiv");
    only_for("--displacements", g->given_disp, job->method, "subdiv");
    only_for("--taps", job->taps != 0, job->method, "subdiv");
    if (job->random_nb && job->displacements)
        cli_die(2, "--displacements correlated: expected the standard neighbourhoods, got --random-neighborhoods %d "
                "(random neighbourhoods have no common error covariance)", job->random_nb);
    if (job->taps && job->displacements != NL_SUBDIV_DISP_ERROR)
        cli_die(2, "--taps %d: expected --displacements correlated (independent displacements have no filter)",
                job->taps);
    only_for("--H", !isnan(job->H), job->method, "midpoint");
    only_for("--variance-scale", g->given_vs, job->method, "midpoint");
    only_for("--density", g->given_density, job->method, "faulting sparse");
    if (g->origin && job->wrap)
        cli_die(2, "synth sparse: --origin \"%s\" and --wrap exclude each other (a periodic tile has no origin)",
                g->origin);
    if (g->origin && !job->nonperiodic && strcmp(job->method, "subdiv") == 0)
        cli_die(2, "synth subdiv: --origin needs --nonperiodic (a periodic field has no origin)");
}

/* Which methods need a model, and whether exactly one was given. */
static void check_model_given(const cli_synth_job *job, const cli_synth_args *g)
{
    if (strcmp(job->method, "midpoint") == 0 && !isnan(job->H) && (g->acf || g->spec))
        cli_die(2, "synth midpoint: give either --H or a power-law model, not both");
    int needs_model = !(strcmp(job->method, "midpoint") == 0 && !isnan(job->H)) && strcmp(job->method, "faulting") &&
                      !(strcmp(job->method, "sparse") == 0 && (job->kernel || job->exemplar));
    if (!needs_model && (g->acf || g->spec) && strcmp(job->method, "faulting") == 0)
        cli_die(2, "synth faulting: takes no model (its spectrum is f^-2); got --acf/--spectrum");
    if (needs_model && !g->acf == !g->spec) {
        if (strcmp(job->method, "sparse") == 0)
            cli_die(2, "synth sparse: expected exactly one kernel: --acf/--spectrum SPEC, --kernel EXPR or "
                    "--exemplar FILE");
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
        cli_die(2, "synth: -o: expected an output file (.exr or .tsv)");
    job->dim = cli_parse_size("--size", g->size, job->n, 2);
    if (g->spacing)
        cli_parse_spacing("--spacing", g->spacing, job->dim, job->h);
    if (!cli_has_ext(g->out, ".exr") && !cli_has_ext(g->out, ".tsv") && !cli_is_h5(g->out))
        cli_die(2, "-o: expected a file name ending in .exr, .tsv or .h5, got \"%s\"", g->out);
    if (g->precision && strcmp(g->precision, "single") && strcmp(g->precision, "double"))
        cli_die(2, "--precision: expected single or double, got \"%s\"", g->precision);
    cli_h5_double = g->precision && !strcmp(g->precision, "double");
    if (cli_h5_double && !cli_is_h5(g->out))
        cli_die(2, "--precision double: EXR stores float32 and TSV ten digits; expected an .h5 output, got \"%s\"",
                g->out);
    if (cli_has_ext(g->out, ".tsv") && job->dim != 1)
        cli_die(2, "-o: TSV holds 1D fields; use .exr for a %dD field, got \"%s\"", job->dim, g->out);
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
    int exr = cli_has_ext(g->out, ".exr") || (cli_is_h5(g->out) && !cli_h5_double);
    size_t k;
    if (nl_field_check_finite(f, exr ? FLT_MAX : INFINITY, &k))
        cli_die(2, "synth %s%s%s: %s%s; %s not written", job->method, job->m ? " " : "",
                job->m ? nl_model_spec(job->m) : "", nl_errmsg(),
                isfinite(f->data[k]) ? " of float32 (lower the variance)" : "", g->out);
}

/* Realization k: the method's field, conditioned when asked, written with its preview. */
static void realization(cli_synth_job *job, cli_synth_args *g, cli_synth_run_fn run, nl_field *f,
                        cli_synth_result *res, size_t k, const char *const *tmps)
{
    char obuf[4096], pbuf[4096];
    const char *out = cli_synth_cond_name(&g->cond, g->out, k, obuf, sizeof obuf);
    const char *prev = cli_synth_cond_name(&g->cond, g->preview, k, pbuf, sizeof pbuf);
    const char *tmp = tmps[0], *ptmp = tmps[1];
    nl_meta meta;
    int st;
    json_decref(res->report);
    memset(res, 0, sizeof *res);
    run(job, f, res);
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
    cli_synth_run_fn run;
    nl_field *f;

    job_defaults(&job);
    memset(&g, 0, sizeof g);
    memset(&res, 0, sizeof res);
    g.cond.K = 1, g.cond.interp = NL_INTERP_LINEAR;
    if (parse_options(argc, argv, &job, &g))
        return 0;
    method_source(argc, argv, &job, &g);
    run = find_method(job.method);
    check_method_options(&job, &g);
    if (g.origin && !g.from)
        parse_origin(g.origin, job.origin);
    check_model_given(&job, &g);
    check_outputs_and_model(&job, &g);
    if (cli_is_h5(g.out) && (g.cond.data || g.cond.K > 1 || g.preview) && cli_h5 && cli_h5->launched)
        cli_die(2, "synth: --condition, --realizations and --preview run on one process; without mpirun, "
                "or with an .exr output");
    if (cli_h5 && cli_h5->launched && cli_is_h5(g.out))
        return cli_h5->synth(&job, g.out, run, g.json);
    if (cli_h5 && cli_h5->size > 1)
        cli_die(2, "-o: a run on %d processes writes one HDF5 file; expected OUT.h5, got \"%s\"", cli_h5->size,
                g.out);
    if (cli_is_h5(g.out))
        cli_h5->check_memory(&job, run);
    cli_synth_cond_prepare(&g.cond, &job, g.from != NULL, g.spacing != NULL);
    const char **tmps = cli_malloc(2 * g.cond.K * sizeof *tmps);
    for (size_t k = 0; k < g.cond.K; k++) { /* every output can be written, before the work */
        char ob[4096], pb[4096];
        tmps[2 * k] = cli_out_begin(cli_synth_cond_name(&g.cond, g.out, k, ob, sizeof ob));
        tmps[2 * k + 1] = cli_out_begin(cli_synth_cond_name(&g.cond, g.preview, k, pb, sizeof pb));
    }
    cli_synth_cond_begin(&g.cond);
    f = cli_field_alloc(job.dim, job.n, job.h);
    uint64_t seed0 = job.seed;
    for (size_t k = 0; k < g.cond.K; k++) {
        cli_phase("synth", job.method);
        job.seed = seed0 + k;
        realization(&job, &g, run, f, &res, k, tmps + 2 * k);
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
