/* noiselab ocean: Tessendorf's ocean on a rank-1 lattice or a grid. */
#include "cli.h"
#include "opt.h"
#include "../core/nl_error.h"
#include "../core/io_obj.h"
#include "../render/shade.h"
#include "../synth/ocean.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char help[] =
    "usage: noiselab ocean (--lattice fibonacci --points N | --grid M) --wind V,ANGLE\n"
    "                      [--time T] [--frames F --dt DT] [--patch P] [--amplitude A]\n"
    "                      [--seed S] [--size W] -o OUT.tsv|OUT.exr [--image I.png]\n"
    "                      [--tile I.png] [--mesh O.obj] [--draw series|delaunay]\n\n"
    "Tessendorf's ocean: Phillips spectrum for wind V m/s from ANGLE degrees, deep-water\n"
    "dispersion w^2 = g |K|, h(k,t) = h0(k) e^{iwt} + conj(h0(-k)) e^{-iwt}, on a patch of\n"
    "P metres (default 100), amplitude A (default 1e-4).  On the Fibonacci lattice\n"
    "(Keller 2001) the heights and gradients come from one FFT of length N (the\n"
    "gradient from one more per axis); on an M x M grid from 2D FFTs.\n"
    "  -o       lattice: TSV x y h nx ny nz, or with a name ending in .exr the field's\n"
    "           heights on the W x W grid of --size (its series, as --draw series);\n"
    "           grid: EXR of heights\n"
    "  --image  shaded height field, W x W (default 512); on the lattice the field itself,\n"
    "           its trigonometric series evaluated at every pixel by one W x W FFT\n"
    "           through the lattice's wave vectors (--draw series, the default), or\n"
    "           its lattice values interpolated over the periodic Delaunay triangles\n"
    "           (--draw delaunay, the paper's rendering)\n"
    "  --tile   the same, 2 x 2 patches (Keller's Fig. 3: the patches tile)\n"
    "  --mesh   lattice: OBJ of the periodic Delaunay triangulation\n"
    "  --frames F with --dt: F time steps, files named OUT-000.ext, ...\n";

static char *frame_name(const char *path, int f, int frames)
{
    char *s = cli_malloc(strlen(path) + 16);
    const char *dot = strrchr(path, '.');
    if (frames <= 1 || !dot)
        strcpy(s, path);
    else
        sprintf(s, "%.*s-%03d%s", (int)(dot - path), path, f, dot);
    return s;
}

/* Frame fr of picture `path`: the W x W image, or 2 x 2 copies of it. */
static void write_png(const char *path, int fr, int frames, const double *img, size_t W, int tile)
{
    size_t T = tile ? 2 * W : W, n[2] = {T, T};
    char *name = frame_name(path, fr, frames);
    nl_field *f = cli_field_alloc(2, n, NULL);
    for (size_t y = 0; y < T; y++)
        for (size_t x = 0; x < T; x++)
            f->data[y * T + x] = img[(y % W) * W + x % W];
    const char *tmp = cli_out_begin(name);
    cli_check(nl_png_write_field(tmp, f, 0, 1));
    cli_out_commit(name);
    nl_field_free(f);
    free(name);
}

/* The command's options. */
typedef struct {
    const char *lat, *out, *image, *tile, *mesh;  /* as given, or NULL */
    int delaunay, draw, sized;                    /* --draw delaunay; --draw, --size given */
    size_t N, M, W;                               /* --points, --grid, --size */
    double t0, dt, v, ang;                        /* --time, --dt, --wind speed and degrees */
    int frames;                                   /* --frames */
    uint64_t seed;                                /* --seed */
    nl_ocean_params o;                            /* the ocean (angle in radians) */
} opts_t;

static void wind_option(void *obj, const char *label, const char *arg)
{
    opts_t *a = obj;
    if (sscanf(arg, "%lf,%lf", &a->v, &a->ang) != 2 || !(a->v > 0) || !isfinite(a->ang))
        cli_die(2, "%s: expected V,ANGLE with a positive speed in m/s, got \"%s\"", label, arg);
}

static const char *const draws[] = {"series", "delaunay", NULL};

static const cli_opt rows[] = {
    CLI_STRING("lattice", opts_t, lat), CLI_COUNT("points", opts_t, N, .lo = 5), /* 3 points: every one on a line */
    CLI_COUNT("grid", opts_t, M, .lo = 4), CLI_CALL("wind", wind_option), CLI_DOUBLE("time", opts_t, t0),
    CLI_INT("frames", opts_t, frames, .lo = 1, .hi = 10000, .what = "at most 10000 frames"),
    CLI_DOUBLE("dt", opts_t, dt), CLI_POSITIVE("patch", opts_t, o.patch, .what = "size in metres"),
    CLI_POSITIVE("amplitude", opts_t, o.amplitude, .what = "number"), CLI_U64("seed", opts_t, seed),
    CLI_COUNT("size", opts_t, W, .lo = 8, CLI_GIVEN(opts_t, sized)), CLI_OPT_OUTPUT(opts_t, out),
    CLI_STRING("image", opts_t, image),
    CLI_STRING("tile", opts_t, tile), CLI_STRING("mesh", opts_t, mesh),
    CLI_CHOICE("draw", opts_t, delaunay, .choices = draws, CLI_GIVEN(opts_t, draw)), {0}};

