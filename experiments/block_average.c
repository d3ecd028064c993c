/* Experiment helper: average an image down by KxK blocks (Lewis 1987 Fig. 5
 * seeds subdivision with an image "averaged down to 32^2 pixels").
 * usage: block_average IN K OUT.exr */
#include "../core/io.h"
#include "../core/nl_error.h"

#include <stdio.h>
#include <stdlib.h>

int main(int argc, char **argv)
{
    nl_field *in, *out;
    size_t K, n[2];
    int st;
    if (argc != 4 || (K = strtoul(argv[2], NULL, 10)) < 1) {
        fprintf(stderr, "usage: block_average IN K OUT.exr\n");
        return 2;
    }
    if ((st = nl_field_read(argv[1], &in, NULL)) || in->dim != 2) {
        fprintf(stderr, "block_average: %s\n", st ? nl_errmsg() : "expected a 2D image");
        return 2;
    }
    n[0] = in->n[0] / K, n[1] = in->n[1] / K;
    out = nl_field_alloc(2, n, NULL, &st);
    if (!out)
        return 1;
    for (size_t y = 0; y < n[1] * K; y++)
        for (size_t x = 0; x < n[0] * K; x++)
            out->data[(y / K) * n[0] + x / K] += in->data[y * in->n[0] + x] / (double)(K * K);
    if ((st = nl_exr_write(argv[3], out, NULL))) {
        fprintf(stderr, "block_average: %s\n", nl_errmsg());
        return 1;
    }
    nl_field_free(in), nl_field_free(out);
    return 0;
}
