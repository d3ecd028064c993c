/* Limits at removable singularities, and a numerical second derivative, by
 * Richardson extrapolation (Neville's tableau on steps h0, h0/2, h0/4, ...;
 * the error estimate and the choice among starting steps after Ridders 1982,
 * Adv. Eng. Software 4(2) 75, as in Numerical Recipes' dfridr).
 *
 * Accuracy, measured in tests/test_expr_funcs.c: sin(r)/r, (1 - cos r)/r^2,
 * r^2/(1 - exp(-r^2)) and x K_1(x) at 0 come out within 1e-12 relative of
 * their limits (1, 1/2, 1, 1): the extrapolation removes the powers of h,
 * and rounding in f(h) (relative 1e-16 / h^2 where f cancels, as in
 * 1 - cos h) is what is left; the best start is the one whose tableau
 * agrees with itself most closely.  A limit that converges like h log h
 * (r log r at 0) is found to about 1e-7 absolute. */
#include "expr_internal.h"

#include <math.h>

enum { STEPS = 8, STARTS = 8 };

/* One tableau on steps h0 2^-k from p0 along d: the extrapolated value
 * with the smallest error estimate into *best, that estimate returned
 * (inf when a value is not finite).  *mag: the largest |f| seen. */
static double tableau(nl_expr_fn f, void *ctx, const double *p0, const double *d, int n, double h0, double *best,
                      double *mag)
{
    double t[STEPS][STEPS], err = INFINITY, p[3];
    for (int k = 0; k < STEPS; k++) {
        double h = ldexp(h0, -k);
        for (int a = 0; a < n; a++)
            p[a] = p0[a] + h * d[a];
        t[k][0] = f(ctx, p);
        if (!isfinite(t[k][0]))
            return INFINITY;
        *mag = fmax(*mag, fabs(t[k][0]));
        for (int j = 1; j <= k; j++) {
            double e;
            t[k][j] = t[k][j - 1] + (t[k][j - 1] - t[k - 1][j - 1]) / (ldexp(1, j) - 1);
            e = fmax(fabs(t[k][j] - t[k][j - 1]), fabs(t[k][j] - t[k - 1][j - 1]));
            if (e < err)
                err = e, *best = t[k][j];
        }
    }
    return err;
}

/* The one-sided limit along d: the best of the starts 10^-s max(1, |p0|). */
static double along(nl_expr_fn f, void *ctx, const double *p0, const double *d, int n, double *err, double *mag)
{
    double size = 1, best = NAN;
    for (int a = 0; a < n; a++)
        size = fmax(size, fabs(p0[a]));
    *err = INFINITY;
    for (int s = 0; s < STARTS; s++) {
        double v = NAN, e = tableau(f, ctx, p0, d, n, size * pow(10, -s), &v, mag);
        if (e < *err)
            *err = e, best = v;
        if (*err <= 1e-15 * fabs(best))
            break;
    }
    return best;
}

double nl_expr_limit(nl_expr_fn f, void *ctx, const double *p0, int n)
{
    /* two directions in 2D and 3D, both ways: a limit that depends on the
     * direction (x^2 / (x^2 + y^2) at 0) or the side (t / |t|) is none */
    static const double dirs[2][3] = {{1, 1, 1}, {1, -0.6, 0.3}};
    double l0 = NAN, mag = 0, errs = 0, vals[4];
    int m = 0;
    for (int i = 0; i < (n > 1 ? 2 : 1); i++)
        for (int sign = -1; sign <= 1; sign += 2) {
            double d[3], norm = 0, err;
            for (int a = 0; a < n; a++)
                norm += dirs[i][a] * dirs[i][a];
            for (int a = 0; a < n; a++)
                d[a] = sign * dirs[i][a] / sqrt(norm);
            vals[m] = along(f, ctx, p0, d, n, &err, &mag);
            if (!isfinite(vals[m]) || !(err <= 1e-7 * fmax(fabs(vals[m]), mag)))
                return NAN;
            errs += err;
            m++;
        }
    l0 = vals[0];
    for (int i = 1; i < m; i++)
        if (!(fabs(vals[i] - l0) <= 1e-7 * fmax(fabs(l0), mag) + 2 * errs))
            return NAN;
    return l0;
}

/* (f(t + h) - 2 f(t) + f(t - h)) / h^2 = f'' + f'''' h^2 / 12 + ...: the
 * tableau in h^2 (factors 4^j). */
double nl_expr_d2(nl_expr_fn f, void *ctx, double t)
{
    double best = NAN, besterr = INFINITY, size = fmax(1, fabs(t)), f0 = f(ctx, &t);
    if (!isfinite(f0))
        return NAN;
    for (int s = 0; s < STARTS; s++) {
        double tab[STEPS][STEPS];
        for (int k = 0; k < STEPS; k++) {
            double h = ldexp(size * pow(10, -s), -k), a = t + h, b = t - h;
            tab[k][0] = (f(ctx, &a) - 2 * f0 + f(ctx, &b)) / (h * h);
            if (!isfinite(tab[k][0]))
                break;
            for (int j = 1; j <= k; j++) {
                double e;
                tab[k][j] = tab[k][j - 1] + (tab[k][j - 1] - tab[k - 1][j - 1]) / (ldexp(1, 2 * j) - 1);
                e = fmax(fabs(tab[k][j] - tab[k][j - 1]), fabs(tab[k][j] - tab[k - 1][j - 1]));
                if (e < besterr)
                    besterr = e, best = tab[k][j];
            }
        }
    }
    return besterr <= 1e-6 * fmax(fabs(best), fabs(f0)) ? best : NAN;
}
