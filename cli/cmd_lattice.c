/* noiselab lattice: rank-1 lattices, their wave vectors, and random fields
 * synthesised on them with one FFT (Keller 2001). */
#include "cli.h"
#include "opt.h"
#include "../core/nl_error.h"
#include "../core/io_obj.h"
#include "../synth/rank1_model.h"

#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char help[] =
    "usage: noiselab lattice --points N --dim S [--generator fibonacci|korobov[:A]|G1,...,GS]\n"
    "                        [--acf SPEC | --spectrum SPEC] [--extent E] [--seed X]\n"
    "                        [--wave-vectors] [--json] [-o OUT.tsv] [--mesh OUT.obj] [--clamp]\n"
    "                        [--image OUT.exr|OUT.png [--size W] [--at X3[,X4]]]\n\n"
    "Rank-1 lattice x_n = (n/N) g mod 1 (Keller 2001).  Generators: fibonacci (2D, N a\n"
    "Fibonacci number, g = (1, F_{k-1})), korobov (g = (1, a, a^2, ...) with a searched\n"
    "for the largest minimum distance, or given), or explicit.  Default: fibonacci in 2D\n"
    "when N is a Fibonacci number, korobov otherwise.\n"
    "  --wave-vectors  print K_N: for each residue m the k with k.g = m (mod N) of least\n"
    "                  norm (TSV m k1..kS norm; --json {\"N\", \"generator\", \"wave_vectors\"})\n"
    "  with a model: a field on the N points by ONE complex FFT of length N, on a torus\n"
    "  of side E (default 1): TSV columns x1..xS value grad1..gradS; a model that is\n"
    "  not positive definite on the lattice (negative spectrum) is refused, or with\n"
    "  --clamp its negative values are zeroed and the header gives the change\n"
    "  --mesh OBJ      (2D) the periodic Delaunay triangulation of the height field\n"
    "  --image         (2D to 4D, with a model) the field between the lattice points: its\n"
    "                  trigonometric series on a W x W grid (default 256) over the first\n"
    "                  two coordinates, by one W x W FFT through the wave vectors, the\n"
    "                  others fixed by --at (unit torus coordinates, default 0); EXR of\n"
    "                  the values, or PNG from -3 to +3 standard deviations\n";

/* The command's options. */
typedef struct {
    const char *gen, *spec, *out, *mesh;  /* as given, or NULL */
    const char *image;                    /* --image, or NULL */
    size_t W;                             /* --size */
    double at[2];                         /* --at */
    size_t N;                             /* --points */
    int s, wv, json, spectral, clamp;     /* --dim, --wave-vectors, --json, --spectrum given, --clamp */
    char note[240];                       /* what the synthesis approximated, for the header */
    double extent;                        /* --extent */
    uint64_t seed;                        /* --seed */
    const char *seed_text, *at_text;      /* --seed and --at as given, or NULL */
} opts_t;

/* --acf SPEC or --spectrum SPEC (one of them: cli/opt.h). */
static void model_option(void *obj, const char *label, const char *arg)
{
    opts_t *a = obj;
    a->spec = arg, a->spectral = strcmp(label, "--spectrum") == 0;
}

static void size_option(void *obj, const char *label, const char *arg)
{
    opts_t *a = obj;
    a->W = cli_parse_count(label, arg, 2);
    if (a->W > 8192)
        cli_die(2, "--size: expected at most 8192 pixels a side, got %zu", a->W);
}

static void at_option(void *obj, const char *label, const char *arg)
{
    opts_t *a = obj;
    char *e;
    a->at[0] = strtod(arg, &e);
    if (*e == ',')
        a->at[1] = strtod(e + 1, &e);
    if (*e || !(fabs(a->at[0]) <= 1e9) || !(fabs(a->at[1]) <= 1e9))
        cli_die(2, "%s: expected X3[,X4] within 1e9, got \"%s\"", label, arg);
    a->at_text = arg;
}

static void seed_option(void *obj, const char *label, const char *arg)
{
    opts_t *a = obj;
    a->seed = cli_parse_u64(label, arg);
    a->seed_text = arg;
}

