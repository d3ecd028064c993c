/* The command line: success paths, and every error path giving exit 2, one
 * line on stderr naming the bad value, and no output file. */
#include "../core/family.h"
#include "../core/io.h"
#include "../core/nl_error.h"
#include "../core/version.h"
#include "util.h"

#include <criterion/criterion.h>
#include <dirent.h>
#include <jansson.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

static char out[1 << 16], err[1 << 12];

/* No file whose name starts with "out" (the final name or a temporary). */
static int outputs_left(void)
{
    DIR *d = opendir(scratch_dir());
    struct dirent *e;
    int n = 0;
    while ((e = readdir(d)))
        n += strncmp(e->d_name, "out", 3) == 0;
    closedir(d);
    return n;
}

static void bad(const char *args, const char *needle)
{
    int rc = run_noiselab(args, out, sizeof out, err, sizeof err);
    cr_expect_eq(rc, 2, "%s: exit %d, stderr: %s", args, rc, err);
    cr_expect_eq(count_lines(err), 1, "%s: expected one line on stderr, got: %s", args, err);
    cr_expect(strncmp(err, "noiselab: ", 10) == 0, "%s: %s", args, err);
    cr_expect(strstr(err, needle) != NULL, "%s: stderr \"%s\" should name \"%s\"", args, err, needle);
    cr_expect_eq(outputs_left(), 0, "%s: left an output file", args);
}

Test(cli_slow, nl_synth_error_paths)
{
    bad("synth fft --acf markov:scale=8 --size 0x5 -o out.exr", "\"0x5\"");
    bad("synth fft --acf markov --size 1 -o out.exr", "\"1\"");
    bad("synth fft --acf markov --size 8x8x8x8 -o out.exr", "\"8x8x8x8\"");
    bad("synth fft --acf nosuch:scale=2 --size 64 -o out.exr", "\"nosuch\"");
    bad("synth fft --acf 'expr:cos(t' --size 64 -o out.exr", "\"cos(t\"");
    bad("synth fft --acf markaussian --size 64 -o out.exr", "alpha");
    bad("synth fft --acf markov:scale=0 --size 64 -o out.exr", "scale");
    bad("synth fft --acf markov --size 64 -o /nonexistent/out.exr", "/nonexistent/out.exr");
    bad("synth fft --acf markov --size 64 --frobnicate -o out.exr", "--frobnicate");
    bad("synth fft --acf markov --size 64 -o", "-o");
    bad("synth fft --acf markov --size 64 --seed -3 -o out.exr", "\"-3\"");
    bad("synth fft --acf markov --size 64 --spacing 0 -o out.exr", "\"0\"");
    bad("synth fft --acf markov --size 64x64 -o out.tsv", "out.tsv");
    bad("synth fft --acf markov --size 64 -o out.txt", "out.txt");
    bad("synth fft --size 64 -o out.exr", "--acf");
    bad("synth fft --acf markov -o out.exr", "--size");
    bad("synth fft --acf markov --size 64", "-o");
    bad("synth wavelets --acf markov --size 64 -o out.exr", "\"wavelets\"");
    bad("synth rank1 --acf markov --size 64 -o out.exr", "\"rank1\"");
    bad("synth lattice --acf markov --size 64x64 -o out.exr", "closed form");
    bad("synth lattice --spectrum power:d=3 --size 64 --octaves 9 --cell 16 -o out.exr", "below 2 samples");
    bad("synth sparse --size 64 -o out.tsv", "exactly one kernel");
    bad("synth sparse --kernel 'exp(-r)' --acf markov --size 64 -o out.tsv", "exactly one kernel");
    bad("synth sparse --kernel 'exp(-q)' --size 64 -o out.tsv", "\"q\"");
    bad("synth sparse --acf markov --size 64 --density -1 -o out.tsv", "\"-1\"");
    bad("synth sparse --kernel 'exp(-r)' --radius 40 --wrap --size 64x64 -o out.exr", "larger than the tile");
    bad("synth sparse --exemplar /nonexistent.png --size 64x64 -o out.exr", "/nonexistent.png");
    bad("synth cholesky --acf markov --size 100x100 -o out.exr", "10000");
    bad("synth circulant --acf gauss-osc:omega=2,scale=3 --size 64x64 -o out.exr", "cannot be embedded");
    bad("synth subdiv --acf markov --size 100 --levels 3 -o out.exr", "100");
    bad("synth subdiv --acf markov --size 64x64x64 -o out.exr", "3D");
    bad("synth subdiv --acf markov --size 64 --origin 5 -o out.exr", "--nonperiodic");
    bad("synth subdiv --acf markov --size 64 --nonperiodic --origin 5,x -o out.exr", "\"5,x\"");
    bad("synth subdiv --acf markov --size 64 --neighborhood 0 -o out.exr", "\"0\"");
    bad("synth subdiv --acf 'expr:cos(10*r)*exp(-r)' --size 128x128 --spacing 0.25 -o out.exr", "not positive definite");
    bad("synth subdiv --spectrum 'spectrum:1/(1+k^2)' --size 64 -o out.exr", "subdivision needs R");
    bad("synth fft --acf markov --size 64 --levels 3 -o out.exr", "--levels");
    bad("synth midpoint --acf markov --size 64 -o out.exr", "power:d=D");
    bad("synth midpoint --H 1.5 --size 64 -o out.exr", "\"1.5\"");
    bad("synth midpoint --spectrum power:d=3.5 --size 64 -o out.exr", "d=3.5");
    bad("coeffs --acf markov --dim 3", "\"3\"");
    bad("check --acf markov --dim 4", "\"4\"");
    bad("check --dim 2", "--acf");
    bad("check --acf nope --dim 2", "\"nope\"");
    bad("coeffs --acf markov", "--dim");
    bad("coeffs --acf markov --dim 1 --spacing0 -1", "\"-1\"");
    bad("coeffs --acf markov --dim 2 --neighborhood 9", "9");
    bad("synth fft --acf power:d=2 --size 64 -o out.exr", "power:d=2");
    bad("synth fft --spectrum markov --size 64 -o out.exr", "\"markov\"");
    bad("synth fft --acf oscillatory:omega=2,scale=10 --size 64x64 -o out.exr", "not positive definite");
    bad("synth fft --acf markov --size 1000000x1000000x1000 -o out.exr", "available");
    bad("synth fft --acf markov --size 99999999999999999999999 -o out.exr", "99999999999999999999999");
    bad("synth fft --acf image:/nonexistent.png --size 64x64 -o out.exr", "/nonexistent.png");
    bad("synth fft --acf markov --size 64 --preview out.png -o out.exr", "--preview");
}

