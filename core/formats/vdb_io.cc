// OpenVDB reader and writer (core/formats/vdb.c says what is stored): C++
// behind the C functions of vdb_internal.h.  Every exception stops here:
// std::bad_alloc is NL_ENOMEM when writing and NL_ETOOBIG when reading (a
// size the file declares), anything else NL_EIO when writing and NL_EINPUT
// when reading, with OpenVDB's reason in the message.  Without
// NL_HAVE_OPENVDB (the build found no OpenVDB) this file is empty.
#ifdef NL_HAVE_OPENVDB

#include "vdb_internal.h"
#include "../nl_error.h"
#include "../provenance.h"

#include <openvdb/openvdb.h>
#include <openvdb/io/Stream.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <istream>
#include <mutex>
#include <new>
#include <streambuf>
#include <string>

namespace {

namespace vdb = openvdb;

// openvdb::initialize() registers the grid and map types; once per process.
void init_once()
{
    static std::once_flag once;
    std::call_once(once, [] { vdb::initialize(); });
}

// A read-only stream over the file's bytes in memory (no copy).
struct MemBuf : std::streambuf {
    MemBuf(const unsigned char *buf, size_t len)
    {
        char *p = const_cast<char *>(reinterpret_cast<const char *>(buf));
        setg(p, p, p + len);
    }
};

// The origin nl_meta records (X[,Y] in samples), 0 where absent or unreadable.
void meta_origin(const nl_meta *meta, long xy[2])
{
    xy[0] = xy[1] = 0;
    if (meta && meta->origin[0] && std::sscanf(meta->origin, "%ld,%ld", &xy[0], &xy[1]) < 1)
        xy[0] = xy[1] = 0;
}

vdb::FloatGrid::Ptr make_grid(const nl_field *f, const nl_meta *meta)
{
    vdb::FloatGrid::Ptr g = vdb::FloatGrid::create(0.0f);
    g->setName("density");
    g->setGridClass(vdb::GRID_FOG_VOLUME);
    vdb::FloatGrid::Accessor acc = g->getAccessor();
    const size_t nx = f->n[0], ny = f->n[1], nz = f->n[2];
    for (size_t k = 0; k < nz; k++)
        for (size_t j = 0; j < ny; j++)
            for (size_t i = 0; i < nx; i++) // setValueOn: every sample active, a zero too
                acc.setValueOn(vdb::Coord(int(i), int(j), int(k)), float(f->data[(k * ny + j) * nx + i]));
    long xy[2];
    meta_origin(meta, xy);
    vdb::Vec3d h(f->h[0], f->h[1], f->h[2]), t(double(xy[0]) * f->h[0], double(xy[1]) * f->h[1], 0.0);
    vdb::math::MapBase::Ptr map(new vdb::math::ScaleTranslateMap(h, t));
    g->setTransform(vdb::math::Transform::Ptr(new vdb::math::Transform(map)));
    for (int i = 0; meta && nl_meta_key(i); i++)
        if (*nl_meta_value(meta, i))
            g->insertMeta(std::string("noiselab.") + nl_meta_key(i), vdb::StringMetadata(nl_meta_value(meta, i)));
    return g;
}

// The grid to read: FloatGrid "density", else the first FloatGrid.
vdb::FloatGrid::Ptr pick_grid(const vdb::GridPtrVec &grids)
{
    vdb::FloatGrid::Ptr first;
    for (const vdb::GridBase::Ptr &b : grids) {
        vdb::FloatGrid::Ptr g = vdb::gridPtrCast<vdb::FloatGrid>(b);
        if (g && g->getName() == "density")
            return g;
        if (g && !first)
            first = g;
    }
    return first;
}

// The noiselab.* string metadata of g into meta, each checked as the EXR
// attributes are: a string within its capacity, no control character.
int read_meta(const char *path, const vdb::FloatGrid &g, nl_meta *meta)
{
    for (int i = 0; nl_meta_key(i); i++) {
        std::string key = std::string("noiselab.") + nl_meta_key(i);
        vdb::Metadata::ConstPtr m = g[key];
        if (!m)
            continue;
        vdb::StringMetadata::ConstPtr s = vdb::DynamicPtrCast<const vdb::StringMetadata>(m);
        if (!s)
            return NL_ERROR(NL_EINPUT, "%s: metadata %s is a %s; expected a string", path, key.c_str(),
                            m->typeName().c_str());
        const std::string &v = s->value();
        if (v.size() >= nl_meta_capacity(i))
            return NL_ERROR(NL_EINPUT, "%s: metadata %s of %zu bytes; expected at most %zu", path, key.c_str(),
                            v.size(), nl_meta_capacity(i) - 1);
        for (unsigned char c : v)
            if (c < 0x20 || c == 0x7f)
                return NL_ERROR(NL_EINPUT, "%s: metadata %s holds a control character", path, key.c_str());
        std::memcpy(nl_meta_slot(meta, i), v.c_str(), v.size() + 1);
    }
    return NL_OK;
}

// The voxel size and the world position of index (0, 0, 0) of a
// scale-and-translate transform; NL_EINPUT for any other.
int read_transform(const char *path, const vdb::math::Transform &xf, vdb::Vec3d &h, vdb::Vec3d &t)
{
    vdb::math::MapBase::ConstPtr map = xf.baseMap();
    if (!map->isLinear())
        return NL_ERROR(NL_EINPUT, "%s: transform %s; expected a linear scale-and-translate one", path,
                        map->type().c_str());
    vdb::Mat4d m = map->getAffineMap()->getMat4(); // row vectors: world = index * m
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 4; c++)
            if (r != c && m(r, c) != 0)
                return NL_ERROR(NL_EINPUT, "%s: transform rotates or shears the grid; expected a "
                                "scale-and-translate one", path);
    h = vdb::Vec3d(m(0, 0), m(1, 1), m(2, 2));
    t = vdb::Vec3d(m(3, 0), m(3, 1), m(3, 2));
    for (int a = 0; a < 3; a++)
        if (!(h[a] > 0 && std::isfinite(h[a]) && std::isfinite(t[a])))
            return NL_ERROR(NL_EINPUT, "%s: voxel size %g along axis %d; expected a positive finite scale", path,
                            h[a], a);
    return NL_OK;
}