static void check(int argc, char **argv, const opts_t *a)
{
    cli_no_operands("ocean", argc, argv);
    if (!a->lat == !a->M)
        cli_die(2, "ocean: expected exactly one of --lattice fibonacci --points N or --grid M");
    if (a->lat && strcmp(a->lat, "fibonacci"))
        cli_die(2, "--lattice: expected fibonacci, got \"%s\"", a->lat);
    if (isnan(a->v))
        cli_die(2, "ocean: --wind: expected V,ANGLE");
    if (!a->out && !a->image && !a->tile)
        cli_die(2, "ocean: expected an output: -o, --image or --tile");
    if (a->frames > 1 && !(a->dt > 0))
        cli_die(2, "--frames: expected --dt with a positive time step");
    if (a->W > 8192 || a->M > 8192)
        cli_die(2, "--size/--grid: expected at most 8192");
    if (!(fabs(a->t0) + (a->frames - 1) * fabs(a->dt) <= 1e9))
        cli_die(2, "--time/--dt: expected times within 1e9 s, got %g + %d x %g", a->t0, a->frames - 1, a->dt);
    if (a->delaunay && !a->lat)
        cli_die(2, "--draw: expected --lattice (a grid ocean is drawn from its samples)");
    if (a->sized && !a->image && !a->tile && !(a->lat && a->out && cli_has_ext(a->out, ".exr")))
        cli_die(2, "--size %zu: expected --image, --tile or, on the lattice, an .exr -o (the pictures' size)", a->W);
    if (a->draw && !a->image && !a->tile)
        cli_die(2, "--draw %s: expected --image or --tile (it says how they are drawn)", draws[a->delaunay]);
    if (a->mesh && !a->lat)
        cli_die(2, "--mesh: expected --lattice");
}

/* Lattice TSV: x y h and the unit normal per point. */
static void write_lattice_tsv(const opts_t *a, const nl_rank1_lattice *L, const double *h, const double *g,
                              double t, const char *tmp)
{
    double *nrm = malloc(3 * L->N * sizeof *nrm);
    FILE *fp = fopen(tmp, "w");
    if (!nrm || !fp)
        cli_die(1, "-o: cannot write");
    nl_ocean_normals(L->N, g, nrm);
    fprintf(fp, "# noiselab ocean: Fibonacci lattice N %zu, wind %g m/s at %g deg, t %g s, patch %g m\n", a->N, a->v,
            a->ang, t, a->o.patch);
    fprintf(fp, "x\ty\th\tnx\tny\tnz\n");
    for (size_t n = 0; n < L->N; n++) {
        double x[2];
        nl_rank1_point(L, n, x);
        fprintf(fp, "%.8g\t%.8g\t%.8g\t%.8g\t%.8g\t%.8g\n", x[0] * a->o.patch, x[1] * a->o.patch, h[n], nrm[3 * n],
                nrm[3 * n + 1], nrm[3 * n + 2]);
    }
    if (fclose(fp))
        cli_die(1, "-o: write failed");
    free(nrm);
}

/* Frame fr's heights (M x M over the patch) as an EXR named after -o. */
static void write_heights(const opts_t *a, int fr, double t, size_t M, double *h, const char *kind)
{
    for (size_t q = 0; q < M * M; q++)
        if (!(fabs(h[q]) <= FLT_MAX))
            cli_die(2, "--amplitude: %g makes heights of %g, beyond the float32 range of EXR (%g)", a->o.amplitude,
                    h[q], FLT_MAX);
    size_t n[2] = {M, M};
    double sp[2] = {a->o.patch / (double)M, a->o.patch / (double)M};
    nl_meta meta = {0};
    char *name = frame_name(a->out, fr, a->frames);
    const char *tmp = cli_out_begin(name);
    nl_field *f = cli_field_alloc(2, n, sp);
    memcpy(f->data, h, M * M * sizeof *h);
    snprintf(meta.method, sizeof meta.method, "ocean:%s=%zu,wind=%g,%g,t=%g,patch=%g", kind, a->lat ? a->N : M, a->v,
             a->ang, t, a->o.patch);
    snprintf(meta.seed, sizeof meta.seed, "%llu", (unsigned long long)a->seed);
    cli_check(nl_exr_write(tmp, f, &meta));
    cli_out_commit(name);
    nl_field_free(f);
    free(name);
}

/* One lattice frame: its TSV and mesh, and the picture's W x W heights and
 * gradients (img, gx, gy) when one is wanted. */
