/* Reading a file once into memory, and reading any field file. */
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

/* Read fd to its end into *buf (capacity *cap); the count in *len. */
static int read_all(int fd, const char *path, unsigned char **buf, size_t *cap, size_t *len, size_t avail)
{
    size_t n = 0;
    int st;
    for (;;) {
        ssize_t got;
        if (n + 1 >= *cap && (st = grow(path, buf, cap, n, avail)))
            return st;
        got = read(fd, *buf + n, *cap - n - 1);
        if (got < 0 && errno == EINTR)
            continue;
        if (got < 0)
            return NL_ERROR(NL_EINPUT, "%s: read failed: %s", path, strerror(errno));
        if (got == 0)
            break;
        n += (size_t)got;
    }
    (*buf)[n] = 0;
    *len = n;
    return NL_OK;
}

int nl_io_slurp(const char *path, unsigned char **buf, size_t *len)
{
    struct stat sb;
    size_t cap = 0, avail = nl_mem_available();
    int st, fd = open(path, O_RDONLY | O_CLOEXEC);
    *buf = NULL, *len = 0;
    if (fd < 0)
        return NL_ERROR(NL_EINPUT, "cannot open %s: %s", path, strerror(errno));
    if (fstat(fd, &sb) == 0 && S_ISDIR(sb.st_mode)) {
        close(fd);
        return NL_ERROR(NL_EINPUT, "%s: is a folder; expected a file", path);
    }
    if (S_ISREG(sb.st_mode) && sb.st_size > 0) { /* one block of the right size; a pipe grows */
        cap = (size_t)sb.st_size + 1;
        if ((off_t)(cap - 1) != sb.st_size || (avail && cap > avail)) {
            close(fd);
            return NL_ERROR(NL_ETOOBIG, "%s: %lld bytes do not fit in the memory available (%zu bytes)", path,
                            (long long)sb.st_size, avail);
        }
        if (!(*buf = malloc(cap))) {
            close(fd);
            return NL_ERROR(NL_ENOMEM, "out of memory reading %s (%zu bytes)", path, cap);
        }
    }
    st = read_all(fd, path, buf, &cap, len, avail);
    close(fd);
    if (st) {
        free(*buf);
        *buf = NULL, *len = 0;
    }
    return st;
}

/* A TSV table in memory, through a stream (the parser reads lines). */
static int tsv_mem(const char *path, unsigned char *buf, size_t len, nl_field **out, nl_meta *meta)
{
    FILE *fp;
    int st;
    *out = NULL;
    if (len == 0)
        return NL_ERROR(NL_EINPUT, "%s: expected a TSV header line, found none", path);
    if (!(fp = fmemopen(buf, len, "r")))
        return NL_ERROR(NL_ENOMEM, "out of memory reading %s", path);
    st = nl_tsv_read_stream(fp, path, out, meta);
    fclose(fp);
    return st;
}

int nl_field_read(const char *path, nl_field **out, nl_meta *meta)
{
    static const unsigned char exr_magic[4] = {0x76, 0x2f, 0x31, 0x01};
    static const unsigned char png_magic[4] = {0x89, 'P', 'N', 'G'};
    unsigned char *buf;
    size_t len;
    int st;
    *out = NULL;
    if (meta)
        memset(meta, 0, sizeof *meta);
    if ((st = nl_io_slurp(path, &buf, &len)))
        return st;
    if (len >= 4 && memcmp(buf, exr_magic, 4) == 0) {
        st = nl_exr_read_mem(path, buf, len, out, meta);
        for (size_t i = 0; !st && i < (*out)->count; i++)
            if (!isfinite((*out)->data[i])) {
                st = NL_ERROR(NL_EINPUT, "%s: sample %zu is %g; expected finite values", path, i, (*out)->data[i]);
                nl_field_free(*out);
                *out = NULL;
            }
    } else if (len >= 4 && memcmp(buf, png_magic, 4) == 0)
        st = nl_png_read_mem(path, buf, len, out);
    else
        st = tsv_mem(path, buf, len, out, meta);
    free(buf);
    return st;
}
