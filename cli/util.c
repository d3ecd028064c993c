/* Errors, option parsing and writing outputs for the subcommands. */
#include "cli.h"
#include "../core/fftw_plan.h"
#include "../core/mem.h"
#include "../core/nl_error.h"
#include "../synth/subdiv.h"

#include <errno.h>
#include <fcntl.h>
#include <getopt.h>
#include <limits.h>
#include <math.h>
#include <omp.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <unistd.h>

void (*cli_exit_hook)(int code);

void cli_die(int code, const char *fmt, ...)
{
    va_list ap;
    cli_progress_done(); /* stop a progress line before the message */
    fputs("noiselab: ", stderr);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
    cli_out_abandon();
    if (cli_exit_hook)
        cli_exit_hook(code);
    exit(code);
}

void cli_die_status(int st)
{
    cli_die(nl_error_is_input(st) ? 2 : 1, "%s", nl_errmsg());
}

void cli_limits(void)
{
    size_t lim;
    int cap = nl_threads_max();
    cli_check(nl_mem_limit(&lim));
    if (omp_get_max_threads() > cap)
        omp_set_num_threads(cap);
}

void cli_check(int st)
{
    if (st)
        cli_die_status(st);
}

void *cli_malloc(size_t size)
{
    void *p = malloc(size);
    if (!p)
        cli_die(1, "out of memory");
    return p;
}

void cli_bad_option(const char *cmd, int c, char **argv)
{
    const char *arg = argv[optind - 1];
    if (c == ':')
        cli_die(2, "%s: option \"%s\" expects a value", cmd, arg);
    if (optopt && (!arg || strncmp(arg, "--", 2) != 0))
        cli_die(2, "%s: unknown option \"-%c\" (see noiselab %s --help)", cmd, optopt, cmd);
    cli_die(2, "%s: unknown option \"%s\" (see noiselab %s --help)", cmd, arg ? arg : "?", cmd);
}

int cli_getopt(int argc, char **argv, const char *shortopts, const struct option *opts, const char *cmd)
{
    int c;
    opterr = 0;
    c = getopt_long(argc, argv, shortopts, opts, NULL);
    if (c == '?' || c == ':')
        cli_bad_option(cmd, c, argv);
    return c;
}

int cli_parse_size(const char *opt, const char *s, size_t *n, size_t min)
{
    const char *p = s;
    int dim = 0;
    while (1) {
        char *end;
        unsigned long long v;
        if (dim == 3 || *p < '0' || *p > '9')
            break;
        errno = 0;
        v = strtoull(p, &end, 10);
        if (errno || v < min)
            break;
        n[dim++] = (size_t)v;
        if (*end == 0)
            return dim;
        if (*end != 'x')
            break;
        p = end + 1;
    }
    cli_die(2, "%s: expected N, NxM or NxMxK with each N >= %zu, got \"%s\"", opt, min, s);
}

uint64_t cli_parse_u64(const char *opt, const char *s)
{
    char *end;
    unsigned long long v;
    errno = 0;
    v = strtoull(s, &end, 10);
    if (*s < '0' || *s > '9' || *end || errno)
        cli_die(2, "%s: expected an integer from 0 to 2^64-1, got \"%s\"", opt, s);
    return (uint64_t)v;
}

double cli_parse_double(const char *opt, const char *s)
{
    char *end;
    double v = strtod(s, &end);
    if (end == s || *end || !isfinite(v))
        cli_die(2, "%s: expected a finite number, got \"%s\"", opt, s);
    return v;
}

size_t cli_parse_count(const char *opt, const char *s, size_t min)
{
    char *end;
    unsigned long long v;
    errno = 0;
    v = strtoull(s, &end, 10);
    if (*s < '0' || *s > '9' || *end || errno || v < min)
        cli_die(2, "%s: expected an integer >= %zu, got \"%s\"", opt, min, s);
    return (size_t)v;
}

double cli_parse_positive(const char *opt, const char *s, const char *what)
{
    double v = cli_parse_double(opt, s);
    if (!(v > 0))
        cli_die(2, "%s: expected a positive %s, got \"%s\"", opt, what, s);
    return v;
}

