/* Options as tables, in the manner of git's parse-options: one row per option
 * (names, type, range or choices, the field it fills, message details), rows
 * shared by commands, and one parse that checks each value (cli/opt.c). */
#ifndef NL_CLI_OPT_H
#define NL_CLI_OPT_H

#include <stddef.h>

/* What an option takes and how its value is checked.  Messages name the
 * option by its label ("--width", or "-o"); "..." is the value. */
typedef enum {
    CLI_OPT_END = 0,  /* ends a table */
    CLI_OPT_FLAG,     /* no value: int field = 1 */
    CLI_OPT_STRING,   /* const char * field, unchecked */
    CLI_OPT_DOUBLE,   /* double: a finite number, in [lo, hi] by flags */
    CLI_OPT_POSITIVE, /* double > 0: "expected a positive WHAT, got ..." */
    CLI_OPT_COUNT,    /* size_t: an integer >= lo, and <= hi when hi > 0 */
    CLI_OPT_INT,      /* int: the same as COUNT */
    CLI_OPT_U64,      /* uint64_t: an integer from 0 to 2^64-1 */
    CLI_OPT_CHOICE,   /* int field = the index of the value in choices (or vals[index]) */
    CLI_OPT_SIZE,     /* size_t[3]: N, NxM or NxMxK, each >= lo; the axes to the int at aux */
    CLI_OPT_DIM,      /* int: 1 to hi (cli_parse_dim's message) */
    CLI_OPT_PAIR,     /* double[2] field: "A,B", both finite */
    CLI_OPT_CALL,     /* fn(obj, label, value) does all of it */
    CLI_OPT_GROUP     /* the rows of sub, their fields at off within this struct */
} cli_opt_type;

/* The field's place in the options struct, and an optional int that is set
 * to 1 when the option is given (0 when none; see CLI_GIVEN). */
#define CLI_AT(T, F) .off = offsetof(T, F)
#define CLI_GIVEN(T, F) .given = offsetof(T, F) + 1
#define CLI_AUX(T, F) .aux = offsetof(T, F) + 1

/* flags: DOUBLE's range checks lo <= v and v <= hi; the value may be left
 * out (a DOUBLE or POSITIVE field is then 0); INT: "auto" sets 0.  COUNT
 * and INT take lo as the least value and hi, when not 0, as the largest.
 * CLI_REPEAT: the option may be given more than once (each value taken in
 * turn; its help says so, "[--fix NAME=VALUE]..."); any other option given
 * twice, or with another row that fills the same field or calls the same
 * function (--acf and --spectrum), is refused: the last would silently win. */
enum { CLI_RANGE_LO = 1, CLI_RANGE_HI = 2, CLI_OPTIONAL = 4, CLI_AUTO = 8, CLI_REPEAT = 16 };

/* One row of an option table. */
typedef struct cli_opt {
    const char *name;              /* the long name, without "--" */
    char letter;                   /* the short option, or 0 */
    cli_opt_type type;             /* what it takes */
    size_t off;                    /* its field (CLI_AT), or the group's struct */
    size_t given;                  /* offset + 1 of an int set when given, or 0 */
    size_t aux;                    /* offset + 1 of a second field (SIZE: the dim), or 0 */
    unsigned flags;                /* CLI_RANGE_*, CLI_OPTIONAL, CLI_AUTO */
    double lo, hi;                 /* the range (see above) */
    const char *label;             /* the name in messages (NULL: "--NAME") */
    const char *what;              /* POSITIVE: the noun; else what is expected, in words
                                    * (e.g. "degrees in [0, 90]"; CHOICE: NULL for "a, b or c") */
    const char *const *choices;    /* CHOICE: the values, NULL-terminated */
    const int *vals;               /* CHOICE: what each sets (NULL: its index) */
    void (*fn)(void *obj, const char *label, const char *arg); /* CALL; arg NULL when left out */
    const struct cli_opt *sub;     /* GROUP: the rows */
    const char *need;              /* required: what cli_opt_need says is expected */
} cli_opt;

/* Parse argv[1..] for subcommand cmd by the rows, filling obj: 0, optind at
 * the first operand; 1 at once on --help (-h), after printing help unless
 * NULL.  A bad option or value, or an option given twice (see CLI_REPEAT),
 * exits 2 with its message (cli_die). */
int cli_opt_parse(const char *cmd, const char *help, const cli_opt *rows, void *obj, int argc, char **argv);

/* A row by its type, in the manner of git's OPT_BOOL: long name N, the
 * field F of options struct T, then any more of the row's fields. */
