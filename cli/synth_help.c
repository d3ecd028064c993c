/* noiselab synth --help: the usage, then each method's paragraph and the
 * options, naming the methods from the registry. */
#include "synth.h"

#include <stdio.h>
#include <string.h>

/* The help: the usage, each method's paragraph (its descriptor's help, in
 * the registry's order), then the common options. */
static const char help_usage[] =
    "usage: noiselab synth METHOD (--acf SPEC | --spectrum SPEC) --size N[xM[xK]]\n"
    "                      [--seed S] [--spacing H[,H...]] [--clamp] [--preview P.png]\n"
    "                      [--json] [method options] -o OUT [--format NAME] [--range LO:HI]\n"
    "                      [--precision single|double]\n\n"
    "METHOD\n";

static const char help[] =
    "\n"
    "  --acf SPEC       autocorrelation model (see noiselab models)\n"
    "  --spectrum SPEC  spectrum model: power:d=..., spectrum:EXPR, or a bare EXPR in f/fx/fy/k\n"
    ;
/* then --size, naming each method's dimensions, then: */
static const char help_seed[] =
    "  --seed           64-bit seed (default 1)\n"
    "  --spacing        output grid spacing, one value or one per axis (default 1)\n";
/* then --clamp, naming the methods honouring it, then: */
static const char help_preview[] =
    "  --preview        8-bit PNG of a 2D field (the first slice of 3D), mean +- 3 sd\n"
    "  --json           print the synthesis report as JSON\n";
/* then --condition's first line, naming the conditionable methods */
static const char help_condition[] =
    "                   data (conditional simulation, Journel: the field plus the ordinary\n"
    "                   kriging of data minus field; --mean M: simple); sample i at\n"
    "                   a + (i + 0.5)(b - a)/N; between samples the field is drawn given\n"
    "                   the 4^d samples around (--interpolation: deprecated, ignored);\n"
    "                   --realizations K: OUT-1.exr ... OUT-K.exr, seeds S..;\n"
    "                   --ensemble-mean M.exr, --ensemble-variance V.exr (divisor K - 1);\n"
    "                   --nmax K: local kriging from the K nearest data (as krige);\n"
    "                   --at PTS.tsv: -o OUT.tsv is PTS.tsv's rows as read, then K columns\n"
    "                   sim1..simK: the realizations at its points (x[, y[, z]] within\n"
    "                   the extent), drawn jointly with the grid (as gstat's krige(...,\n"
    "                   newdata = points, nsim = K)); the grids are then written only to\n"
    "                   --grid-out G.exr (G-1.exr ... G-K.exr; G.tsv in 1D; drawn with the\n"
    "                   points, so not the grids of the same seeds without --at)\n"
    "  --from FILE      regenerate FILE from what it records (method, options, model,\n"
    "                   seed, size, spacing): bit for bit for every method; with it only\n"
    "                   -o, --preview, --json and --precision are taken, any other option\n"
    "                   (--seed included) is refused: for another seed or size, give the\n"
    "                   method and options FILE records; a file the record names (model\n"
    "                   image:F, --seed-image F, --exemplar F) is read only when the\n"
    "                   command line names it too (--acf image:F, ...)\n"
    "  -o               EXR (any dimension; attributes noiselab.model, .method, .seed,\n"
    "                   .size, .spacing, .origin, .version, .flags) or TSV (1D: the same as\n"
    "                   \"# key: value\" lines, then columns t, value, t = (origin + i) h);\n"
    "                   or HDF5 (.h5: dataset /field, float32, attributes model, method, seed,\n"
    "                   size, spacing, origin, version, flags, processes; read by noiselab-mpi,\n"
    "                   which noiselab hands .h5 runs to, with an .xmf sidecar for ParaView);\n"
    "                   or NumPy .npy, a 16-bit PNG heightmap (.png), raw .r16 or .f32 (noiselab\n"
    "                   formats lists them); nothing is written unless every sample is finite\n"
    "                   (and, in float32, within its range)\n"
    "  --format NAME    write -o in format NAME whatever its extension\n"
    "  --range LO:HI    16-bit outputs (png16, r16): the values mapped to 0 and 65535\n"
    "  --crs CRS        georeferenced outputs (.tif, .nc, --cog): the CRS, e.g. EPSG:28992\n"
    "  --cog            write -o as a cloud-optimised GeoTIFF (format cog)\n"
    "                   (default: the field's min and max)\n"
    "  --precision single|double  .h5 and .npy outputs: float32 or float64 (.h5 default\n"
    "                   float32, .npy float64)\n";
