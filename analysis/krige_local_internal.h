/* Internals of local kriging shared by krige_local.c and krige_solve.c. */
#ifndef NL_KRIGE_LOCAL_INTERNAL_H
#define NL_KRIGE_LOCAL_INTERNAL_H

#include "krige.h"
#include "krige_local.h"
#include "../core/spindex.h"

struct nl_krige_local {
    const nl_model *m;        /* covariance (borrowed) */
    int dim;                  /* 1..3 */
    size_t n, p, cap;         /* data, drift terms, neighbours at most */
    nl_krige_local_options o; /* as given */
    double r0;                /* R(0) (+ shift) */
    double shift;             /* intrinsic models: constant added to K = -gamma (analysis/krige.c); 0 */
    double centre[3], scale[3]; /* drift coordinates (x - centre) / scale */
    double *pts, *val;        /* copies of the data */
    double *cov;              /* n * o.ncov covariates (copy), or NULL */
    double *cc, *cs;          /* covariate drift columns (c - cc) / cs (o.ncov each) */
    nl_spindex *index;        /* k-d tree of pts */
    struct nl_gq_node *gq;    /* gstat's search tree (nmax < n), for ties; NULL */
};

/* gstat's neighbour order at ties (analysis/krige_gstat_order.c).  The tree
 * of the data less datum skip (SIZE_MAX: none), NULL when out of memory;
 * the first `want` data in gstat's search order from x (within the radius),
 * their number; the squared distance as gstat computes it. */
typedef struct nl_gq_node nl_gq_node;
nl_gq_node *nl_gq_build(const nl_krige_local *k, size_t skip);
void nl_gq_free(nl_gq_node *root);
size_t nl_gq_select(const nl_krige_local *k, const nl_gq_node *root, const double *x, size_t want, size_t *out);
double nl_gq_d2(int dim, const double *x, const double *p);

/* Per-thread workspace: the cached neighbourhood and its factors. */
typedef struct {
    size_t cap, p;          /* sizes allocated for */
    size_t *next, *set;     /* candidate and cached neighbour sets (cap + 1) */
    double *d2;             /* squared distances (cap + 1) */
    int overflow, valid;    /* too many within the radius; cache valid */
    size_t K;               /* cached set size */
    double *L, *Q, *M;      /* chol(C) K x K, L^-1 X (p rows of K), chol(X' C^-1 X) p x p */
    double *beta, *r;       /* drift coefficients (p), dual weights C^-1 (z - X beta) (K) */
    double *c0, *v, *f, *u, *u2, *y; /* scratch */
    double *C, *Cp;         /* covariances of the cached set and of the one before (K x K, lower) */
    size_t *prev, Kp, *pos; /* the set before (Kp points; 0: none), positions of set in prev */
} nl_kl_work;

int nl_kl_work_init(nl_kl_work *w, size_t cap, size_t p);
void nl_kl_work_free(nl_kl_work *w);
/* The drift terms f (p) at x with covariates c (o.ncov; NULL when none). */
void nl_kl_drift(const nl_krige_local *k, const double *x, const double *c, double *f);
/* Factor the cached set w->set (w->K points); x names the location in messages. */
int nl_kl_factor(const nl_krige_local *k, nl_kl_work *w, const double *x);
/* x = L^-1 b for lower-triangular L (n x n, row-major). */
void nl_kl_lsolve(const double *L, size_t n, const double *b, double *x);
/* "(x, y)" of a location in buf (64 bytes). */
const char *nl_kl_where(const nl_krige_local *k, const double *x, char *buf);
/* The neighbours of x (less datum skip; SIZE_MAX: none) into w->next,
 * ascending; returns their number (w->overflow: too many within the radius). */
size_t nl_kl_neighbours(const nl_krige_local *k, const double *x, size_t skip, nl_kl_work *w);
/* Estimate and variance at x (covariates c) from its neighbourhood without
 * datum skip (SIZE_MAX: none); NaN for both when it has too few data and
 * o.missing is set. */
int nl_kl_point(const nl_krige_local *k, const double *x, const double *c, size_t skip, nl_kl_work *w, double *est,
                double *var);
/* Estimates (and variances, var may be NULL) at nb <= NL_KRIGE_BLOCK
 * locations x that share the factored set of w; C0 (cap x NL_KRIGE_BLOCK)
 * and U (p x NL_KRIGE_BLOCK) are scratch. */
void nl_kl_batch(const nl_krige_local *k, const double *x, const double *c, size_t nb, nl_kl_work *w, double *C0,
                 double *U, double *est, double *var);
/* The summary of cross-validation predictions (NaN ones left out with o.missing). */
int nl_kl_cv_summary(const nl_krige_local *k, const double *pred, const double *var, nl_krige_cv_summary *s);

#endif
