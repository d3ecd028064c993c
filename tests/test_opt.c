/* The option tables of the command line (cli/opt.c): each type fills its
 * field, each bad value gives the message and exit status the commands
 * print, and a shared group lands at its struct's place. */
#include "../cli/cli.h"
#include "../cli/inputs.h"
#include "../cli/opt.h"

#include <criterion/criterion.h>
#include <setjmp.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* A command's options, one field per type. */
typedef struct {
    int flag, level, given, choice, drift, dim, sdim, views, nb;
    const char *str, *out;
    double x, angle, pos, pair[2], opt;
    size_t count, n[3];
    int small;
    uint64_t seed;
    cli_inputs in;
    const char *seen; /* the callback's value */
    int adds;         /* --add's calls */
} opts_t;

static void call(void *obj, const char *label, const char *arg)
{
    if (strcmp(arg, "bad") == 0)
        cli_die(2, "%s: expected anything but bad, got \"%s\"", label, arg);
    ((opts_t *)obj)->seen = arg;
}

static void add(void *obj, const char *label, const char *arg)
{
    (void)label, (void)arg;
    ((opts_t *)obj)->adds++;
}

static const char *const words[] = {"alpha", "beta", "gamma", NULL};
static const char *const drifts[] = {"constant", "linear", NULL};
static const int drift_vals[] = {7, 9};

static const cli_opt rows[] = {
    {.name = "flag", .letter = 'f', .type = CLI_OPT_FLAG, CLI_AT(opts_t, flag)},
    {.name = "str", .type = CLI_OPT_STRING, CLI_AT(opts_t, str), CLI_GIVEN(opts_t, given)},
    {.name = "x", .type = CLI_OPT_DOUBLE, CLI_AT(opts_t, x)},
    {.name = "angle", .type = CLI_OPT_DOUBLE, CLI_AT(opts_t, angle), .flags = CLI_RANGE_LO | CLI_RANGE_HI, .lo = 0,
     .hi = 90, .what = "degrees in [0, 90]"},
    {.name = "pos", .type = CLI_OPT_POSITIVE, CLI_AT(opts_t, pos), .what = "bin width"},
    {.name = "count", .type = CLI_OPT_COUNT, CLI_AT(opts_t, count), .lo = 2},
    {.name = "small", .type = CLI_OPT_INT, CLI_AT(opts_t, small), CLI_FROM_TO(1, 30)},
    {.name = "choice", .type = CLI_OPT_CHOICE, CLI_AT(opts_t, choice), .choices = words},
    {.name = "drift", .type = CLI_OPT_CHOICE, CLI_AT(opts_t, drift), .choices = drifts, .vals = drift_vals,
     .what = "constant or linear (the drift)"},
    {.name = "pair", .type = CLI_OPT_PAIR, CLI_AT(opts_t, pair), CLI_GIVEN(opts_t, views)},
    {.name = "opt", .type = CLI_OPT_POSITIVE, CLI_AT(opts_t, opt), CLI_GIVEN(opts_t, views), .flags = CLI_OPTIONAL,
     .what = "largest lag"},
    {.name = "call", .type = CLI_OPT_CALL, .fn = call},
    {.name = "add", .type = CLI_OPT_CALL, .fn = add, .flags = CLI_REPEAT},
    {.name = "alias", .type = CLI_OPT_STRING, CLI_AT(opts_t, str)},
    CLI_INT("nb", opts_t, nb, CLI_FROM_TO(1, 9), .flags = CLI_AUTO, .need = "a neighbourhood"),
    CLI_OPT_DIMS(opts_t, dim, 3),
    CLI_OPT_OUTPUT(opts_t, out),
    {.name = "grid", .type = CLI_OPT_SIZE, CLI_AT(opts_t, n), CLI_AUX(opts_t, sdim), .lo = 2},
    {.type = CLI_OPT_GROUP, .sub = cli_inputs_rows, CLI_AT(opts_t, in)},
    {0}};

static jmp_buf back;
static int code;
static char *msg;
static size_t msglen;

static void escape(int c)
{
    code = c;
    longjmp(back, 1);
}

/* Parse "cmd ARGS..." (split at spaces) into o: the parse's return, or
 * 100 + the exit status with the message in msg. */
