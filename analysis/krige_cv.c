/* k-fold cross-validation of local and universal kriging, as gstat.cv
 * (gstat's R/gstat.cv.R): for each fold id in increasing order, the data of
 * the fold predicted by a plan made on the other data. */
#include "krige_local.h"
#include "../core/rng.h"
#include "krige_local_internal.h"
#include "../core/nl_error.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int cmp_long(const void *a, const void *b)
{
    long x = *(const long *)a, y = *(const long *)b;
    return x < y ? -1 : x > y;
}

/* The data split by fold id: training (not id) and test (id) sets. */
typedef struct {
    double *pts, *val, *cov;   /* training data (ntrain) */
    double *tpts, *tcov;       /* test locations (ntest) */
    double *est, *var;         /* their predictions */
    size_t *idx;               /* test data's indices */
    size_t ntrain, ntest;
} split_t;

static void split_free(split_t *s)
{
    free(s->pts), free(s->val), free(s->cov), free(s->tpts), free(s->tcov), free(s->est), free(s->var), free(s->idx);
}

static int split_alloc(const nl_krige_local *k, split_t *s)
{
    size_t n = k->n, d = (size_t)k->dim, q = k->o.ncov ? k->o.ncov : 1;
    memset(s, 0, sizeof *s);
    s->pts = malloc(n * d * sizeof(double)), s->val = malloc(n * sizeof(double)), s->cov = malloc(n * q * sizeof(double));
    s->tpts = malloc(n * d * sizeof(double)), s->tcov = malloc(n * q * sizeof(double));
    s->est = malloc(n * sizeof(double)), s->var = malloc(n * sizeof(double)), s->idx = malloc(n * sizeof(size_t));
    if (!s->pts || !s->val || !s->cov || !s->tpts || !s->tcov || !s->est || !s->var || !s->idx) {
        split_free(s);
        return NL_ERROR(NL_ENOMEM, "kriging: cross-validation: out of memory for %zu points", n);
    }
    return NL_OK;
}

static void split_fill(const nl_krige_local *k, const long *fold, long id, split_t *s)
{
    size_t d = (size_t)k->dim, q = k->o.ncov;
    s->ntrain = s->ntest = 0;
    for (size_t i = 0; i < k->n; i++) {
        if (fold[i] == id) {
            memcpy(s->tpts + s->ntest * d, k->pts + i * d, d * sizeof(double));
            if (q)
                memcpy(s->tcov + s->ntest * q, k->cov + i * q, q * sizeof(double));
            s->idx[s->ntest++] = i;
        } else {
            memcpy(s->pts + s->ntrain * d, k->pts + i * d, d * sizeof(double));
            if (q)
                memcpy(s->cov + s->ntrain * q, k->cov + i * q, q * sizeof(double));
            s->val[s->ntrain++] = k->val[i];
        }
    }
}

/* Predict the test set of s from its training set. */
static int one_fold(const nl_krige_local *k, long id, split_t *s)
{
    nl_krige_local_options o = k->o;
    nl_krige_local *sub;
    o.cov = k->o.ncov ? s->cov : NULL;
    int st = nl_krige_local_alloc(k->m, k->dim, s->ntrain, s->pts, s->val, &o, &sub);
    if (!st) {
        st = nl_krige_local_eval_at(sub, s->ntest, s->tpts, k->o.ncov ? s->tcov : NULL, s->est, s->var);
        nl_krige_local_free(sub);
    }
    if (st) {
        char why[NL_ERRMSG_MAX];
        snprintf(why, sizeof why, "%s", nl_errmsg());
        return NL_ERROR(st, "kriging: cross-validation, fold %ld (%zu data predicted from the %zu others): %s", id,
                        s->ntest, s->ntrain, why);
    }
    return NL_OK;
}

int nl_krige_local_cv_folds(const nl_krige_local *k, const long *fold, double *pred, double *var,
                            nl_krige_cv_summary *s)
{
    size_t n = k->n, nid = 0;
    long *ids = malloc(n * sizeof *ids);
    split_t sp;
    int st;
    if (!ids)
        return NL_ERROR(NL_ENOMEM, "kriging: cross-validation: out of memory for %zu folds", n);
    memcpy(ids, fold, n * sizeof *ids);
    qsort(ids, n, sizeof *ids, cmp_long);
    for (size_t i = 0; i < n; i++)
        if (!nid || ids[i] != ids[nid - 1])
            ids[nid++] = ids[i];
    if (nid < 2) {
        free(ids);
        return NL_ERROR(NL_EINVAL, "kriging: cross-validation: every datum is in fold %ld; expected 2 folds at least",
                        fold[0]);
    }
    if ((st = split_alloc(k, &sp))) {
        free(ids);
        return st;
    }
    for (size_t f = 0; !st && f < nid; f++) {
        split_fill(k, fold, ids[f], &sp);
        if (!(st = one_fold(k, ids[f], &sp)))
            for (size_t t = 0; t < sp.ntest; t++)
                pred[sp.idx[t]] = sp.est[t], var[sp.idx[t]] = sp.var[t];
    }
    split_free(&sp), free(ids);
    return st ? st : nl_kl_cv_summary(k, pred, var, s);
}

void nl_krige_draw_folds(uint64_t seed, size_t n, size_t K, long *fold)
{
    for (size_t i = 0; i < n; i++) {
        long f = 1 + (long)(nl_rng_uniform(seed, 0, i) * (double)K);
        fold[i] = f > (long)K ? (long)K : f; /* a uniform of 1 - 2^-53 times K may round up to K */
    }
}
