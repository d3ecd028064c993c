/* noiselab lattice: rank-1 lattices, their wave vectors, and random fields
 * synthesised on them with one FFT (Keller 2001). */
#include "cli.h"
#include "rank1_spec.h"
#include "../core/nl_error.h"
#include "../synth/rank1.h"

#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char help[] =
    "usage: noiselab lattice --points N --dim S [--generator fibonacci|korobov[:A]|G1,...,GS]\n"
    "                        [--acf SPEC | --spectrum SPEC] [--extent E] [--seed X]\n"
    "                        [--wave-vectors] [--json] [-o OUT.tsv] [--mesh OUT.obj]\n\n"
    "Rank-1 lattice x_n = (n/N) g mod 1 (Keller 2001).  Generators: fibonacci (2D, N a\n"
    "Fibonacci number, g = (1, F_{k-1})), korobov (g = (1, a, a^2, ...) with a searched\n"
    "for the largest minimum distance, or given), or explicit.  Default: fibonacci in 2D\n"
    "when N is a Fibonacci number, korobov otherwise.\n"
    "  --wave-vectors  print K_N: for each residue m the k with k.g = m (mod N) of least\n"
    "                  norm (TSV m k1..kS norm; --json {\"N\", \"generator\", \"wave_vectors\"})\n"
    "  with a model: a field on the N points by ONE complex FFT of length N, on a torus\n"
    "  of side E (default 1): TSV columns x1..xS value grad1..gradS\n"
    "  --mesh OBJ      (2D) the periodic Delaunay triangulation of the height field\n";

static int fib_index(size_t N)
{
    unsigned long long a = 1, b = 1;
    for (int i = 2; i < 80 && b <= N; i++) {
        if (b == N && i >= 3)
            return i;
        unsigned long long c = a + b;
        a = b, b = c;
    }
    return 0;
}