static int parse(opts_t *o, const char *args)
{
    static char buf[512];
    static char *argv[32];
    static volatile int rc;
    FILE *saved = stderr;
    int argc = 0;
    extern int optind;
    snprintf(buf, sizeof buf, "t %s", args);
    for (char *t = strtok(buf, " "); t && argc < 31; t = strtok(NULL, " "))
        argv[argc++] = t;
    argv[argc] = NULL;
    memset(o, 0, sizeof *o);
    free(msg), msg = NULL;
    stderr = open_memstream(&msg, &msglen);
    cli_exit_hook = escape;
    optind = 0;
    if (setjmp(back) == 0)
        rc = cli_opt_parse("t", NULL, rows, o, argc, argv);
    else
        rc = 100 + code;
    fclose(stderr);
    stderr = saved;
    return rc;
}

Test(opt, each_type_fills_its_field)
{
    opts_t o;
    cr_assert_eq(parse(&o, "-f --str s --x -2.5 --angle 90 --pos 0.25 --count 2 --small 30 --choice gamma "
                           "--drift linear --pair 1.5,-2 --call v --dim 2 -o out.tsv --grid 4x5"), 0, "%s", msg);
    cr_expect_eq(o.flag, 1);
    cr_expect_str_eq(o.str, "s");
    cr_expect_eq(o.given, 1);
    cr_expect_eq(o.x, -2.5);
    cr_expect_eq(o.angle, 90);
    cr_expect_eq(o.pos, 0.25);
    cr_expect_eq(o.count, 2);
    cr_expect_eq(o.small, 30);
    cr_expect_eq(o.choice, 2);
    cr_expect_eq(o.drift, 9, "a choice sets its value from vals");
    cr_expect(o.pair[0] == 1.5 && o.pair[1] == -2);
    cr_expect_str_eq(o.seen, "v");
    cr_expect_eq(o.dim, 2);
    cr_expect_str_eq(o.out, "out.tsv");
    cr_expect(o.sdim == 2 && o.n[0] == 4 && o.n[1] == 5);
    cr_expect_eq(o.views, 1, "--pair marks its given field");
}

/* Each message is the one the commands printed before the tables. */
static void bad(const char *args, const char *want)
{
    opts_t o;
    int rc = parse(&o, args);
    cr_expect_eq(rc, 102, "%s: exit %d", args, rc - 100);
    cr_expect_str_eq(msg, want, "%s", args);
}

Test(opt, bad_values_name_the_option)
{
    bad("--x 1e999", "noiselab: --x: expected a finite number, got \"1e999\"\n");
    bad("--angle 90.5", "noiselab: --angle: expected degrees in [0, 90], got \"90.5\"\n");
    bad("--angle -0.5", "noiselab: --angle: expected degrees in [0, 90], got \"-0.5\"\n");
    bad("--pos 0", "noiselab: --pos: expected a positive bin width, got \"0\"\n");
    bad("--count 1", "noiselab: --count: expected an integer >= 2, got \"1\"\n");
    bad("--small 31", "noiselab: --small: expected 1 to 30, got \"31\"\n");
    bad("--small 0", "noiselab: --small: expected an integer >= 1, got \"0\"\n");
    bad("--choice delta", "noiselab: --choice: expected alpha, beta or gamma, got \"delta\"\n");
    bad("--drift cubic", "noiselab: --drift: expected constant or linear (the drift), got \"cubic\"\n");
    bad("--pair 1,inf", "noiselab: --pair: expected two numbers A,B, got \"1,inf\"\n");
    bad("--opt=-1", "noiselab: --opt: expected a positive largest lag, got \"-1\"\n");
    bad("--call bad", "noiselab: --call: expected anything but bad, got \"bad\"\n");
    bad("--dim 4", "noiselab: --dim: expected 1 to 3, got \"4\"\n");
    bad("--grid 4x1", "noiselab: --grid: expected N, NxM or NxMxK with each N >= 2, got \"4x1\"\n");
    bad("--seed -1", "noiselab: --seed: expected an integer from 0 to 2^64-1, got \"-1\"\n");
}

Test(opt, getopt_errors)
{
    bad("--x", "noiselab: t: option \"--x\" expects a value\n");
    bad("--bogus", "noiselab: t: unknown option \"--bogus\" (see noiselab t --help)\n");
    bad("-q", "noiselab: t: unknown option \"-q\" (see noiselab t --help)\n");
    bad("--flag=1", "noiselab: t: unknown option \"--flag=1\" (see noiselab t --help)\n");
}

