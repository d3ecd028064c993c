/* The outputs of one run, all or none.
 *
 * Every output is written to a temporary beside it (cli_out_begin) and only
 * marked ready by cli_out_commit; the renames happen together when the
 * command returns success (cli_out_finish from cli_main).  A failure
 * (cli_die, a non-zero return, exit) and a fatal signal remove every
 * temporary and then every folder this run created, when it is empty (a
 * file another process put there stays, and so does the folder).  The table of outputs grows
 * in chunks that never move, and an entry is filled before its state is
 * published, so the signal handler can walk it at any moment using only
 * unlink, rmdir and directory reads (async-signal-safe). */
#include "cli.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <time.h>
#include <unistd.h>

/* An entry: a file's temporary (PENDING until committed, READY after), a
 * folder this run made (DIR_NEW: removed on failure once the temporaries in
 * it are gone, if nothing else is there), a scratch folder (TMP_DIR: emptied
 * and removed at the end whatever happens), another process's temporary
 * that this one also writes (SHARED: removed on failure, forgotten on
 * success); DONE once renamed. */
enum { FREE, PENDING, READY, DONE, DIR_NEW, TMP_DIR, SHARED };
enum { CHUNK = 16 };

typedef struct {
    _Atomic int state;
    char tmp[PATH_MAX];   /* the temporary, or the folder */
    char final[PATH_MAX]; /* the output's name as given */
    dev_t dev;            /* the folder holding the output, to find one output named twice */
    ino_t ino;
} entry;

typedef struct chunk {
    entry e[CHUNK];
    struct chunk *_Atomic next;
} chunk;

static chunk first;
static int guarded;                   /* cli_out_guard: a watcher for each temporary */
static size_t used;                   /* entries handed out in this run (main thread only) */
static _Atomic int committing, caught; /* renaming now; the signal that came meanwhile */
static int cmd_argc;
static char **cmd_argv;

static entry *at(size_t i)
{
    chunk *c = &first;
    for (size_t k = i / CHUNK; k; k--) {
        chunk *n = atomic_load(&c->next);
        if (!n) {
            if (!(n = calloc(1, sizeof *n)))
                cli_die(1, "out of memory for the list of outputs");
            atomic_store(&c->next, n);
        }
        c = n;
    }
    return &c->e[i % CHUNK];
}

/* Empty and remove scratch folder e (async-signal-safe: getdents64,
 * unlinkat, rmdir). */
static void purge_dir(const entry *e)
{
    char buf[4096];
    long got;
    int fd = open(e->tmp, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0)
        return;
    while ((got = syscall(SYS_getdents64, fd, buf, sizeof buf)) > 0)
        for (long off = 0; off < got;) {
            struct {
                unsigned long long ino;
                long long off;
                unsigned short reclen;
                unsigned char type;
                char name[];
            } *d = (void *)(buf + off);
            off += d->reclen;
            if (strcmp(d->name, ".") == 0 || strcmp(d->name, "..") == 0)
                continue;
            unlinkat(fd, d->name, 0);
        }
    close(fd);
    rmdir(e->tmp);
}

/* Undo every output of this run (async-signal-safe): the files' temporaries
 * and scratch folders first, then the folders made for outputs, which only
 * go when nothing else is left in them (rmdir). */
static void remove_all(void)
{
    for (int pass = 0; pass < 2; pass++)
        for (chunk *c = &first; c; c = atomic_load(&c->next))
            for (int i = 0; i < CHUNK; i++) {
                entry *e = &c->e[i];
                int s = atomic_load(&e->state);
                if ((s == DIR_NEW) != pass || atomic_exchange(&e->state, FREE) != s)
                    continue;
                if (s == PENDING || s == READY || s == SHARED)
                    unlink(e->tmp);
                else if (s == TMP_DIR)
                    purge_dir(e);
                else if (s == DIR_NEW)
                    rmdir(e->tmp);
            }
}