/* then the paragraph on distributed runs, naming the distributed methods,
 * filled to this width */
#define HELP_MPI_WIDTH 82

/* The methods with every capability in `have`, none in `lack` and, dims
 * != 0, exactly those dimensions (nl_method_type.dims), joined as
 * nl_method_names does; returns how many. */
static int names_where(unsigned have, unsigned lack, unsigned dims, const char *last, char *buf, size_t size)
{
    int n = 0, count = 0;
    size_t len = 0;
    buf[0] = '\0';
    for (int pass = 0; pass < 2; pass++)
        for (int i = 0; i < nl_method_count(); i++) {
            const nl_method_type *t = nl_method_at(i);
            if ((t->caps & have) != have || (t->caps & lack) || (dims && t->dims != dims))
                continue;
            if (!pass)
                count++;
            else if (len < size)
                len += (size_t)snprintf(buf + len, size - len, "%s%s", !n ? "" : n == count - 1 ? last : ", ",
                                        t->name), n++;
        }
    return count;
}

/* --size with the dimensions of each method, --clamp with the methods
 * honouring it (spectrum methods zero the negative spectrum, subdivision
 * its negative variances), then --seed and --spacing between them. */
static void print_size_clamp(void)
{
    char text[512], spec[128], var[128], d3[128], d2[128];
    names_where(0, 0, 7, " and ", d3, sizeof d3);
    names_where(0, 0, 3, " and ", d2, sizeof d2);
    snprintf(text, sizeof text, "samples per axis, each >= 2 (1D, 2D or 3D: %s; 1D or 2D: %s)", d3, d2);
    cli_fill_lead(stdout, "  --size           ", text, 86);
    fputs(help_seed, stdout);
    names_where(NL_METHOD_CLAMP, NL_METHOD_SUBDIVISION, 0, ", ", spec, sizeof spec);
    names_where(NL_METHOD_CLAMP | NL_METHOD_SUBDIVISION, 0, 0, ", ", var, sizeof var);
    snprintf(text, sizeof text, "synthesise a model that is not positive definite by zeroing its negative spectrum "
             "(%s) or variances (%s); flagged \"clamped\" in the output, the change in the report", spec, var);
    cli_fill_lead(stdout, "  --clamp          ", text, 86);
    fputs(help_preview, stdout);
}

void cli_synth_print_help(void)
{
    char list[256], mpi[512];
    fputs(help_usage, stdout);
    for (int i = 0; i < nl_method_count(); i++) {
        const char *p = nl_method_at(i)->help;
        printf("  %-10s", nl_method_at(i)->name);
        while (*p) {
            size_t l = strcspn(p, "\n");
            printf("%s%.*s\n", p == nl_method_at(i)->help ? "" : "            ", (int)l, p);
            p += l + (p[l] == '\n');
        }
    }
    fputs(help, stdout);
    print_size_clamp();
    nl_method_names(NL_METHOD_CONDITIONABLE | NL_METHOD_EXACT_FIRST, NULL, ", ", ", ", list, sizeof list);
    printf("  --condition DATA.tsv --extent a:b[,c:d[,e:f]]  %s: honour the\n", list);
    fputs(help_condition, stdout);
    nl_method_names(NL_METHOD_DISTRIBUTED | NL_METHOD_EXACT_FIRST, NULL, ", ", " and ", list, sizeof list);
    snprintf(mpi, sizeof mpi, "Under an MPI launcher (mpirun -np P noiselab synth ... -o OUT.h5) %s run "
             "distributed, each process holding 1/P of the field (docs/scale-out.md).", list);
    cli_fill(stdout, mpi, HELP_MPI_WIDTH);
}
