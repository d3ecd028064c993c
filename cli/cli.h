/* Helpers shared by the subcommands: errors, option values, outputs. */
#ifndef NL_CLI_H
#define NL_CLI_H

#include "../analysis/hist.h"
#include "../analysis/slope.h"
#include "../core/field.h"
#include "../core/format.h"
#include "../core/io.h"

#include <jansson.h>
#include <stddef.h>
#include <stdint.h>

/* Subcommand entry points: argv[0] is the subcommand name. */
int cli_cmd_synth(int argc, char **argv);
int cli_cmd_acf(int argc, char **argv);
int cli_cmd_psd(int argc, char **argv);
int cli_cmd_hist(int argc, char **argv);
int cli_cmd_models(int argc, char **argv);
int cli_cmd_formats(int argc, char **argv);
int cli_cmd_coeffs(int argc, char **argv);
int cli_cmd_check(int argc, char **argv);
int cli_cmd_validate(int argc, char **argv);
int cli_cmd_card(int argc, char **argv);
int cli_cmd_nonlin(int argc, char **argv);
int cli_cmd_lattice(int argc, char **argv);
int cli_cmd_ocean(int argc, char **argv);
int cli_cmd_krige(int argc, char **argv);
int cli_cmd_sample(int argc, char **argv);
int cli_cmd_variogram(int argc, char **argv);
int cli_cmd_fit(int argc, char **argv);
int cli_cmd_cloud(int argc, char **argv);
int cli_cmd_detect(int argc, char **argv);
int cli_cmd_shape(int argc, char **argv);
int cli_cmd_render(int argc, char **argv);
int cli_cmd_bench(int argc, char **argv);

/* Print "noiselab: MSG" on stderr and exit with `code` (2: bad usage or
 * input, 1: failure while running).  Pending outputs are removed. */
void cli_die(int code, const char *fmt, ...) __attribute__((noreturn, format(printf, 2, 3)));

/* When set, cli_die calls it (after printing and removing pending outputs)
 * instead of exit(); it must not return.  The command-line fuzz target sets
 * it to longjmp back to its loop. */
extern void (*cli_exit_hook)(int code);

/* Run the command line argv[0] COMMAND ... (what main does). */
int cli_main(int argc, char **argv);

/* Exit with the library's last message for status `st` (exit 2 or 1). */
void cli_die_status(int st) __attribute__((noreturn));

/* The process-wide bounds, checked before a command runs: exit 2 when
 * NOISELAB_MEMORY_LIMIT does not parse (nl_mem_limit); OpenMP's thread
 * count capped at nl_threads_max() (a few per online processor). */
void cli_limits(void);

/* Exit through cli_die_status unless st is NL_OK (0). */
void cli_check(int st);

/* malloc(size), or exit 1 with "out of memory". */
void *cli_malloc(size_t size);

/* Report an option error from getopt for subcommand `cmd` and exit 2. */
void cli_bad_option(const char *cmd, int c, char **argv);

/* getopt_long with getopt's own messages off; an unknown option or a
 * missing value goes to cli_bad_option (exit 2). */
struct option;
int cli_getopt(int argc, char **argv, const char *shortopts, const struct option *opts, const char *cmd);

/* Option values; each exits 2 with a message naming the option on error. */
int cli_parse_size(const char *opt, const char *s, size_t *n, size_t min);   /* returns dim */
uint64_t cli_parse_u64(const char *opt, const char *s);
double cli_parse_double(const char *opt, const char *s);
size_t cli_parse_count(const char *opt, const char *s, size_t min);
/* A finite number > 0; otherwise "OPT: expected a positive WHAT, got ..." */
double cli_parse_positive(const char *opt, const char *s, const char *what);
/* "A,B" with both finite; otherwise "OPT: expected two numbers A,B, got ..." */
void cli_parse_pair(const char *opt, const char *s, double *a, double *b);
/* --dim D with 1 <= D <= max (dies with exit 2 otherwise) */
int cli_parse_dim(const char *s, int max);
int cli_parse_spacing(const char *opt, const char *s, int dim, double *h);

/* Operands after the options: cli_no_operands exits 2 on any ("CMD:
 * unexpected argument ..."); cli_one_operand returns the one operand or
 * exits 2 ("CMD: expected one WHAT, got N"). */
void cli_no_operands(const char *cmd, int argc, char **argv);
const char *cli_one_operand(const char *cmd, const char *what, int argc, char **argv);

/* Does path end with ext (case-insensitive, ext with its dot)? */
int cli_has_ext(const char *path, const char *ext);

/* Print text (words separated by single spaces; a double space is kept
 * inside a line) filled to width columns, then a newline (cli/text.c). */
void cli_fill(FILE *f, const char *text, int width);
/* cli_fill after `lead` (an option's name column), later lines indented
 * by its length. */
void cli_fill_lead(FILE *f, const char *lead, const char *text, int width);

/* "noiselab WHAT: NN%" on stderr when it is a terminal and the work has run
 * for over a second since the first call; cli_progress_done clears it. */
