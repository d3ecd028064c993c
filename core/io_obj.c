/* OBJ meshes of separate triangles, streamed. */
#include "io_obj.h"
#include "nl_error.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>

int nl_obj_write_triangles(const char *path, const char *comment, size_t ntri, nl_obj_triangle tri, const void *ctx)
{
    FILE *fp;
    int bad;
    if (!tri)
        return NL_ERROR(NL_EINVAL, "%s: expected a triangle source", path);
    if (!(fp = fopen(path, "w")))
        return NL_ERROR(NL_EIO, "%s: cannot write: %s", path, strerror(errno));
    if (comment)
        fprintf(fp, "# %s\n", comment);
    for (size_t t = 0; t < ntri; t++) {
        double v[9];
        tri(ctx, t, v);
        for (int k = 0; k < 3; k++)
            fprintf(fp, "v %.8g %.8g %.8g\n", v[3 * k], v[3 * k + 1], v[3 * k + 2]);
    }
    for (size_t t = 0; t < ntri; t++)
        fprintf(fp, "f %zu %zu %zu\n", 3 * t + 1, 3 * t + 2, 3 * t + 3);
    bad = ferror(fp);
    if (fclose(fp) || bad)
        return NL_ERROR(NL_EIO, "%s: write failed", path);
    return NL_OK;
}
