/* The inputs of the analysis commands (acf, psd, hist): fields read from
 * files, or realizations made on the spot by FFT synthesis (--realizations
 * K --acf SPEC --size N [--seed S]: the fields `noiselab synth fft --acf SPEC
 * --size N --seed S`, S + 1, ... computes, before a file rounds them to its
 * 10 digits (TSV) or float32 (EXR)), so that an ensemble needs no shell
 * loop. */
#ifndef NL_CLI_INPUTS_H
#define NL_CLI_INPUTS_H

#include "cli.h"
#include "opt.h"
#include "../analysis/ensemble.h"
#include "../core/model.h"
#include "../synth/fft.h"

/* Where a command's fields come from. */
typedef struct {
    char **files;              /* operands */
    size_t count;              /* fields: operands, or --realizations */
    size_t K;                  /* --realizations (0: files) */
    const char *spec;          /* --acf SPEC of the realizations */
    int dim;                   /* from --size (0: not given) */
    size_t n[3];               /* --size */
    uint64_t seed;             /* first seed (--seed, default 1) */
    int seed_set;              /* --seed given */
    nl_model *m;               /* the model, parsed once */
    nl_synth_fft_plan *plan;   /* planned on first use */
    char name[96];             /* the name of the last field asked for */
    nl_meta meta;              /* the provenance of the last file read (zero: none) */
} cli_inputs;

/* The rows of --realizations K, --acf SPEC, --size N and --seed S, for a
 * command's table (cli/opt.h) as a group over its cli_inputs field:
 * {.type = CLI_OPT_GROUP, .sub = cli_inputs_rows, CLI_AT(type, field)}. */
extern const cli_opt cli_inputs_rows[];

/* After the options: the operands are the files, unless --realizations was
 * given (then there must be none, and --acf and --size are required).
 * Exits 2 naming what is missing or extra. */
void cli_inputs_operands(cli_inputs *in, const char *cmd, int argc, char **argv);

/* Field k (0 .. count - 1), released by nl_field_free.  When `like` is not
 * NULL the field must have its dim, size and spacing (an ensemble), or the
 * command exits 2. */
nl_field *cli_inputs_read(cli_inputs *in, size_t k, const nl_field *like);

/* The model whose spectrum the last field read holds: the spec of
 * --realizations, or the model its file records, unless the file records a
 * memoryless shaping (noiselab shape: its spectrum reaches beyond the
 * model's band); "" when none (a field without provenance, a picture). */
const char *cli_inputs_model(const cli_inputs *in);

/* The same for a file's provenance (the model it records, or "" when it
 * records none or a shaping); a string inside meta. */
const char *cli_meta_model(const nl_meta *meta);

/* The name of field k for messages: its file, or "realization (seed S)". */
const char *cli_inputs_name(cli_inputs *in, size_t k);

void cli_inputs_free(cli_inputs *in);

/* The fields of `in` as an ensemble's source (analysis/ensemble.h): field 0
 * is `first`, read already; field k > 0 is read when the driver asks for
 * it, checked against `first` (cli_inputs_read), and freed when handed
 * back.  e lives as long as the source. */
typedef struct {
    cli_inputs *in;         /* where the fields come from */
    const nl_field *first;  /* field 0, the caller's */
} cli_ensemble;
nl_ensemble_source cli_inputs_source(cli_ensemble *e);

#endif
