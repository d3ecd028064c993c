/* Internals shared by the kriging flavours (krige_block.c, krige_tg.c,
 * krige_indicator.c): one location's estimate from a neighbourhood plan,
 * for a point or a discretised block. */
#ifndef NL_KRIGE_FLAVOURS_INTERNAL_H
#define NL_KRIGE_FLAVOURS_INTERNAL_H

#include "krige_flavours.h"
#include "krige_local_internal.h"

/* A support: the discretisation of a block (nd points, offsets d, weights
 * w) and its block-to-block covariance cbb; nd = 1 with d = 0, w = 1 and
 * cbb = R(0) is a point. */
typedef struct {
    size_t nd;     /* discretisation points */
    double *d, *w; /* offsets (nd * dim) and weights (nd) */
    double cbb;    /* C(B, B) (+ the plan's shift) */
} nl_kf_support;

/* What one location gives. */
typedef struct {
    double est, var; /* estimate and kriging variance */
    double mu, lag;  /* constant drift only: the GLS mean of the neighbourhood and the Lagrange multiplier m */
} nl_kf_out;

/* The support of b (NULL: a point) for plan k; nl_kf_support_free
 * releases it.  Errors: those of nl_krige_block_discretise; NL_ENOMEM. */
int nl_kf_support_init(const nl_krige_local *k, const nl_krige_block *b, nl_kf_support *s);
void nl_kf_support_free(nl_kf_support *s);

/* count locations x (cv: the data themselves, each left out; x unused), in
 * parallel; out (count) receives each. */
int nl_kf_run(const nl_krige_local *k, const nl_kf_support *s, size_t count, const double *x, int cv, nl_kf_out *out);

#endif
