/* libFuzzer target 8, synthcli: the synthesis case of num_case.h (a
 * method, a model with hostile but parseable parameters, a tiny size, the
 * method's options) as a command line, `noiselab synth ... -o out.exr`,
 * run in-process by cli_main (cli_die's exit replaced by a longjmp, as in
 * fuzz_cli.c), in the working folder `make fuzz` makes for it.
 * The checker traps (__builtin_trap, a crash libFuzzer records) when
 *   - a refusal's stderr is not one line "noiselab: ...", or it leaves a
 *     file in the working folder;
 *   - a success writes an out.exr that is not finite (the reader refuses
 *     it), prints nan or inf on stdout (--json), or leaves another file.
 * FUZZ_DEBUG=1 prints the decoded case; FUZZ_IGNORE skips recorded
 * findings (num_case.h); tests/fuzz/FINDINGS.md lists what it found. */
#include "../../cli/cli.h"
#include "../../core/io.h"
#include "../../core/model.h"
#include "../../core/nl_error.h"
#include "num_case.h"

#include <dirent.h>
#include <sanitizer/common_interface_defs.h>
#include <stdint.h>
#include <math.h>
#include <setjmp.h>
#include <strings.h>
#include <unistd.h>


static jmp_buf back;
static char errpath[64], outpath[64];

static void escape(int code) { longjmp(back, code + 1); }

static void setup_cli(void)
{
    static int done;
    if (done++)
        return;
    cli_exit_hook = escape;
    /* stderr is a file while the command runs: sanitizer reports of a
     * crash inside it go to the real stderr, beside libFuzzer's */
    __sanitizer_set_report_fd((void *)(intptr_t)dup(2));
    snprintf(errpath, sizeof errpath, "/tmp/noiselab-fuzz-err-%ld", (long)getpid());
    snprintf(outpath, sizeof outpath, "/tmp/noiselab-fuzz-out-%ld", (long)getpid());
}

static long slurp(const char *path, char *buf, size_t cap)
{
    FILE *fp = fopen(path, "rb");
    if (!fp)
        return -1;
    size_t k = fread(buf, 1, cap - 1, fp);
    buf[k] = 0;
    fclose(fp);
    return (long)k;
}

/* nan or inf as a word of the text (not "info"). */
static int has_nonfinite(const char *s)
{
    for (const char *p = s; *p; p++) {
        int start = p == s || !((p[-1] | 32) >= 'a' && (p[-1] | 32) <= 'z');
        if (start && (!strncasecmp(p, "nan", 3) || !strncasecmp(p, "inf", 3))) {
            char e = p[3];
            if (!((e | 32) >= 'a' && (e | 32) <= 'z') || !strncasecmp(p, "infinity", 8))
                return 1;
        }
    }
    return 0;
}

static void fail(const fcase *c, const char *kind, const char *why, const char *detail)
{
    char what[32];
    snprintf(what, sizeof what, "cli-%s", c->method->name);
    if (ignored(what, kind))
        return;
    fprintf(stderr, "fuzz: %s: %s\n", why, detail);
    setenv("FUZZ_DEBUG", "1", 1);
    debug(c);
    __builtin_trap();
}

/* Files in the working folder other than the ones expected. */
static void leftovers(const fcase *c, int ok)
{
    DIR *d = opendir(".");
    struct dirent *e;
    while (d && (e = readdir(d)))
        if (strcmp(e->d_name, ".") && strcmp(e->d_name, "..") && !(ok && !strcmp(e->d_name, "out.exr")))
        {
            fail(c, "leftover", ok ? "a success left an extra file" : "a refusal left a file", e->d_name);
            unlink(e->d_name); /* ignored (FUZZ_IGNORE): clean up for the next run */
        }
    if (d)
        closedir(d);
}

/* Empty the working folder: a run that crashed or timed out (fork mode)
 * could not clean up, and its files would be blamed on the next one. */
static void sweep(void)
{
    DIR *d = opendir(".");
    struct dirent *e;
    while (d && (e = readdir(d)))
        if (strcmp(e->d_name, ".") && strcmp(e->d_name, ".."))
            unlink(e->d_name);
    if (d)
        closedir(d);
}

/* The command line of case c: argv (at most 40 entries) points into buf. */
typedef struct {
    char sz[64], seed[32], org[64], opt[NL_METHOD_MAX_OPTIONS][64];
} argbuf;