static void lattice_frame(const opts_t *a, const nl_rank1_lattice *L, int fr, double t, double *img, double *gx,
                          double *gy)
{
    size_t N = L->N;
    double *h = cli_malloc(N * sizeof *h), *g = cli_malloc(2 * N * sizeof *g);
    int st;
    cli_check(nl_ocean_lattice_frame(L, &a->o, a->seed, t, h, g));
    if (a->out && !cli_has_ext(a->out, ".exr")) {
        char *name = frame_name(a->out, fr, a->frames);
        write_lattice_tsv(a, L, h, g, t, cli_out_begin(name));
        cli_out_commit(name);
        free(name);
    }
    if (a->mesh) {
        nl_rank1_mesh me;
        char *name = frame_name(a->mesh, fr, a->frames);
        const char *tmp = cli_out_begin(name);
        if ((st = nl_rank1_mesh_init(L, a->o.patch, h, &me)) ||
            (st = nl_obj_write_triangles(tmp, NULL, 2 * N, nl_rank1_mesh_triangle, &me)))
            cli_die_status(st);
        cli_out_commit(name);
        free(name);
    }
    if ((a->image || a->tile) && (st = a->delaunay ? nl_rank1_rasterize(L, h, g, a->W, img, gx, gy)
                                                   : nl_ocean_lattice_image(L, &a->o, a->seed, t, a->W, img, gx, gy)))
        cli_die_status(st);
    if (a->out && cli_has_ext(a->out, ".exr")) {
        size_t W = a->W;
        double *hw = cli_malloc(W * W * sizeof *hw);
        cli_check(nl_ocean_lattice_image(L, &a->o, a->seed, t, W, hw, NULL, NULL));
        write_heights(a, fr, t, W, hw, "lattice");
        free(hw);
    }
    free(h), free(g);
}

/* One grid frame: its EXR, and the heights and gradients resampled onto
 * the W x W image. */
static void grid_frame(const opts_t *a, int fr, double t, double *img, double *gx, double *gy)
{
    size_t M = a->M;
    double *h = cli_malloc(M * M * sizeof *h), *hx = cli_malloc(M * M * sizeof *hx), *hy = cli_malloc(M * M * sizeof *hy);
    cli_check(nl_ocean_grid(M, &a->o, a->seed, t, h, hx, hy));
    if (a->out)
        write_heights(a, fr, t, M, h, "grid");
    nl_render_nearest(M, h, a->W, img), nl_render_nearest(M, hx, a->W, gx), nl_render_nearest(M, hy, a->W, gy);
    free(h), free(hx), free(hy);
}

/* The shaded pictures of one frame. */
static void pictures(const opts_t *a, int fr, const double *gx, const double *gy)
{
    static const double light[3] = {-0.74, -0.43, 0.5};
    size_t W = a->W;
    double *sh = cli_malloc(W * W * sizeof *sh);
    nl_render_shade_gradients(W * W, gx, gy, light, 0.1, sh);
    if (a->image)
        write_png(a->image, fr, a->frames, sh, W, 0);
    if (a->tile)
        write_png(a->tile, fr, a->frames, sh, W, 1);
    free(sh);
}

int cli_cmd_ocean(int argc, char **argv)
{
    opts_t a = {.W = 512, .v = NAN, .frames = 1, .seed = 1, .o = {0, 0, 100, 1e-4}};
    nl_rank1_lattice L;
    if (cli_opt_parse("ocean", help, rows, &a, argc, argv))
        exit(0);
    check(argc, argv, &a);
    a.o.wind = a.v, a.o.angle = a.ang * M_PI / 180;
    memset(&L, 0, sizeof L);
    if (a.lat) {
        int idx = nl_rank1_fibonacci_index(a.N);
        if (!idx)
            cli_die(2, "--points: expected a Fibonacci number (e.g. 55, 1597, 10946), got %zu", a.N);
        cli_check(nl_rank1_fibonacci(idx, &L));
    }
    {
        /* per frame: the picture's three W x W arrays, and on a grid its two
         * complex M x M FFT buffers and three M x M outputs */
        size_t nw[2] = {a.W, a.W}, nm[2] = {a.M, a.M};
        if (a.image || a.tile)
            cli_check(nl_size_check(2, nw, 4 * sizeof(double), 1, NULL));
        if (a.M)
            cli_check(nl_size_check(2, nm, 8 * sizeof(double), 1, NULL));
    }
    cli_progress("ocean", 0);
    for (int fr = 0; fr < a.frames; fr++) {
        cli_progress("ocean", (double)fr / a.frames);
        double t = a.t0 + fr * a.dt, *img = cli_malloc(a.W * a.W * sizeof *img),
               *gx = cli_malloc(a.W * a.W * sizeof *gx), *gy = cli_malloc(a.W * a.W * sizeof *gy);
        if (a.lat)
            lattice_frame(&a, &L, fr, t, img, gx, gy);
        else
            grid_frame(&a, fr, t, img, gx, gy);
        if (a.image || a.tile)
            pictures(&a, fr, gx, gy);
        free(img), free(gx), free(gy);
    }
    nl_rank1_free(&L);
    cli_progress_done();
    return 0;
}
