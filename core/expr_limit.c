/* Limits at removable singularities, and a numerical second derivative, by
 * Richardson extrapolation (Neville's tableau on steps h0, h0/2, h0/4, ...;
 * the error estimate and the choice among starting steps after Ridders 1982,
 * Adv. Eng. Software 4(2) 75, as in Numerical Recipes' dfridr).
 *
 * Accuracy, measured (tests/test_expr_limit.c asserts 1e-10): at 0,
 * sin(r)/r is 1 to 2e-16, (1 - cos r)/r^2 is 1/2 to 5e-12, r^2/(1 -
 * exp(-r^2)) 1 to 6e-12, r K_1(r) 1 to 5e-12 relative: the extrapolation
 * removes the powers of h, and what is left is the rounding of f near the
 * point (relative 1e-16 / h^2 where f cancels, as 1 - cos h does), which
 * is why the tableau starts at the largest step where f already behaves
 * as a power series.  R'' of smooth profiles comes out within 1e-11
 * (exp(-t^2), sin(t)/t, 1/(1 + t^2)); 1e-9 where f cancels.  A limit
 * approached like h log h (r log r at 0) does not converge to 1e-8 and is
 * reported as none (NAN); so is one that underflows to a tableau of zeros.
 * Cost: about 40 us for sin(r)/r at 0 in 2D, 300 us for r K_1(r)
 * (evaluated only where the expression is not finite). */
#include "expr_internal.h"

#include <float.h>
#include <math.h>

enum { STEPS = 10, STARTS = 9 }; /* steps per tableau; decades 10^-s, s < STARTS */

/* y(h) for h -> 0 */
typedef struct {
    nl_expr_fn f;        /* the function */
    void *ctx;           /* its context */
    const double *p0;    /* the point */
    const double *d;     /* limit: the direction */
    int n;               /* dimension of the point */
    double f0;           /* d2: f(t) */
    int d2;              /* 1: the second difference quotient, 0: f(p0 + h d) */
} seq;

static double y_of(const seq *s, double h)
{
    double p[3] = {0, 0, 0}; /* coordinates past n are 0 */
    if (s->d2) {
        double a = s->p0[0] + h, b = s->p0[0] - h, num = s->f(s->ctx, &a) - 2 * s->f0 + s->f(s->ctx, &b);
        /* a difference at the rounding level of f says nothing */
        return fabs(num) > 64 * DBL_EPSILON * fabs(s->f0) ? num / (h * h) : NAN;
    }
    for (int a = 0; a < s->n; a++)
        p[a] = s->p0[a] + h * s->d[a];
    return s->f(s->ctx, p);
}

/* Neville's tableau on h0 2^-k, the j-th column removing h^j (q = 2) or
 * h^2j (q = 4), after Ridders: the entry whose differences from its
 * neighbours (left, upper left, and below, so that one chance agreement
 * of a function that is not monotone, 0.25 log 0.25 = 0.5 log 0.5, is not
 * taken for convergence) are smallest.  Its error estimate into *err (inf:
 * none), the largest |y| of the tableau into *mag. */
static double ridders(const seq *s, double h0, double q, double *err, double *mag)
{
    double t[STEPS][STEPS], best = NAN, noise[STEPS];
    int rows = 0;
    *err = INFINITY, *mag = 0;
    for (int k = 0; k < STEPS; k++, rows++) {
        double fac = q, h = ldexp(h0, -k);
        /* d2: the rounding of f(t), about 8 eps |f(t)| / h^2 in y, which
         * the tableau's differences may miss */
        noise[k] = s->d2 ? 8 * DBL_EPSILON * fabs(s->f0) / (h * h) : 0;
        t[k][0] = y_of(s, h);
        if (!isfinite(t[k][0]))
            break;
        *mag = fmax(*mag, fabs(t[k][0]));
        for (int j = 1; j <= k; j++, fac *= q)
            t[k][j] = t[k][j - 1] + (t[k][j - 1] - t[k - 1][j - 1]) / (fac - 1);
    }
    for (int k = 1; k + 1 < rows; k++)
        for (int j = 1; j <= k; j++) {
            double e = fmax(fmax(fabs(t[k][j] - t[k][j - 1]), fabs(t[k][j] - t[k - 1][j - 1])),
                            fabs(t[k + 1][j] - t[k][j])) + noise[k + 1];
            if (e < *err)
                *err = e, best = t[k][j];
        }
    return best;
}

