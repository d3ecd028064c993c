/* Distribution shaping by a memoryless nonlinearity (Lewis GI '86,
 * section 4): y = g(x) = F_y^-1(F_x(x)) maps a field with distribution F_x
 * onto the target distribution F_y.
 *
 * F_x is either the Gaussian CDF with the field's measured mean and
 * standard deviation (default), applied through a lookup table of g over
 * z = (x - mean)/sd in [-NL_SHAPE_ZMAX, NL_SHAPE_ZMAX] with NL_SHAPE_TABLE intervals
 * and linear interpolation (z beyond the range takes the end value), or
 * the field's empirical CDF (the rank (r + 1/2) / N of each sample; ties
 * keep their order), which gives the target histogram exactly whatever the
 * input distribution.  An expr: nonlinearity (core/dist.h) is applied as
 * y = g(z) to the standardised z (the table) or to the Gaussian score
 * Phi^-1((r + 1/2) / N) of the rank. */
#ifndef NL_SYNTH_SHAPE_H
#define NL_SYNTH_SHAPE_H

#ifdef __cplusplus
extern "C" {
#endif

#include "../core/dist.h"
#include "../core/field.h"

#define NL_SHAPE_TABLE 65536
#define NL_SHAPE_ZMAX 8.5

/* Shape f in place (every sample replaced; f->n, f->h unchanged) onto the
 * distribution `to` (core/dist.h), by the Gaussian table or, when
 * `empirical`, by ranks.  Thread-safe for distinct fields.  Returns NL_OK,
 * or NL_EINVAL (fewer than 2 samples; Gaussian mode: a constant field),
 * NL_ENOMEM (f is then unchanged). */
int nl_synth_shape(nl_field *f, const nl_dist *to, int empirical);

#ifdef __cplusplus
}
#endif

#endif
