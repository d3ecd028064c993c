/* Midpoint estimation coefficients of generalized stochastic subdivision:
 * Lewis 1987, eqs. (4), (6), (7), (10), (12). */
#include "subdiv.h"
#include "../core/gsl_guard_internal.h"
#include "../core/nl_error.h"
#include "../core/rng.h"
#include "method.h"

#include <float.h>
#include <gsl/gsl_eigen.h>
#include <gsl/gsl_linalg.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *const flag_names[] = {"singular", "pseudo-inverse", "not-positive-definite",
                                         "negative-variance", "diagonal-bias", "nearest-neighbour-reset"};

const char *nl_subdiv_flag_name(unsigned bit) { return bit < 6 ? flag_names[bit] : "?"; }

void nl_subdiv_flag_names(unsigned flags, char *buf, size_t len)
{
    size_t k = 0;
    buf[0] = 0;
    for (unsigned b = 0; b < 6 && k < len; b++)
        if (flags & (1u << b))
            k += (size_t)snprintf(buf + k, len - k, "%s%s", k ? "," : "", nl_subdiv_flag_name(b));
}

const char *nl_subdiv_class_name(int cls)
{
    static const char *const names[] = {"mid", "face", "edge-x", "edge-y"};
    return cls >= 0 && cls < 4 ? names[cls] : "?";
}

/* R at the lags a plan evaluates, remembered: the systems of one plan share
 * most of their lags (every class, level and random neighbourhood repeats
 * the same few hundred), and for power: models each R is a quadrature.
 * Keyed by the exact lag, so a remembered value is the value itself. */
struct memo {
    size_t n, cap;   /* entries, slots (a power of two, or 0: no memory) */
    double *key;     /* 2 per slot */
    double *val;
    unsigned char *used;
};

static void memo_free(struct memo *mm)
{
    free(mm->key), free(mm->val), free(mm->used);
    memset(mm, 0, sizeof *mm);
}

static size_t memo_slot(const struct memo *mm, const double *lag)
{
    uint64_t h[2], x;
    memcpy(h, lag, sizeof h);
    /* the bits of a lag like 3.5 sit at the top: mix them all down
     * (splitmix64's finaliser) */
    x = h[0] ^ (h[1] >> 32 | h[1] << 32);
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9u;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebu;
    return (size_t)(x ^ (x >> 31)) & (mm->cap - 1);
}

/* Doubles the table; on failure the memo is dropped (values are then
 * evaluated each time, as without it). */
static void memo_grow(struct memo *mm)
{
    struct memo big = {0, mm->cap ? 2 * mm->cap : 1024, NULL, NULL, NULL};
    big.key = malloc(2 * big.cap * sizeof *big.key);
    big.val = malloc(big.cap * sizeof *big.val);
    big.used = calloc(big.cap, 1);
    if (!big.key || !big.val || !big.used || big.cap > ((size_t)1 << 22)) {
        memo_free(&big);
        memo_free(mm);
        return;
    }
    for (size_t i = 0; i < mm->cap; i++) {
        size_t j;
        if (!mm->used[i])
            continue;
        for (j = memo_slot(&big, mm->key + 2 * i); big.used[j]; j = (j + 1) & (big.cap - 1))
            ;
        big.used[j] = 1;
        memcpy(big.key + 2 * j, mm->key + 2 * i, 2 * sizeof *big.key);
        big.val[j] = mm->val[i];
        big.n++;
    }
    memo_free(mm);
    *mm = big;
}

static double acf_at(const nl_model *m, int dim, const double *p, const double *q, struct memo *mm)
{
    double lag[3] = {0, 0, 0}, v;
    size_t j = 0;
    for (int a = 0; a < dim; a++)
        lag[a] = p[a] - q[a];
    if (mm && 2 * (mm->n + 1) > mm->cap)
        memo_grow(mm);
    if (mm && mm->cap) {
        for (j = memo_slot(mm, lag); mm->used[j]; j = (j + 1) & (mm->cap - 1))
            if (!memcmp(mm->key + 2 * j, lag, 2 * sizeof *lag))
                return mm->val[j];
    }
    v = nl_model_acf(m, dim, lag);
    if (mm && mm->cap) {
        mm->used[j] = 1;
        memcpy(mm->key + 2 * j, lag, 2 * sizeof *lag);
        mm->val[j] = v;
        mm->n++;
    }
    return v;
}