Test(cli_slow, estimator_error_paths)
{
    bad("acf /nonexistent.exr", "/nonexistent.exr");
    bad("acf", "expected one input file");
    cr_assert_eq(run_noiselab("synth fft --acf markov --size 64 -o f.tsv", 0, 0, err, sizeof err), 0, "%s", err);
    bad("acf f.tsv --axis y", "axis");
    bad("acf f.tsv --axis w", "\"w\"");
    bad("acf f.tsv --max-lag 64", "64");
    bad("acf f.tsv --radial", "--radial");
    bad("acf f.tsv --target markov:bad=1 -o out.tsv", "\"bad\"");
    bad("psd f.tsv --mean nan", "\"nan\"");
    bad("hist f.tsv --bins 0", "\"0\"");
    bad("hist f.tsv --bins x", "\"x\"");
    bad("nosuchcommand", "\"nosuchcommand\"");
    bad("shape f.tsv --to cauchy -o out.tsv", "\"cauchy\"");
    bad("psd f.tsv --slope 0.3:0.1", "\"0.3:0.1\"");
    bad("synth faulting --size 64 --density -2 -o out.tsv", "\"-2\"");
    bad("synth faulting --acf markov --size 64 -o out.tsv", "takes no model");
    bad("synth faulting --size 8x8x8 -o out.exr", "3D");
    bad("shape f.tsv --to laplace:a=-1 -o out.tsv", "laplace:a=-1");
    bad("shape f.tsv --to laplace", "-o");
    bad("shape f.tsv -o out.tsv", "--to");
    bad("shape /nonexistent.exr --to laplace -o out.tsv", "/nonexistent.exr");
    bad("hist f.tsv --against nope", "\"nope\"");
    FILE *fp = fopen("/tmp/noiselab-pts.tsv", "w");
    fputs("x\ty\tvalue\n0.1\t0.2\t1\n0.3\tx\t2\n", fp);
    fclose(fp);
    bad("krige --data /tmp/noiselab-pts.tsv --acf markov --grid 8x8 --extent 0:1,0:1 -o out.exr", ":3:");
    fp = fopen("/tmp/noiselab-pts.tsv", "w");
    fputs("x\ty\tvalue\n0.1\t0.2\t1\n0.1\t0.2\t2\n", fp);
    fclose(fp);
    bad("krige --data /tmp/noiselab-pts.tsv --acf gauss --grid 8x8 --extent 0:1,0:1 --strict -o out.exr", "singular");
    bad("krige --data /tmp/noiselab-pts.tsv --acf markov --grid 8x8 --extent 0:1 -o out.exr", "--extent");
    bad("krige --data /tmp/noiselab-pts.tsv --acf markov --grid 8x8x8 --extent 0:1,0:1,0:1 -o out.exr", "2 coordinates");
    fp = fopen("/tmp/noiselab-scene.json", "w");
    fputs("{\"size\": [32, 24], \"box\": [[-1,-1,-1],[1,1,1]], \"points\": [[0,0,0,1]], \"acf\": \"gauss:scale=0.5\", "
          "\"noise\": {\"acf\": \"markov:scale=0.1\"}, \"camera\": {\"position\": [0,0,-4], \"look_at\": [0,0,0]}, "
          "\"sun\": [0,0,0]}", fp);
    fclose(fp);
    bad("cloud /tmp/noiselab-scene.json -o out.png", "\"sun\"");
    fp = fopen("/tmp/noiselab-scene.json", "w");
    fputs("{\"size\": [32, 24], \"box\": [[-1,-1,-1],[1,1,1]], \"points\": [[0,0,0,1]], ", fp);
    fclose(fp);
    bad("cloud /tmp/noiselab-scene.json -o out.png", "not valid JSON");
    bad("krige --data /nonexistent.tsv --acf markov --grid 8x8 --extent 0:1,0:1 -o out.exr", "/nonexistent.tsv");
    fp = fopen("/tmp/noiselab-bad.tsv", "w");
    fputs("t\tvalue\n0\t1\n1\tabc\n", fp);
    fclose(fp);
    bad("hist /tmp/noiselab-bad.tsv", "\"abc\"");
    cr_assert_eq(run_noiselab("synth fft --acf markov:scale=4 --size 32x32 -o f2.exr", 0, 0, err, sizeof err), 0, "%s", err);
    bad("render f2.exr --tile -o out.png", "--perspective");
    bad("render f2.exr --perspective --camera 1,2 -o out.png", "\"1,2\"");
    bad("render f2.exr --perspective --look 90,45 -o out.png", "pitch");
    bad("render f2.exr --perspective --size 0x10 -o out.png", "\"0x10\"");
    bad("render f2.exr --perspective --sun 10 -o out.png", "\"10\"");
    bad("render f2.exr --perspective --matrix out.txt -o out.png", "--matrix");
    bad("render f.tsv --perspective -o out.png", "2D");
    /* a picture larger than the memory allowed is refused before allocating */
    setenv("NOISELAB_MEMORY_LIMIT", "100000000", 1);
    bad("render f2.exr --perspective --size 8000x4000 -o out.png", "384000000");
    unsetenv("NOISELAB_MEMORY_LIMIT");
}

