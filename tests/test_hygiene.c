/* Process hygiene of the library: inputs are read once (a FIFO gives the
 * same field as the file), reads are bounded by the memory limit, a memory
 * limit that does not parse is refused, and the thread count is capped. */
#include "../core/fftw_plan.h"
#include "../core/io.h"
#include "../core/mem.h"
#include "../core/nl_error.h"
#include "util.h"

#include <criterion/criterion.h>
#include <dirent.h>
#include <fcntl.h>
#include <math.h>
#include <omp.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

/* A writer thread copying a file into a FIFO, as `cat FILE >FIFO` would. */
typedef struct {
    char from[512], to[512];
} copy_job;

static void *copy_into(void *arg)
{
    const copy_job *j = arg;
    char buf[4096];
    size_t got;
    FILE *in = fopen(j->from, "rb"), *out = fopen(j->to, "wb");
    while (in && out && (got = fread(buf, 1, sizeof buf, in)) > 0)
        fwrite(buf, 1, got, out);
    if (in)
        fclose(in);
    if (out)
        fclose(out);
    return NULL;
}

/* Read `name` (in the scratch folder) through a FIFO and from the file:
 * the two fields must be the same, sample for sample.  Both read the same
 * bytes, so they must agree exactly (no tolerance). */
static void same_through_fifo(const char *name)
{
    copy_job j;
    pthread_t t;
    nl_field *a = NULL, *b = NULL;
    snprintf(j.from, sizeof j.from, "%s/%s", scratch_dir(), name);
    snprintf(j.to, sizeof j.to, "%s/fifo", scratch_dir());
    unlink(j.to);
    cr_assert_eq(mkfifo(j.to, 0600), 0);
    cr_assert_eq(pthread_create(&t, NULL, copy_into, &j), 0);
    int st = nl_field_read(j.to, &b, NULL);
    pthread_join(t, NULL);
    unlink(j.to);
    cr_assert_eq(st, NL_OK, "%s through a FIFO: %s", name, nl_errmsg());
    cr_assert_eq(nl_field_read(j.from, &a, NULL), NL_OK, "%s", nl_errmsg());
    cr_assert_eq(a->dim, b->dim);
    cr_assert_eq(a->count, b->count);
    cr_assert_eq(memcmp(a->data, b->data, a->count * sizeof *a->data), 0, "%s: the FIFO gave other samples", name);
    nl_field_free(a), nl_field_free(b);
}

Test(hygiene, field_files_read_once_from_a_fifo)
{
    size_t n[2] = {48, 32}, n1 = 100;
    nl_field *f = nl_field_alloc(2, n, NULL, NULL), *g = nl_field_alloc(1, &n1, NULL, NULL);
    char path[512];
    static const char *const names[] = {"t", "value"};
    double t[100];
    for (size_t i = 0; i < f->count; i++)
        f->data[i] = sin(0.1 * (double)i) + 0.25 * (double)(i % 7);
    for (size_t i = 0; i < n1; i++)
        g->data[i] = cos(0.3 * (double)i), t[i] = (double)i;
    snprintf(path, sizeof path, "%s/h.exr", scratch_dir());
    cr_assert_eq(nl_exr_write(path, f, NULL), NL_OK);
    snprintf(path, sizeof path, "%s/h.png", scratch_dir());
    cr_assert_eq(nl_png_write_field(path, f, -1, 2), NL_OK);
    snprintf(path, sizeof path, "%s/h.tsv", scratch_dir());
    cr_assert_eq(nl_tsv_write(path, NULL, 2, names, n1, (const double *const[]){t, g->data}), NL_OK);
    same_through_fifo("h.exr");
    same_through_fifo("h.png");
    same_through_fifo("h.tsv");
    nl_field_free(f), nl_field_free(g);
}

/* Reading an endless input is bounded: text is parsed as it is read, so
 * endless rows stop at the memory limit with NL_ETOOBIG (the samples, not
 * the text, count), and endless bytes that are not text (/dev/zero) at
 * the first line with NL_EINPUT. */
Test(hygiene, endless_input_is_bounded)
{
    nl_field *f = NULL;
    char path[64];
    int fd[2], st;
    pid_t child;
    setenv("NOISELAB_MEMORY_LIMIT", "1000000", 1);
    st = nl_field_read("/dev/zero", &f, NULL);
    cr_assert_eq(st, NL_EINPUT, "got %d: %s", st, nl_errmsg());
    cr_assert_null(f);
    cr_assert(strstr(nl_errmsg(), "/dev/zero") != NULL, "%s", nl_errmsg());
    cr_assert_eq(pipe(fd), 0);
    if ((child = fork()) == 0) { /* endless rows, until the reader closes */
        static const char rows[] = "1.5\n2.25\n-3\n0.5\n";
        close(fd[0]);
        signal(SIGPIPE, SIG_DFL);
        if (write(fd[1], "value\n", 6) == 6)
            while (write(fd[1], rows, sizeof rows - 1) > 0)
                ;
        _exit(0);
    }
    close(fd[1]);
    snprintf(path, sizeof path, "/dev/fd/%d", fd[0]);
    st = nl_field_read(path, &f, NULL);
    close(fd[0]);
    waitpid(child, NULL, 0);
    unsetenv("NOISELAB_MEMORY_LIMIT");
    cr_assert_eq(st, NL_ETOOBIG, "got %d: %s", st, nl_errmsg());
    cr_assert_null(f);
    cr_assert(strstr(nl_errmsg(), "samples do not fit") != NULL, "%s", nl_errmsg());
}