/* Eigenvalues of the symmetric A (destroyed): min and max |.|. */
static int eig_range(gsl_matrix *A, double *lmin, double *amax, double *amin)
{
    size_t n = A->size1;
    gsl_vector *ev = gsl_vector_alloc(n);
    gsl_eigen_symm_workspace *w = gsl_eigen_symm_alloc(n);
    int st = (!ev || !w) ? GSL_ENOMEM : gsl_eigen_symm(A, ev, w);
    if (!st) {
        *lmin = INFINITY, *amax = 0, *amin = INFINITY;
        for (size_t i = 0; i < n; i++) {
            double l = gsl_vector_get(ev, i);
            *lmin = fmin(*lmin, l);
            *amax = fmax(*amax, fabs(l));
            *amin = fmin(*amin, fabs(l));
        }
    }
    gsl_vector_free(ev);
    gsl_eigen_symm_free(w);
    return st;
}

/* Pseudo-inverse solution through the SVD, dropping singular values below
 * sigma_max / NL_SUBDIV_COND_MAX. */
static int pinv_solve(gsl_matrix *A, const gsl_vector *b, gsl_vector *x)
{
    size_t n = A->size1;
    gsl_matrix *V = gsl_matrix_alloc(n, n);
    gsl_vector *S = gsl_vector_alloc(n), *work = gsl_vector_alloc(n);
    int st = (!V || !S || !work) ? GSL_ENOMEM : gsl_linalg_SV_decomp(A, V, S, work);
    if (!st) {
        double smax = gsl_vector_get(S, 0);
        for (size_t i = 0; i < n; i++)
            if (gsl_vector_get(S, i) < smax / NL_SUBDIV_COND_MAX)
                gsl_vector_set(S, i, 0.0);
        st = gsl_linalg_SV_solve(A, V, S, b, x);
    }
    gsl_matrix_free(V);
    gsl_vector_free(S);
    gsl_vector_free(work);
    return st;
}

/* Every covariance of the system finite (a singularity of the model at a
 * lag of this level would make the coefficients NaN): NL_EINVAL naming
 * the first lag where it is not. */
static int check_finite(const nl_model *m, int dim, size_t n, const double *pts, const double *target,
                        const gsl_matrix *A, const gsl_vector *b)
{
    for (size_t j = 0; j < n; j++)
        for (size_t k = 0; k <= n; k++) {
            const double *q = k < n ? pts + k * dim : target;
            double v = k < n ? gsl_matrix_get(A, j, k) : gsl_vector_get(b, j);
            if (!isfinite(v))
                return NL_ERROR(NL_EINVAL, "%s: the covariance is not finite (%g) at lag (%g, %g), which "
                                "subdivision evaluates", nl_model_spec(m), v, q[0] - pts[j * dim],
                                dim == 2 ? q[1] - pts[j * dim + 1] : 0.0);
        }
    return NL_OK;
}