#define CLI_FLAG(N, T, F, ...) {.name = N, .type = CLI_OPT_FLAG, CLI_AT(T, F), __VA_ARGS__}
#define CLI_STRING(N, T, F, ...) {.name = N, .type = CLI_OPT_STRING, CLI_AT(T, F), __VA_ARGS__}
#define CLI_DOUBLE(N, T, F, ...) {.name = N, .type = CLI_OPT_DOUBLE, CLI_AT(T, F), __VA_ARGS__}
#define CLI_POSITIVE(N, T, F, ...) {.name = N, .type = CLI_OPT_POSITIVE, CLI_AT(T, F), __VA_ARGS__}
#define CLI_COUNT(N, T, F, ...) {.name = N, .type = CLI_OPT_COUNT, CLI_AT(T, F), __VA_ARGS__}
#define CLI_INT(N, T, F, ...) {.name = N, .type = CLI_OPT_INT, CLI_AT(T, F), __VA_ARGS__}
#define CLI_U64(N, T, F, ...) {.name = N, .type = CLI_OPT_U64, CLI_AT(T, F), __VA_ARGS__}
#define CLI_CHOICE(N, T, F, ...) {.name = N, .type = CLI_OPT_CHOICE, CLI_AT(T, F), __VA_ARGS__}
#define CLI_PAIR(N, T, F, ...) {.name = N, .type = CLI_OPT_PAIR, CLI_AT(T, F), __VA_ARGS__}
#define CLI_CALL(N, FN, ...) {.name = N, .type = CLI_OPT_CALL, .fn = (FN), __VA_ARGS__}
#define CLI_GROUP(ROWS, T, F) {.type = CLI_OPT_GROUP, .sub = (ROWS), CLI_AT(T, F)}

/* An INT or COUNT from LO to HI (integers or their macros): "expected LO to HI" */
#define CLI_STR_(X) #X
#define CLI_STR(X) CLI_STR_(X)
#define CLI_FROM_TO(LO, HI) .lo = (LO), .hi = (HI), .what = CLI_STR(LO) " to " CLI_STR(HI)

/* The first row with need whose field is unset (NULL or 0), in the rows'
 * order: exit 2 with "CMD: LABEL: expected NEED". */
void cli_opt_need(const char *cmd, const cli_opt *rows, const void *obj);

/* Rows many commands share: one definition each (T the options struct, F the field). */
#define CLI_OPT_OUTPUT(T, F, ...) CLI_STRING("output", T, F, .letter = 'o', .label = "-o", __VA_ARGS__)
/* --format NAME, --range LO:HI, --crs CRS and --cog of a field output (cli_field_format, cli/field_out.c) */
#define CLI_OPT_FORMAT                                                                                            \
    CLI_CALL("format", cli_opt_format, .what = "a format (noiselab formats)"),                                    \
        CLI_CALL("range", cli_opt_range, .what = "LO:HI"),                                                         \
        CLI_CALL("crs", cli_opt_crs, .what = "a CRS, EPSG:N (geotiff, cog, netcdf)"),                            \
        CLI_CALL("cog", cli_opt_cog, .what = "no value (format cog)", .flags = CLI_OPTIONAL)
#define CLI_OPT_JSON(T, F) {.name = "json", .type = CLI_OPT_FLAG, CLI_AT(T, F)}
/* --seed S, and G set when given */
#define CLI_OPT_SEED(T, F, G) {.name = "seed", .type = CLI_OPT_U64, CLI_AT(T, F), CLI_GIVEN(T, G)}
#define CLI_OPT_DIMS(T, F, MAX, ...) {.name = "dim", .type = CLI_OPT_DIM, CLI_AT(T, F), .hi = (MAX), __VA_ARGS__}
/* --acf SPEC and --spectrum SPEC, one model spec (the rest of the row goes with --acf) */
#define CLI_OPT_MODEL(T, F, ...) CLI_STRING("acf", T, F, __VA_ARGS__), CLI_STRING("spectrum", T, F)
/* The variogram's bins (--width, --cutoff, --bins gstat|floor) in an nl_variogram_options field */
extern const char *const cli_bins_choices[]; /* NL_VARIOGRAM_BINS_* by index (cli/opt.c) */
#define CLI_OPT_BINS(T, F)                                                                                        \
    CLI_POSITIVE("width", T, F.width, .what = "bin width"),                                                       \
        CLI_POSITIVE("cutoff", T, F.cutoff, .what = "cutoff distance"),                                           \
        CLI_CHOICE("bins", T, F.bins, .choices = cli_bins_choices)

#endif