void cli_parse_pair(const char *opt, const char *s, double *a, double *b)
{
    char c;
    if (sscanf(s, "%lf,%lf%c", a, b, &c) != 2 || !isfinite(*a) || !isfinite(*b))
        cli_die(2, "%s: expected two numbers A,B, got \"%s\"", opt, s);
}

int cli_parse_dim(const char *s, int max)
{
    if (strlen(s) != 1 || s[0] < '1' || s[0] > '0' + max)
        cli_die(2, "--dim: expected 1 to %d, got \"%s\"", max, s);
    return s[0] - '0';
}

int cli_parse_spacing(const char *opt, const char *s, int dim, double *h)
{
    const char *p = s;
    int k = 0;
    while (k < 3) {
        char *end;
        double v = strtod(p, &end);
        if (end == p || !(v > 0) || !isfinite(v))
            break;
        h[k++] = v;
        if (*end == 0) {
            if (k == 1)
                for (int a = 1; a < dim; a++)
                    h[a] = v;
            else if (k != dim)
                break;
            return k;
        }
        if (*end != ',')
            break;
        p = end + 1;
    }
    cli_die(2, "%s: expected a positive spacing H or one per axis (H0,H1,...), got \"%s\"", opt, s);
}

void cli_no_operands(const char *cmd, int argc, char **argv)
{
    if (optind < argc)
        cli_die(2, "%s: unexpected argument \"%s\"", cmd, argv[optind]);
}

const char *cli_one_operand(const char *cmd, const char *what, int argc, char **argv)
{
    if (optind + 1 != argc)
        cli_die(2, "%s: expected one %s, got %d", cmd, what, argc - optind);
    return argv[optind];
}

int cli_has_ext(const char *path, const char *ext)
{
    size_t lp = strlen(path), le = strlen(ext);
    return lp > le && strcasecmp(path + lp - le, ext) == 0;
}

void cli_subdiv_flags(unsigned flags, char *buf, size_t len) { nl_subdiv_flag_names(flags, buf, len); }

const char *cli_spectrum_spec(const char *s, char *buf, size_t len)
{
    if (strncmp(s, "power", 5) == 0 || strncmp(s, "spectrum:", 9) == 0)
        return s;
    snprintf(buf, len, "spectrum:%s", s);
    return buf;
}

void cli_json_print(json_t *obj)
{
    char *s = json_dumps(obj, JSON_PRESERVE_ORDER | JSON_COMPACT | JSON_REAL_PRECISION(10));
    if (!s)
        cli_die(1, "cannot format the JSON output");
    puts(s);
    free(s);
    json_decref(obj);
}

json_t *cli_json_array(const double *v, size_t n)
{
    json_t *a = json_array();
    for (size_t i = 0; i < n; i++)
        json_array_append_new(a, isfinite(v[i]) ? json_real(v[i]) : json_null());
    return a;
}

const cli_h5_hooks *cli_h5;
int cli_h5_double;

int cli_mpi_launched(void)
{
    return getenv("OMPI_COMM_WORLD_SIZE") || getenv("PMIX_RANK") || getenv("PMI_RANK");
}

int cli_is_h5(const char *path) { return path && cli_has_ext(path, ".h5"); }

/* The HDF5 hooks, or exit 2 naming the file (noiselab hands .h5 runs on). */
static const cli_h5_hooks *h5_or_die(const char *path)
{
    if (!cli_h5)
        cli_die(2, "%s: HDF5 files are read and written by noiselab-mpi", path);
    return cli_h5;
}

int cli_h5_read_meta(const char *path, nl_meta *meta) { return h5_or_die(path)->meta(path, meta); }

nl_field *cli_field_alloc(int dim, const size_t *n, const double *h)
{
    int st;
    nl_field *f = nl_field_alloc(dim, n, h, &st);
    if (!f)
        cli_die_status(st);
    return f;
}

nl_field *cli_read_field(const char *path, nl_meta *meta)
{
    nl_field *f;
    int st = cli_is_h5(path) ? h5_or_die(path)->read(path, &f, meta) : nl_field_read(path, &f, meta);
    cli_check(st);
    return f;
}

int cli_write_table(const char *path, const char *comment, int ncols, const char *const *names, size_t nrows,
                const double *const *cols)
{
    if (path)
        return nl_tsv_write(path, comment, ncols, names, nrows, cols);
    return nl_tsv_fwrite(stdout, comment, ncols, names, nrows, cols);
}
