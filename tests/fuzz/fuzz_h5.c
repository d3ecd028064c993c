/* libFuzzer target for the HDF5 reader (mpi/h5.h): the input is written to
 * a temporary .h5 and read by one process, whole (nl_mpi_h5_read) and for
 * its provenance alone (nl_mpi_h5_read_meta), as noiselab and synth --from
 * read it.  No MPI_Init: comm MPI_COMM_NULL uses HDF5's POSIX driver.
 * Expect findings inside libhdf5 itself on corrupted internals (1.10:
 * H5HG_read and H5T__conv_vlen reading a variable-length string whose
 * global-heap entry is damaged); they are HDF5's, not this reader's. */
#include "../../core/io.h"
#include "../../mpi/h5.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static char path[64];
    nl_field *f;
    nl_meta meta;
    FILE *fp;
    /* a file may declare any size: refuse beyond 512 MB, as a small machine would */
    setenv("NOISELAB_MEMORY_LIMIT", "536870912", 0);
    if (!path[0])
        snprintf(path, sizeof path, "/tmp/noiselab-fuzz-%ld.h5", (long)getpid());
    if (!(fp = fopen(path, "wb")))
        return 0;
    fwrite(data, 1, size, fp);
    fclose(fp);
    if (nl_mpi_h5_read(path, &f, &meta) == 0) {
        /* what was read is a field's: finite samples, NUL-terminated provenance */
        for (size_t i = 0; i < f->count; i++)
            if (f->data[i] != f->data[i])
                abort();
        nl_field_free(f);
    }
    if (nl_mpi_h5_read_meta(path, &meta) == 0 && !memchr(meta.model, 0, sizeof meta.model))
        abort();
    return 0;
}