Test(opt, help_stops_the_parse)
{
    opts_t o;
    cr_expect_eq(parse(&o, "--flag --help --count 0"), 1, "a value after --help is not read");
    cr_expect_eq(o.flag, 1);
    cr_expect_eq(parse(&o, "--count 0 --help"), 102, "a value before it is");
}

Test(opt, optional_value_and_abbreviation)
{
    opts_t o;
    cr_assert_eq(parse(&o, "--opt"), 0);
    cr_expect(o.views == 1 && o.opt == 0, "left out: given, and 0");
    cr_assert_eq(parse(&o, "--opt=2.5 --ang 3"), 0, "%s", msg);
    cr_expect(o.opt == 2.5 && o.angle == 3, "a unique prefix names the option, as getopt_long allows");
    cr_expect_eq(parse(&o, "--s x"), 102, "--s is ambiguous (--str, --small, --seed, --size)");
}

Test(opt, shared_group_lands_in_its_struct)
{
    opts_t o;
    cr_assert_eq(parse(&o, "--realizations 3 --acf markov --size 8x4 --seed 5 --x 1"), 0, "%s", msg);
    cr_expect_eq(o.in.K, 3);
    cr_expect_str_eq(o.in.spec, "markov");
    cr_expect(o.in.dim == 2 && o.in.n[0] == 8 && o.in.n[1] == 4);
    cr_expect(o.in.seed == 5 && o.in.seed_set == 1);
    cr_expect_eq(o.x, 1, "the command's own rows beside the group's");
    bad("--realizations 100001", "noiselab: --realizations: expected at most 100000, got \"100001\"\n");
    bad("--size 1", "noiselab: --size: expected N, NxM or NxMxK with each N >= 2, got \"1\"\n");
}

Test(opt, auto_and_need)
{
    opts_t o;
    cr_assert_eq(parse(&o, "--nb auto"), 0, "%s", msg);
    cr_expect_eq(o.nb, 0, "auto is 0");
    cr_assert_eq(parse(&o, "--nb 9"), 0, "%s", msg);
    cr_expect_eq(o.nb, 9);
    bad("--nb 10", "noiselab: --nb: expected 1 to 9, got \"10\"\n");
    bad("--nb automatic", "noiselab: --nb: expected an integer >= 1, got \"automatic\"\n");
    memset(&o, 0, sizeof o);
    o.nb = 3;
    cli_opt_need("t", rows, &o); /* set: no exit */
    o.nb = 0;
    free(msg), msg = NULL;
    stderr = open_memstream(&msg, &msglen);
    if (setjmp(back) == 0)
        cli_opt_need("t", rows, &o);
    fclose(stderr);
    cr_expect_eq(code, 2);
    cr_expect_str_eq(msg, "noiselab: t: --nb: expected a neighbourhood\n");
}

/* The last of two values would silently win: an option given twice is
 * refused, by any of its spellings, and so are two rows that fill one field
 * (--acf and --spectrum); one marked CLI_REPEAT takes each value in turn. */
Test(opt, an_option_given_twice_is_refused)
{
    opts_t o;
    bad("--x 1 --x 2", "noiselab: t: --x: given twice (\"1\", then \"2\"); expected it once\n");
    bad("-f --flag", "noiselab: t: --flag: given twice; expected it once\n");
    bad("-o a.tsv --output b.tsv", "noiselab: t: -o: given twice (\"a.tsv\", then \"b.tsv\"); expected it once\n");
    bad("--choice alpha --choice alpha",
        "noiselab: t: --choice: given twice (\"alpha\", then \"alpha\"); expected it once\n");
    bad("--call a --call b", "noiselab: t: --call: given twice (\"a\", then \"b\"); expected it once\n");
    bad("--opt --opt=2", "noiselab: t: --opt: given twice; expected it once\n");
    bad("--str a --alias b", "noiselab: t: --alias \"b\": --str was given too; expected one of --str and --alias\n");
    bad("--size 8 --size 16", "noiselab: t: --size: given twice (\"8\", then \"16\"); expected it once\n");
    cr_assert_eq(parse(&o, "--pair 1,2 --opt=3"), 0, "%s", msg);
    cr_expect_eq(o.views, 1, "two options marking one given field are two options");
    cr_assert_eq(parse(&o, "--add a --x 1 --add b --add c"), 0, "%s", msg);
    cr_expect_eq(o.adds, 3, "a repeatable option takes every value");
}
