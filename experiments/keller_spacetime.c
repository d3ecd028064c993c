/* Keller 2001, section 2: evolving fields over space-time (rho: R^3 or R^4
 * -> R) from one rank-1 lattice.  A 3D Korobov lattice field (x, y, t) and a
 * 4D one (x, y, z, t) of the isotropic Gaussian correlation exp(-(r/L)^2)
 * (variance per wave vector: its closed-form spectrum (sqrt(pi) L)^s
 * exp(-(pi L |k|)^2) on the unit torus), drawn as time slices: each slice is
 * the lattice's trigonometric series on a W x W grid (nl_rank1_grid, one
 * 2D FFT through the wave vectors, the other coordinates fixed).
 *
 * usage: keller_spacetime PREFIX -> the slices PREFIX-S-C.png (S = 3, 4:
 * the lattice's dimension; C = 0..4: t = 0, 0.04, ..., 0.16 of the
 * period), W x W grey pictures of the field over its standard deviation
 * from -2.5 (black) to 2.5 (white), x and y over one period (plots/
 * spacetime.gp puts them together with axes), and on stdout, per
 * lattice, N, the number of slices, the largest difference between a slice
 * and the direct series at 97 pixels each, and between the slices at t = 0
 * and t = 1 (the field is periodic in time), both relative to sum |c_m|
 * (bound 1e-12: the rounding of N-term sums).  Exit 1 when a bound fails,
 * 2 on a library failure. */
#include "../core/field.h"
#include "../core/io.h"
#include "../core/nl_error.h"
#include "../synth/rank1.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { W = 128, COLS = 5 };

static double spectrum(const long *k, int s, void *ctx)
{
    double L = *(const double *)ctx, k2 = 0;
    for (int a = 0; a < s; a++)
        k2 += (double)(k[a] * k[a]);
    return pow(sqrt(M_PI) * L, s) * exp(-M_PI * M_PI * L * L * k2);
}

/* The slices of one lattice; returns 0, 1 (a bound failed) or 2. */
static int row(int s, size_t N, double L, const char *prefix, nl_field *slice)
{
    nl_rank1_lattice lat;
    double *c = malloc(2 * N * sizeof *c), *img = malloc(W * W * sizeof *img), *first = malloc(W * W * sizeof *first),
           var = 0, sum = 0, err = 0, per = 0;
    if (nl_rank1_korobov(N, s, 0, &lat) || nl_rank1_coefficients(&lat, spectrum, &L, 17, c)) {
        fprintf(stderr, "keller_spacetime: %s\n", nl_errmsg());
        return 2;
    }
    for (size_t m = 0; m < N; m++)
        var += c[2 * m] * c[2 * m] + c[2 * m + 1] * c[2 * m + 1], sum += hypot(c[2 * m], c[2 * m + 1]);
    for (int col = 0; col <= COLS; col++) {
        /* the last slice is t = 1: the period, compared with t = 0 */
        double at[2] = {0, col == COLS ? 1 : 0.04 * col}, *fix = s == 3 ? at + 1 : at;
        if (nl_rank1_grid(&lat, c, 1.0, W, fix, img, NULL, NULL, NULL)) {
            fprintf(stderr, "keller_spacetime: %s\n", nl_errmsg());
            return 2;
        }
        if (col == COLS) {
            for (size_t q = 0; q < W * W; q++)
                per = fmax(per, fabs(img[q] - first[q]));
            break;
        }
        if (col == 0)
            memcpy(first, img, W * W * sizeof *img);
        for (size_t q = 0; q < W * W; q += 97) {
            double x[4] = {((double)(q % W) + 0.5) / W, ((double)(q / W) + 0.5) / W, at[0], at[1]}, v;
            if (s == 3)
                x[2] = at[1];
            nl_rank1_eval(&lat, c, 1.0, 1, x, &v, NULL, NULL);
            err = fmax(err, fabs(v - img[q]));
        }
        char path[4096];
        for (size_t q = 0; q < W * W; q++)
            slice->data[q] = img[q] / sqrt(var);
        snprintf(path, sizeof path, "%s-%d-%d.png", prefix, s, col);
        if (nl_png_write_field(path, slice, -2.5, 2.5)) {
            fprintf(stderr, "keller_spacetime: %s\n", nl_errmsg());
            return 2;
        }
    }
    printf("%dD lattice N %zu scale %g: %d slices, slice vs series %.1e, t = 1 vs t = 0 %.1e (of sum |c| = %.3g)\n", s, N,
           L, COLS, err / sum, per / sum, sum);
    nl_rank1_free(&lat), free(c), free(img), free(first);
    return err <= 1e-12 * sum && per <= 1e-12 * sum ? 0 : 1;
}

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: keller_spacetime PREFIX\n");
        return 2;
    }
    size_t n[2] = {W, W};
    int st = 0, r;
    nl_field *slice = nl_field_alloc(2, n, NULL, &st);
    if (!slice)
        return 2;
    if ((r = row(3, 8192, 0.12, argv[1], slice)) > 1 || (st = row(4, 16384, 0.16, argv[1], slice) | r) > 1)
        return 2;
    nl_field_free(slice);
    return st;
}
