/* Levinson's recursion for the 1D midpoint equations of generalized
 * stochastic subdivision (Lewis 1987, eq. (4) and its remark that "the
 * Levinson algorithm would need to be modified for our purposes, since
 * only even neighborhood sizes are used").
 *
 * The 2N observations sit at k = 1-N..N (times s), the target at 1/2:
 *     sum_k a_k R((j - k) s) = R((1/2 - j) s),  j = 1-N..N,       eq. (4)
 * a symmetric Toeplitz system T_n a = y of order n = 2N.  Going from N to
 * N + 1 adds one point at each end.  Toeplitz matrices of one order are the
 * same matrix whichever end grew, so Levinson's forward vector f_n
 * (T_n f_n = e_1; the backward vector is f_n reversed, T symmetric) serves
 * both extensions: with e = sum_j rho(n - j + 1) f_n(j) (rho(m) = R(m s)),
 *     f_{n+1} = ([f_n; 0] - e [0; rev f_n]) / (1 - e^2),
 * and the solution, extended at the end by the position p with the
 * right-hand side y_p, is
 *     a_{n+1} = [a_n; 0] + (y_p - sum_j rho(n - j + 1) a_n(j)) rev f_{n+1},
 * at the front [0; a_n] + (y_p - sum_j rho(j) a_n(j)) f_{n+1}.  Each step
 * costs O(n); the error variance (7), R(0) - sum a_k y_k, comes with every
 * N, so the growth can stop on it (the paper's rule) or on its improvement.
 * Where 1 - e^2 is not positive (not positive definite), or the prediction
 * error power 1 / f_n(1) falls below 1 / NL_SUBDIV_COND_MAX (the direct
 * solve's bound on the condition number: singular), the recursion stops: the caller keeps the direct solve, which
 * flags and pseudo-inverts.  2D: the (2N)^2 block neighbourhoods grow by a
 * ring, which is not a Toeplitz bordering; 2D keeps the direct solve. */
#include "subdiv.h"
#include "../core/nl_error.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* One bordering of order n -> n + 1; f, g hold n + 1 entries. */
static int grow_f(const double *rho, int n, double *f, double *g)
{
    double e = 0, d;
    for (int j = 0; j < n; j++)
        e += rho[n - j] * f[j];
    d = 1 - e * e;
    if (!(d > 0) || !isfinite(d))
        return 0;
    for (int j = 0; j <= n; j++) {
        double fj = j < n ? f[j] : 0, bj = j > 0 ? f[n - j] : 0;  /* [f; 0] and [0; rev f] */
        g[j] = (fj - e * bj) / d;
    }
    /* f[0] = (T^-1)_11 = 1 / (the prediction error power), at most
     * 1 / lambda_min: past NL_SUBDIV_COND_MAX the direct solve would call
     * the system singular (lambda_max >= rho(0) = 1) */
    if (!(g[0] <= NL_SUBDIV_COND_MAX))
        return 0;
    memcpy(f, g, (size_t)(n + 1) * sizeof *f);
    return 1;
}

int nl_subdiv_levinson(const nl_model *m, double s, int nmax, int rule, double tol, double *a, double *var,
                       int *nout)
{
    const int n2 = 2 * nmax;
    double *rho, *y, *f, *g, *x, r0, zero = 0;
    int n = 1, lo = nmax - 1;  /* the current order and the index of its first position */
    *nout = 0;
    if (nmax < 1 || nmax > 64)
        return NL_ERROR(NL_EINVAL, "levinson: expected 1 to 64 half-widths, got %d", nmax);
    r0 = nl_model_acf(m, 1, &zero);
    if (!(r0 > 0) || !isfinite(r0))
        return NL_ERROR(NL_EINVAL, "levinson: R(0) = %g; expected a positive variance", r0);
    rho = malloc((size_t)(n2 + 1) * sizeof *rho), y = malloc((size_t)n2 * sizeof *y);
    f = calloc((size_t)n2 + 1, sizeof *f), g = malloc((size_t)(n2 + 1) * sizeof *g);
    x = calloc((size_t)n2 + 1, sizeof *x);
    if (!rho || !y || !f || !g || !x) {
        free(rho), free(y), free(f), free(g), free(x);
        return NL_ERROR(NL_ENOMEM, "out of memory");
    }
    for (int k = 0; k <= n2; k++) {
        double lag = k * s;
        rho[k] = nl_model_acf(m, 1, &lag) / r0;  /* normalised: rho[0] = 1 */
    }
    /* y[i]: position p = i + 1 - nmax, R((1/2 - p) s) / R(0) */
    for (int i = 0; i < n2; i++) {
        double lag = (0.5 - (i + 1 - nmax)) * s;
        y[i] = nl_model_acf(m, 1, &lag) / r0;
    }
    /* order 1 at position 0 */
    f[0] = 1, x[0] = y[lo];
    for (int N = 1; N <= nmax; N++) {
        double e = 0, v = 1;
        /* extend at the end by position N (index lo + n) */
        for (int j = 0; j < n; j++)
            e += rho[n - j] * x[j];
        if (!grow_f(rho, n, f, g))
            break;
        for (int j = 0; j <= n; j++)
            x[j] += (y[lo + n] - e) * f[n - j];  /* x[n] was 0 */
        n++;
        /* then at the front by 1 - N (N = 1 has its two points already) */
        if (N > 1) {
            e = 0;
            for (int j = 0; j < n; j++)
                e += rho[j + 1] * x[j];
            if (!grow_f(rho, n, f, g))
                break;
            memmove(x + 1, x, (size_t)n * sizeof *x);
            x[0] = 0;
            lo--;
            for (int j = 0; j <= n; j++)
                x[j] += (y[lo] - e) * f[j];
            n++;
        }
        for (int j = 0; j < n; j++)
            v -= x[j] * y[lo + j];
        var[N - 1] = v * r0;
        /* the improvement rule keeps N - 1 (a holds its coefficients) */
        if (rule == NL_SUBDIV_STOP_IMPROVEMENT && N > 1 && var[N - 2] - var[N - 1] < tol * r0)
            break;
        memcpy(a, x, (size_t)n * sizeof *a);
        *nout = N;
        if (rule == NL_SUBDIV_STOP_VARIANCE && var[N - 1] < tol * r0)
            break;
    }
    free(rho), free(y), free(f), free(g), free(x);
    return NL_OK;
}