static int subdiv_solve(const nl_model *m, int dim, size_t n, const double *pts, const double *target,
                        const double *reset, nl_subdiv_class *cls, struct memo *mm)
{
    gsl_matrix *A = gsl_matrix_alloc(n, n), *F = gsl_matrix_alloc(n, n);
    gsl_vector *b = gsl_vector_alloc(n), *x = gsl_vector_alloc(n);
    double lmin = 0, amax = 0, amin = 0, v, r0;
    int st = NL_OK, uniform = 1, e = 0;

    cls->flags = 0;
    cls->n = n;
    if (!A || !F || !b || !x) {
        st = NL_ERROR(NL_ENOMEM, "out of memory for a %zu x %zu system", n, n);
        goto done;
    }
    for (size_t j = 0; j < n; j++) {
        for (size_t k = 0; k < n; k++)
            gsl_matrix_set(A, j, k, acf_at(m, dim, pts + j * dim, pts + k * dim, mm));
        gsl_vector_set(b, j, acf_at(m, dim, target, pts + j * dim, mm));
    }
    if ((st = check_finite(m, dim, n, pts, target, A, b)))
        goto done;
    /* R(0) far from 1 (a variance near DBL_MIN makes the covariances
     * denormal, on which GSL's eigen iteration never converges): solve the
     * system scaled by 2^-e, R(0) 2^-e in [1, 2), exact in binary, and scale
     * the eigenvalue and the variance back.  e = 0 (no scaling) otherwise. */
    r0 = acf_at(m, dim, target, target, mm);
    if (isfinite(r0) && r0 > 0 && (r0 < 0x1p-500 || r0 > 0x1p500)) {
        e = ilogb(r0);
        gsl_matrix_scale(A, ldexp(1.0, -e));
        gsl_vector_scale(b, ldexp(1.0, -e));
    }
    gsl_matrix_memcpy(F, A);
    if ((st = eig_range(F, &lmin, &amax, &amin))) {
        st = NL_ERROR(NL_EFAIL, "the eigenvalues of a %zu x %zu system did not converge: %s", n, n,
                      nl_gsl_reason(st));
        goto done;
    }
    cls->min_eigenvalue = ldexp(lmin, e);
    cls->condition = amin > 0 ? amax / amin : INFINITY;
    if (lmin < -(double)n * DBL_EPSILON * amax)
        cls->flags |= NL_SUBDIV_NOT_PD;
    if (cls->condition > NL_SUBDIV_COND_MAX)
        cls->flags |= NL_SUBDIV_SINGULAR;
    gsl_matrix_memcpy(F, A);
    if (!(cls->flags & (NL_SUBDIV_NOT_PD | NL_SUBDIV_SINGULAR)) && gsl_linalg_cholesky_decomp1(F) == 0) {
        gsl_linalg_cholesky_solve(F, b, x);
    } else {
        gsl_matrix_memcpy(F, A);
        cls->flags |= NL_SUBDIV_PINV;
        if ((st = pinv_solve(F, b, x))) {
            st = NL_ERROR(NL_EFAIL, "the SVD of a %zu x %zu system failed: %s", n, n, nl_gsl_reason(st));
            goto done;
        }
    }
    for (size_t k = 0; k < n; k++) {
        cls->a[k] = gsl_vector_get(x, k);
        if (fabs(cls->a[k] - 1.0 / (double)n) > 1e-3 / (double)n)
            uniform = 0;
    }
    if ((cls->flags & NL_SUBDIV_PINV) && uniform && reset && n > 1) {
        memcpy(cls->a, reset, n * sizeof *cls->a);
        cls->flags |= NL_SUBDIV_NN_RESET;
    }
    /* eq. (7) */
    v = ldexp(r0, -e);
    for (size_t k = 0; k < n; k++)
        v -= cls->a[k] * gsl_vector_get(b, k);
    v = ldexp(v, e);
    cls->raw_variance = v;
    cls->variance = v > 0 ? v : 0.0;
    if (v < 0)
        cls->flags |= NL_SUBDIV_NEG_VAR;
done:
    gsl_matrix_free(A);
    gsl_matrix_free(F);
    gsl_vector_free(b);
    gsl_vector_free(x);
    return st;
}

/* Bracketed for GSL (core/gsl_guard_internal.h): its errors come back as statuses. */
static int solve_guarded(const nl_model *m, int dim, size_t n, const double *pts, const double *target,
                         const double *reset, nl_subdiv_class *cls, struct memo *mm)
{
    int st;
    nl_gsl_enter();
    st = subdiv_solve(m, dim, n, pts, target, reset, cls, mm);
    nl_gsl_leave();
    return st;
}

