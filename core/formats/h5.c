/* HDF5 (mpi/h5.h): a descriptor only; libnoiselab_mpi reads and writes it,
 * and its callers write the XDMF sidecar (nl_xdmf_write). */
#include "formats_internal.h"

const nl_format nl_format_h5 = {
    .name = "h5",
    .extensions = ".h5",
    .summary = "HDF5 dataset /field, float32 or float64, slowest axis first, with an .xmf sidecar "
               "for ParaView; through libnoiselab_mpi",
    .dims = 1 << 1 | 1 << 2 | 1 << 3,
    .types = NL_FORMAT_F32 | NL_FORMAT_F64,
    .precision = 32,
    .meta = NL_FORMAT_META_PROVENANCE | NL_FORMAT_META_SPACING | NL_FORMAT_META_ORIGIN,
    .flags = NL_FORMAT_EXTERNAL,
    .magic = "\x89HDF\r\n\x1a\n",
    .magic_len = 8,
};
