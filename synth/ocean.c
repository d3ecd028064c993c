/* Tessendorf's ocean on rank-1 lattices and regular grids. */
#include "ocean.h"
#include "../core/fftw_plan.h"
#include "../core/mem.h"
#include "../core/nl_error.h"
#include "../core/rng.h"

#include <complex.h>
#include <fftw3.h>
#include <math.h>
#include <stdlib.h>

double nl_ocean_phillips(const nl_ocean_params *o, double kx, double ky)
{
    double Kx = 2 * M_PI * kx / o->patch, Ky = 2 * M_PI * ky / o->patch, K2 = Kx * Kx + Ky * Ky;
    double L = o->wind * o->wind / NL_OCEAN_G, l = L / 1000, c;
    if (K2 == 0)
        return 0;
    c = (Kx * cos(o->angle) + Ky * sin(o->angle)) / sqrt(K2);
    return o->amplitude * exp(-1 / (K2 * L * L)) / (K2 * K2) * c * c * exp(-K2 * l * l);
}

static double complex h0(const nl_ocean_params *o, uint64_t seed, uint64_t index, double kx, double ky)
{
    double p = nl_ocean_phillips(o, kx, ky);
    return sqrt(p / 2) * (nl_rng_gauss2(seed, NL_OCEAN_STREAM, index, 0) + I * nl_rng_gauss2(seed, NL_OCEAN_STREAM, index, 1));
}

static double omega(const nl_ocean_params *o, double kx, double ky)
{
    return sqrt(NL_OCEAN_G * 2 * M_PI * hypot(kx, ky) / o->patch);
}

static int check(const nl_ocean_params *o, double t)
{
    if (!(o->wind > 0) || !(o->patch > 0) || !(o->amplitude > 0) || !isfinite(o->wind) || !isfinite(o->patch) ||
        !isfinite(o->amplitude) || !isfinite(o->angle) || !isfinite(t))
        return NL_ERROR(NL_EINVAL, "ocean: expected a positive wind, patch and amplitude and a finite angle and "
                        "time, got %g, %g, %g, %g, %g", o->wind, o->patch, o->amplitude, o->angle, t);
    if (!(fabs(t) <= 1e9))
        return NL_ERROR(NL_EINVAL, "ocean: time: expected |t| <= 1e9 s (the phases keep their precision), got %g", t);
    if (!(fabs(o->angle) <= 1e6))
        return NL_ERROR(NL_EINVAL, "ocean: angle: expected |angle| <= 1e6 radians, got %g", o->angle);
    return NL_OK;
}

/* The spectrum's total over the wave vectors (sum) must be positive and
 * finite: a wind or patch that leaves every wave vector without energy, or
 * an amplitude that overflows, is refused. */
static int check_power(const nl_ocean_params *o, double sum)
{
    if (!isfinite(sum))
        return NL_ERROR(NL_EINVAL, "ocean: amplitude: %g (wind %g m/s, patch %g m) makes the wave heights overflow",
                        o->amplitude, o->wind, o->patch);
    if (!(sum > 0)) {
        double L = o->wind * o->wind / NL_OCEAN_G;
        return NL_ERROR(NL_EINVAL, "ocean: the Phillips spectrum vanishes on every wave vector: wind %g m/s makes "
                        "waves of %g m and suppresses those below %g m, on a patch of %g m", o->wind, L, L / 1000,
                        o->patch);
    }
    return NL_OK;
}

static int check_finite(const nl_ocean_params *o, const double *x, size_t n)
{
    for (size_t i = 0; x && i < n; i++)
        if (!isfinite(x[i]))
            return check_power(o, INFINITY);
    return NL_OK;
}

int nl_ocean_lattice_coefficients(const nl_rank1_lattice *L, const nl_ocean_params *o, uint64_t seed, double t, double *c)
{
    size_t N = L->N;
    if (L->s != 2)
        return NL_ERROR(NL_EINVAL, "ocean: expected a 2D lattice");
    if (check(o, t))
        return NL_EINVAL;
    double sum = 0;
    for (size_t m = 0; m < N; m++) {
        size_t mn = (N - m) % N;
        double kx = (double)L->k[2 * m], ky = (double)L->k[2 * m + 1], w = omega(o, kx, ky);
        /* h0(-k) is the draw of the residue N - m, whose vector is -k_m */
        double complex v = h0(o, seed, m, kx, ky) * cexp(I * w * t) + conj(h0(o, seed, mn, -kx, -ky)) * cexp(-I * w * t);
        if (2 * m == N)
            v = creal(v);  /* k and -k share the residue: keep the real part */
        c[2 * m] = creal(v), c[2 * m + 1] = cimag(v);
        sum += c[2 * m] * c[2 * m] + c[2 * m + 1] * c[2 * m + 1];
    }
    return check_power(o, sum);
}

