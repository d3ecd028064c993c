/* Wavefront OBJ meshes of separate triangles.
 *
 * The file holds an optional '#' comment line, then 3 * ntri vertex lines
 * "v x y z" (%.8g), then ntri faces "f 3t+1 3t+2 3t+3": every triangle has
 * its own vertices, so a mesh with seams (a periodic one unwrapped
 * triangle by triangle) needs no shared vertex table.  The writer streams:
 * the triangles come one at a time from a callback, so a mesh never has to
 * be held in memory. */
#ifndef NL_IO_OBJ_H
#define NL_IO_OBJ_H

#ifdef __cplusplus
extern "C" {
#endif

#include <stddef.h>

/* Triangle t (0 <= t < ntri) of the mesh ctx: xyz receives x y z of its
 * three vertices (counter-clockwise seen from +z for an upward face). */
typedef void (*nl_obj_triangle)(const void *ctx, size_t t, double xyz[9]);

/* Write ntri triangles from tri(ctx, t) to path (created or truncated);
 * comment (may be NULL) becomes the first line after "# ".
 * Errors: NL_EINVAL for tri NULL; NL_EIO when the file cannot be opened or
 * written.  Thread-safe for distinct paths. */
int nl_obj_write_triangles(const char *path, const char *comment, size_t ntri, nl_obj_triangle tri, const void *ctx);

#ifdef __cplusplus
}
#endif

#endif
