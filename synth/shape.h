/* Distribution shaping by a memoryless nonlinearity (Lewis GI '86,
 * section 4): y = g(x) = F_y^-1(F_x(x)) maps a field with distribution F_x
 * onto the target distribution F_y.
 *
 * F_x is either the Gaussian CDF with the field's measured mean and
 * standard deviation (default), applied through a lookup table of g over
 * z = (x - mean)/sd in [-SHAPE_ZMAX, SHAPE_ZMAX] with SHAPE_TABLE intervals
 * and linear interpolation (z beyond the range takes the end value), or
 * the field's empirical CDF (the rank (r + 1/2) / N of each sample; ties
 * keep their order), which gives the target histogram exactly whatever the
 * input distribution. */
#ifndef SYNTH_SHAPE_H
#define SYNTH_SHAPE_H

#include "../core/dist.h"
#include "../core/field.h"

#define SHAPE_TABLE 65536
#define SHAPE_ZMAX 8.5

/* Shape f in place. */
int synth_shape(nl_field *f, const nl_dist *to, int empirical);

#endif
