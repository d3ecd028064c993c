/* noiselab: the command line.  A run that names an .h5 file or is started
 * by an MPI launcher continues in noiselab-mpi, installed beside this
 * program: HDF5 and Open MPI load some 40 libraries (about 10 ms at every
 * start), which the other runs do without. */
#include "cli.h"

#include <errno.h>
#include <limits.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static int wants_mpi(int argc, char **argv)
{
    if (cli_mpi_launched())
        return 1;
    for (int i = 1; i < argc; i++)
        if (cli_has_ext(argv[i], ".h5"))
            return 1;
    return 0;
}

int main(int argc, char **argv)
{
    char self[PATH_MAX], *slash;
    ssize_t len;
    if (argc < 2 || !wants_mpi(argc, argv))
        return cli_main(argc, argv);
    len = readlink("/proc/self/exe", self, sizeof self - 16);
    if (len > 0) {
        self[len] = 0;
        if ((slash = strrchr(self, '/'))) {
            strcpy(slash + 1, "noiselab-mpi");
            execv(self, argv);
        }
    }
    cli_die(2, "HDF5 files and MPI runs need noiselab-mpi beside this program (%s): %s",
            len > 0 ? self : "?", strerror(errno));
}