Test(hygiene, folder_as_input_is_refused)
{
    nl_field *f = NULL;
    cr_assert_eq(nl_field_read(scratch_dir(), &f, NULL), NL_EINPUT);
    cr_assert(strstr(nl_errmsg(), "folder") != NULL, "%s", nl_errmsg());
}

Test(hygiene, memory_limit_that_does_not_parse_is_refused)
{
    static const char *const bad[] = {"", "abc", "-5", "+5", " 100", "100 ", "1e9", "1.5", "12MB", "0",
                                      "99999999999999999999999"};
    size_t lim = 1, n[1] = {16};
    unsetenv("NOISELAB_MEMORY_LIMIT");
    cr_assert_eq(nl_mem_limit(&lim), NL_OK);
    cr_assert_eq(lim, 0, "unset means no limit of its own");
    setenv("NOISELAB_MEMORY_LIMIT", "4000000000", 1);
    cr_assert_eq(nl_mem_limit(&lim), NL_OK);
    cr_assert_eq(lim, (size_t)4000000000u);
    for (size_t i = 0; i < sizeof bad / sizeof *bad; i++) {
        char quoted[64];
        setenv("NOISELAB_MEMORY_LIMIT", bad[i], 1);
        cr_expect_eq(nl_mem_limit(&lim), NL_EINVAL, "\"%s\" accepted", bad[i]);
        snprintf(quoted, sizeof quoted, "\"%s\"", bad[i]);
        cr_expect(strstr(nl_errmsg(), "NOISELAB_MEMORY_LIMIT") && strstr(nl_errmsg(), quoted), "%s", nl_errmsg());
        /* every size check refuses too, so no allocation goes ahead unbounded */
        cr_expect_eq(nl_size_check(1, n, sizeof(double), 1, NULL), NL_EINVAL, "\"%s\"", bad[i]);
    }
    unsetenv("NOISELAB_MEMORY_LIMIT");
}

/* An absurd OpenMP thread count is capped at NL_THREADS_PER_CPU per online
 * processor; a sane one passes unchanged. */
Test(hygiene, thread_count_is_capped)
{
    long cpus = sysconf(_SC_NPROCESSORS_ONLN);
    int keep = omp_get_max_threads();
    omp_set_num_threads(100000);
    cr_assert_leq(nl_threads_max(), (int)cpus * NL_THREADS_PER_CPU);
    cr_assert_geq(nl_threads_max(), 1);
    omp_set_num_threads(1);
    cr_assert_eq(nl_threads_max(), 1);
    omp_set_num_threads(keep);
}

/* Files of the scratch folder whose name starts with `prefix`. */
static int files_named(const char *prefix)
{
    DIR *d = opendir(scratch_dir());
    struct dirent *e;
    int n = 0;
    while (d && (e = readdir(d)))
        n += strncmp(e->d_name, prefix, strlen(prefix)) == 0;
    if (d)
        closedir(d);
    return n;
}

/* SIGTERM while a command has begun its two outputs (it is blocked opening
 * a FIFO for its seed image): both temporaries are removed and the process
 * dies of SIGTERM (the status a shell shows as 143). */
Test(hygiene, signal_removes_the_outputs_begun)
{
    const char *bin = getenv("NOISELAB");
    char fifo[512], tmp[600], exe[1024], here[256];
    pid_t pid;
    int status, i;
    snprintf(exe, sizeof exe, "%s", bin ? bin : "../bin/noiselab");
    if (exe[0] != '/' && getcwd(here, sizeof here)) /* relative to here, before the child changes folder */
        snprintf(exe, sizeof exe, "%s/%s", here, bin ? bin : "../bin/noiselab");
    snprintf(fifo, sizeof fifo, "%s/seed", scratch_dir());
    unlink(fifo);
    cr_assert_eq(mkfifo(fifo, 0600), 0);
    pid = fork();
    cr_assert_geq(pid, 0);
    if (pid == 0) {
        if (chdir(scratch_dir()) == 0)
            execl(exe, "noiselab", "synth", "subdiv", "--acf", "markov:scale=8", "--size", "64x64", "--seed-image",
                  "seed", "-o", "sig.exr", "--preview", "sig.png", (char *)NULL);
        _exit(127);
    }
    snprintf(tmp, sizeof tmp, "%s/sig.png.tmp.%ld", scratch_dir(), (long)pid);
    for (i = 0; i < 500 && !file_exists(tmp); i++)
        usleep(10000);
    cr_expect(file_exists(tmp), "the command never began its outputs");
    cr_expect_eq(files_named("sig."), 2, "expected the two temporaries");
    kill(pid, SIGTERM);
    cr_assert_eq(waitpid(pid, &status, 0), pid);
    unlink(fifo);
    cr_expect(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM, "status %#x", status);
    cr_expect_eq(files_named("sig."), 0, "a temporary was left");
}

/* More outputs than the old table of 8: all 18 files of 9 frames appear. */
Test(hygiene, nine_frames_commit_all_their_files)
{
    char err[1024];
    int rc = run_noiselab("ocean --grid 16 --wind 10,30 --frames 9 --dt 0.1 -o fr.exr --image fr.png --size 16", NULL, 0,
                          err, sizeof err);
    cr_assert_eq(rc, 0, "%s", err);
    cr_expect_eq(files_named("fr-"), 18);
}