/* Text output to stdout keeps everything printed before the table. */
/* acf -o .exr holds the whole estimate, lag 0 at the centre: it is even and
 * its x row through the centre is the axis estimate printed as TSV. */
Test(cli, acf_writes_the_whole_estimate)
{
    char path[512];
    nl_field *c;
    nl_meta meta;
    double lag, v[4];
    const char *p;
    cr_assert_eq(run_noiselab("synth fft --acf markov:scale=1 --size 32x16 --seed 3 -o f.exr", 0, 0, err, sizeof err),
                 0, "%s", err);
    cr_assert_eq(run_noiselab("acf f.exr -o c.exr", 0, 0, err, sizeof err), 0, "%s", err);
    cr_assert_eq(run_noiselab("acf f.exr --max-lag 3", out, sizeof out, err, sizeof err), 0, "%s", err);
    snprintf(path, sizeof path, "%s/c.exr", scratch_dir());
    cr_assert_eq(nl_exr_read(path, &c, &meta), 0);
    cr_assert_eq(c->n[0], 63);
    cr_assert_eq(c->n[1], 31);
    p = strstr(out, "\n0\t") ? strstr(out, "\n0\t") + 1 : out;
    for (int i = 0; i < 4; i++) {
        cr_assert_eq(sscanf(p, "%lf %lf", &lag, &v[i]), 2, "%s", p);
        p = strchr(p, '\n') + 1;
    }
    for (int i = 0; i < 4; i++)
        cr_expect(fabs(c->data[15 * 63 + 31 + i] - v[i]) <= 1e-6 * fabs(v[0]), "lag %d: %g vs %g", i,
                  c->data[15 * 63 + 31 + i], v[i]);
    for (size_t j = 0; j < 31; j++)
        for (size_t i = 0; i < 63; i++)
            cr_expect_eq(c->data[j * 63 + i], c->data[(30 - j) * 63 + 62 - i], "not even at (%zu, %zu)", i, j);
    nl_field_free(c);
}