void cli_progress(const char *what, double frac);
/* Long work of unknown length: "noiselab WHAT: PHASE (N s)", refreshed
 * from a helper thread, on a terminal only and after a second; a new call
 * replaces the phase.  cli_progress_done ends it. */
void cli_phase(const char *what, const char *phase);
void cli_progress_done(void);
/* Clear a progress line from a signal handler (async-signal-safe). */
void cli_progress_abandon(void);

/* Outputs appear whole or not at all, and all of a run's or none
 * (cli/outputs.c).  cli_out_begin checks that a temporary file beside `path`
 * can be created (exit 2 naming the option and the path if not, if `path`
 * is a folder, or if another output of this run names the same file) and
 * returns its name; cli_out_commit marks it ready.  The ready outputs are
 * renamed together when the command returns 0 (cli_out_finish, from
 * cli_main); a failure (cli_die, a non-zero return, exit) or a fatal signal
 * (SIGINT, SIGTERM, SIGHUP, SIGPIPE, SIGQUIT, SIGXCPU, SIGXFSZ, SIGALRM, SIGUSR1,
 * SIGUSR2, and SIGABRT, SIGSEGV, SIGBUS, SIGFPE, SIGILL unless a sanitizer
 * handles them; signals ignored at start stay ignored: the handler removes, then the
 * signal kills with its default action) removes every temporary of the run.
 * An output not asked for (path NULL) has no temporary (NULL) and nothing
 * to commit.  Any number of outputs. */
const char *cli_out_begin(const char *path);
void cli_out_commit(const char *path);

/* Another process's temporary `tmp` (from its cli_out_begin) that this
 * process writes too (a collective HDF5 create may make the file anew after
 * its owner removed it): removed by this process on a failure or a fatal
 * signal, forgotten by cli_out_finish(1); never renamed here. */
void cli_out_share(const char *tmp);

/* From now on, each temporary made by cli_out_begin is also watched by a
 * process of its own that removes it once this process has ended without
 * renaming it, however it ended: an MPI library that ends its process with
 * _exit when its launcher dies runs no handler. */
void cli_out_guard(void);

/* A folder of outputs named by option `opt` (e.g. a report), whose files
 * are written through cli_out_begin like any output (temporaries renamed
 * together at the end).  A missing folder is created, and removed on
 * failure or a signal once this run's temporaries in it are gone, if
 * nothing else is in it; an existing one is never removed, nor anything
 * in it but this run's temporaries.  Exit 2 naming opt and the folder when
 * it cannot be made, is a file, is the root folder, or exists and is not
 * empty unless `force`. */
void cli_out_dir(const char *opt, const char *dir, int force);

/* mkdtemp(templ) for scratch files, removed with its contents at the end of
 * the run whatever happens; NULL (errno set) when it cannot be made. */
char *cli_out_tmpdir(char *templ);

/* The run's bookkeeping (cli_main): cli_out_start forgets the previous run,
 * remembers argv (to name the option of a path in messages) and installs
 * the signal handlers once; cli_out_finish(1) commits every ready output
 * (all or none: exit 1 when a rename fails, after removing the others),
 * cli_out_finish(0) and cli_out_abandon remove every output of the run. */
void cli_out_start(int argc, char **argv);
void cli_out_finish(int ok);
void cli_out_abandon(void);

/* Subdivision flags (synth/subdiv.h) as "name,name,..." ("" for none). */
void cli_subdiv_flags(unsigned flags, char *buf, size_t len);

/* The spec for --spectrum: a bare expression means spectrum:EXPR (in buf). */
const char *cli_spectrum_spec(const char *s, char *buf, size_t len);

/* Print a JSON object on stdout (compact keys in insertion order). */
void cli_json_print(json_t *obj);

/* A JSON array of n doubles (NaN becomes null). */
json_t *cli_json_array(const double *v, size_t n);

/* A TSV table to `path`, or to stdout when path is NULL. */
int cli_write_table(const char *path, const char *comment, int ncols, const char *const *names, size_t nrows,
                const double *const *cols);

/* This process's part of a field read collectively (mpi/dist.h's slabs):
 * the whole field's dim, n and h, and rows s0 .. s0 + ns - 1 of its slowest
 * axis (data NULL when ns = 0). */
typedef struct {
    int dim;
    size_t n[3];
    double h[3];
    size_t s0, ns;
    double *data;
    double origin[3]; /* this slab's first sample, x first, in length units: the field's
                         origin (nl_meta_origin) plus s0 h on the slowest axis */
} cli_slab;

/* The HDF5 and MPI parts of the command line (cli/h5_*.c, mpi/), present in
 * noiselab-mpi only: its main sets cli_h5 before cli_main; NULL in
 * noiselab, whose main hands every run that names an .h5 file or runs under
 * an MPI launcher to noiselab-mpi (cli/main.c). */
