/* Experiment helper: a GIMP pattern (.pat: a big-endian header of header
 * size, version, width, height and bytes per pixel, the magic "GPAT" and a
 * name, then 8-bit pixels) as a grey field in [0, 1] (Rec. 601 luma for
 * RGB), repeated to fill SIZE x SIZE samples (GIMP's patterns tile
 * seamlessly).
 * usage: gimp_pattern IN.pat SIZE OUT.exr */
#include "../core/io.h"
#include "../core/nl_error.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static uint32_t be32(const unsigned char *p) { return (uint32_t)p[0] << 24 | (uint32_t)p[1] << 16 | (uint32_t)p[2] << 8 | p[3]; }

int main(int argc, char **argv)
{
    unsigned char head[24], *px;
    uint32_t hs, w, h, b;
    size_t K, n[2];
    nl_field *out;
    FILE *fp;
    int st;
    if (argc != 4 || (K = strtoul(argv[2], NULL, 10)) < 1 || !(fp = fopen(argv[1], "rb"))) {
        fprintf(stderr, "usage: gimp_pattern IN.pat SIZE OUT.exr\n");
        return 2;
    }
    if (fread(head, 1, 24, fp) != 24 || memcmp(head + 20, "GPAT", 4) != 0) {
        fprintf(stderr, "gimp_pattern: %s: not a GIMP pattern\n", argv[1]);
        return 2;
    }
    hs = be32(head), w = be32(head + 8), h = be32(head + 12), b = be32(head + 16);
    if (hs < 24 || w < 1 || h < 1 || w > 4096 || h > 4096 || b < 1 || b > 4 || fseek(fp, hs, SEEK_SET) != 0 ||
        !(px = malloc((size_t)w * h * b)) || fread(px, b, (size_t)w * h, fp) != (size_t)w * h) {
        fprintf(stderr, "gimp_pattern: %s: bad or truncated pattern\n", argv[1]);
        return 2;
    }
    fclose(fp);
    n[0] = n[1] = K;
    if (!(out = nl_field_alloc(2, n, NULL, &st)))
        return 1;
    for (size_t y = 0; y < n[1]; y++)
        for (size_t x = 0; x < n[0]; x++) {
            const unsigned char *p = px + ((y % h) * w + x % w) * b;
            double v = b >= 3 ? 0.299 * p[0] + 0.587 * p[1] + 0.114 * p[2] : p[0];
            out->data[y * n[0] + x] = v / 255;
        }
    if ((st = nl_exr_write(argv[3], out, NULL))) {
        fprintf(stderr, "gimp_pattern: %s\n", nl_errmsg());
        return 1;
    }
    free(px), nl_field_free(out);
    return 0;
}