Test(cli, hist_text_output_is_whole)
{
    cr_assert_eq(run_noiselab("synth fft --acf markov --size 64 -o h.tsv", 0, 0, err, sizeof err), 0, "%s", err);
    cr_assert_eq(run_noiselab("hist h.tsv --bins 5", out, sizeof out, err, sizeof err), 0, "%s", err);
    cr_assert(strstr(out, "# mean ") != NULL, "%s", out);
    cr_assert(strstr(out, "lo\thi\tcount\n") != NULL, "%s", out);
    cr_assert_eq(count_lines(out), 5 + 1 + 5);
}

Test(cli, nl_synth_writes_exr_with_provenance)
{
    char path[512];
    nl_field *f;
    nl_meta meta;
    int rc = run_noiselab("synth fft --acf markov:scale=2 --size 64x32 --seed 7 --spacing 0.5 -o a.exr "
                          "--preview a.png",
                          out, sizeof out, err, sizeof err);
    cr_assert_eq(rc, 0, "%s", err);
    cr_assert_eq(err[0], 0, "success is quiet: %s", err);
    snprintf(path, sizeof path, "%s/a.exr", scratch_dir());
    cr_assert_eq(nl_exr_read(path, &f, &meta), 0);
    cr_assert_eq(f->n[0], 64);
    cr_assert_eq(f->n[1], 32);
    cr_assert_eq(f->h[1], 0.5);
    cr_assert_str_eq(meta.model, "markov:scale=2");
    cr_assert_str_eq(meta.method, "fft");
    cr_assert_str_eq(meta.seed, "7");
    cr_assert_str_eq(meta.spacing, "0.5,0.5");
    cr_assert_str_eq(meta.version, NL_VERSION_STRING);
    nl_field_free(f);
    snprintf(path, sizeof path, "%s/a.png", scratch_dir());
    cr_assert(file_exists(path));
}

/* Subdivision reports its flags in the EXR and in --json. */
Test(cli, nl_subdiv_flags_reach_the_output)
{
    char path[512];
    nl_field *f;
    nl_meta meta;
    json_error_t je;
    json_t *j;
    int rc = run_noiselab("synth subdiv --acf gauss:scale=2 --size 4096 --levels 6 --spacing 0.005 --json -o g.exr", out, sizeof out,
                          err, sizeof err);
    cr_assert_eq(rc, 0, "%s", err);
    snprintf(path, sizeof path, "%s/g.exr", scratch_dir());
    cr_assert_eq(nl_exr_read(path, &f, &meta), 0);
    cr_assert(strstr(meta.flags, "singular") != NULL, "noiselab.flags = \"%s\"", meta.flags);
    cr_assert(strncmp(meta.method, "subdiv:levels=6", 15) == 0, "%s", meta.method);
    nl_field_free(f);
    j = json_loads(out, 0, &je);
    cr_assert_not_null(j, "%s", je.text);
    cr_assert_str_eq(json_string_value(json_array_get(json_object_get(j, "flags"), 0)), "singular");
    cr_assert_eq(json_array_size(json_object_get(j, "levels")), 6);
    json_decref(j);
    rc = run_noiselab("coeffs --acf markov --dim 1 --levels 3 --json", out, sizeof out, err, sizeof err);
    cr_assert_eq(rc, 0, "%s", err);
    j = json_loads(out, 0, &je);
    cr_assert_not_null(j, "%s", je.text);
    json_t *cls = json_array_get(json_object_get(json_array_get(json_object_get(j, "levels"), 2), "classes"), 0);
    cr_assert_str_eq(json_string_value(json_object_get(cls, "class")), "mid");
    cr_assert_eq(json_array_size(json_object_get(cls, "coefficients")), 4);
    json_decref(j);
}