// The field of g's active box, its spacing and origin, into out and meta.
int read_field(const char *path, const vdb::FloatGrid &g, nl_field **out, nl_meta *meta)
{
    vdb::Vec3d h, t;
    int st;
    if ((st = read_transform(path, g.transform(), h, t)))
        return st;
    vdb::CoordBBox box = g.evalActiveVoxelBoundingBox();
    if (box.empty())
        return NL_ERROR(NL_EINPUT, "%s: grid \"%s\" has no active voxel; expected a 3D field", path,
                        g.getName().c_str());
    const vdb::Coord lo = box.min(), dim = box.dim();
    size_t n[3] = {size_t(dim[0]), size_t(dim[1]), size_t(dim[2])};
    double hh[3] = {h[0], h[1], h[2]};
    nl_field *f = nl_field_alloc(3, n, hh, &st);
    if (!f)
        return st;
    vdb::FloatGrid::ConstAccessor acc = g.getConstAccessor();
    for (size_t k = 0; k < n[2]; k++)
        for (size_t j = 0; j < n[1]; j++)
            for (size_t i = 0; i < n[0]; i++)
                f->data[(k * n[1] + j) * n[0] + i] = acc.getValue(lo.offsetBy(int(i), int(j), int(k)));
    if (meta) {
        nl_meta m = nl_meta();
        if ((st = read_meta(path, g, &m))) {
            nl_field_free(f);
            return st;
        }
        // Size and spacing are the grid's; the origin too, where it is a whole sample of x and y at z = 0.
        std::snprintf(m.size, sizeof m.size, "%zux%zux%zu", n[0], n[1], n[2]);
        std::snprintf(m.spacing, sizeof m.spacing, "%.17g,%.17g,%.17g", h[0], h[1], h[2]);
        double x = t[0] / h[0] + lo[0], y = t[1] / h[1] + lo[1], z = t[2] + lo[2] * h[2];
        m.origin[0] = 0;
        if ((x != 0 || y != 0) && x == std::round(x) && y == std::round(y) && z == 0 && std::fabs(x) < 1e15 &&
            std::fabs(y) < 1e15)
            std::snprintf(m.origin, sizeof m.origin, "%.0f,%.0f", x, y);
        *meta = m;
    }
    *out = f;
    return NL_OK;
}

} // namespace

extern "C" int nl_vdb_write(const char *path, const nl_field *f, const nl_meta *meta, const nl_write_options *o)
{
    (void)o;
    if (f->n[0] > INT32_MAX || f->n[1] > INT32_MAX || f->n[2] > INT32_MAX)
        return NL_ERROR(NL_ETOOBIG, "%s: %zu x %zu x %zu samples; OpenVDB indexes at most 2^31 - 1 per axis", path,
                        f->n[0], f->n[1], f->n[2]);
    try {
        init_once();
        vdb::GridPtrVec grids{make_grid(f, meta)};
        vdb::io::File file(path);
        file.write(grids);
        file.close();
    } catch (const std::bad_alloc &) {
        return NL_ERROR(NL_ENOMEM, "%s: out of memory writing the OpenVDB grid", path);
    } catch (const std::exception &e) {
        return NL_ERROR(NL_EIO, "%s: OpenVDB write failed: %s", path, e.what());
    } catch (...) {
        return NL_ERROR(NL_EIO, "%s: OpenVDB write failed", path);
    }
    return NL_OK;
}

extern "C" int nl_vdb_read(const char *path, const unsigned char *buf, size_t len, const nl_read_options *o,
                           nl_field **out, nl_meta *meta)
{
    (void)o;
    *out = NULL;
    try {
        init_once();
        MemBuf mb(buf, len);
        std::istream is(&mb);
        // OpenVDB does not test the stream after each read: a truncated file
        // would be parsed on from zeros, for seconds.  Throw at the first
        // read past the end instead.
        is.exceptions(std::ios::eofbit | std::ios::failbit | std::ios::badbit);
        vdb::io::Stream stream(is, false); // delayLoad false: read here, not through a temporary file
        vdb::GridPtrVecPtr grids = stream.getGrids();
        vdb::FloatGrid::Ptr g = grids ? pick_grid(*grids) : vdb::FloatGrid::Ptr();
        if (!g)
            return NL_ERROR(NL_EINPUT, "%s: no float grid among its %zu grids; expected a FloatGrid (\"density\")",
                            path, grids ? grids->size() : size_t(0));
        return read_field(path, *g, out, meta);
    } catch (const std::ios_base::failure &) {
        return NL_ERROR(NL_EINPUT, "%s: not a readable OpenVDB file: it ends before its grids do (%zu bytes)", path,
                        len);
    } catch (const std::bad_alloc &) { // a size the file declares (a corrupt one, or too large a grid)
        return NL_ERROR(NL_ETOOBIG, "%s: the OpenVDB file declares more than fits in memory", path);
    } catch (const std::exception &e) {
        return NL_ERROR(NL_EINPUT, "%s: not a readable OpenVDB file: %s", path, e.what());
    } catch (...) {
        return NL_ERROR(NL_EINPUT, "%s: not a readable OpenVDB file", path);
    }
}

#endif