static void on_signal(int sig)
{
    int keep = errno;
    if (atomic_load(&committing)) { /* let the renames finish; cli_out_finish raises it then */
        atomic_store(&caught, sig);
        errno = keep;
        return;
    }
    remove_all();
    cli_progress_abandon();
    signal(sig, SIG_DFL);
    raise(sig); /* delivered when the handler returns: the status says which signal */
    errno = keep;
}

static void at_exit(void) { remove_all(); }

void cli_out_start(int argc, char **argv)
{
    static int installed;
    cmd_argc = argc, cmd_argv = argv;
    remove_all();
    used = 0;
    if (!installed++) {
        static const int sigs[] = {SIGINT,  SIGTERM, SIGHUP,  SIGPIPE, SIGQUIT, SIGXCPU, SIGXFSZ, SIGALRM,
                                   SIGUSR1, SIGUSR2, SIGABRT, SIGSEGV, SIGBUS,  SIGFPE,  SIGILL};
        struct sigaction sa;
        memset(&sa, 0, sizeof sa);
        sa.sa_handler = on_signal;
        sigemptyset(&sa.sa_mask);
        for (size_t i = 0; i < sizeof sigs / sizeof *sigs; i++)
            sigaddset(&sa.sa_mask, sigs[i]);
        for (size_t i = 0; i < sizeof sigs / sizeof *sigs; i++) {
            struct sigaction old;
            /* a signal the caller ignores (nohup, a shell's background job) stays ignored, and one
             * somebody else handles (a sanitizer's SIGSEGV) stays theirs */
            if (sigaction(sigs[i], NULL, &old) == 0 && !(old.sa_flags & SA_SIGINFO) && old.sa_handler == SIG_DFL)
                sigaction(sigs[i], &sa, NULL);
        }
        atexit(at_exit);
    }
}

void cli_out_abandon(void) { remove_all(); }

/* Does the option value v name path: the same, or (loose) a name made from
 * it, as frames are: "x.png" gives "x-000.png"? */
static int names(const char *v, const char *path, int loose)
{
    const char *dot = strrchr(v, '.');
    size_t stem = dot ? (size_t)(dot - v) : strlen(v), lp = strlen(path), le = strlen(v) - stem;
    if (!loose)
        return strcmp(v, path) == 0;
    return stem && lp > stem + le && strncmp(v, path, stem) == 0 && strcmp(path + lp - le, v + stem) == 0;
}

/* The option that named `path` on the command line, looking from argv[*i]
 * on (*i is left past it); "output" if none. */
static const char *option_from(const char *path, int *i, char *buf, size_t len)
{
    for (int loose = 0; loose < 2; loose++)
        for (int k = *i; cmd_argv && k < cmd_argc; k++) {
            const char *a = cmd_argv[k], *eq = strchr(a, '=');
            if (names(a, path, loose) && k > 1 && cmd_argv[k - 1][0] == '-')
                snprintf(buf, len, "%s", cmd_argv[k - 1]);
            else if (a[0] == '-' && a[1] == '-' && eq && names(eq + 1, path, loose))
                snprintf(buf, len, "%.*s", (int)(eq - a), a);
            else if (a[0] == '-' && a[1] && a[1] != '-' && !eq && names(a + 2, path, loose))
                snprintf(buf, len, "-%c", a[1]);
            else
                continue;
            *i = k + 1;
            return buf;
        }
    return "output";
}

static const char *option_of(const char *path, char *buf, size_t len)
{
    int i = 1;
    return option_from(path, &i, buf, len);
}

/* The folder holding `path` (its device and inode), to tell one file named
 * twice; exits 2 when it does not exist. */
static void folder_of(const char *path, entry *e)
{
    char dir[PATH_MAX], ob[64];
    const char *slash = strrchr(path, '/');
    struct stat st;
    if (!slash)
        snprintf(dir, sizeof dir, ".");
    else
        snprintf(dir, sizeof dir, "%.*s", slash == path ? 1 : (int)(slash - path), path);
    if (stat(dir, &st))
        cli_die(2, "%s: cannot write \"%s\": %s", option_of(path, ob, sizeof ob), path, strerror(errno));
    if (!S_ISDIR(st.st_mode))
        cli_die(2, "%s: cannot write \"%s\": \"%s\" is not a folder", option_of(path, ob, sizeof ob), path, dir);
    e->dev = st.st_dev, e->ino = st.st_ino;
}

