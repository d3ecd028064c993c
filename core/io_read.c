/* Reading a file once into memory, and reading any field file through
 * the format registry (core/format.h): binary formats from a copy in
 * memory, text formats parsed as they are read. */
#include "io_read_internal.h"
#include "field.h"
#include "format.h"
#include "nl_error.h"

#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* Grow *buf to hold more than n bytes (doubling), within `avail` (0: no
 * ceiling known). */
static int grow(const char *path, unsigned char **buf, size_t *cap, size_t n, size_t avail)
{
    size_t want = *cap < ((size_t)1 << 16) ? (size_t)1 << 16 : 2 * *cap;
    unsigned char *more;
    if (want < *cap || (avail && want > avail && (want = avail) <= n + 1))
        return NL_ERROR(NL_ETOOBIG, "%s: more than %zu bytes; they do not fit in the memory available", path, n);
    if (!(more = realloc(*buf, want)))
        return NL_ERROR(NL_ENOMEM, "out of memory reading %s (%zu bytes)", path, want);
    *buf = more, *cap = want;
    return NL_OK;
}

/* One read(2) of at most k bytes into p, retried when interrupted; the
 * count in *got (0 at the end of the file). */
static int read_some(int fd, const char *path, void *p, size_t k, size_t *got)
{
    ssize_t r;
    while ((r = read(fd, p, k)) < 0 && errno == EINTR)
        ;
    if (r < 0)
        return NL_ERROR(NL_EINPUT, "%s: read failed: %s", path, strerror(errno));
    *got = (size_t)r;
    return NL_OK;
}

/* Read fd to its end into *buf (capacity *cap) after the n0 bytes already
 * there; the count in *len. */
static int read_all(int fd, const char *path, unsigned char **buf, size_t *cap, size_t *len, size_t avail, size_t n0)
{
    size_t n = n0;
    int st;
    for (;;) {
        size_t got = 0;
        if (n + 1 >= *cap && (st = grow(path, buf, cap, n, avail)))
            return st;
        if ((st = read_some(fd, path, *buf + n, *cap - n - 1, &got)))
            return st;
        if (got == 0)
            break;
        n += got;
    }
    (*buf)[n] = 0;
    *len = n;
    return NL_OK;
}

/* The rest of open file fd, after the n <= 8 bytes already read into
 * head, into a new block (*buf, *len bytes of it), within the memory
 * available. */
static int slurp_fd(int fd, const char *path, const unsigned char *head, size_t n, unsigned char **buf, size_t *len)
{
    struct stat sb;
    size_t cap = 0, avail = nl_mem_available(), got = 0;
    int st;
    *buf = NULL, *len = 0;
    if (fstat(fd, &sb) == 0 && S_ISREG(sb.st_mode) && sb.st_size > 0) { /* one block of the right size; a pipe grows */
        cap = (size_t)sb.st_size + 1;
        if ((off_t)(cap - 1) != sb.st_size || (avail && cap > avail))
            return NL_ERROR(NL_ETOOBIG, "%s: %lld bytes do not fit in the memory available (%zu bytes)", path,
                            (long long)sb.st_size, avail);
        if (cap <= n) /* the file changed meanwhile */
            cap = n + 1;
        if (!(*buf = malloc(cap)))
            return NL_ERROR(NL_ENOMEM, "out of memory reading %s (%zu bytes)", path, cap);
    } else if (n && (st = grow(path, buf, &cap, 0, avail)))
        return st;
    if (n)
        memcpy(*buf, head, n);
    st = read_all(fd, path, buf, &cap, &got, avail, n);
    if (st) {
        free(*buf);
        *buf = NULL;
        return st;
    }
    *len = got;
    return NL_OK;
}

/* Open path for reading: NL_EINPUT naming it when it cannot be, or is a folder. */
static int open_input(const char *path, int *fd)
{
    struct stat sb;
    *fd = open(path, O_RDONLY | O_CLOEXEC);
    if (*fd < 0)
        return NL_ERROR(NL_EINPUT, "cannot open %s: %s", path, strerror(errno));
    if (fstat(*fd, &sb) == 0 && S_ISDIR(sb.st_mode)) {
        close(*fd);
        return NL_ERROR(NL_EINPUT, "%s: is a folder; expected a file", path);
    }
    return NL_OK;
}

int nl_io_slurp(const char *path, unsigned char **buf, size_t *len)
{
    int fd, st;
    *buf = NULL, *len = 0;
    if ((st = open_input(path, &fd)))
        return st;
    st = slurp_fd(fd, path, NULL, 0, buf, len);
    close(fd);
    return st;
}

/* A stream over fd that first gives back the bytes already read from it
 * (the TSV parser reads it line by line, as it arrives). */
typedef struct {
    int fd;                 /* the file, read on after the head */
    unsigned char head[8];  /* bytes read to tell the format */
    size_t n, pos;          /* how many, how many given back */
} prefixed;

