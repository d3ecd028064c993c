/* Private parts of the model checks, shared by analysis/check*.c. */
#ifndef NL_CHECK_INTERNAL_H
#define NL_CHECK_INTERNAL_H

#include "check.h"
#include "../core/field.h"
#include "../core/taper_internal.h"

/* The checks of a spectral model (power:, spectrum:) from its closed-form
 * density (check_spectral.c); c is zeroed and c->dim set by the caller.
 * Codes as nl_check_model. */
int nl_check_spectral(const nl_model *m, int dim, nl_check *c);

/* The order of mean-square differentiability from the line spectrum's
 * decay f^-b: the largest m with int f^(2m) S1 finite, m < (b - 1)/2, with
 * 0.05 of slack for the fit; -1 (infinitely) for b = INFINITY. */
int nl_check_order(double b);

/* The subdivision singularity along x (check.c): the largest spacing
 * L / 2^k, k <= 24, whose N = 2 matrix of 4 points on the x axis is
 * singular, 0 if none. */
double nl_check_singular_spacing(const nl_model *m, int dim, double L);

/* The d-dimensional spectrum of m on check's periodic grid (4096, 256^2
 * or 64^3 points of spacing h, core/wk.h) into *out (free it with
 * nl_field_free; NULL on failure).  Codes of nl_wk_sample_spectrum. */
int nl_check_grid_spectrum(const nl_model *m, int dim, double h, nl_field **out);

/* |k| (cycles per unit) of the wrapped index i of such a grid. */
double nl_check_grid_k(const nl_field *S, size_t i);


/* The first failed test, from the fields of c (positive_definite is set
 * from it). */
void nl_check_verdict(nl_check *c);

#endif