/* Observation points, target and reset pattern of a class at spacing s. */
static void geometry(int cls, int N, double s, double *pts, double *target, double *reset)
{
    int w = 2 * N;
    if (cls == NL_SUBDIV_MID) {
        for (int i = 0; i < w; i++) {
            pts[i] = (i + 1 - N) * s;
            reset[i] = (i == N - 1 || i == N) ? 0.5 : 0.0;
        }
        target[0] = 0.5 * s;
        return;
    }
    target[0] = (cls == NL_SUBDIV_EDGE_Y ? 0.0 : 0.5) * s;  /* x */
    target[1] = (cls == NL_SUBDIV_EDGE_X ? 0.0 : 0.5) * s;  /* y */
    for (int r = 1 - N; r <= N; r++)
        for (int c = 1 - N; c <= N; c++) {
            int i = (r + N - 1) * w + (c + N - 1);
            int near_r = cls == NL_SUBDIV_EDGE_X ? r == 0 : (r == 0 || r == 1);
            int near_c = cls == NL_SUBDIV_EDGE_Y ? c == 0 : (c == 0 || c == 1);
            pts[2 * i] = c * s;
            pts[2 * i + 1] = r * s;
            reset[i] = near_r && near_c ? (cls == NL_SUBDIV_FACE ? 0.25 : 0.5) : 0.0;
        }
}

static int solve_class(const nl_model *m, int dim, int cls, int N, double s, nl_subdiv_class *out,
                       struct memo *mm)
{
    size_t n = dim == 1 ? (size_t)(2 * N) : (size_t)(4 * N * N);
    double *pts = malloc(n * dim * sizeof *pts), *reset = malloc(n * sizeof *reset), target[2];
    int st;
    out->cls = cls;
    out->a = malloc(n * sizeof *out->a);
    if (!pts || !reset || !out->a) {
        free(pts), free(reset);
        return NL_ERROR(NL_ENOMEM, "out of memory");
    }
    geometry(cls, N, s, pts, target, reset);
    st = solve_guarded(m, dim, n, pts, target, reset, out, mm);
    if (!st && dim == 2) {
        double amax = 0;
        size_t w = (size_t)(2 * N), corner[4] = {0, w - 1, w * (w - 1), w * w - 1};
        for (size_t k = 0; k < n; k++)
            amax = fmax(amax, fabs(out->a[k]));
        for (int k = 0; k < 4 && N > 1; k++)
            if (fabs(out->a[corner[k]]) > NL_SUBDIV_DIAG_BIAS_FRAC * amax)
                out->flags |= NL_SUBDIV_DIAG_BIAS;
    }
    free(pts);
    free(reset);
    return st;
}

static void free_level(nl_subdiv_level *l)
{
    for (int c = 0; c < l->nclass; c++) {
        nl_subdiv_class *cl = &l->cls[c];
        free(cl->a), free(cl->offx), free(cl->offy), free(cl->alt_a), free(cl->alt_var);
        cl->a = cl->alt_a = cl->alt_var = NULL;
        cl->offx = cl->offy = NULL;
        cl->nalt = 0;
    }
    free(l->filt);
    l->filt = NULL;
    l->taps = 0;
}

static int solve_level(const nl_model *m, int dim, int N, double s, nl_subdiv_level *l, struct memo *mm)
{
    static const int classes2[] = {NL_SUBDIV_FACE, NL_SUBDIV_EDGE_X, NL_SUBDIV_EDGE_Y};
    int st = NL_OK;
    l->N = N;
    l->reach = N;
    l->spacing = s;
    l->nclass = dim == 1 ? 1 : 3;
    memset(l->cls, 0, sizeof l->cls);
    l->taps = 0, l->filt = NULL, l->filt_error = 0;
    for (int c = 0; c < l->nclass && !st; c++)
        st = solve_class(m, dim, dim == 1 ? NL_SUBDIV_MID : classes2[c], N, s, &l->cls[c], mm);
    return st;
}

void nl_subdiv_coeffs_free(nl_subdiv_coeffs *c)
{
    if (!c)
        return;
    for (int k = 0; c->level && k < c->levels; k++)
        free_level(&c->level[k]);
    free(c->level);
    free(c);
}

