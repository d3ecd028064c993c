/* noiselab ocean: Tessendorf's ocean on a rank-1 lattice or a grid. */
#include "cli.h"
#include "../core/nl_error.h"
#include "../synth/ocean.h"

#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char help[] =
    "usage: noiselab ocean (--lattice fibonacci --points N | --grid M) --wind V,ANGLE\n"
    "                      [--time T] [--frames F --dt DT] [--patch P] [--amplitude A]\n"
    "                      [--seed S] [--size W] -o OUT.tsv|OUT.exr [--image I.png]\n"
    "                      [--tile I.png] [--mesh O.obj]\n\n"
    "Tessendorf's ocean: Phillips spectrum for wind V m/s from ANGLE degrees, deep-water\n"
    "dispersion w^2 = g |K|, h(k,t) = h0(k) e^{iwt} + conj(h0(-k)) e^{-iwt}, on a patch of\n"
    "P metres (default 100), amplitude A (default 1e-4).  On the Fibonacci lattice\n"
    "(Keller 2001) the heights and gradients come from one FFT of length N (the\n"
    "gradient from one more per axis); on an M x M grid from 2D FFTs.\n"
    "  -o       lattice: TSV x y h nx ny nz; grid: EXR of heights\n"
    "  --image  shaded height field, W x W (default 512; the lattice rasterised over its\n"
    "           periodic Delaunay triangles)\n"
    "  --tile   the same, 2 x 2 patches (Keller's Fig. 3: the patches tile)\n"
    "  --mesh   lattice: OBJ of the periodic Delaunay triangulation\n"
    "  --frames F with --dt: F time steps, files named OUT-000.ext, ...\n";

static void shade(const double *gx, const double *gy, size_t W, double *out)
{
    double l[3] = {-0.74, -0.43, 0.5}, ln = sqrt(l[0] * l[0] + l[1] * l[1] + l[2] * l[2]);
    for (size_t q = 0; q < W * W; q++) {
        double n = sqrt(gx[q] * gx[q] + gy[q] * gy[q] + 1);
        out[q] = 0.1 + 0.9 * fmax(0, (-gx[q] * l[0] - gy[q] * l[1] + l[2]) / (n * ln));
    }
}

static char *frame_name(const char *path, int f, int frames)
{
    char *s = malloc(strlen(path) + 16);
    const char *dot = strrchr(path, '.');
    if (!s)
        cli_die(1, "out of memory");
    if (frames <= 1 || !dot)
        strcpy(s, path);
    else
        sprintf(s, "%.*s-%03d%s", (int)(dot - path), path, f, dot);
    return s;
}

static void write_png(const char *path, const double *img, size_t W, int tile)
{
    size_t T = tile ? 2 * W : W, n[2] = {T, T};
    int st;
    nl_field *f = nl_field_alloc(2, n, NULL, &st);
    if (!f)
        cli_die_status(st);
    for (size_t y = 0; y < T; y++)
        for (size_t x = 0; x < T; x++)
            f->data[y * T + x] = img[(y % W) * W + x % W];
    const char *tmp = cli_out_begin(path);
    if ((st = nl_png_write_field(tmp, f, 0, 1)))
        cli_die_status(st);
    cli_out_commit(path);
    nl_field_free(f);
}