/* The tableaux from h0 = 10^-k size, k = start, start + 1, ...: the first
 * that converges to 1e-10 of its size (the largest steps: least rounding),
 * else the one of smallest error (x K_1(x) at 0 has h^2 log h terms that
 * only small steps tame). */
static double from_start(const seq *s, double q, double size, int start, double *err, double *mag)
{
    double best = NAN;
    for (int k = start; k < STARTS; k++) {
        double e, m, v = ridders(s, size * pow(10, -k), q, &e, &m);
        if (e < *err)
            *err = e, *mag = m, best = v;
        if (*err <= 1e-10 * fmax(fabs(best), *mag))
            break;
    }
    return best;
}

/* The step to start the tableaux from: y at the decades h = 10^-s
 * max(1, |p0|), s = first, first + 1, ..., and the first s from which the
 * changes between decades shrink at least fourfold twice in a row: below
 * it y behaves as a power series in h (sin(1000 r)/(1000 r) starts at
 * 1e-3; a profile that underflows to 0 at the larger steps, or grows as
 * 1/r, never qualifies there).  The tableau there: its estimate, its
 * error into *err and its magnitude into *mag; NAN when no decade
 * qualifies, unless y is the same at every decade (then that value). */
static double best_start(const seq *s, double q, int first, double *err, double *mag)
{
    double size = 1, v[STARTS + 3], same = 1;
    int n = 0;
    for (int a = 0; a < s->n; a++)
        size = fmax(size, fabs(s->p0[a]));
    *err = INFINITY, *mag = 0;
    for (int k = first; k < STARTS && n < STARTS + 3; k++) {
        v[n] = y_of(s, size * pow(10, -k));
        same = same && (n == 0 || v[n] == v[0]) && isfinite(v[n]);
        n++;
        if (n >= 4) {
            int i = n - 4;
            double d0 = fabs(v[i] - v[i + 1]), d1 = fabs(v[i + 1] - v[i + 2]), d2 = fabs(v[i + 2] - v[i + 3]);
            if (isfinite(v[i]) && isfinite(v[i + 1]) && isfinite(v[i + 2]) && isfinite(v[i + 3]) && d0 > 0 &&
                d1 <= d0 / 4 && d2 <= d1 / 4)
                return from_start(s, q, size, first + i, err, mag);
        }
    }
    if (same && n) {
        *err = 0, *mag = fabs(v[0]);
        return v[0];
    }
    return NAN;
}

double nl_expr_limit(nl_expr_fn f, void *ctx, const double *p0, int n)
{
    /* two directions in 2D and 3D, both ways: a limit that depends on the
     * direction (x^2 / (x^2 + y^2) at 0) or the side (t / |t|) is none */
    static const double dirs[2][3] = {{1, 1, 1}, {1, -0.6, 0.3}};
    double l0 = NAN, scale = 0, errs = 0;
    for (int i = 0; i < (n > 1 ? 2 : 1); i++)
        for (int sign = -1; sign <= 1; sign += 2) {
            double d[3], norm = 0, err, mag, v;
            seq s = {f, ctx, p0, d, n, 0, 0};
            for (int a = 0; a < n; a++)
                norm += dirs[i][a] * dirs[i][a];
            for (int a = 0; a < n; a++)
                d[a] = sign * dirs[i][a] / sqrt(norm);
            v = best_start(&s, 2, 0, &err, &mag);
            /* converged: the tableau agrees with itself to 1e-8 of its size
             * (1/r's does not: its values double at each step) */
            if (!isfinite(v) || !(err <= 1e-8 * fmax(fabs(v), mag)))
                return NAN;
            if (isnan(l0))
                l0 = v;
            scale = fmax(scale, mag), errs += err;
            if (!(fabs(v - l0) <= 1e-8 * scale + 2 * errs))
                return NAN;
        }
    return l0;
}

/* (f(t + h) - 2 f(t) + f(t - h)) / h^2 = f''(t) + f''''(t) h^2 / 12 + ...:
 * the tableau in h^2. */
double nl_expr_d2(nl_expr_fn f, void *ctx, double t)
{
    double err, mag, v;
    seq s = {f, ctx, &t, NULL, 1, f(ctx, &t), 1};
    if (!isfinite(s.f0))
        return NAN;
    /* steps up to 1000 max(1, |t|): a wide profile such as exp(-(t/1000)^2)
     * has no usable difference at steps below 1 (its R'' is 2e-6) */
    v = best_start(&s, 4, -3, &err, &mag);
    return err <= 1e-6 * fmax(fabs(v), fabs(s.f0)) ? v : NAN;
}