/* Grows N from n0 (solved here into l) by direct solves of every N until
 * the rule stops it (nl_subdiv_coeffs_alloc_rule). */
static int grow_direct(const nl_model *m, int dim, int rule, double tol, double r0, int n0, int nmax, double s,
                       nl_subdiv_level *l, struct memo *mm)
{
    int st = solve_level(m, dim, n0, s, l, mm);
    for (int n = n0 + 1; !st && n <= nmax; n++) {
        nl_subdiv_level next;
        if (rule == NL_SUBDIV_STOP_VARIANCE && l->cls[0].variance < tol * r0)
            break;
        next.level = l->level;
        if ((st = solve_level(m, dim, n, s, &next, mm))) {
            free_level(&next);
            break;
        }
        if (rule == NL_SUBDIV_STOP_IMPROVEMENT && l->cls[0].variance - next.cls[0].variance < tol * r0) {
            free_level(&next);
            break;
        }
        free_level(l);
        *l = next;
    }
    return st;
}

/* 1D auto: Levinson's recursion (synth/subdiv_levinson.c) grows N in O(N)
 * per step and applies the rule; the chosen N is then solved directly (its
 * condition number and flags).  Where the recursion broke down before the
 * rule fired (singular or not positive definite from N + 1 on: var[N] is
 * still NAN), the direct growth takes over from N, pseudo-inverting. */
static int auto_1d(const nl_model *m, int rule, double tol, double r0, int nmax, double s, nl_subdiv_level *l,
                   struct memo *mm)
{
    double *a = malloc((size_t)(2 * nmax) * sizeof *a), var[64];
    int nout = 0, st, done;
    if (!a)
        return NL_ERROR(NL_ENOMEM, "out of memory");
    for (int i = 0; i < 64; i++)
        var[i] = NAN;
    st = nl_subdiv_levinson(m, s, nmax, rule, tol, a, var, &nout);
    free(a);
    if (st)
        return st;
    if (nout < 1)
        return grow_direct(m, 1, rule, tol, r0, 1, nmax, s, l, mm);
    done = nout == nmax || (rule == NL_SUBDIV_STOP_VARIANCE && var[nout - 1] < tol * r0) ||
           (rule == NL_SUBDIV_STOP_IMPROVEMENT && !isnan(var[nout]));
    if (done)
        return solve_level(m, 1, nout, s, l, mm);
    return grow_direct(m, 1, rule, tol, r0, nout, nmax, s, l, mm);
}

static int check_args(int dim, int levels, double spacing0, int N, int rule, double tol, int nmax)
{
    int wmax = dim == 1 ? 64 : NL_SUBDIV_MAX_N;
    if (dim != 1 && dim != 2)
        return NL_ERROR(NL_EINVAL, "subdivision: expected dimension 1 or 2, got %d", dim);
    if (levels < 1 || levels > 40)
        return NL_ERROR(NL_EINVAL, "levels: expected 1 to 40, got %d", levels);
    if (!(spacing0 > 0) || !isfinite(spacing0))
        return NL_ERROR(NL_EINVAL, "spacing0: expected a positive number, got %g", spacing0);
    if (N < 0 || N > wmax || (N == 0 && (nmax < 1 || nmax > wmax)))
        return NL_ERROR(NL_EINVAL, "neighborhood: expected a half-width from 1 to %d, got %d", wmax, N ? N : nmax);
    if (N == 0 && !(tol > 0))
        return NL_ERROR(NL_EINVAL, "tol: expected a positive tolerance, got %g", tol);
    if (rule != NL_SUBDIV_STOP_IMPROVEMENT && rule != NL_SUBDIV_STOP_VARIANCE && rule != NL_SUBDIV_STOP_NONE)
        return NL_ERROR(NL_EINVAL, "stopping rule: expected improvement, variance or none, got %d", rule);
    return NL_OK;
}

int nl_subdiv_coeffs_alloc(const nl_model *m, int dim, int levels, double spacing0, int N, double tol, int nmax,
                        nl_subdiv_coeffs **out)
{
    return nl_subdiv_coeffs_alloc_rule(m, dim, levels, spacing0, N, NL_SUBDIV_STOP_IMPROVEMENT, tol, nmax, out);
}

