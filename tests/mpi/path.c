/* nl_mpi_same_file and the collective HDF5 calls on paths that name other
 * files on other processes, under mpirun -np 1..4 (tests/mpi/run.sh).
 *
 * A collective MPI-IO open or create of files that differ between
 * processes never returns, so the property checked is: whenever the
 * processes' paths name different files (per-process names, a file on
 * process 0 only), every process gets NL_EINPUT, the same status, with a
 * message naming the path and a process that differs, and no call hangs
 * (run.sh's mpirun has no limit of its own: a hang here is the failure
 * the module exists to prevent); whenever they name one file, however
 * spelled (a link, "./", "x/../"), NL_OK.  On one process every path is
 * the same file. */
#include "../../mpi/dist.h"
#include "../../mpi/h5.h"
#include "../../core/nl_error.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static int rank, P, fails;
static char dir[256];

/* Every process got `want` (NL_OK or, when the paths differ and P > 1,
 * NL_EINPUT whose message names `needle`). */
static void expect(const char *what, int st, int differ, const char *needle)
{
    int want = differ && P > 1 ? NL_EINPUT : NL_OK, lo, hi, bad;
    MPI_Allreduce(&st, &lo, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
    MPI_Allreduce(&st, &hi, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
    bad = lo != want || hi != want || (want && needle && !strstr(nl_errmsg(), needle));
    MPI_Allreduce(MPI_IN_PLACE, &bad, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
    if (bad) {
        fails++;
        if (rank == 0)
            fprintf(stderr, "FAIL %s on %d processes: statuses %d..%d, expected %d (%s)\n", what, P, lo, hi, want,
                    nl_errmsg());
    }
}

static void touch(const char *path)
{
    FILE *fp = fopen(path, "w");
    if (!fp || fputs("x\n", fp) < 0 || fclose(fp)) {
        fprintf(stderr, "cannot make %s\n", path);
        MPI_Abort(MPI_COMM_WORLD, 1);
    }
}

static void same_file_cases(void)
{
    char p[512];
    /* one file: by one name, by a link, by "./" and "sub/../" */
    snprintf(p, sizeof p, "%s/f", dir);
    expect("one file", nl_mpi_same_file(MPI_COMM_WORLD, p, 0), 0, NULL);
    snprintf(p, sizeof p, rank % 3 == 0 ? "%s/f" : rank % 3 == 1 ? "%s/link" : "%s/sub/../f", dir);
    expect("one file, other spellings", nl_mpi_same_file(MPI_COMM_WORLD, p, 0), 0, NULL);
    snprintf(p, sizeof p, rank % 2 ? "%s/./out.h5" : "%s/sub/../out.h5", dir);
    expect("one new file, other spellings", nl_mpi_same_file(MPI_COMM_WORLD, p, 1), 0, NULL);
    /* missing everywhere: the open that follows says why */
    snprintf(p, sizeof p, "%s/none", dir);
    expect("missing everywhere", nl_mpi_same_file(MPI_COMM_WORLD, p, 0), 0, NULL);
    /* a file of each process's own */
    snprintf(p, sizeof p, "%s/f%d", dir, rank);
    expect("per-process files", nl_mpi_same_file(MPI_COMM_WORLD, p, 0), 1, "on process 1");
    /* on process 0 only */
    snprintf(p, sizeof p, "%s/%s", dir, rank ? "none" : "f");
    expect("missing on process 1", nl_mpi_same_file(MPI_COMM_WORLD, p, 0), 1, "cannot be resolved on process 1");
    /* a new file in each process's own folder, or in a folder of process 0 only */
    snprintf(p, sizeof p, "%s/r%d/out.h5", dir, rank);
    expect("per-process folders", nl_mpi_same_file(MPI_COMM_WORLD, p, 1), 1, "on process 1");
    snprintf(p, sizeof p, "%s/%s/out.h5", dir, rank ? "nofolder" : "sub");
    expect("folder on process 0 only", nl_mpi_same_file(MPI_COMM_WORLD, p, 1), 1, "process 1");
}

/* The collective HDF5 calls refuse instead of hanging. */
static void h5_cases(void)
{
    char p[512];
    size_t n[2] = {8, 6}, s0, ns, nn[3];
    double slab[48], h[3], *got = NULL;
    nl_meta meta;
    int dim;
    memset(&meta, 0, sizeof meta);
    for (int i = 0; i < 48; i++)
        slab[i] = 0.125 * i;
    nl_mpi_block(6, P, rank, &s0, &ns);
    snprintf(p, sizeof p, "%s/r%d/w.h5", dir, rank);
    expect("h5 write to per-process folders",
           nl_mpi_h5_write(p, MPI_COMM_WORLD, 2, n, s0, ns, ns ? slab + 8 * s0 : NULL, &meta, 1, P), 1,
           "on process 1");
    snprintf(p, sizeof p, "%s/w.h5", dir);
    expect("h5 write to one file",
           nl_mpi_h5_write(p, MPI_COMM_WORLD, 2, n, s0, ns, ns ? slab + 8 * s0 : NULL, &meta, 1, P), 0, NULL);
    /* each process's own copy of it */
    if (rank == 0)
        for (int r = 0; r < P; r++) {
            char q[600], cmd[1400];
            snprintf(q, sizeof q, "%s/r%d/w.h5", dir, r);
            snprintf(cmd, sizeof cmd, "cp '%s' '%s'", p, q);
            if (system(cmd))
                MPI_Abort(MPI_COMM_WORLD, 1);
        }
    MPI_Barrier(MPI_COMM_WORLD);
    snprintf(p, sizeof p, "%s/r%d/w.h5", dir, rank);
    expect("h5 read of per-process files",
           nl_mpi_h5_read_slab(p, MPI_COMM_WORLD, &dim, nn, h, NULL, &s0, &ns, &got), 1, "on process 1");
    free(got);
}

int main(int argc, char **argv)
{
    char p[512];
    MPI_Init(&argc, &argv);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &P);
    if (rank == 0) {
        snprintf(dir, sizeof dir, "%s/nl-mpi-path-XXXXXX", getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp");
        if (!mkdtemp(dir))
            MPI_Abort(MPI_COMM_WORLD, 1);
        snprintf(p, sizeof p, "%s/f", dir);
        touch(p);
        snprintf(p, sizeof p, "%s/link", dir);
        if (symlink("f", p))
            MPI_Abort(MPI_COMM_WORLD, 1);
        snprintf(p, sizeof p, "%s/sub", dir);
        mkdir(p, 0755);
        for (int r = 0; r < P; r++) {
            snprintf(p, sizeof p, "%s/f%d", dir, r);
            touch(p);
            snprintf(p, sizeof p, "%s/r%d", dir, r);
            mkdir(p, 0755);
        }
    }
    MPI_Bcast(dir, sizeof dir, MPI_CHAR, 0, MPI_COMM_WORLD);
    same_file_cases();
    h5_cases();
    MPI_Barrier(MPI_COMM_WORLD);
    if (rank == 0) {
        char cmd[600];
        snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
        if (system(cmd))
            fprintf(stderr, "cannot remove %s\n", dir);
    }
    if (rank == 0 && !fails)
        printf("mpi path: every case passed on %d processes\n", P);
    MPI_Finalize();
    return fails != 0;
}
