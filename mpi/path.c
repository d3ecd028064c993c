/* Does a path name the same file on every process?  A collective open or
 * create of a path that resolves to different files on different processes
 * (per-process working folders, node-local scratch, a symbolic link that
 * differs) never returns: MPI-IO waits for processes that opened another
 * file.  So every process resolves the path first and compares with
 * process 0. */
#include "dist.h"
#include "../core/nl_error.h"

#include <errno.h>
#include <limits.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

/* What one process sees at a path. */
typedef struct {
    char given[PATH_MAX]; /* the path as this process was given it */
    char real[PATH_MAX];  /* the resolved path ("" when it cannot be resolved) */
    int err;             /* errno of resolving it, 0 when resolved */
    uint64_t dev, ino;   /* the file's identity (create: its folder's) */
    int64_t size;        /* bytes (create: 0) */
    int64_t mt_s, mt_ns; /* last modification (create: 0) */
} ident;

/* Resolve path: the file itself, or (create) its folder plus the name. */
static void resolve(const char *path, int create, ident *id)
{
    char dir[PATH_MAX], rdir[PATH_MAX];
    const char *slash = strrchr(path, '/'), *name = slash ? slash + 1 : path;
    struct stat st;
    memset(id, 0, sizeof *id);
    snprintf(id->given, sizeof id->given, "%s", path);
    if (create)
        snprintf(dir, sizeof dir, "%.*s", slash ? (slash == path ? 1 : (int)(slash - path)) : 1, slash ? path : ".");
    if (!realpath(create ? dir : path, create ? rdir : id->real) || stat(create ? rdir : id->real, &st)) {
        id->err = errno ? errno : ENOENT;
        id->real[0] = 0;
        return;
    }
    if (create && snprintf(id->real, sizeof id->real, "%s%s%s", rdir, strcmp(rdir, "/") ? "/" : "", name) >=
                      (int)sizeof id->real) {
        id->err = ENAMETOOLONG;
        id->real[0] = 0;
        return;
    }
    id->dev = (uint64_t)st.st_dev, id->ino = (uint64_t)st.st_ino;
    if (!create) {
        id->size = (int64_t)st.st_size;
        id->mt_s = (int64_t)st.st_mtim.tv_sec, id->mt_ns = (int64_t)st.st_mtim.tv_nsec;
    }
}

/* This process's verdict against process 0's view (z) and its node's first
 * process's (nz): NL_OK or NL_EINPUT with the message, which names the path
 * as process 0 has it (the processes may be given other spellings). */
static int compare(int create, const ident *me, const ident *z, const ident *nz, int rank)
{
    const char *path = z->given, *what = create ? "its folder" : "the file";
    if (me->err || z->err) {
        if (me->err && z->err)
            return NL_OK; /* the same failure everywhere: the caller's open tells */
        if (me->err)
            return NL_ERROR(NL_EINPUT, "\"%s\" is \"%s\" on process 0 but cannot be resolved on process %d (%s); "
                            "expected a path that names the same file on every process", path, z->real, rank,
                            strerror(me->err));
        return NL_ERROR(NL_EINPUT, "\"%s\" cannot be resolved on process 0 (%s) but is \"%s\" on process %d; "
                        "expected a path that names the same file on every process", path, strerror(z->err),
                        me->real, rank);
    }
    if (strcmp(me->real, z->real))
        return NL_ERROR(NL_EINPUT, "\"%s\" is \"%s\" on process 0 but \"%s\" on process %d; expected a path that "
                        "names the same file on every process (not per-process folders)", path, z->real, me->real,
                        rank);
    /* device numbers are per machine (an NFS mount's differs between
     * nodes): compared only with a process of the same node */
    if (me->dev != nz->dev || me->ino != nz->ino)
        return NL_ERROR(NL_EINPUT, "\"%s\" is \"%s\" on every process but %s is another one on process %d (device "
                        "and inode differ: node-local storage?); expected one file shared by every process", path,
                        me->real, what, rank);
    if (!create && (me->size != z->size || me->mt_s != z->mt_s || me->mt_ns != z->mt_ns))
        return NL_ERROR(NL_EINPUT, "\"%s\" is \"%s\" on every process but another file on process %d (its %s "
                        "differs); expected one file shared by every process", path, me->real, rank,
                        me->size != z->size ? "size" : "modification time");
    return NL_OK;
}

int nl_mpi_same_file(MPI_Comm comm, const char *path, int create)
{
    ident *me = calloc(3, sizeof *me), *z = me + 1, *nz = me + 2;
    MPI_Comm node = MPI_COMM_NULL;
    int rank, st = NL_OK;
    if (MPI_Comm_rank(comm, &rank) != MPI_SUCCESS)
        st = NL_ERROR(NL_EFAIL, "MPI: the communicator cannot be queried");
    else if (!me)
        st = NL_ERROR(NL_ENOMEM, "out of memory comparing \"%s\" between processes", path);
    if ((st = nl_mpi_agree(comm, st))) {
        free(me);
        return st;
    }
    resolve(path, create, me);
    *z = *me, *nz = *me;
    if (MPI_Bcast(z, sizeof *z, MPI_BYTE, 0, comm) != MPI_SUCCESS ||
        MPI_Comm_split_type(comm, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node) != MPI_SUCCESS ||
        MPI_Bcast(nz, sizeof *nz, MPI_BYTE, 0, node) != MPI_SUCCESS)
        st = NL_ERROR(NL_EFAIL, "MPI: comparing \"%s\" between processes failed", path);
    else
        st = compare(create, me, z, nz, rank);
    if (node != MPI_COMM_NULL)
        MPI_Comm_free(&node);
    free(me);
    return nl_mpi_agree(comm, st);
}