/* A tiny cloud renders: sky in the corners (blue above red), cloud in the middle. */
Test(cli, cloud_renders)
{
    char path[512];
    nl_field *f;
    FILE *fp = fopen("/tmp/noiselab-scene-ok.json", "w");
    fputs("{\"size\": [32, 24], \"box\": [[-1,-1,-1],[1,1,1]], \"points\": [[0,0,0,1]], \"acf\": \"gauss:scale=0.6\", "
          "\"noise\": {\"acf\": \"markov:scale=0.1\", \"amplitude\": 0.3, \"period\": 2}, \"grid\": 24, \"camera\": {\"position\": "
          "[0,0,-4], \"look_at\": [0,0,0], \"fov\": 40}, \"sun\": [0.3,1,-0.5]}", fp);
    fclose(fp);
    int rc = run_noiselab("cloud /tmp/noiselab-scene-ok.json -o c.png --exr c.exr", out, sizeof out, err, sizeof err);
    cr_assert_eq(rc, 0, "%s", err);
    snprintf(path, sizeof path, "%s/c.exr", scratch_dir());
    cr_assert_eq(nl_exr_read(path, &f, NULL), 0);
    /* the cloud is brighter than the sky beside it */
    cr_expect_gt(f->data[12 * 32 + 16], f->data[12 * 32 + 1], "centre %g, edge %g", f->data[12 * 32 + 16],
                 f->data[12 * 32 + 1]);
    nl_field_free(f);
}

static int same_file(const char *a, const char *b)
{
    char pa[512], pb[512], ca, cb;
    snprintf(pa, sizeof pa, "%s/%s", scratch_dir(), a);
    snprintf(pb, sizeof pb, "%s/%s", scratch_dir(), b);
    FILE *fa = fopen(pa, "rb"), *fb = fopen(pb, "rb");
    int same = fa && fb;
    while (same) {
        size_t na = fread(&ca, 1, 1, fa), nb = fread(&cb, 1, 1, fb);
        if (na != nb || (na && ca != cb))
            same = 0;
        if (!na || !nb)
            break;
    }
    if (fa) fclose(fa);
    if (fb) fclose(fb);
    return same;
}

/* A field's EXR records everything needed to regenerate it, bit for bit. */
Test(cli_slow, nl_synth_from_regenerates)
{
    const char *cmds[] = {"synth fft --acf markov:scale=3 --size 64x48 --seed 5",
                          "synth subdiv --acf markaussian:alpha=1.4,scale=8 --size 128x128 --seed 3 --neighborhood auto",
                          "synth subdiv --acf markov:scale=8 --size 100 --nonperiodic --origin -17 --levels 5",
                          "synth midpoint --H 0.7 --size 256",
                          "synth circulant --acf matern:nu=1.5,scale=4 --size 50x40",
                          "synth sparse --kernel 'cos(0.5*x)*exp(-r/4)' --radius 8 --size 64x64 --density 2 --wrap",
                          "synth sparse --acf markov:scale=3 --size 40x40 --origin 5,-3",
                          "synth faulting --size 64x64 --density 3",
                          "synth lattice --spectrum power:d=3 --size 128x128"};
    char args[512];
    for (size_t i = 0; i < sizeof cmds / sizeof *cmds; i++) {
        snprintf(args, sizeof args, "%s -o from-a.exr", cmds[i]);
        cr_assert_eq(run_noiselab(args, 0, 0, err, sizeof err), 0, "%s: %s", cmds[i], err);
        cr_assert_eq(run_noiselab("synth --from from-a.exr -o from-b.exr", 0, 0, err, sizeof err), 0, "%s: %s",
                     cmds[i], err);
        cr_expect(same_file("from-a.exr", "from-b.exr"), "%s: --from does not regenerate the same file", cmds[i]);
    }
    bad("synth --from from-a.exr --size 8 -o out.exr", "--from");
}

/* validate writes a complete report (a tolerance far above what 16
 * realizations resolve, so that every method is within it); a model that is
 * not positive definite is refused by every method: exit 3, report kept. */
Test(cli_slow, validate_reports)
{
    char path[512];
    json_error_t je;
    json_t *j;
    int rc = run_noiselab("validate --acf markov:scale=5 --dim 1 --size 1024 --realizations 16 --tolerance 10 -o v1", out, sizeof out,
                          err, sizeof err);
    cr_assert_eq(rc, 0, "%s", err);
    snprintf(path, sizeof path, "%s/v1/verdict.json", scratch_dir());
    j = json_load_file(path, 0, &je);
    cr_assert_not_null(j, "%s", je.text);
    cr_expect(json_is_true(json_object_get(j, "positive_definite")));
    cr_expect_str_eq(json_string_value(json_object_get(json_object_get(json_object_get(j, "methods"), "fft"), "verdict")),
                     "within");
    json_decref(j);
    snprintf(path, sizeof path, "%s/v1/index.md", scratch_dir());
    cr_expect(file_exists(path));
    /* every method has its line in the plots: gnuplot made all of them */
    for (int k = 0; k < 3; k++) {
        static const char *const png[] = {"acf.png", "error.png", "spectrum.png"};
        snprintf(path, sizeof path, "%s/v1/%s", scratch_dir(), png[k]);
        cr_expect(file_exists(path), "%s missing", png[k]);
    }
    rc = run_noiselab("validate --acf 'expr:cos(4*r)*exp(-r)' --dim 2 --size 64 --realizations 4 -o v2", out, sizeof out,
                      err, sizeof err);
    cr_assert_eq(rc, 4, "%s", err);
    cr_expect(strstr(out, "NOT positive definite") != NULL, "%s", out);
    cr_expect(strstr(out, "fft refused") != NULL, "%s", out);
}