int nl_ocean_grid(size_t M, const nl_ocean_params *o, uint64_t seed, double t, double *h, double *gx, double *gy)
{
    size_t N = M * M;
    if (M < 2 || M > 65536)
        return NL_ERROR(NL_EINVAL, "ocean: expected a grid of 2 to 65536 samples per side, got %zu", M);
    if (check(o, t))
        return NL_EINVAL;
    fftw_complex *b = nl_alloc(N * sizeof *b), *hk = nl_alloc(N * sizeof *hk);
    fftw_plan p = b ? fftw_plan_dft_2d((int)M, (int)M, b, b, FFTW_BACKWARD, nl_fftw_flags(N)) : NULL;
    if (!p || !hk) {
        nl_free(b), nl_free(hk);
        return NL_ERROR(NL_ENOMEM, "cannot plan a %zu x %zu FFT", M, M);
    }
    double sum = 0;
    for (size_t j = 0; j < M; j++)
        for (size_t i = 0; i < M; i++) {
            long kx = i <= M / 2 ? (long)i : (long)i - (long)M, ky = j <= M / 2 ? (long)j : (long)j - (long)M;
            size_t in = ((M - j) % M) * M + (M - i) % M;
            double w = omega(o, (double)kx, (double)ky);
            double complex v = h0(o, seed, j * M + i, (double)kx, (double)ky) * cexp(I * w * t) +
                               conj(h0(o, seed, in, (double)-kx, (double)-ky)) * cexp(-I * w * t);
            /* the Nyquist row and column have no distinct partner: left out */
            if (2 * i == M || 2 * j == M)
                v = 0;
            hk[j * M + i] = v;
            sum += creal(v) * creal(v) + cimag(v) * cimag(v);
        }
    int st = check_power(o, sum);
    for (int comp = 0; !st && comp < 3; comp++) {
        double *out = comp == 0 ? h : comp == 1 ? gx : gy;
        if (!out)
            continue;
        for (size_t j = 0; j < M; j++)
            for (size_t i = 0; i < M; i++) {
                long kx = i <= M / 2 ? (long)i : (long)i - (long)M, ky = j <= M / 2 ? (long)j : (long)j - (long)M;
                double k = comp == 1 ? (double)kx : comp == 2 ? (double)ky : 0;
                b[j * M + i] = comp == 0 ? hk[j * M + i] : I * 2 * M_PI * k / o->patch * hk[j * M + i];
            }
        fftw_execute(p);
        for (size_t n = 0; n < N; n++)
            out[n] = creal(b[n]);
        st = check_finite(o, out, N);
    }
    fftw_destroy_plan(p), nl_free(b), nl_free(hk);
    return st;
}

int nl_ocean_lattice_frame(const nl_rank1_lattice *L, const nl_ocean_params *o, uint64_t seed, double t, double *h,
                           double *grad)
{
    double *cf = malloc(2 * L->N * sizeof *cf), imag;
    int st;
    if (!cf)
        return NL_ERROR(NL_ENOMEM, "out of memory for %zu coefficients", L->N);
    if (!(st = nl_ocean_lattice_coefficients(L, o, seed, t, cf)))
        st = nl_rank1_synthesize(L, cf, o->patch, h, grad, &imag);
    if (!st && !(st = check_finite(o, h, L->N)))
        st = check_finite(o, grad, 2 * L->N);
    free(cf);
    return st;
}

int nl_ocean_lattice_image(const nl_rank1_lattice *L, const nl_ocean_params *o, uint64_t seed, double t, size_t W,
                           double *h, double *gx, double *gy)
{
    double *cf = malloc(2 * L->N * sizeof *cf);
    int st;
    if (!cf)
        return NL_ERROR(NL_ENOMEM, "out of memory for %zu coefficients", L->N);
    if (!(st = nl_ocean_lattice_coefficients(L, o, seed, t, cf)))
        st = nl_rank1_grid(L, cf, o->patch, W, NULL, h, gx, gy, NULL);
    if (!st && !(st = check_finite(o, h, W * W)) && gx && gy && !(st = check_finite(o, gx, W * W)))
        st = check_finite(o, gy, W * W);
    free(cf);
    return st;
}

void nl_ocean_normals(size_t count, const double *grad, double *nrm)
{
    for (size_t n = 0; n < count; n++) {
        double nn = sqrt(grad[2 * n] * grad[2 * n] + grad[2 * n + 1] * grad[2 * n + 1] + 1);
        nrm[3 * n] = -grad[2 * n] / nn, nrm[3 * n + 1] = -grad[2 * n + 1] / nn, nrm[3 * n + 2] = 1 / nn;
    }
}