static const char *base(const char *p)
{
    const char *s = strrchr(p, '/');
    return s ? s + 1 : p;
}

/* Refuse a path that another output of this run already names. */
static void check_twice(const char *path, const entry *e)
{
    char a[64], b[64];
    for (size_t i = 0; i + 1 < used; i++) {
        const entry *o = at(i);
        int s = atomic_load(&o->state);
        if ((s == PENDING || s == READY) && o->dev == e->dev && o->ino == e->ino &&
            strcmp(base(o->final), base(path)) == 0) {
            int k = 1;
            const char *oa = option_from(o->final, &k, a, sizeof a), *ob = option_of(path, b, sizeof b);
            if (strcmp(o->final, path) == 0)
                ob = option_from(path, &k, b, sizeof b);
            if (strcmp(oa, ob) == 0)
                cli_die(2, "%s: \"%s\" is written twice by this command; expected a different name for each output",
                        oa, path);
            cli_die(2, "%s and %s: both name \"%s\"; expected a different file for each output", oa, ob, path);
        }
    }
}

void cli_out_guard(void) { guarded = 1; }

/* A watcher process that removes tmp once this process has ended, however
 * it ended: it waits for the end of a pipe only this process holds (close
 * on exec), in a session of its own with the usual fatal signals ignored,
 * and calls only async-signal-safe functions.  After a rename or the
 * handlers' own removal the name is gone and the unlink does nothing. */
static void watch(const char *tmp)
{
    int fd[2], nul;
    char c;
    pid_t pid;
    if (pipe2(fd, O_CLOEXEC))
        return;
    if ((pid = fork()) != 0) {
        close(fd[0]);
        if (pid < 0)
            close(fd[1]);
        return;
    }
    static const int sigs[] = {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGPIPE, SIGUSR1, SIGUSR2, SIGALRM};
    for (size_t i = 0; i < sizeof sigs / sizeof *sigs; i++)
        signal(sigs[i], SIG_IGN);
    setsid();
    if ((nul = open("/dev/null", O_RDWR)) >= 0) /* the launcher's pipes are not kept open */
        dup2(nul, 0), dup2(nul, 1), dup2(nul, 2);
    if (dup2(fd[0], 3) == 3)
        syscall(SYS_close_range, 4u, ~0u, 0u);
    while (read(3, &c, 1) < 0 && errno == EINTR)
        ;
    unlink(tmp);
    _exit(0);
}