int nl_subdiv_coeffs_alloc_rule(const nl_model *m, int dim, int levels, double spacing0, int N, int rule, double tol,
                                int nmax, nl_subdiv_coeffs **out)
{
    nl_subdiv_coeffs *c;
    struct memo mm = {0, 0, NULL, NULL, NULL};
    double zero[2] = {0, 0};
    int st;
    *out = NULL;
    if ((st = check_args(dim, levels, spacing0, N, rule, tol, nmax)) || (st = nl_model_check_dim(m, dim)))
        return st;
    if (!nl_model_has_acf(m))
        return NL_ERROR(NL_EINVAL, "%s: subdivision needs R(lag); give the autocorrelation, or a power: model "
                        "(whose R is computed by quadrature)", nl_model_spec(m));
    if (nl_model_nugget(m) != 0) {
        char list[64];
        nl_method_names(NL_METHOD_NUGGET, NULL, ", ", " or ", list, sizeof list);
        return NL_ERROR(NL_EINVAL, "subdiv: %s: a nugget is not represented by subdivision (coarse nodes would keep "
                        "their white noise through every level); use %s", nl_model_spec(m), list);
    }
    c = calloc(1, sizeof *c);
    if (!c || !(c->level = calloc((size_t)levels, sizeof *c->level))) {
        free(c);
        return NL_ERROR(NL_ENOMEM, "out of memory");
    }
    c->dim = dim;
    c->levels = levels;
    c->spacing0 = spacing0;
    c->r0 = nl_model_acf(m, dim, zero);
    if (!(c->r0 > 0)) {
        double r0 = c->r0;
        nl_subdiv_coeffs_free(c);
        return NL_ERROR(NL_EINVAL, "%s: R(0) = %g; expected a positive variance", nl_model_spec(m), r0);
    }
    for (int k = 0; k < levels && !st; k++) {
        double s = ldexp(spacing0, -k);
        nl_subdiv_level *l = &c->level[k];
        l->level = k;
        if (N > 0)
            st = solve_level(m, dim, N, s, l, &mm);
        else if (dim == 1)
            st = auto_1d(m, rule, tol, c->r0, nmax, s, l, &mm);
        else
            st = grow_direct(m, dim, rule, tol, c->r0, 1, nmax, s, l, &mm);
        for (int j = 0; !st && j < l->nclass; j++)
            c->flags |= l->cls[j].flags;
    }
    memo_free(&mm);
    if (st) {
        nl_subdiv_coeffs_free(c);
        return st;
    }
    *out = c;
    return NL_OK;
}

/* One random neighbourhood of n points for class cls, grown from its
 * nearest points; writes offsets (x, y). */
static void random_set(int cls, size_t n, uint64_t seed, uint32_t stream, int *ox, int *oy)
{
    enum { MAXF = 4096 };
    static const int dx[4] = {1, -1, 0, 0}, dy[4] = {0, 0, 1, -1};
    int fx[MAXF], fy[MAXF];
    size_t m = 0, nf = 0;
    uint64_t step = 0;
    /* nearest: face corners (0,0),(1,0),(0,1),(1,1); edge-x (0,0),(1,0); edge-y (0,0),(0,1) */
    ox[m] = 0, oy[m++] = 0;
    if (cls != NL_SUBDIV_EDGE_Y)
        ox[m] = 1, oy[m++] = 0;
    if (cls != NL_SUBDIV_EDGE_X)
        ox[m] = 0, oy[m++] = 1;
    if (cls == NL_SUBDIV_FACE)
        ox[m] = 1, oy[m++] = 1;
    while (m < n) {
        /* the frontier: points 4-adjacent to the set, not in it, each once */
        nf = 0;
        for (size_t p = 0; p < m; p++)
            for (int d = 0; d < 4; d++) {
                int x = ox[p] + dx[d], y = oy[p] + dy[d], dup = 0;
                for (size_t q = 0; q < m && !dup; q++)
                    dup = ox[q] == x && oy[q] == y;
                for (size_t q = 0; q < nf && !dup; q++)
                    dup = fx[q] == x && fy[q] == y;
                if (!dup && nf < MAXF)
                    fx[nf] = x, fy[nf++] = y;
            }
        size_t pick = (size_t)(nl_rng_uniform(seed, stream, step++) * (double)nf);
        ox[m] = fx[pick < nf ? pick : nf - 1], oy[m] = fy[pick < nf ? pick : nf - 1];
        m++;
    }
}