int cli_cmd_ocean(int argc, char **argv)
{
    static const struct option opts[] = {
        {"lattice", required_argument, 0, 'l'}, {"points", required_argument, 0, 'n'},
        {"grid", required_argument, 0, 'g'},    {"wind", required_argument, 0, 'w'},
        {"time", required_argument, 0, 't'},    {"frames", required_argument, 0, 'F'},
        {"dt", required_argument, 0, 'D'},      {"patch", required_argument, 0, 'P'},
        {"amplitude", required_argument, 0, 'A'}, {"seed", required_argument, 0, 's'},
        {"size", required_argument, 0, 'W'},    {"output", required_argument, 0, 'o'},
        {"image", required_argument, 0, 'i'},   {"tile", required_argument, 0, 'T'},
        {"mesh", required_argument, 0, 'M'},    {"help", no_argument, 0, 'h'},
        {0}};
    const char *lat = NULL, *out = NULL, *image = NULL, *tile = NULL, *mesh = NULL;
    size_t N = 0, M = 0, W = 512;
    double t0 = 0, dt = 0, v = NAN, ang = 0;
    int c, frames = 1, st;
    uint64_t seed = 1;
    nl_ocean_params o = {0, 0, 100, 1e-4};
    opterr = 0;
    while ((c = getopt_long(argc, argv, ":ho:", opts, NULL)) != -1) {
        switch (c) {
        case 'l': lat = optarg; break;
        case 'n': N = cli_parse_count("--points", optarg, 3); break;
        case 'g': M = cli_parse_count("--grid", optarg, 4); break;
        case 'w':
            if (sscanf(optarg, "%lf,%lf", &v, &ang) != 2 || !(v > 0) || !isfinite(ang))
                cli_die(2, "--wind: expected V,ANGLE with a positive speed in m/s, got \"%s\"", optarg);
            break;
        case 't': t0 = cli_parse_double("--time", optarg); break;
        case 'F': frames = (int)cli_parse_count("--frames", optarg, 1); break;
        case 'D': dt = cli_parse_double("--dt", optarg); break;
        case 'P':
            o.patch = cli_parse_double("--patch", optarg);
            if (!(o.patch > 0))
                cli_die(2, "--patch: expected a positive size in metres, got \"%s\"", optarg);
            break;
        case 'A':
            o.amplitude = cli_parse_double("--amplitude", optarg);
            if (!(o.amplitude > 0))
                cli_die(2, "--amplitude: expected a positive number, got \"%s\"", optarg);
            break;
        case 's': seed = cli_parse_u64("--seed", optarg); break;
        case 'W': W = cli_parse_count("--size", optarg, 8); break;
        case 'o': out = optarg; break;
        case 'i': image = optarg; break;
        case 'T': tile = optarg; break;
        case 'M': mesh = optarg; break;
        case 'h': fputs(help, stdout); return 0;
        default: cli_bad_option("ocean", c, argv);
        }
    }
    if (optind < argc)
        cli_die(2, "ocean: unexpected argument \"%s\"", argv[optind]);
    if (!lat == !M)
        cli_die(2, "ocean: expected exactly one of --lattice fibonacci --points N or --grid M");
    if (lat && strcmp(lat, "fibonacci"))
        cli_die(2, "--lattice: expected fibonacci, got \"%s\"", lat);
    if (isnan(v))
        cli_die(2, "ocean: --wind: expected V,ANGLE");
    if (!out && !image && !tile)
        cli_die(2, "ocean: expected an output: -o, --image or --tile");
    if (frames > 1 && !(dt > 0))
        cli_die(2, "--frames: expected --dt with a positive time step");
    if (W > 8192 || M > 8192)
        cli_die(2, "--size/--grid: expected at most 8192");
    if (mesh && !lat)
        cli_die(2, "--mesh: expected --lattice");
    o.wind = v, o.angle = ang * M_PI / 180;
    nl_rank1_lattice L;
    memset(&L, 0, sizeof L);
    if (lat) {
        unsigned long long a = 1, b = 1;
        int idx = 2;
        while (b < N) {
            unsigned long long t = a + b;
            a = b, b = t, idx++;
        }
        if (b != N || idx < 3)
            cli_die(2, "--points: expected a Fibonacci number (e.g. 55, 1597, 10946), got %zu", N);
        if ((st = nl_rank1_fibonacci(idx, &L)))
            cli_die_status(st);
    }
    cli_progress("ocean", 0);
    for (int fr = 0; fr < frames; fr++) {
        cli_progress("ocean", (double)fr / frames);
        double t = t0 + fr * dt, *img = malloc(W * W * sizeof *img), *gx = malloc(W * W * sizeof *gx),
               *gy = malloc(W * W * sizeof *gy);
        if (!img || !gx || !gy)
            cli_die(1, "out of memory");
        if (lat) {
            double *cf = malloc(2 * N * sizeof *cf), *h = malloc(N * sizeof *h), *g = malloc(2 * N * sizeof *g), imag;
            if (!cf || !h || !g)
                cli_die(1, "out of memory");
            if ((st = nl_ocean_lattice_coefficients(&L, &o, seed, t, cf)) ||
                (st = nl_rank1_synthesize(&L, cf, o.patch, h, g, &imag)))
                cli_die_status(st);
            if (out) {
                char *name = frame_name(out, fr, frames);
                const char *tmp = cli_out_begin(name);
                FILE *fp = fopen(tmp, "w");
                fprintf(fp, "# noiselab ocean: Fibonacci lattice N %zu, wind %g m/s at %g deg, t %g s, patch %g m\n",
                        N, v, ang, t, o.patch);
                fprintf(fp, "x\ty\th\tnx\tny\tnz\n");
                for (size_t n = 0; n < N; n++) {
                    double x[2], nn = sqrt(g[2 * n] * g[2 * n] + g[2 * n + 1] * g[2 * n + 1] + 1);
                    nl_rank1_point(&L, n, x);
                    fprintf(fp, "%.8g\t%.8g\t%.8g\t%.8g\t%.8g\t%.8g\n", x[0] * o.patch, x[1] * o.patch, h[n],
                            -g[2 * n] / nn, -g[2 * n + 1] / nn, 1 / nn);
                }
                if (fclose(fp))
                    cli_die(1, "-o: write failed");
                cli_out_commit(name);
                free(name);
            }
            if (mesh) {
                size_t n1, n2;
                double v1[2], v2[2];
                char *name = frame_name(mesh, fr, frames);
                const char *tmp = cli_out_begin(name);
                FILE *fp = fopen(tmp, "w");
                if ((st = nl_rank1_delaunay(&L, &n1, &n2, v1, v2)))
                    cli_die_status(st);
                for (size_t n = 0; n < N; n++) {
                    double x[2];
                    size_t id[4] = {n, (n + n1) % N, (n + n2) % N, (n + n1 + n2) % N};
                    nl_rank1_point(&L, n, x);
                    double P[4][2] = {{x[0], x[1]}, {x[0] + v1[0], x[1] + v1[1]}, {x[0] + v2[0], x[1] + v2[1]},
                                      {x[0] + v1[0] + v2[0], x[1] + v1[1] + v2[1]}};
                    static const int tri[2][3] = {{0, 1, 2}, {1, 3, 2}};
                    for (int q = 0; q < 2; q++)
                        for (int k = 0; k < 3; k++)
                            fprintf(fp, "v %.8g %.8g %.8g\n", P[tri[q][k]][0] * o.patch, P[tri[q][k]][1] * o.patch,
                                    h[id[tri[q][k]]]);
                }
                for (size_t q = 0; q < 2 * N; q++)
                    fprintf(fp, "f %zu %zu %zu\n", 3 * q + 1, 3 * q + 2, 3 * q + 3);
                if (fclose(fp))
                    cli_die(1, "--mesh: write failed");
                cli_out_commit(name);
                free(name);
            }
            if ((image || tile) && (st = nl_rank1_rasterize(&L, h, g, W, img, gx, gy)))
                cli_die_status(st);
            free(cf), free(h), free(g);
        } else {
            double *h = malloc(M * M * sizeof *h), *hx = malloc(M * M * sizeof *hx), *hy = malloc(M * M * sizeof *hy);
            if (!h || !hx || !hy)
                cli_die(1, "out of memory");
            if ((st = nl_ocean_grid(M, &o, seed, t, h, hx, hy)))
                cli_die_status(st);
            if (out) {
                size_t n[2] = {M, M};
                double sp[2] = {o.patch / (double)M, o.patch / (double)M};
                nl_field *f = nl_field_alloc(2, n, sp, &st);
                nl_meta meta;
                char *name = frame_name(out, fr, frames);
                const char *tmp = cli_out_begin(name);
                if (!f)
                    cli_die_status(st);
                memcpy(f->data, h, M * M * sizeof *h);
                memset(&meta, 0, sizeof meta);
                snprintf(meta.method, sizeof meta.method, "ocean:grid=%zu,wind=%g,%g,t=%g,patch=%g", M, v, ang, t,
                         o.patch);
                snprintf(meta.seed, sizeof meta.seed, "%llu", (unsigned long long)seed);
                if ((st = nl_exr_write(tmp, f, &meta)))
                    cli_die_status(st);
                cli_out_commit(name);
                nl_field_free(f);
                free(name);
            }
            /* nearest-sample resampling of the grid onto the image */
            for (size_t y = 0; y < W; y++)
                for (size_t x = 0; x < W; x++) {
                    size_t q = (y * M / W) * M + x * M / W;
                    img[y * W + x] = h[q], gx[y * W + x] = hx[q], gy[y * W + x] = hy[q];
                }
            free(h), free(hx), free(hy);
        }
        if (image || tile) {
            double *sh = malloc(W * W * sizeof *sh);
            if (!sh)
                cli_die(1, "out of memory");
            shade(gx, gy, W, sh);
            if (image) {
                char *name = frame_name(image, fr, frames);
                write_png(name, sh, W, 0);
                free(name);
            }
            if (tile) {
                char *name = frame_name(tile, fr, frames);
                write_png(name, sh, W, 1);
                free(name);
            }
            free(sh);
        }
        free(img), free(gx), free(gy);
    }
    nl_rank1_free(&L);
    cli_progress_done();
    return 0;
}
