/* libFuzzer targets for the command line: FUZZ_TARGET selects one.
 *   4 cli    the input is a command line, one argument per line, run by
 *            cli_main: every subcommand's option parsing except the
 *            long-running bench, validate, card and cloud
 *   5 krige  the input is the data file of `krige --data` (the TSV reader)
 *   6 cloud  the input is the scene file of `cloud` (the JSON reader);
 *            scenes asking for more than a 48 x 48 picture or a 24^3 grid,
 *            or leaving a grid at its default of 64, are skipped, to keep
 *            each run short
 * Commands run in-process: cli_die's exit is replaced by a longjmp back
 * here (cli_exit_hook), so bad input costs no process.  Inputs naming
 * paths with '/' are skipped: outputs go to the working directory, which
 * `make fuzz` makes a scratch folder of its own.  Memory is limited to 4 MiB per request
 * (NOISELAB_MEMORY_LIMIT), so sizes that would take long are refused. */
#include "../../cli/cli.h"

#include <jansson.h>
#include <setjmp.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static jmp_buf back;

static void escape(int code) { longjmp(back, code + 1); }

static void setup(void)
{
    static int done;
    if (done++)
        return;
    setenv("NOISELAB_MEMORY_LIMIT", "4194304", 1);
    setenv("NOISELAB_FFTW", "estimate", 1);
    cli_exit_hook = escape;
    if (!freopen("/dev/null", "w", stdout))
        abort();
}

static void run(int argc, char **argv)
{
    extern int optind;
    optind = 0; /* a full reinitialisation of getopt */
    if (setjmp(back) == 0)
        (void)cli_main(argc, argv);
}

static int write_file(const char *path, const uint8_t *data, size_t size)
{
    FILE *fp = fopen(path, "wb");
    if (!fp)
        return -1;
    fwrite(data, 1, size, fp);
    return fclose(fp);
}

#if FUZZ_TARGET == 4
static int allowed(const char *cmd)
{
    static const char *const ok[] = {"models", "check", "coeffs", "synth", "acf", "psd",    "hist",
                                     "nonlin", "shape", "krige",  "lattice", "ocean", "render", "detect"};
    for (size_t i = 0; i < sizeof ok / sizeof *ok; i++)
        if (strcmp(cmd, ok[i]) == 0)
            return 1;
    return 0;
}
#endif

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    setup();
#if FUZZ_TARGET == 4
    enum { MAXARG = 24 };
    char *buf = malloc(size + 1), *argv[MAXARG + 2];
    int argc = 1;
    if (!buf)
        return 0;
    memcpy(buf, data, size);
    buf[size] = 0;
    argv[0] = "noiselab";
    for (char *p = buf, *nl; p && argc <= MAXARG; p = nl ? nl + 1 : NULL) {
        if ((nl = strchr(p, '\n')))
            *nl = 0;
        argv[argc++] = p;
    }
    argv[argc] = NULL;
    int ok = argc >= 2 && allowed(argv[1]);
    for (int i = 1; ok && i < argc; i++)
        if (strchr(argv[i], '/') || strstr(argv[i], "bench"))
            ok = 0;
    if (ok)
        run(argc, argv);
    free(buf);
#elif FUZZ_TARGET == 5
    char *argv[] = {"noiselab", "krige", "--acf", "markov:scale=0.3", "--data", "pts.tsv", "--grid", "8x8",
                    "--extent", "0:1,0:1", "--variance", "v.exr", "-o", "k.tsv", NULL};
    if (write_file("pts.tsv", data, size) == 0)
        run(14, argv);
#else
    char *argv[] = {"noiselab", "cloud", "scene.json", "-o", "c.png", NULL};
    json_t *j = json_loadb((const char *)data, size, 0, NULL), *sz = json_object_get(j, "size");
    json_t *g = json_object_get(j, "grid"), *ng = json_object_get(json_object_get(j, "noise"), "grid");
    /* both grids default to 64 when absent: require them, and small */
    int small = j && json_integer_value(json_array_get(sz, 0)) <= 48 && json_integer_value(json_array_get(sz, 1)) <= 48 &&
                json_is_number(g) && json_number_value(g) <= 24 && json_is_number(ng) && json_number_value(ng) <= 24;
    json_decref(j);
    if (small && write_file("scene.json", data, size) == 0)
        run(5, argv);
#endif
    return 0;
}
