/* Slabs and agreement on errors across processes. */
#include "dist.h"
#include "../core/nl_error.h"

#include <stdio.h>
#include <string.h>

void nl_mpi_block(size_t N, int P, int r, size_t *s0, size_t *ns)
{
    size_t b = P > 0 ? (N + (size_t)P - 1) / (size_t)P : N, a = (size_t)r * b;
    *s0 = a < N ? a : N;
    *ns = N - *s0 < b ? N - *s0 : b;
}

enum { MSG = 512 };

int nl_mpi_agree(MPI_Comm comm, int status)
{
    int size, rank, worst, who, mine;
    char msg[MSG];
    if (MPI_Comm_size(comm, &size) != MPI_SUCCESS || MPI_Comm_rank(comm, &rank) != MPI_SUCCESS)
        return NL_ERROR(NL_EFAIL, "MPI: the communicator cannot be queried");
    if (MPI_Allreduce(&status, &worst, 1, MPI_INT, MPI_MAX, comm) != MPI_SUCCESS)
        return NL_ERROR(NL_EFAIL, "MPI: agreeing on a status failed");
    if (worst == NL_OK)
        return NL_OK;
    /* the lowest rank holding the worst status tells its message */
    mine = status == worst ? rank : size;
    if (MPI_Allreduce(&mine, &who, 1, MPI_INT, MPI_MIN, comm) != MPI_SUCCESS)
        return NL_ERROR(NL_EFAIL, "MPI: agreeing on a status failed");
    memset(msg, 0, sizeof msg);
    if (rank == who)
        snprintf(msg, sizeof msg, "%s", nl_errmsg());
    if (MPI_Bcast(msg, MSG, MPI_CHAR, who, comm) != MPI_SUCCESS)
        return NL_ERROR(NL_EFAIL, "MPI: sharing an error message failed");
    msg[MSG - 1] = 0;
    return NL_ERROR(worst, "%s", msg);
}

int nl_mpi_processes_needed(size_t (*bytes)(int P, const void *arg), const void *arg, size_t limit, int pmax)
{
    for (int P = 1; P <= pmax; P++)
        if (bytes(P, arg) <= limit)
            return P;
    return 0;
}
