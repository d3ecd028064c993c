/* Reading a file once into memory, and reading any field file (images
 * from a copy in memory, TSV series parsed as they are read). */
#include "io_read_internal.h"
#include "field.h"
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

/* The rest of open file fd, after the n <= 4 bytes already read into
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
    unsigned char head[4];  /* bytes read to tell the format */
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

/* A TSV series from fd (the n bytes of head already read), parsed as it is
 * read: memory grows with the samples, within the memory limit, and never
 * holds the file. */
static int tsv_fd(const char *path, int fd, const unsigned char *head, size_t n, nl_field **out, nl_meta *meta)
{
    prefixed p = {.fd = fd, .n = n};
    cookie_io_functions_t io = {.read = prefixed_read};
    FILE *fp;
    int st;
    *out = NULL;
    if (n == 0)
        return NL_ERROR(NL_EINPUT, "%s: expected a TSV header line, found none", path);
    memcpy(p.head, head, n);
    if (!(fp = fopencookie(&p, "r", io)))
        return NL_ERROR(NL_ENOMEM, "out of memory reading %s", path);
    st = nl_tsv_read_stream(fp, path, out, meta);
    fclose(fp);
    return st;
}

/* Up to 4 bytes from fd into head (fewer at the end of the file). */
static int read_head(int fd, const char *path, unsigned char *head, size_t *n)
{
    size_t got = 1;
    int st;
    *n = 0;
    while (*n < 4 && got > 0) {
        if ((st = read_some(fd, path, head + *n, 4 - *n, &got)))
            return st;
        *n += got;
    }
    return NL_OK;
}

/* An EXR or PNG image, decoded from a copy of the whole file. */
static int image_fd(const char *path, int fd, const unsigned char *head, size_t n, int exr, nl_field **out,
                    nl_meta *meta)
{
    unsigned char *buf;
    size_t len;
    int st = slurp_fd(fd, path, head, n, &buf, &len);
    if (st)
        return st;
    if (!exr)
        st = nl_png_read_mem(path, buf, len, out);
    else if (!(st = nl_exr_read_mem(path, buf, len, out, meta)))
        for (size_t i = 0; i < (*out)->count; i++)
            if (!isfinite((*out)->data[i])) {
                st = NL_ERROR(NL_EINPUT, "%s: sample %zu is %g; expected finite values", path, i, (*out)->data[i]);
                nl_field_free(*out);
                *out = NULL;
                break;
            }
    free(buf);
    return st;
}

int nl_field_read(const char *path, nl_field **out, nl_meta *meta)
{
    static const unsigned char exr_magic[4] = {0x76, 0x2f, 0x31, 0x01};
    static const unsigned char png_magic[4] = {0x89, 'P', 'N', 'G'};
    unsigned char head[4];
    size_t n;
    int st, fd, exr, png;
    *out = NULL;
    if (meta)
        memset(meta, 0, sizeof *meta);
    if ((st = open_input(path, &fd)))
        return st;
    if (!(st = read_head(fd, path, head, &n))) {
        exr = n == 4 && memcmp(head, exr_magic, 4) == 0, png = n == 4 && memcmp(head, png_magic, 4) == 0;
        st = exr || png ? image_fd(path, fd, head, n, exr, out, meta) : tsv_fd(path, fd, head, n, out, meta);
    }
    close(fd);
    return st;
}
