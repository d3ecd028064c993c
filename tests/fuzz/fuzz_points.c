/* libFuzzer target for the point-table readers (core/io_points.h and
 * core/io_coords.h, which share the header of core/io_points_header.c): the
 * input is written to a temporary file and read by both; what they return
 * must hold their contracts (1 to 3 coordinates, at least one point, every
 * number finite, NULL on failure), else the target traps. */
#include "../../core/io_coords.h"
#include "../../core/io_points.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

static void check_points(const nl_points *p)
{
    if (p->dim < 1 || p->dim > 3 || p->n < 1)
        __builtin_trap();
    for (size_t i = 0; i < p->n; i++) {
        if (!isfinite(p->val[i]))
            __builtin_trap();
        for (int a = 0; a < p->dim; a++)
            if (!isfinite(p->pts[i * (size_t)p->dim + (size_t)a]))
                __builtin_trap();
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static char path[64];
    nl_points *p = (nl_points *)1;
    double *c = (double *)1;
    size_t n = 0;
    int dim = 0;
    setenv("NOISELAB_MEMORY_LIMIT", "536870912", 0);
    if (!path[0])
        snprintf(path, sizeof path, "/tmp/noiselab-fuzz-points-%ld", (long)getpid());
    FILE *fp = fopen(path, "wb");
    if (!fp)
        return 0;
    fwrite(data, 1, size, fp);
    fclose(fp);
    if (nl_points_read(path, &p) == 0) {
        check_points(p);
        nl_points_free(p);
    } else if (p)
        __builtin_trap();
    if (nl_coords_read(path, &dim, &n, &c) == 0) {
        if (dim < 1 || dim > 3 || n < 1)
            __builtin_trap();
        for (size_t i = 0; i < n * (size_t)dim; i++)
            if (!isfinite(c[i]))
                __builtin_trap();
        free(c);
    } else if (c)
        __builtin_trap();
    return 0;
}
