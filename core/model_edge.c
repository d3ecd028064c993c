/* Compactly supported isotropic R: the sign of the spectrum at high
 * frequencies from the asymptotics of R at the origin and at the edge of
 * its support.
 *
 * If R(0) - R(r) = c0 r^alpha + (even powers) near 0 (alpha not even) and
 * R(a - s) = c1 s^nu near the edge a, the d-dimensional spectrum at large
 * |k| is (Erdelyi 1956, the Fourier transform of an algebraic endpoint
 * singularity, radially with the Bessel kernel's k^-(d-1)/2 decay)
 *     S(k) ~ A k^-(d + alpha) + B k^-(nu + (d+1)/2) cos(2 pi k a + phase),
 * so when nu + (d+1)/2 < d + alpha the oscillating term wins and S takes
 * negative values, however far out and small: (1-r)_+^nu in d dimensions
 * (alpha = 1) fails exactly below Askey's nu = (d+1)/2 (Zastavnyi 2000),
 * Wendland's psi_{mu,1} (alpha = 3, nu = mu + 1) below mu = (d+3)/2
 * (Zastavnyi 2006), the circular model (nu = 3/2) in 3D.  No sampled
 * spectrum reaches these lobes (1e-12 of the peak at k ~ 240 for
 * (1-r)^1.9 in 3D).  Equality (the spherical model in 3D) decides nothing.
 *
 * alpha: the scaling of E(h) = -10 R(0) + 15 R(h) - 6 R(2h) + R(3h), which
 * annihilates 1, r^2 and r^4 (E ~ h^6 for smooth R: alpha is reported as 6),
 * at h = a/100 and a/200; nu: the log-log slope of R(a - s) over s = a 1e-4
 * .. a 1e-3.  Both must agree to 0.02 across the two scales used, and the
 * verdict takes 0.05 of margin. */
#include "taper_internal.h"

#include <math.h>

static double acf(const nl_model *m, int dim, double t)
{
    double lag[3] = {t, 0, 0};
    return nl_model_acf(m, dim, lag);
}

/* The edge a of the support within [0, L] (0: R is not 0 on [a, 5 L]). */
static double support_edge(const nl_model *m, int dim, double L)
{
    double lo = 0, hi = L;
    for (int i = 0; i <= 64; i++)
        if (acf(m, dim, L * (1 + i / 16.0)) != 0)
            return 0;
    for (int i = 0; i < 80; i++) {
        double mid = 0.5 * (lo + hi);
        if (acf(m, dim, mid) != 0)
            lo = mid;
        else
            hi = mid;
    }
    return hi;
}

static double origin_exponent(const nl_model *m, int dim, double h)
{
    double r0 = acf(m, dim, 0);
    double e1 = -10 * r0 + 15 * acf(m, dim, h) - 6 * acf(m, dim, 2 * h) + acf(m, dim, 3 * h);
    double e2 = -10 * r0 + 15 * acf(m, dim, 2 * h) - 6 * acf(m, dim, 4 * h) + acf(m, dim, 6 * h);
    return log(fabs(e2 / e1)) / M_LN2;
}

static double edge_exponent(const nl_model *m, int dim, double a, double s)
{
    return log(fabs(acf(m, dim, a - 10 * s) / acf(m, dim, a - s))) / M_LN10;
}

int nl_model_edge_invalid(const nl_model *m, int dim, double L)
{
    double nugget = 0, a, al1, al2, nu1, nu2;
    nl_model_param(m, "nugget", &nugget);
    if (nugget != 0 || !((a = support_edge(m, dim, L)) > 0))
        return 0;
    al1 = origin_exponent(m, dim, a / 100), al2 = origin_exponent(m, dim, a / 200);
    nu1 = edge_exponent(m, dim, a, a * 1e-4), nu2 = edge_exponent(m, dim, a, a * 1e-5);
    if (!(fabs(al1 - al2) < 0.02 && fabs(nu1 - nu2) < 0.02))
        return 0;
    return nu2 + (dim + 1) / 2.0 < dim + fmin(al2, 6) - 0.05;
}

/* A power-law tail R ~ -c r^-b (c > 0) with b <= d: int R over R^d
 * diverges to -infinity, so S -> -infinity at k -> 0 (Bochner).  The tail
 * is R at 64 lags from 1e2 L0 to 1e5 L0 (at most 2^20), of one sign, with
 * log |R| linear in log r to 0.05 in the exponent over each half. */
int nl_model_negative_tail(const nl_model *m, int dim, double L0)
{
    double hi = fmin(1e5 * L0, 1048576), lo = hi / 1e3, b[2];
    for (int half = 0; half < 2; half++) {
        double t0 = lo * pow(1e3, half / 2.0), t1 = t0 * sqrt(1e3), r0 = acf(m, dim, t0), r1 = acf(m, dim, t1);
        for (int j = 0; j <= 32; j++)
            if (!(acf(m, dim, t0 * pow(t1 / t0, j / 32.0)) < 0))
                return 0;
        b[half] = log(r0 / r1) / log(t1 / t0);
    }
    return fabs(b[0] - b[1]) < 0.05 && b[1] <= dim;
}