struct cli_synth_job;
struct cli_synth_result;
typedef struct {
    int launched;           /* MPI initialised (started by mpirun, srun, ...) */
    int size, rank;         /* processes and this one's rank (1, 0 without a launcher) */
    /* one process: read or write a whole field as HDF5 (mpi/h5.h) */
    int (*read)(const char *path, nl_field **out, nl_meta *meta);
    int (*write)(const char *path, const nl_field *f, const nl_meta *meta, int dbl);
    int (*meta)(const char *path, nl_meta *meta);   /* the provenance alone */
    /* every process: the worst status and its message (mpi/dist.h) */
    int (*agree)(int status);
    /* synth -o OUT.h5 under a launcher: the distributed run (cli/h5_synth.c) */
    int (*synth)(struct cli_synth_job *job, const char *out,
                 void (*run)(const struct cli_synth_job *, nl_field *, struct cli_synth_result *), int json);
    /* synth -o OUT.h5 on one process: exit 2 when the field does not fit
     * NOISELAB_MEMORY_LIMIT, naming the process count that would hold it */
    void (*check_memory)(const struct cli_synth_job *job,
                         void (*run)(const struct cli_synth_job *, nl_field *, struct cli_synth_result *));
    /* every process, collectively, agreeing on the status (launched runs):
     * the slab of an .h5 field (free with slab_free), and the distributed
     * estimates of mpi/analysis.h on it, on every process */
    int (*read_slab)(const char *path, cli_slab *s);
    void (*slab_free)(cli_slab *s);
    int (*acf)(const cli_slab *s, double mean, int unbiased, int radial, int axis, size_t nl, double *lag,
               double *val);
    int (*psd)(const cli_slab *s, double mean, double *freq, double *val, size_t *nf, size_t nsec, double flo,
               double fhi, double *sector, double *aniso, const double *band, nl_slope *sl);
    int (*hist)(const cli_slab *s, size_t bins, nl_moments *m, double *edges, double *counts);
} cli_h5_hooks;
extern const cli_h5_hooks *cli_h5;

/* Started by an MPI launcher (Open MPI's mpirun, PMIx as under srun, PMI)? */
int cli_mpi_launched(void);
/* Does path name an HDF5 file (by its .h5 extension)? */
int cli_is_h5(const char *path);
/* The provenance of an .h5 file (through cli_h5, exit 2 without it). */
int cli_h5_read_meta(const char *path, nl_meta *meta);
/* HDF5 outputs in float64 (synth --precision double); float32 otherwise. */
extern int cli_h5_double;
/* --precision single given: float32 outputs where the format has them (.npy). */
extern int cli_field_single;

/* Fields written through the format registry (cli/field_out.c).  --format
 * NAME and --range LO:HI (CLI_OPT_FORMAT, or synth's own parse) set
 * cli_field_format (NULL: by the output's extension) and cli_field_range
 * (both 0: the field's min..max, for integer formats). */
extern const char *cli_field_format;
extern double cli_field_range[2];
void cli_opt_format(void *obj, const char *label, const char *arg);
void cli_opt_range(void *obj, const char *label, const char *arg);
/* --crs CRS (cli_field_crs: NULL, none given): a CRS GDAL knows, recorded in
 * the output's nl_meta.crs; exit 2 for another.  --cog: format cog. */
extern const char *cli_field_crs;
void cli_opt_crs(void *obj, const char *label, const char *arg);
void cli_opt_cog(void *obj, const char *label, const char *arg);
/* The format path is written in (--format, else its extension); exit 2
 * naming label (e.g. "-o") and listing the registry when there is none,
 * when it does not hold dim-D fields (dim 0: not checked yet), when
 * --precision double or --range does not fit it. */
const nl_format *cli_field_out_check(const char *label, const char *path, int dim);
/* Does path's format (as cli_field_out_check finds it) store float32? */
int cli_field_is_float32(const char *path);
/* Write f to tmp (the temporary of path, from cli_out_begin) in path's
 * format with meta; an .h5 through cli_h5, with the XDMF sidecar PATH.xmf
 * (minus .h5) beside it, committed with the run's outputs; exits on error. */
void cli_write_field(const char *path, const char *tmp, const nl_field *f, const nl_meta *meta);
/* The XDMF sidecar of the .h5 output path (PATH minus .h5, plus .xmf): a
 * dim-D grid of n samples at spacing h, first sample where meta says
 * (nl_meta_origin), float64 when cli_h5_double; begun and committed as an output. */
void cli_write_xdmf(const char *path, int dim, const size_t *n, const double *h, const nl_meta *meta);

/* Record in m the grid of a map made on an extent lo..hi (x first) of
 * n cells per axis: spacing (hi - lo) / n, sample 0 at the first cell
 * centre (nl_meta_set_origin); exits on error. */
void cli_meta_extent(nl_meta *m, int dim, const double *lo, const double *hi, const size_t *n);

/* nl_field_alloc, exiting on error. */
nl_field *cli_field_alloc(int dim, const size_t *n, const double *h);

/* Read a field (EXR, PNG or TSV), exiting on error. */
nl_field *cli_read_field(const char *path, nl_meta *meta);

#endif