int nl_subdiv_coeffs_randomize(nl_subdiv_coeffs *c, const nl_model *m, int k, uint64_t plan_seed)
{
    struct memo mm = {0, 0, NULL, NULL, NULL};
    if (c->dim != 2)
        return NL_ERROR(NL_EINVAL, "random neighbourhoods: expected a 2D plan");
    if (k < 1 || k > 256)
        return NL_ERROR(NL_EINVAL, "random neighbourhoods: expected 1 to 256 alternatives, got %d", k);
    for (int lv = 0; lv < c->levels; lv++) {
        nl_subdiv_level *l = &c->level[lv];
        for (int j = 0; j < l->nclass; j++) {
            nl_subdiv_class *cl = &l->cls[j], tmp;
            size_t n = cl->n;
            double *pts = malloc(2 * n * sizeof *pts), target[2];
            cl->offx = malloc((size_t)k * n * sizeof *cl->offx);
            cl->offy = malloc((size_t)k * n * sizeof *cl->offy);
            cl->alt_a = malloc((size_t)k * n * sizeof *cl->alt_a);
            cl->alt_var = malloc((size_t)k * sizeof *cl->alt_var);
            if (!pts || !cl->offx || !cl->offy || !cl->alt_a || !cl->alt_var) {
                free(pts);
                memo_free(&mm);
                return NL_ERROR(NL_ENOMEM, "out of memory");
            }
            cl->nalt = k;
            target[0] = (cl->cls == NL_SUBDIV_EDGE_Y ? 0.0 : 0.5) * l->spacing;
            target[1] = (cl->cls == NL_SUBDIV_EDGE_X ? 0.0 : 0.5) * l->spacing;
            for (int a = 0; a < k; a++) {
                int *ox = cl->offx + (size_t)a * n, *oy = cl->offy + (size_t)a * n, st;
                random_set(cl->cls, n, plan_seed, (uint32_t)(lv * 4 + cl->cls) * 256u + (uint32_t)a, ox, oy);
                for (size_t p = 0; p < n; p++)
                    pts[2 * p] = ox[p] * l->spacing, pts[2 * p + 1] = oy[p] * l->spacing;
                tmp.a = cl->alt_a + (size_t)a * n;
                if ((st = solve_guarded(m, 2, n, pts, target, NULL, &tmp, &mm))) {
                    memo_free(&mm);
                    free(pts);
                    return st;
                }
                cl->alt_var[a] = tmp.variance;
                for (size_t p = 0; p < n; p++) {
                    int r = abs(ox[p]) > abs(oy[p]) ? abs(ox[p]) : abs(oy[p]);
                    if (r > l->reach)
                        l->reach = r;
                }
                cl->flags |= tmp.flags & ~NL_SUBDIV_DIAG_BIAS;
                c->flags |= cl->flags;
            }
            cl->flags &= ~NL_SUBDIV_DIAG_BIAS;
            free(pts);
        }
    }
    memo_free(&mm);
    c->flags &= ~NL_SUBDIV_DIAG_BIAS;
    for (int lv = 0; lv < c->levels; lv++)
        for (int j = 0; j < c->level[lv].nclass; j++)
            c->flags |= c->level[lv].cls[j].flags;
    return NL_OK;
}

int nl_subdiv_solve(const nl_model *m, int dim, size_t n, const double *pts, const double *target,
                    const double *reset, nl_subdiv_class *cls)
{
    return solve_guarded(m, dim, n, pts, target, reset, cls, NULL);
}