static const cli_opt rows[] = {
    CLI_COUNT("points", opts_t, N, .lo = 2, .need = "the number of lattice points"),
    CLI_OPT_DIMS(opts_t, s, 4, .need = "1 to 4"), CLI_STRING("generator", opts_t, gen), CLI_CALL("acf", model_option),
    CLI_CALL("spectrum", model_option), CLI_POSITIVE("extent", opts_t, extent, .what = "length"),
    CLI_CALL("seed", seed_option), CLI_FLAG("wave-vectors", opts_t, wv), CLI_OPT_JSON(opts_t, json),
    CLI_OPT_OUTPUT(opts_t, out), CLI_STRING("mesh", opts_t, mesh), CLI_FLAG("clamp", opts_t, clamp),
    CLI_STRING("image", opts_t, image), CLI_CALL("size", size_option), CLI_CALL("at", at_option), {0}};

static void parse(int argc, char **argv, opts_t *a)
{
    if (cli_opt_parse("lattice", help, rows, a, argc, argv))
        exit(0);
    cli_no_operands("lattice", argc, argv);
    cli_opt_need("lattice", rows, a);
    if (a->N > (1u << 24))
        cli_die(2, "--points: expected at most 16777216, got %zu", a->N);
    if (a->mesh && a->s != 2)
        cli_die(2, "--mesh: expected --dim 2, got %d", a->s);
    if (!a->spec && a->seed_text)
        cli_die(2, "--seed \"%s\": expected a model (--acf or --spectrum): without one there is no field",
                a->seed_text);
    if (!a->spec && a->clamp)
        cli_die(2, "--clamp: expected a model (--acf or --spectrum): without one there is no field");
    if (!a->image && a->W)
        cli_die(2, "--size %zu: expected --image (the size of its picture)", a->W);
    if (!a->image && a->at_text)
        cli_die(2, "--at \"%s\": expected --image (where its picture cuts the lattice)", a->at_text);
    if (a->image && (a->s < 2 || !a->spec))
        cli_die(2, "--image: expected --dim 2 to 4 and a model (--acf or --spectrum)");
    if (a->image && !cli_has_ext(a->image, ".exr") && !cli_has_ext(a->image, ".png"))
        cli_die(2, "--image: expected a file ending in .exr or .png, got \"%s\"", a->image);
}

/* The lattice of --generator (default: fibonacci in 2D when N is a
 * Fibonacci number, korobov otherwise). */
static void make_lattice(opts_t *a, nl_rank1_lattice *L)
{
    size_t N = a->N;
    int s = a->s, st;
    if (!a->gen)
        a->gen = s == 2 && nl_rank1_fibonacci_index(N) ? "fibonacci" : "korobov";
    const char *gen = a->gen;
    if (strcmp(gen, "fibonacci") == 0) {
        if (s != 2 || !nl_rank1_fibonacci_index(N))
            cli_die(2, "--generator fibonacci: expected --dim 2 and a Fibonacci number of points, got %zu in %dD", N, s);
        st = nl_rank1_fibonacci(nl_rank1_fibonacci_index(N), L);
    } else if (strncmp(gen, "korobov", 7) == 0) {
        long k = 0;
        char *end = NULL;
        if (gen[7] && (gen[7] != ':' || (k = strtol(gen + 8, &end, 10)) <= 0 || *end || k == LONG_MAX))
            cli_die(2, "--generator: expected korobov:A with 0 < A < 2^63 - 1, got \"%s\"", gen);
        if (k > 0) {
            long g[NL_RANK1_MAX_DIM] = {1};
            for (int d = 1; d < s; d++)
                g[d] = (long)((unsigned long long)g[d - 1] * (unsigned long long)(k % (long)N) % N);
            if ((st = nl_rank1_check_generator(N, s, g)))
                cli_die(2, "--generator %s: %s", gen, nl_errmsg());
        }
        st = nl_rank1_korobov(N, s, k, L);
    } else {
        long g[NL_RANK1_MAX_DIM];
        char *p = (char *)gen, *end;
        int k = 0;
        errno = 0;
        while (k < NL_RANK1_MAX_DIM) {
            g[k++] = strtol(p, &end, 10);
            if (end == p)
                break;
            if (*end != ',')
                break;
            p = end + 1;
        }
        if (k != s || *end || end == p || errno == ERANGE)
            cli_die(2, "--generator: expected fibonacci, korobov[:A] or %d integers G1,...,G%d, got \"%s\"", s, s, gen);
        if ((st = nl_rank1_check_generator(N, s, g)))
            cli_die(2, "--generator %s: %s", gen, nl_errmsg());
        st = nl_rank1_generator(N, s, g, L);
    }
    cli_check(st);
    /* a 2D default generator of very few points can be degenerate too (N =
     * 3: (1, 2), every point on x1 + x2 = 0), and then has no Delaunay
     * mesh; in more dimensions the defaults are left as they were */
    if (s == 2 && (st = nl_rank1_check_generator(N, s, L->g))) {
        const char *why = nl_errmsg(), *pre = "generator: degenerate: ";
        if (strncmp(why, pre, strlen(pre)) == 0)
            why += strlen(pre);
        nl_rank1_free(L);
        cli_die(2, "--points %zu: the %s lattice of %zu points is degenerate: %s; expected more points", N, gen, N,
                why);
    }
}

