/* Experiment: local orientation of a 2D field from the spectra of windows.
 *
 * usage: local_orient FIELD.exr WINDOW FMIN FMAX
 * Splits the field into WINDOW x WINDOW tiles; for each, the periodogram of
 * the Hann-windowed tile (mean removed) over FMIN <= |f| <= FMAX cycles per
 * sample gives the dominant direction of the wave vector by the doubled
 * angle, phi = arg(sum P(f) e^(2 i atan2(fy, fx))) / 2 (a direction, defined
 * modulo 180 degrees), and the coherence |sum P e^(2 i phi)| / sum P (1: one
 * direction, 0: isotropic).  Prints one TSV row per tile: centre x, centre
 * y (samples), phi in degrees in [0, 180), coherence. */
#include "../core/field.h"
#include "../core/io.h"
#include "../core/nl_error.h"

#include <complex.h>
#include <fftw3.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

int main(int argc, char **argv)
{
    nl_field *f;
    size_t W;
    double fmin, fmax;
    fftw_complex *buf;
    fftw_plan plan;
    if (argc != 5 || sscanf(argv[2], "%zu", &W) != 1 || W < 8 || W > 1024 || sscanf(argv[3], "%lf", &fmin) != 1 ||
        sscanf(argv[4], "%lf", &fmax) != 1 || !(fmin < fmax)) {
        fprintf(stderr, "usage: local_orient FIELD.exr WINDOW FMIN FMAX\n");
        return 2;
    }
    if (nl_exr_read(argv[1], &f, NULL) || f->dim != 2 || f->n[0] < W || f->n[1] < W) {
        fprintf(stderr, "local_orient: %s: expected a 2D field of at least %zu x %zu\n", argv[1], W, W);
        return 1;
    }
    buf = fftw_malloc(W * W * sizeof *buf);
    plan = fftw_plan_dft_2d((int)W, (int)W, buf, buf, FFTW_FORWARD, FFTW_ESTIMATE);
    printf("x\ty\tphi\tcoherence\n");
    for (size_t ty = 0; ty + W <= f->n[1]; ty += W)
        for (size_t tx = 0; tx + W <= f->n[0]; tx += W) {
            double mean = 0, sp = 0;
            double complex z = 0;
            for (size_t j = 0; j < W; j++)
                for (size_t i = 0; i < W; i++)
                    mean += f->data[(ty + j) * f->n[0] + tx + i] / (double)(W * W);
            for (size_t j = 0; j < W; j++)
                for (size_t i = 0; i < W; i++) {
                    double hann = (0.5 - 0.5 * cos(2 * M_PI * (i + 0.5) / W)) *
                                  (0.5 - 0.5 * cos(2 * M_PI * (j + 0.5) / W));
                    buf[j * W + i] = hann * (f->data[(ty + j) * f->n[0] + tx + i] - mean);
                }
            fftw_execute(plan);
            for (size_t j = 0; j < W; j++)
                for (size_t i = 0; i < W; i++) {
                    double fx = (double)(i < W / 2 ? (long)i : (long)i - (long)W) / (double)W;
                    double fy = (double)(j < W / 2 ? (long)j : (long)j - (long)W) / (double)W;
                    double r = hypot(fx, fy), P = creal(buf[j * W + i] * conj(buf[j * W + i]));
                    if (r < fmin || r > fmax)
                        continue;
                    z += P * cexp(2 * I * atan2(fy, fx));
                    sp += P;
                }
            {
                double phi = carg(z) / 2 * 180 / M_PI;
                if (phi < 0)
                    phi += 180;
                printf("%g\t%g\t%.3f\t%.4f\n", tx + W / 2.0, ty + W / 2.0, phi, sp > 0 ? cabs(z) / sp : 0);
            }
        }
    fftw_destroy_plan(plan);
    fftw_free(buf);
    nl_field_free(f);
    return 0;
}