int cli_cmd_lattice(int argc, char **argv)
{
    static const struct option opts[] = {
        {"points", required_argument, 0, 'n'}, {"dim", required_argument, 0, 'd'},
        {"generator", required_argument, 0, 'g'}, {"acf", required_argument, 0, 'a'},
        {"spectrum", required_argument, 0, 'S'}, {"extent", required_argument, 0, 'E'},
        {"seed", required_argument, 0, 's'},    {"wave-vectors", no_argument, 0, 'w'},
        {"json", no_argument, 0, 'j'},          {"output", required_argument, 0, 'o'},
        {"mesh", required_argument, 0, 'M'},    {"help", no_argument, 0, 'h'},
        {0}};
    const char *gen = NULL, *spec = NULL, *out = NULL, *mesh = NULL, *tmp = NULL, *mtmp = NULL;
    size_t N = 0;
    int c, s = 0, wv = 0, json = 0, st, spectral = 0;
    double extent = 1;
    uint64_t seed = 1;
    nl_rank1_lattice L;
    opterr = 0;
    while ((c = getopt_long(argc, argv, ":ho:", opts, NULL)) != -1) {
        switch (c) {
        case 'n': N = cli_parse_count("--points", optarg, 2); break;
        case 'd': s = cli_parse_dim(optarg, 4); break;
        case 'g': gen = optarg; break;
        case 'a': spec = optarg; spectral = 0; break;
        case 'S': spec = optarg; spectral = 1; break;
        case 'E':
            extent = cli_parse_double("--extent", optarg);
            if (!(extent > 0))
                cli_die(2, "--extent: expected a positive length, got \"%s\"", optarg);
            break;
        case 's': seed = cli_parse_u64("--seed", optarg); break;
        case 'w': wv = 1; break;
        case 'j': json = 1; break;
        case 'o': out = optarg; break;
        case 'M': mesh = optarg; break;
        case 'h': fputs(help, stdout); return 0;
        default: cli_bad_option("lattice", c, argv);
        }
    }
    if (optind < argc)
        cli_die(2, "lattice: unexpected argument \"%s\"", argv[optind]);
    if (!N)
        cli_die(2, "lattice: --points: expected the number of lattice points");
    if (!s)
        cli_die(2, "lattice: --dim: expected 1 to 4");
    if (N > (1u << 24))
        cli_die(2, "--points: expected at most 16777216, got %zu", N);
    if (mesh && s != 2)
        cli_die(2, "--mesh: expected --dim 2, got %d", s);
    if (!gen)
        gen = s == 2 && fib_index(N) ? "fibonacci" : "korobov";
    if (strcmp(gen, "fibonacci") == 0) {
        if (s != 2 || !fib_index(N))
            cli_die(2, "--generator fibonacci: expected --dim 2 and a Fibonacci number of points, got %zu in %dD", N, s);
        st = nl_rank1_fibonacci(fib_index(N), &L);
    } else if (strncmp(gen, "korobov", 7) == 0) {
        long a = 0;
        if (gen[7] == ':' && (a = atol(gen + 8)) <= 0)
            cli_die(2, "--generator: expected korobov:A with A > 0, got \"%s\"", gen);
        st = nl_rank1_korobov(N, s, a, &L);
    } else {
        long g[NL_RANK1_MAX_DIM];
        char *p = (char *)gen, *end;
        int k = 0;
        while (k < NL_RANK1_MAX_DIM) {
            g[k++] = strtol(p, &end, 10);
            if (end == p)
                break;
            if (*end != ',')
                break;
            p = end + 1;
        }
        if (k != s || *end || end == p)
            cli_die(2, "--generator: expected fibonacci, korobov[:A] or %d integers G1,...,G%d, got \"%s\"", s, s, gen);
        st = nl_rank1_generator(N, s, g, &L);
    }
    if (st)
        cli_die_status(st);
    if (wv) {
        if (json) {
            json_t *o = json_pack("{s:I,s:[],s:[]}", "N", (json_int_t)N, "generator", "wave_vectors");
            json_t *ga = json_object_get(o, "generator"), *wa = json_object_get(o, "wave_vectors");
            for (int a = 0; a < s; a++)
                json_array_append_new(ga, json_integer(L.g[a]));
            for (size_t m = 0; m < N; m++) {
                json_t *k = json_array();
                for (int a = 0; a < s; a++)
                    json_array_append_new(k, json_integer(L.k[m * s + a]));
                json_array_append_new(wa, k);
            }
            cli_json_print(o);
        } else {
            printf("# N %zu, generator", N);
            for (int a = 0; a < s; a++)
                printf(" %ld", L.g[a]);
            printf(", minimum distance %.6g\nm", L.min_dist);
            for (int a = 0; a < s; a++)
                printf("\tk%d", a + 1);
            printf("\tnorm\n");
            for (size_t m = 0; m < N; m++) {
                double n2 = 0;
                printf("%zu", m);
                for (int a = 0; a < s; a++)
                    printf("\t%ld", L.k[m * s + a]), n2 += (double)L.k[m * s + a] * L.k[m * s + a];
                printf("\t%.6g\n", sqrt(n2));
            }
        }
    }
    if (spec) {
        nl_model *m;
        double *coef = malloc(2 * N * sizeof *coef), *f = malloc(N * sizeof *f), *grad = malloc(N * s * sizeof *grad);
        double imag;
        char sbuf[1100];
        nl_rank1_model_ctx ctx;
        if (spectral && strncmp(spec, "power", 5) && strncmp(spec, "spectrum:", 9))
            snprintf(sbuf, sizeof sbuf, "spectrum:%s", spec), spec = sbuf;
        if ((st = nl_model_parse(spec, &m)) || (st = cli_rank1_model_check(m, s)))
            cli_die_status(st);
        if (!coef || !f || !grad)
            cli_die(1, "out of memory");
        if (out)
            tmp = cli_out_begin(out);
        if (mesh)
            mtmp = cli_out_begin(mesh);
        ctx.m = m, ctx.s = s, ctx.extent = extent;
        if ((st = nl_rank1_coefficients(&L, cli_rank1_model_spectrum, &ctx, seed, coef)) ||
            (st = nl_rank1_synthesize(&L, coef, extent, f, grad, &imag)))
            cli_die_status(st);
        if (out || (!mesh && !wv)) {
            FILE *fp = out ? fopen(tmp, "w") : stdout;
            if (!fp)
                cli_die(2, "-o: cannot write \"%s\"", out);
            fprintf(fp, "# noiselab lattice: N %zu, dim %d, %s, seed %llu, extent %g, max |imag| %.3g\n", N, s, spec,
                    (unsigned long long)seed, extent, imag);
            for (int a = 0; a < s; a++)
                fprintf(fp, "x%d\t", a + 1);
            fprintf(fp, "value");
            for (int a = 0; a < s; a++)
                fprintf(fp, "\tgrad%d", a + 1);
            fprintf(fp, "\n");
            for (size_t n = 0; n < N; n++) {
                double x[NL_RANK1_MAX_DIM];
                nl_rank1_point(&L, n, x);
                for (int a = 0; a < s; a++)
                    fprintf(fp, "%.10g\t", x[a] * extent);
                fprintf(fp, "%.10g", f[n]);
                for (int a = 0; a < s; a++)
                    fprintf(fp, "\t%.10g", grad[n * s + a]);
                fprintf(fp, "\n");
            }
            if (out && fclose(fp))
                cli_die(1, "-o: write failed");
        }
        if (mesh) {
            size_t n1, n2;
            double v1[2], v2[2];
            FILE *fp = fopen(mtmp, "w");
            if ((st = nl_rank1_delaunay(&L, &n1, &n2, v1, v2)))
                cli_die_status(st);
            if (!fp)
                cli_die(2, "--mesh: cannot write \"%s\"", mesh);
            fprintf(fp, "# noiselab lattice: periodic Delaunay triangulation, N %zu, %s\n", N, spec);
            /* each triangle with its own unwrapped vertices: 6N vertices, 2N faces */
            for (size_t n = 0; n < N; n++) {
                double x[2];
                size_t a = n, b = (n + n1) % N, c2 = (n + n2) % N, d = (n + n1 + n2) % N;
                nl_rank1_point(&L, n, x);
                double P[4][2] = {{x[0], x[1]}, {x[0] + v1[0], x[1] + v1[1]}, {x[0] + v2[0], x[1] + v2[1]},
                                  {x[0] + v1[0] + v2[0], x[1] + v1[1] + v2[1]}};
                size_t id[4] = {a, b, c2, d};
                int tri[2][3] = {{0, 1, 2}, {1, 3, 2}};
                for (int t = 0; t < 2; t++)
                    for (int v = 0; v < 3; v++)
                        fprintf(fp, "v %.8g %.8g %.8g\n", P[tri[t][v]][0] * extent, P[tri[t][v]][1] * extent,
                                f[id[tri[t][v]]]);
            }
            for (size_t t = 0; t < 2 * N; t++)
                fprintf(fp, "f %zu %zu %zu\n", 3 * t + 1, 3 * t + 2, 3 * t + 3);
            if (fclose(fp))
                cli_die(1, "--mesh: write failed");
        }
        if (out)
            cli_out_commit(out);
        if (mesh)
            cli_out_commit(mesh);
        free(coef), free(f), free(grad);
        nl_model_free(m);
    }
    if (!spec && (out || mesh)) {
        /* the points alone (-o) and the triangulation at height 0 (--mesh) */
        if (out) {
            tmp = cli_out_begin(out);
            FILE *fp = fopen(tmp, "w");
            if (!fp)
                cli_die(2, "-o: cannot write \"%s\"", out);
            for (int a = 0; a < s; a++)
                fprintf(fp, "x%d%c", a + 1, a + 1 < s ? '\t' : '\n');
            for (size_t n = 0; n < N; n++) {
                double x[NL_RANK1_MAX_DIM];
                nl_rank1_point(&L, n, x);
                for (int a = 0; a < s; a++)
                    fprintf(fp, "%.10g%c", x[a] * extent, a + 1 < s ? '\t' : '\n');
            }
            if (fclose(fp))
                cli_die(1, "-o: write failed");
            cli_out_commit(out);
        }
        if (mesh) {
            size_t n1, n2;
            double v1[2], v2[2];
            if ((st = nl_rank1_delaunay(&L, &n1, &n2, v1, v2)))
                cli_die_status(st);
            mtmp = cli_out_begin(mesh);
            FILE *fp = fopen(mtmp, "w");
            if (!fp)
                cli_die(2, "--mesh: cannot write \"%s\"", mesh);
            for (size_t n = 0; n < N; n++) {
                double x[2];
                nl_rank1_point(&L, n, x);
                double P[4][2] = {{x[0], x[1]}, {x[0] + v1[0], x[1] + v1[1]}, {x[0] + v2[0], x[1] + v2[1]},
                                  {x[0] + v1[0] + v2[0], x[1] + v1[1] + v2[1]}};
                static const int tri[2][3] = {{0, 1, 2}, {1, 3, 2}};
                for (int t = 0; t < 2; t++)
                    for (int v = 0; v < 3; v++)
                        fprintf(fp, "v %.8g %.8g 0\n", P[tri[t][v]][0] * extent, P[tri[t][v]][1] * extent);
            }
            for (size_t t = 0; t < 2 * N; t++)
                fprintf(fp, "f %zu %zu %zu\n", 3 * t + 1, 3 * t + 2, 3 * t + 3);
            if (fclose(fp))
                cli_die(1, "--mesh: write failed");
            cli_out_commit(mesh);
        }
    }
    nl_rank1_free(&L);
    return 0;
}