/* validate -o: never into the root folder, into an existing folder that
 * holds files only with --force (which replaces the report's own files and
 * keeps the others), and the refusal leaves the folder as it was. */
Test(cli, validate_refuses_folders)
{
    char path[512];
    FILE *fp;
    snprintf(path, sizeof path, "%s/vf", scratch_dir());
    cr_assert_eq(mkdir(path, 0755), 0);
    snprintf(path, sizeof path, "%s/vf/keep.txt", scratch_dir());
    fp = fopen(path, "w");
    cr_assert_not_null(fp);
    fputs("kept\n", fp);
    fclose(fp);
    bad("validate --acf markov --dim 1 --size 64 --realizations 4 -o vf", "exists and is not empty");
    bad("validate --acf markov --dim 1 --size 64 --realizations 4 -o / --force", "root folder");
    snprintf(path, sizeof path, "%s/vf/index.md", scratch_dir());
    cr_expect(!file_exists(path), "a refused run wrote into the folder");
    cr_assert_eq(run_noiselab("validate --acf markov:scale=4 --dim 1 --size 64 --realizations 4 --tolerance 100 -o vf --force",
                              out, sizeof out, err, sizeof err), 0, "%s", err);
    cr_expect(file_exists(path), "--force: no index.md");
    snprintf(path, sizeof path, "%s/vf/keep.txt", scratch_dir());
    cr_expect(file_exists(path), "--force removed a file that was not the report's");
}

Test(cli, card)
{
    char path[512];
    cr_assert_eq(run_noiselab("synth fft --acf markov:scale=4 --size 64x64 -o card.exr", 0, 0, err, sizeof err), 0);
    cr_assert_eq(run_noiselab("card card.exr --acf markov:scale=4 -o card.png", 0, 0, err, sizeof err), 0, "%s", err);
    snprintf(path, sizeof path, "%s/card.png", scratch_dir());
    cr_expect(file_exists(path));
    /* 1D fields have a card too; shorter ones are refused */
    cr_assert_eq(run_noiselab("synth fft --acf markov:scale=4 --size 256 -o card1.tsv", 0, 0, err, sizeof err), 0);
    cr_assert_eq(run_noiselab("card card1.tsv --acf markov:scale=4 -o card1.png", 0, 0, err, sizeof err), 0, "%s",
                 err);
    snprintf(path, sizeof path, "%s/card1.png", scratch_dir());
    cr_expect(file_exists(path));
    cr_assert_eq(run_noiselab("synth fft --acf markov --size 32 -o card2.tsv", 0, 0, err, sizeof err), 0);
    bad("card card2.tsv -o out.png", "at least 64");
}

/* render --colorbar: the picture grows by the bar's width, the field's
 * pixels are those of the plain picture. */
Test(cli, render_colorbar)
{
    char path[512];
    nl_field *plain, *bar;
    cr_assert_eq(run_noiselab("synth fft --acf markov:scale=4 --size 64x48 -o cb.exr", 0, 0, err, sizeof err), 0);
    cr_assert_eq(run_noiselab("render cb.exr -o cb.png", 0, 0, err, sizeof err), 0, "%s", err);
    cr_assert_eq(run_noiselab("render cb.exr --colorbar -o cb2.png", 0, 0, err, sizeof err), 0, "%s", err);
    snprintf(path, sizeof path, "%s/cb.png", scratch_dir());
    cr_assert_eq(nl_png_read(path, &plain), 0);
    snprintf(path, sizeof path, "%s/cb2.png", scratch_dir());
    cr_assert_eq(nl_png_read(path, &bar), 0);
    cr_assert_eq(bar->n[0], 64 + 112);
    cr_assert_eq(bar->n[1], 48);
    for (size_t j = 0; j < 48; j++)
        for (size_t i = 0; i < 64; i++)
            cr_assert_eq(bar->data[j * bar->n[0] + i], plain->data[j * 64 + i]);
    nl_field_free(plain), nl_field_free(bar);
    bad("render cb.exr --colorbar --shade 315,30 -o out.png", "--colorbar");
}

