/* The synthesis methods behind `noiselab synth`: each fills a field from a
 * parsed job and describes what it did. */
#ifndef NL_CLI_SYNTH_H
#define NL_CLI_SYNTH_H

#include "cli.h"
#include "../analysis/condsim.h"
#include "../analysis/ensemble.h"
#include "../core/io_table.h"
#include "../core/model.h"
#include "../synth/circulant.h"
#include "../synth/method.h"

typedef struct cli_synth_job {
    const char *method;    /* the method's name (its descriptor: type) */
    const nl_method_type *type; /* the method (synth/method.h) */
    nl_method_options opts;/* its options (--levels, ..., or those --from read) */
    nl_model *m;           /* the model */
    int dim;               /* 1..3 */
    size_t n[3];           /* output size */
    double h[3];           /* output spacing */
    uint64_t seed;         /* --seed */
    int clamp;             /* --clamp */
    long origin[2];        /* --origin, finest-grid indices */
    int nonperiodic;       /* a window made by an option (subdiv --nonperiodic), for the provenance */
    int wrap;              /* a window unmade by an option (sparse --wrap), for the provenance */
    int from;              /* the options come from a field's provenance (--from) */
    int slab;              /* distributed: f holds rows s0 .. s0 + ns - 1 of the slowest axis */
    size_t s0, ns;         /* (cli/h5_synth.c; ns may be 0: plan, describe, do not execute) */
} cli_synth_job;

typedef struct cli_synth_result {
    char method[256];      /* method and its parameters, for noiselab.method */
    char flags[256];       /* comma-separated flags, for noiselab.flags */
    double sd;             /* standard deviation for the preview range */
    double offset;         /* centre of the preview range */
    json_t *report;        /* method-specific JSON report (owned) */
} cli_synth_result;

/* A method's run: plan, fill f (or, with job->slab, its slab), describe. */
typedef void (*cli_synth_run_fn)(const cli_synth_job *, nl_field *, cli_synth_result *);

/* What synth --json prints of a field (a new object; cmd_synth.c). */
json_t *cli_synth_json(const cli_synth_job *job, const nl_meta *meta, const cli_synth_result *res);

/* The provenance of a synthesised field (cmd_synth.c). */
void cli_synth_fill_meta(const cli_synth_job *job, const nl_field *f, const cli_synth_result *res, nl_meta *meta);

/* synth --help (cli/synth_help.c). */
void cli_synth_print_help(void);

/* An integer option in min..max, checked before it is narrowed to int
 * (exit 2 naming opt otherwise). */
int cli_synth_parse_int(const char *opt, const char *s, int min, int max);
/* --neighborhood N|auto: N >= 1, or 0 for auto (exit 2 otherwise). */
int cli_synth_parse_neighborhood(const char *s);
/* --tol [variance:|improvement:]E: E > 0 finite, the rule in *rule
 * (NL_SUBDIV_STOP_*; no prefix: improvement).  Exit 2 otherwise. */
double cli_synth_parse_tol(const char *opt, const char *s, int *rule);

/* --condition DATA.tsv --extent ... [--realizations K] [--mean M]
 * [--interpolation nearest|bilinear: deprecated, ignored] [--at PTS.tsv
 * [--grid-out GRID]] (cli/synth_condition.c).  With --at, -o is the table
 * PTS.tsv with the realizations at its points as columns sim1..simK (as
 * gstat's krige(..., newdata = points, nsim = K)); the grids are written
 * only to --grid-out, named as -o is without --at. */
typedef struct {
    const char *data, *extent;   /* --condition, --extent, or NULL */
    size_t K;                    /* --realizations (default 1) */
    int given_K, given_interp;   /* given explicitly */
    int simple;                  /* --mean given: simple kriging */
    double mean;                 /* --mean */
    size_t nmax;                 /* --nmax: local kriging from the nmax nearest data; 0: all */
    int interp;                  /* unused: --interpolation is deprecated (U is drawn given the grid) */
    double lo[3], hi[3];         /* --extent */
    const char *emean, *evar;    /* --ensemble-mean, --ensemble-variance, or NULL */
    const char *etmp[2];         /* their temporaries */
    nl_welford *acc;             /* running mean and variance of the realizations */
    nl_condsim_plan *plan;       /* made by cli_synth_cond_prepare */
    nl_condsim_info info;        /* its figures */
    const char *at, *grid_out;   /* --at, --grid-out, or NULL */
    nl_table *table;             /* --at's table, as read */
    size_t np;                   /* its rows */
    double *at_pts;              /* their coordinates (np * dim, row-major) */
    double *zat;                 /* realization k at point j: zat[k * np + j] */
    const char *out, *ttmp;      /* with --at: -o and its temporary */
} cli_synth_cond;

/* Take option `opt` (the getopt code of one of the options above). */
void cli_synth_cond_option(cli_synth_cond *c, int opt, const char *arg);
/* After the size and model are known: check the options, set job->h from
 * the extent, read the data and make the plan (exit 2 on bad input). */
void cli_synth_cond_prepare(cli_synth_cond *c, cli_synth_job *job, int from, int spacing);
/* Where the grids go: -o (out), or with --at --grid-out (NULL: nowhere). */
const char *cli_synth_cond_grid(const cli_synth_cond *c, const char *out);
/* With --at: -o (out) must be a .tsv, --grid-out an .exr (or a .tsv in
 * 1D); exit 2 otherwise.  Returns 1 when it checked (--at given), else 0:
 * the caller checks -o as the grid. */
int cli_synth_cond_check_out(const cli_synth_cond *c, const char *out, int dim);
/* Begin the ensemble outputs and, with --at, the table -o (out), after the
 * realizations' own. */
void cli_synth_cond_begin(cli_synth_cond *c, const char *out);
/* Add realization k (from 0) to the ensemble statistics. */
void cli_synth_cond_accumulate(cli_synth_cond *c, const nl_field *f, size_t k);
/* Write the table of --at and the ensemble mean and variance (meta: the
 * last realization's record). */
void cli_synth_cond_finish(cli_synth_cond *c, const nl_meta *meta);
/* The output name of realization k (path itself unless K > 1; buf holds it). */
const char *cli_synth_cond_name(const cli_synth_cond *c, const char *path, size_t k, char *buf, size_t len);
/* Condition the unconditional field f (realization k) and say so in r->method. */
void cli_synth_cond_apply(const cli_synth_cond *c, const cli_synth_job *job, nl_field *f, cli_synth_result *r,
                          size_t k);
/* Write f (a 1D TSV takes the cell centres as its x column when conditioned). */
void cli_synth_cond_write(const cli_synth_cond *c, const char *path, const char *tmp, const nl_field *f,
                          const nl_meta *meta);
/* The "condition" object of the JSON report; a note on stderr about data between samples. */
void cli_synth_cond_report(const cli_synth_cond *c, json_t *o);
void cli_synth_cond_note(const cli_synth_cond *c);
void cli_synth_cond_free(cli_synth_cond *c);

/* Any method through its descriptor (cli/synth_methods.c): plan, fill f
 * (or, with job->slab, its slab), describe; the method's report when it
 * has one.  Exits through cli_die on bad input; returns only on success. */
void cli_synth_run(const cli_synth_job *job, nl_field *f, cli_synth_result *r);
/* A method's report (synth/method.h) as the result's flags, preview range
 * and JSON report (shared with the distributed runs, cli/h5_synth.c). */
void cli_synth_take_report(const nl_method_report *mr, cli_synth_result *r);

#endif
