/* The statistics of the bootstrap goodness-of-fit test on one pooled
 * sample (analysis/gof_boot.h; internal, not installed). */
#ifndef NL_GOF_BOOT_INTERNAL_H
#define NL_GOF_BOOT_INTERNAL_H

#include "gof_boot.h"

#include <stddef.h>

/* Scratch for nl_gof_boot_stats on n samples. */
typedef struct {
    size_t n;        /* samples */
    size_t bins;     /* chi-square bins */
    double *sorted;  /* n: u in bucket order */
    size_t *start;   /* n + 1: bucket starts */
    size_t *count;   /* bins: chi-square counts */
} nl_gof_boot_work;

/* Returns NL_OK or NL_ENOMEM; free with nl_gof_boot_work_free. */
int nl_gof_boot_work_alloc(size_t n, size_t bins, nl_gof_boot_work *w);
void nl_gof_boot_work_free(nl_gof_boot_work *w);

/* The statistics of u (in [0, 1]) and x = F^-1(u) (NULL when no moment is
 * wanted) into T[NL_GOF_KS .. NL_GOF_KURTOSIS] (the moments only where
 * want[i]), and F_n(1/2) - 1/2 into *half. */
void nl_gof_boot_stats(const double *u, const double *x, const int *want, nl_gof_boot_work *w, double *T,
                       double *half);

/* The Kolmogorov tail Q_KS(l) = 2 sum_{k>=1} (-1)^(k-1) exp(-2 k^2 l^2)
 * (1 below l = 0.2), shared by analysis/gof.c and the bootstrap. */
double nl_gof_ks_tail(double l);

#endif
