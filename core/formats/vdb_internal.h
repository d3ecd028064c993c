/* OpenVDB volumes: the reader and writer of core/formats/vdb_io.cc, C++
 * behind a C interface, compiled in when the build found OpenVDB (the
 * Makefile defines NL_HAVE_OPENVDB; core/formats/vdb.c registers them).
 * Internal. */
#ifndef NL_VDB_INTERNAL_H
#define NL_VDB_INTERNAL_H

#include "../format.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The readers' and writers' contracts of core/io.h and core/format.h; every
 * C++ exception stops at these functions and becomes a status code. */
int nl_vdb_read(const char *path, const unsigned char *buf, size_t len, const nl_read_options *o, nl_field **out,
                nl_meta *meta);
int nl_vdb_write(const char *path, const nl_field *f, const nl_meta *meta, const nl_write_options *o);

#ifdef __cplusplus
}
#endif

#endif