/* A 1D TSV records what an EXR records, as "# key: value" lines; a window's
 * t starts at its origin; reading it back gives the provenance, and
 * --from regenerates it. */
Test(cli, tsv_provenance_and_origin)
{
    char path[512], line[256];
    nl_field *f;
    nl_meta meta;
    FILE *fp;
    cr_assert_eq(run_noiselab("synth subdiv --acf markov:scale=8 --size 64 --nonperiodic --origin 5000 --seed 3 "
                              "--spacing 0.5 -o w.tsv", 0, 0, err, sizeof err), 0, "%s", err);
    snprintf(path, sizeof path, "%s/w.tsv", scratch_dir());
    cr_assert_eq(nl_field_read(path, &f, &meta), 0, "%s", nl_errmsg());
    cr_assert_str_eq(meta.model, "markov:scale=8");
    cr_assert(strncmp(meta.method, "subdiv:", 7) == 0, "%s", meta.method);
    cr_assert_str_eq(meta.seed, "3");
    cr_assert_str_eq(meta.spacing, "0.5");
    cr_assert_str_eq(meta.origin, "5000");
    cr_assert_str_eq(meta.version, NL_VERSION_STRING);
    cr_assert_eq(f->h[0], 0.5);
    nl_field_free(f);
    fp = fopen(path, "r");
    cr_assert_not_null(fp);
    while (fgets(line, sizeof line, fp) && line[0] == '#')
        ;
    cr_assert_str_eq(line, "t\tvalue\n");
    cr_assert(fgets(line, sizeof line, fp) != NULL);
    cr_assert(strncmp(line, "2500\t", 5) == 0, "t = origin * spacing: %s", line);
    fclose(fp);
    cr_assert_eq(run_noiselab("synth --from w.tsv -o w2.tsv", 0, 0, err, sizeof err), 0, "%s", err);
    cr_assert_eq(run_noiselab("acf w.tsv --max-lag 4", out, sizeof out, err, sizeof err), 0, "%s", err);
    cr_assert(strstr(out, "\n0.5\t") != NULL, "lags in length units: %s", out);
}

/* Every reader says "cannot open FILE: reason" for a missing file. */
Test(cli, missing_files_are_named)
{
    bad("acf /nonexistent/f.exr", "cannot open /nonexistent/f.exr: No such file");
    bad("cloud /nonexistent/s.json -o out.png", "cannot open /nonexistent/s.json: No such file");
    bad("synth sparse --exemplar /nonexistent/e.png --size 64x64 -o out.exr", "cannot open /nonexistent/e.png:");
    bad("synth subdiv --acf markov --size 64x64 --seed-image /nonexistent/i.png -o out.exr",
        "cannot open /nonexistent/i.png:");
    bad("krige --data /nonexistent/p.tsv --acf markov --grid 8x8 --extent 0:1,0:1 -o out.exr",
        "cannot open /nonexistent/p.tsv:");
    bad("synth fft --acf image:/nonexistent/m.png --size 64x64 -o out.exr", "cannot open /nonexistent/m.png:");
    bad("synth --from /nonexistent/f.exr -o out.tsv", "cannot open /nonexistent/f.exr:");
}

/* A missing required option is named alone. */
Test(cli, missing_options_named_alone)
{
    bad("krige --data p.tsv --grid 8x8 --extent 0:1,0:1 -o out.exr", "krige: --acf:");
    bad("krige --data p.tsv --acf markov --extent 0:1,0:1 -o out.exr", "krige: --grid:");
    bad("nonlin --acf markov", "nonlin: --g:");
    bad("nonlin --g laplace", "nonlin: --acf:");
    bad("nonlin --design --g laplace", "--target:");
}