static int build_argv(const fcase *c, argbuf *b, char **argv)
{
    int argc = 0, spectral = 0;
    nl_model *m;
    if (nl_model_parse(c->model, &m) == NL_OK) {
        spectral = nl_model_is_spectral(m);
        nl_model_free(m);
    }
    if (c->dim == 1)
        snprintf(b->sz, sizeof b->sz, "%zu", c->n[0]), snprintf(b->org, sizeof b->org, "%ld", c->origin[0]);
    else
        snprintf(b->sz, sizeof b->sz, c->dim == 2 ? "%zux%zu" : "%zux%zux%zu", c->n[0], c->n[1], c->n[2]),
            snprintf(b->org, sizeof b->org, "%ld,%ld", c->origin[0], c->origin[1]);
    snprintf(b->seed, sizeof b->seed, "%llu", (unsigned long long)c->seed);
#define ARG(s) (argv[argc++] = (char *)(s))
    ARG("noiselab"), ARG("synth"), ARG(c->method->name), ARG(spectral ? "--spectrum" : "--acf"), ARG(c->model);
    ARG("--size"), ARG(b->sz), ARG("--seed"), ARG(b->seed), ARG("--spacing"), ARG(c->h), ARG("--json");
    if (c->clamp)
        ARG("--clamp");
    for (int k = 0; k < c->method->noptions; k++) /* each given option; a flag without a value */
        if (c->opt[k]) {
            snprintf(b->opt[k], sizeof b->opt[k], "--%s", c->method->options[k].name);
            ARG(b->opt[k]);
            if (c->method->options[k].type != NL_METHOD_FLAG)
                ARG(c->opt[k]);
        }
    if (c->origin[0] || c->origin[1])
        ARG("--origin"), ARG(b->org);
    ARG("-o"), ARG("out.exr");
#undef ARG
    argv[argc] = NULL;
    return argc;
}

/* cli_main with stdout and stderr in files; returns the exit code. */
static int run(int argc, char **argv)
{
    fflush(stdout);
    fflush(stderr);
    int so = dup(1), se = dup(2), code;
    if (!freopen(outpath, "w", stdout) || !freopen(errpath, "w", stderr))
        abort();
    extern int optind;
    optind = 0; /* a full reinitialisation of getopt */
    if ((code = setjmp(back)) == 0)
        code = cli_main(argc, argv);
    else
        code--;
    fflush(stdout);
    fflush(stderr);
    dup2(so, 1), dup2(se, 2);
    close(so), close(se);
    return code;
}

/* A success: nothing non-finite on stdout or in out.exr, no other file. */
static void check_success(const fcase *c)
{
    static char text[1 << 16];
    if (slurp(outpath, text, sizeof text) > 0 && has_nonfinite(text))
        fail(c, "stdout", "stdout holds nan or inf", text);
    nl_field *f;
    nl_meta meta;
    if (nl_field_read("out.exr", &f, &meta) != NL_OK)
        fail(c, "nonfinite", "a success wrote an out.exr that does not read back (the reader refuses non-finite samples)",
             nl_errmsg());
    else {
        for (size_t i = 0; i < f->count; i++)
            if (!isfinite(f->data[i])) {
                fail(c, "nonfinite", "a success wrote a non-finite sample into out.exr", "");
                break;
            }
        nl_field_free(f);
    }
    leftovers(c, 1);
    unlink("out.exr");
}

/* A refusal: one line "noiselab: ..." on stderr, no file left. */
static void check_refusal(const fcase *c)
{
    static char text[1 << 16];
    long k = slurp(errpath, text, sizeof text);
    char *nl = k > 0 ? strchr(text, '\n') : NULL;
    if (k <= 0 || strncmp(text, "noiselab: ", 10) || !nl || nl[1] || nl == text + 10)
        fail(c, "stderr", "a refusal's stderr is not one line \"noiselab: ...\"", k > 0 ? text : "(empty)");
    leftovers(c, 0);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fcase c;
    argbuf b;
    char *argv[40];
    setup();
    setup_cli();
    sweep();
    decode(data, size, &c);
    debug(&c);
    if (run(build_argv(&c, &b, argv), argv) == 0)
        check_success(&c);
    else
        check_refusal(&c);
    return 0;
}
