/* Experiment helper: how steep a 2D height field is at its high and at its
 * low heights.
 * usage: height_slope FIELD.exr Q -> "LOW HIGH RATIO"
 * LOW and HIGH are the root mean square lag-1 increments (forward
 * differences along x and y, periodic) taken at the samples whose height is
 * in the lowest, respectively highest, fraction Q of the field (0 < Q <=
 * 0.5), each over the root mean square increment of the whole field;
 * RATIO = HIGH / LOW.  A stationary field gives RATIO near 1; Lewis 1987's
 * y <- y^2.5 ("selectively exaggerating the most prominent features")
 * makes the peaks steeper than the valleys, RATIO well above 1.  Exit
 * status 2 on bad arguments or an unreadable field. */
#include "../core/io.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

int main(int argc, char **argv)
{
    nl_field *f;
    double q = argc == 3 ? strtod(argv[2], NULL) : 0;
    if (argc != 3 || !(q > 0 && q <= 0.5) || nl_field_read(argv[1], &f, NULL) || f->dim != 2) {
        fprintf(stderr, "usage: height_slope FIELD.exr Q (a 2D field, 0 < Q <= 0.5)\n");
        return 2;
    }
    size_t nx = f->n[0], ny = f->n[1], n = f->count;
    double *sorted = malloc(n * sizeof *sorted);
    if (!sorted)
        return 2;
    memcpy(sorted, f->data, n * sizeof *sorted);
    qsort(sorted, n, sizeof *sorted, cmp_double);
    size_t k = (size_t)(q * (double)n);
    double lo = sorted[k > 0 ? k - 1 : 0], hi = sorted[n - 1 - (k > 0 ? k - 1 : 0)];
    double all = 0, low = 0, high = 0;
    size_t nl = 0, nh = 0;
    for (size_t j = 0; j < ny; j++)
        for (size_t i = 0; i < nx; i++) {
            double z = f->data[j * nx + i];
            double dx = f->data[j * nx + (i + 1) % nx] - z, dy = f->data[((j + 1) % ny) * nx + i] - z;
            double s = 0.5 * (dx * dx + dy * dy);
            all += s;
            if (z <= lo)
                low += s, nl++;
            if (z >= hi)
                high += s, nh++;
        }
    double rall = sqrt(all / (double)n), rlow = sqrt(low / (double)nl), rhigh = sqrt(high / (double)nh);
    printf("%.4f %.4f %.4f\n", rlow / rall, rhigh / rall, rhigh / rlow);
    free(sorted);
    return 0;
}
