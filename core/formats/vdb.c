/* OpenVDB (.vdb): a 3D field as one FloatGrid "density", the sparse-volume
 * format that Blender (a volume object), Houdini and ParaView import.
 *
 * Written: every sample an active voxel at index (i, j, k) = (x, y, z)
 * sample indices, background 0, nothing pruned, so every value (0 and NaN
 * included) comes back bit for bit as float32; the grid class is "fog
 * volume"; the transform maps index (i, j, k) to world (X + i h0, Y + j h1,
 * k h2), a scale-and-translate map (voxel size = spacing, a different one
 * per axis allowed), with (X, Y) the window's first sample (nl_meta.origin,
 * in samples) times the spacing; the provenance is grid metadata, strings
 * "noiselab.model", "noiselab.seed", ... as the EXR attributes.
 *
 * Read: the FloatGrid named "density", else the first FloatGrid of the
 * file; the field is the box of its active voxels (values of inactive
 * voxels and tiles inside it as the grid gives them), spacing the voxel
 * size, and nl_meta.origin the box's first voxel in samples when the
 * transform puts it on a whole sample of x and y and at z = 0 (else left
 * empty).  The transform must be a scale-and-translate one (no rotation,
 * shear or perspective, positive scales).  A file that OpenVDB cannot
 * parse, without a FloatGrid, or with an empty one is NL_EINPUT.
 *
 * 1D and 2D fields are refused (a volume is 3D; a 2D field goes to EXR or
 * a 16-bit PNG).  Thread safety: openvdb::initialize() runs once
 * (std::call_once); reads and writes share no state, so they are
 * thread-safe as long as two threads do not write one path.  Built without
 * OpenVDB, the format is registered but off (NL_FORMAT_OFF). */
#include "vdb_internal.h"

const nl_format nl_format_vdb = {
    .name = "openvdb",
    .extensions = ".vdb",
#ifdef NL_HAVE_OPENVDB
    .summary = "OpenVDB volume, FloatGrid \"density\" (Blender, Houdini), voxel size the spacing",
    .read = nl_vdb_read,
    .write = nl_vdb_write,
#else
    .summary = "off: built without OpenVDB (install libopenvdb-dev and rebuild)",
    .flags = NL_FORMAT_OFF,
#endif
    .dims = 1 << 3,
    .types = NL_FORMAT_F32,
    .precision = 32,
    .meta = NL_FORMAT_META_PROVENANCE | NL_FORMAT_META_SPACING | NL_FORMAT_META_ORIGIN,
    .magic = " BDV\0\0\0\0", /* the int64 0x56444220 (OPENVDB_MAGIC), little-endian */
    .magic_len = 8,
};