static void print_wave_vectors(const opts_t *a, const nl_rank1_lattice *L)
{
    size_t N = a->N;
    int s = a->s;
    if (a->json) {
        json_t *o = json_pack("{s:I,s:[],s:[]}", "N", (json_int_t)N, "generator", "wave_vectors");
        json_t *ga = json_object_get(o, "generator"), *wa = json_object_get(o, "wave_vectors");
        for (int d = 0; d < s; d++)
            json_array_append_new(ga, json_integer(L->g[d]));
        for (size_t m = 0; m < N; m++) {
            json_t *k = json_array();
            for (int d = 0; d < s; d++)
                json_array_append_new(k, json_integer(L->k[m * s + d]));
            json_array_append_new(wa, k);
        }
        cli_json_print(o);
        return;
    }
    printf("# N %zu, generator", N);
    for (int d = 0; d < s; d++)
        printf(" %ld", L->g[d]);
    printf(", minimum distance %.6g\nm", L->min_dist);
    for (int d = 0; d < s; d++)
        printf("\tk%d", d + 1);
    printf("\tnorm\n");
    for (size_t m = 0; m < N; m++) {
        printf("%zu", m);
        for (int d = 0; d < s; d++)
            printf("\t%ld", L->k[m * s + d]);
        printf("\t%.6g\n", nl_rank1_wave_norm(L, m));
    }
}

/* The points (scaled by extent) and, with f, the field and its gradient. */
static void write_points(FILE *fp, const opts_t *a, const nl_rank1_lattice *L, const double *f, const double *grad,
                         double imag)
{
    int s = a->s;
    if (f) {
        fprintf(fp, "# noiselab lattice: N %zu, dim %d, %s, seed %llu, extent %g, max |imag| %.3g%s\n", a->N, s,
                a->spec, (unsigned long long)a->seed, a->extent, imag, a->note);
        for (int d = 0; d < s; d++)
            fprintf(fp, "x%d\t", d + 1);
        fprintf(fp, "value");
        for (int d = 0; d < s; d++)
            fprintf(fp, "\tgrad%d", d + 1);
        fprintf(fp, "\n");
    } else
        for (int d = 0; d < s; d++)
            fprintf(fp, "x%d%c", d + 1, d + 1 < s ? '\t' : '\n');
    for (size_t n = 0; n < a->N; n++) {
        double x[NL_RANK1_MAX_DIM];
        nl_rank1_point(L, n, x);
        if (!f) {
            for (int d = 0; d < s; d++)
                fprintf(fp, "%.10g%c", x[d] * a->extent, d + 1 < s ? '\t' : '\n');
            continue;
        }
        for (int d = 0; d < s; d++)
            fprintf(fp, "%.10g\t", x[d] * a->extent);
        fprintf(fp, "%.10g", f[n]);
        for (int d = 0; d < s; d++)
            fprintf(fp, "\t%.10g", grad[n * s + d]);
        fprintf(fp, "\n");
    }
}

/* -o (stdout when there is no other output) and --mesh. */
static void write_outputs(const opts_t *a, const nl_rank1_lattice *L, const double *f, const double *grad,
                          double imag)
{
    char comment[1200];
    nl_rank1_mesh me;
    int st;
    if (a->out) {
        FILE *fp = fopen(cli_out_begin(a->out), "w");
        if (!fp)
            cli_die(2, "-o: cannot write \"%s\"", a->out);
        write_points(fp, a, L, f, grad, imag);
        if (fclose(fp))
            cli_die(1, "-o: write failed");
    } else if (f && !a->mesh && !a->wv && !a->image)
        write_points(stdout, a, L, f, grad, imag);
    if (a->mesh) {
        snprintf(comment, sizeof comment, "noiselab lattice: periodic Delaunay triangulation, N %zu, %s", a->N,
                 a->spec ? a->spec : "");
        if ((st = nl_rank1_mesh_init(L, a->extent, f, &me)) ||
            (st = nl_obj_write_triangles(cli_out_begin(a->mesh), f ? comment : NULL, 2 * a->N,
                                         nl_rank1_mesh_triangle, &me)))
            cli_die_status(st);
    }
    cli_out_commit(a->out);
    cli_out_commit(a->mesh);
}