Test(cli, json_outputs)
{
    json_error_t je;
    json_t *j;
    cr_assert_eq(run_noiselab("synth fft --acf gauss:scale=4 --size 256 -o g.tsv", 0, 0, err, sizeof err), 0);
    cr_assert_eq(run_noiselab("acf g.tsv --max-lag 8 --target gauss:scale=4 --json", out, sizeof out, 0, 0), 0);
    j = json_loads(out, 0, &je);
    cr_assert_not_null(j, "%s", je.text);
    cr_assert_eq(json_array_size(json_object_get(j, "lag")), 9);
    cr_assert_eq(json_array_size(json_object_get(j, "acf")), 9);
    cr_assert_float_eq(json_real_value(json_array_get(json_object_get(j, "target"), 4)), exp(-1), 1e-9);
    json_decref(j);
    cr_assert_eq(run_noiselab("psd g.tsv --json", out, sizeof out, 0, 0), 0);
    j = json_loads(out, 0, &je);
    cr_assert_not_null(j, "%s", je.text);
    cr_assert_eq(json_array_size(json_object_get(j, "freq")), 129);
    cr_assert_str_eq(json_string_value(json_object_get(j, "sided")), "two-sided");
    json_decref(j);
    cr_assert_eq(run_noiselab("hist g.tsv --bins 7 --json", out, sizeof out, 0, 0), 0);
    j = json_loads(out, 0, &je);
    cr_assert_not_null(j, "%s", je.text);
    const char *keys[] = {"mean", "variance", "skewness", "kurtosis"};
    for (int i = 0; i < 4; i++)
        cr_assert(json_is_number(json_object_get(j, keys[i])), "%s", keys[i]);
    cr_assert_eq(json_array_size(json_object_get(j, "edges")), 8);
    cr_assert_eq(json_array_size(json_object_get(j, "counts")), 7);
    json_decref(j);
    cr_assert_eq(run_noiselab("models --json", out, sizeof out, 0, 0), 0);
    j = json_loads(out, 0, &je);
    cr_assert_eq(json_array_size(json_object_get(j, "models")), nl_family_count(), "one entry per registered family");
    json_decref(j);
}

Test(cli, help_and_version)
{
    const char *cmds[] = {"synth", "acf", "psd", "hist", "models", "coeffs"};
    char args[64];
    cr_assert_eq(run_noiselab("--version", out, sizeof out, 0, 0), 0);
    cr_assert(strncmp(out, "noiselab ", 9) == 0);
    cr_assert_eq(run_noiselab("--help", out, sizeof out, 0, 0), 0);
    for (int i = 0; i < 6; i++) {
        cr_assert(strstr(out, cmds[i]) != NULL, "--help lists %s", cmds[i]);
        snprintf(args, sizeof args, "%s --help", cmds[i]);
        cr_assert_eq(run_noiselab(args, out, sizeof out, 0, 0), 0, "%s", args);
        cr_assert(strncmp(out, "usage: noiselab", 15) == 0, "%s", args);
        run_noiselab("--help", out, sizeof out, 0, 0);
    }
    cr_assert_eq(run_noiselab("", 0, 0, 0, 0), 2);
    /* the top-level help names every synthesis method */
    const char *methods[] = {"fft",    "subdiv", "midpoint", "circulant", "cholesky",
                             "faulting", "sparse", "lattice",  "intrinsic"};
    cr_assert_eq(run_noiselab("--help", out, sizeof out, 0, 0), 0);
    for (int i = 0; i < 9; i++)
        cr_expect(strstr(out, methods[i]) != NULL, "--help names the method %s", methods[i]);
}

/* Progress goes to a terminal only: with progress due at once
 * (NOISELAB_PROGRESS_AFTER=0), a synthesis and a cloud leave stderr empty
 * when stderr is a pipe, as it is here. */
Test(cli, no_progress_when_stderr_is_not_a_terminal)
{
    int rc;
    setenv("NOISELAB_PROGRESS_AFTER", "0", 1);
    rc = run_noiselab("synth subdiv --acf markov:scale=16 --size 1024x1024 --seed 1 -o big.exr", out, sizeof out, err,
                      sizeof err);
    cr_expect_eq(rc, 0, "%s", err);
    cr_expect_eq(strlen(err), 0, "synth: stderr \"%s\"", err);
    FILE *fp = fopen("/tmp/noiselab-scene-progress.json", "w");
    fputs("{\"size\": [32, 24], \"box\": [[-1,-1,-1],[1,1,1]], \"points\": [[0,0,0,1]], \"acf\": \"gauss:scale=0.6\", "
          "\"noise\": {\"acf\": \"markov:scale=0.1\", \"period\": 2}, \"grid\": 16, \"camera\": {\"position\": [0,0,-4], "
          "\"look_at\": [0,0,0]}, \"sun\": [0.3,1,-0.5]}", fp);
    fclose(fp);
    rc = run_noiselab("cloud /tmp/noiselab-scene-progress.json -o c2.png", out, sizeof out, err, sizeof err);
    cr_expect_eq(rc, 0, "%s", err);
    cr_expect_eq(strlen(err), 0, "cloud: stderr \"%s\"", err);
    unsetenv("NOISELAB_PROGRESS_AFTER");
}
