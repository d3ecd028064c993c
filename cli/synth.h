/* The synthesis methods behind `noiselab synth`: each fills a field from a
 * parsed job and describes what it did. */
#ifndef NL_CLI_SYNTH_H
#define NL_CLI_SYNTH_H

#include "cli.h"
#include "../core/model.h"

typedef struct {
    const char *method;    /* fft, subdiv, midpoint */
    nl_model *m;           /* the model */
    int dim;               /* 1..3 */
    size_t n[3];           /* output size */
    double h[3];           /* output spacing */
    uint64_t seed;         /* --seed */
    int clamp;             /* --clamp */
    int levels;            /* --levels, 0 = default */
    int N;                 /* --neighborhood: -1 default, 0 auto */
    double tol;            /* --tol for auto */
    int nonperiodic;       /* --nonperiodic */
    long origin[2];        /* --origin, finest-grid indices */
    const char *seed_image;/* --seed-image */
    int random_nb;         /* --random-neighborhoods K, 0 = the standard block */
    int displacements;     /* --displacements: NL_SUBDIV_DISP_INDEPENDENT or _ERROR (correlated) */
    int taps;              /* --taps M, 0 = the default */
    double H;              /* midpoint: Hurst exponent, NAN if unset */
    double vscale;         /* midpoint: --variance-scale factor per level */
    double density;        /* faulting, sparse: --density */
    const char *kernel;    /* sparse: --kernel EXPR */
    const char *exemplar;  /* sparse: --exemplar FILE */
    const char *angle;     /* sparse: --angle EXPR */
    int radius;            /* sparse: --radius, 0 = automatic */
    int cell;              /* sparse: --cell, 0 = the radius */
    int wrap;              /* sparse: --wrap */
    int octaves;           /* lattice: --octaves, 0 = down to cell 2 */
    double cell0;          /* lattice: --cell (largest cell), 0 = size / 4 */
    int from;              /* the options come from a field's provenance (--from) */
} cli_synth_job;

typedef struct {
    char method[256];      /* method and its parameters, for noiselab.method */
    char flags[256];       /* comma-separated flags, for noiselab.flags */
    double sd;             /* standard deviation for the preview range */
    double offset;         /* centre of the preview range */
    json_t *report;        /* method-specific JSON report (owned) */
} cli_synth_result;

/* An integer option in min..max, checked before it is narrowed to int
 * (exit 2 naming opt otherwise). */
int cli_synth_parse_int(const char *opt, const char *s, int min, int max);
/* --neighborhood N|auto: N >= 1, or 0 for auto (exit 2 otherwise). */
int cli_synth_parse_neighborhood(const char *s);

/* Each exits through cli_die on bad input; returns only on success. */
void cli_synth_fft_run(const cli_synth_job *job, nl_field *f, cli_synth_result *r);
void cli_synth_subdiv_run(const cli_synth_job *job, nl_field *f, cli_synth_result *r);
void cli_synth_midpoint_run(const cli_synth_job *job, nl_field *f, cli_synth_result *r);
void cli_synth_circulant_run(const cli_synth_job *job, nl_field *f, cli_synth_result *r);
void cli_synth_cholesky_run(const cli_synth_job *job, nl_field *f, cli_synth_result *r);
void cli_synth_faulting_run(const cli_synth_job *job, nl_field *f, cli_synth_result *r);
void cli_synth_sparse_run(const cli_synth_job *job, nl_field *f, cli_synth_result *r);
void cli_synth_lattice_run(const cli_synth_job *job, nl_field *f, cli_synth_result *r);

#endif