const char *cli_out_begin(const char *path)
{
    char ob[64];
    struct stat st;
    entry *e;
    int fd;
    if (!path)
        return NULL;
    if (!*path)
        cli_die(2, "%s: expected a file name, got \"\"", option_of(path, ob, sizeof ob));
    if (path[strlen(path) - 1] == '/' || (stat(path, &st) == 0 && S_ISDIR(st.st_mode)))
        cli_die(2, "%s: \"%s\" is a folder; expected a file name", option_of(path, ob, sizeof ob), path);
    e = at(used++);
    atomic_store(&e->state, FREE);
    folder_of(path, e);
    snprintf(e->final, PATH_MAX, "%s", path);
    check_twice(path, e);
    if (snprintf(e->tmp, PATH_MAX, "%s.tmp.%ld", path, (long)getpid()) >= PATH_MAX)
        cli_die(2, "%s: path too long: \"%s\"", option_of(path, ob, sizeof ob), path);
    atomic_store(&e->state, PENDING); /* published before the file exists: a signal removes it */
    fd = open(e->tmp, O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
    if (fd < 0) {
        int err = errno;
        atomic_store(&e->state, FREE); /* not ours (EEXIST) or not made */
        cli_die(2, "%s: cannot write \"%s\": %s", option_of(path, ob, sizeof ob), path, strerror(err));
    }
    close(fd);
    if (guarded)
        watch(e->tmp);
    return e->tmp;
}

void cli_out_share(const char *tmp)
{
    entry *e = at(used++);
    e->final[0] = 0;
    snprintf(e->tmp, PATH_MAX, "%s", tmp);
    atomic_store(&e->state, SHARED);
}

void cli_out_commit(const char *path)
{
    for (size_t i = 0; path && i < used; i++) {
        entry *e = at(i);
        int s = PENDING;
        if (strcmp(e->final, path) == 0)
            atomic_compare_exchange_strong(&e->state, &s, READY);
    }
}

/* Is dir the root folder (whatever its spelling: "/", "//", "/.."...)? */
static int is_root(const struct stat *st)
{
    struct stat root;
    return stat("/", &root) == 0 && root.st_dev == st->st_dev && root.st_ino == st->st_ino;
}

/* Does folder dir hold anything? */
static int has_entries(const char *dir)
{
    DIR *d = opendir(dir);
    struct dirent *de;
    int any = 0;
    while (d && !any && (de = readdir(d)))
        any = strcmp(de->d_name, ".") != 0 && strcmp(de->d_name, "..") != 0;
    if (d)
        closedir(d);
    return any || !d;
}

void cli_out_dir(const char *opt, const char *dir, int force)
{
    struct stat st;
    entry *e;
    if (!*dir)
        cli_die(2, "%s: expected a folder name, got \"\"", opt);
    if (strlen(dir) >= PATH_MAX)
        cli_die(2, "%s: path too long: \"%s\"", opt, dir);
    if (stat(dir, &st) == 0) {
        if (!S_ISDIR(st.st_mode))
            cli_die(2, "%s: \"%s\" exists and is not a folder", opt, dir);
        if (is_root(&st))
            cli_die(2, "%s: \"%s\" is the root folder; expected a folder of its own for the files", opt, dir);
        if (!force && has_entries(dir))
            cli_die(2, "%s: folder \"%s\" exists and is not empty; expected a new or empty folder (--force writes "
                    "into it, replacing files of the same names)", opt, dir);
        return;
    }
    e = at(used++);
    e->final[0] = 0;
    snprintf(e->tmp, PATH_MAX, "%s", dir);
    atomic_store(&e->state, DIR_NEW); /* before it exists, as for files */
    if (mkdir(dir, 0755)) {
        int err = errno;
        atomic_store(&e->state, FREE);
        cli_die(2, "%s: cannot create folder \"%s\": %s", opt, dir, strerror(err));
    }
}

void cli_out_finish(int ok)
{
    size_t i;
    if (!ok) {
        remove_all();
        return;
    }
    atomic_store(&committing, 1);
    for (i = 0; i < used; i++) {
        entry *e = at(i);
        if (atomic_load(&e->state) != READY)
            continue;
        if (rename(e->tmp, e->final) != 0) {
            int err = errno;
            for (size_t k = 0; k < i; k++) /* all or none: what was renamed goes too */
                if (atomic_load(&at(k)->state) == DONE)
                    unlink(at(k)->final);
            atomic_store(&committing, 0);
            cli_die(1, "output: cannot rename to \"%s\": %s", e->final, strerror(err));
        }
        atomic_store(&e->state, DONE);
    }
    for (i = 0; i < used; i++) { /* begun and never committed: dropped; scratch folders: removed */
        entry *e = at(i);
        int s = atomic_exchange(&e->state, FREE);
        if (s == PENDING)
            unlink(e->tmp);
        else if (s == TMP_DIR)
            purge_dir(e);
        e->final[0] = 0;
    }
    atomic_store(&committing, 0);
    if (atomic_load(&caught)) {
        signal(caught, SIG_DFL);
        raise(caught);
    }
}

char *cli_out_tmpdir(char *templ)
{
    entry *e;
    if (strlen(templ) >= PATH_MAX || !mkdtemp(templ))
        return NULL;
    e = at(used++);
    e->final[0] = 0;
    snprintf(e->tmp, PATH_MAX, "%s", templ);
    atomic_store(&e->state, TMP_DIR);
    return templ;
}