/* --image: the series on the W x W grid. */
static void write_image(const opts_t *a, const nl_rank1_lattice *L, const double *coef)
{
    size_t W = a->W ? a->W : 256, n[2] = {W, W};
    double sp[2] = {a->extent / (double)W, a->extent / (double)W}, var = 0;
    nl_meta meta = {0};
    cli_check(nl_size_check(2, n, 3 * sizeof(double), 1, NULL));
    nl_field *img = cli_field_alloc(2, n, sp);
    cli_check(nl_rank1_grid(L, coef, a->extent, W, a->at, img->data, NULL, NULL, NULL));
    for (size_t m = 0; m < L->N; m++)
        var += coef[2 * m] * coef[2 * m] + coef[2 * m + 1] * coef[2 * m + 1];
    const char *tmp = cli_out_begin(a->image);
    if (cli_has_ext(a->image, ".png"))
        cli_check(nl_png_write_field(tmp, img, -3 * sqrt(var), 3 * sqrt(var) + (var > 0 ? 0 : 1)));
    else {
        snprintf(meta.model, sizeof meta.model, "%s", a->spec);
        snprintf(meta.method, sizeof meta.method, "rank1:N=%zu,dim=%d,at=%g,%g", L->N, L->s, a->at[0], a->at[1]);
        snprintf(meta.seed, sizeof meta.seed, "%llu", (unsigned long long)a->seed);
        cli_check(nl_exr_write(tmp, img, &meta));
    }
    cli_out_commit(a->image);
    nl_field_free(img);
}

/* The field of --acf/--spectrum on the lattice, and its outputs. */
static void field(opts_t *a, const nl_rank1_lattice *L)
{
    nl_model *m;
    double *f, *grad, imag;
    char sbuf[1100];
    int st;
    if (a->spectral)
        a->spec = cli_spectrum_spec(a->spec, sbuf, sizeof sbuf);
    if ((st = nl_model_parse(a->spec, &m)) || (st = nl_rank1_model_check(m, a->s)))
        cli_die_status(st);
    nl_rank1_model_info info;
    cli_check(nl_size_check(1, &a->N, (1 + (size_t)a->s) * sizeof *f, 1, NULL));
    f = cli_malloc(a->N * sizeof *f), grad = cli_malloc(a->N * a->s * sizeof *grad);
    double *coef = cli_malloc(2 * a->N * sizeof *coef);
    /* nl_rank1_model_synthesize_info in two steps, to keep the coefficients */
    cli_check(nl_rank1_model_coefficients(L, m, a->extent, a->seed, a->clamp ? NL_RANK1_CLAMP : 0, coef, &info));
    cli_check(nl_rank1_synthesize(L, coef, a->extent, f, grad, &imag));
    size_t k = 0;
    if (info.nodes)
        k += (size_t)snprintf(a->note, sizeof a->note, ", spectrum on a radial table of %zu nodes (interpolation "
                              "error <= %.2g of S(0))", info.nodes, info.interp_error);
    if (info.negatives)
        snprintf(a->note + k, sizeof a->note - k, ", clamped: %zu negative spectrum values zeroed (variance changed "
                 "by %.2g of it)", info.negatives, info.clamp_error);
    write_outputs(a, L, f, grad, imag);
    if (a->image)
        write_image(a, L, coef);
    free(f), free(grad), free(coef);
    nl_model_free(m);
}

int cli_cmd_lattice(int argc, char **argv)
{
    opts_t a = {.extent = 1, .seed = 1};
    nl_rank1_lattice L;
    parse(argc, argv, &a);
    make_lattice(&a, &L);
    if (a.wv)
        print_wave_vectors(&a, &L);
    if (a.spec)
        field(&a, &L);
    else if (a.out || a.mesh)
        /* the points alone (-o) and the triangulation at height 0 (--mesh) */
        write_outputs(&a, &L, NULL, NULL, 0);
    nl_rank1_free(&L);
    return 0;
}