static ssize_t prefixed_read(void *cookie, char *buf, size_t size)
{
    prefixed *p = cookie;
    ssize_t got;
    if (p->pos < p->n) {
        size_t k = p->n - p->pos < size ? p->n - p->pos : size;
        memcpy(buf, p->head + p->pos, k);
        p->pos += k;
        return (ssize_t)k;
    }
    while ((got = read(p->fd, buf, size)) < 0 && errno == EINTR)
        ;
    return got;
}

/* A text format from fd (the n bytes of head already read), parsed as it
 * is read: memory grows with the samples, within the memory limit, and
 * never holds the file. */
static int stream_fd(const nl_format *t, const char *path, int fd, const unsigned char *head, size_t n,
                     nl_field **out, nl_meta *meta)
{
    prefixed p = {.fd = fd, .n = n};
    cookie_io_functions_t io = {.read = prefixed_read};
    FILE *fp;
    int st;
    *out = NULL;
    memcpy(p.head, head, n);
    if (!(fp = fopencookie(&p, "r", io)))
        return NL_ERROR(NL_ENOMEM, "out of memory reading %s", path);
    st = t->read_stream(fp, path, out, meta);
    fclose(fp);
    return st;
}

/* Up to 8 bytes from fd into head (fewer at the end of the file). */
static int read_head(int fd, const char *path, unsigned char *head, size_t *n)
{
    size_t got = 1;
    int st;
    *n = 0;
    while (*n < 8 && got > 0) {
        if ((st = read_some(fd, path, head + *n, 8 - *n, &got)))
            return st;
        *n += got;
    }
    return NL_OK;
}

/* The format of a file that starts with the n bytes of head: o->format by
 * name, else the first whose signature matches, else the one path's
 * extension selects (formats without a signature), else the fallback. */
static int choose(const char *path, const nl_read_options *o, const unsigned char *head, size_t n,
                  const nl_format **out)
{
    const nl_format *t, *fallback = NULL;
    int st;
    *out = NULL;
    if (o && o->format)
        return nl_format_resolve(path, o->format, out);
    for (size_t i = 0; (t = nl_format_get(i)); i++) {
        if (t->magic && n >= t->magic_len && memcmp(head, t->magic, t->magic_len) == 0)
            return *out = t, NL_OK;
        if (t->flags & NL_FORMAT_FALLBACK && !fallback)
            fallback = t;
    }
    t = nl_format_for_path(path);
    *out = t && (!t->magic || (t->flags & NL_FORMAT_EXTERNAL)) ? t : fallback;
    st = *out ? NL_OK : NL_ERROR(NL_EINPUT, "%s: not a field file this library reads", path);
    return st;
}

/* Any sample not finite: NL_EINPUT naming the first, f released. */
static int check_finite(const char *path, nl_field **f)
{
    for (size_t i = 0; i < (*f)->count; i++)
        if (!isfinite((*f)->data[i])) {
            int st = NL_ERROR(NL_EINPUT, "%s: sample %zu is %g; expected finite values", path, i, (*f)->data[i]);
            nl_field_free(*f);
            *f = NULL;
            return st;
        }
    return NL_OK;
}

/* Read fd (the n bytes of head already read) as format t. */
static int read_as(const nl_format *t, const char *path, int fd, const unsigned char *head, size_t n,
                   const nl_read_options *o, nl_field **out, nl_meta *meta)
{
    unsigned char *buf;
    size_t len;
    int st;
    if (t->flags & NL_FORMAT_EXTERNAL)
        return NL_ERROR(NL_EINVAL, "%s: format %s is read by libnoiselab_mpi (mpi/h5.h), not here", path, t->name);
    if (t->flags & NL_FORMAT_OFF)
        return NL_ERROR(NL_EINVAL, "%s: format %s: %s", path, t->name, t->summary);
    if (t->read_stream)
        return stream_fd(t, path, fd, head, n, out, meta);
    if ((st = slurp_fd(fd, path, head, n, &buf, &len)))
        return st;
    st = t->read(path, buf, len, o, out, meta);
    free(buf);
    return st;
}

int nl_field_read_opts(const char *path, const nl_read_options *o, nl_field **out, nl_meta *meta)
{
    const nl_format *t;
    unsigned char head[8];
    size_t n;
    int st, fd;
    *out = NULL;
    if (meta)
        memset(meta, 0, sizeof *meta);
    if ((st = open_input(path, &fd)))
        return st;
    if (!(st = read_head(fd, path, head, &n)) && !(st = choose(path, o, head, n, &t)) &&
        !(st = read_as(t, path, fd, head, n, o, out, meta)))
        st = check_finite(path, out);
    close(fd);
    return st;
}

int nl_field_read(const char *path, nl_field **out, nl_meta *meta) { return nl_field_read_opts(path, NULL, out, meta); }
