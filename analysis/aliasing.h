/* Aliasing across subdivision levels (Lewis 1987, "Aliasing").
 *
 * Subdivision keeps old samples, so the field at level L-1 is the field at
 * level L decimated without a low-pass filter.  The half-resolution field a
 * viewer should see is the low-passed one: frequencies above half the
 * Nyquist rate (|f_a| > 1 / (4 h_a) on any axis) removed, then every other
 * sample kept.  Their difference is the high band folded down; its energy
 * relative to the variance of the field is
 *     measured  A = sum (x[2i] - lowpass(x)[2i])^2 / sum (x[2i] - mean)^2,
 *     predicted A = (spectrum mass above half Nyquist) / (total mass),
 * the prediction from the target's spectrum on the field's grid.
 * Flag: A > NL_ALIAS_MAX, a tenth of the variance changing between levels
 * (Lewis's Fig. 2, levels 3 to 4 of an oscillatory noise, is far above;
 * monotone spectra at fine levels are far below). */
#ifndef NL_ALIASING_H
#define NL_ALIASING_H

#ifdef __cplusplus
extern "C" {
#endif

#include "../core/field.h"
#include "../core/model.h"

#define NL_ALIAS_MAX 0.1

/* Measured A (dimensionless, >= 0; 0 for a constant field) of a 1D or 2D
 * field with even sizes (periodic).  NL_EINVAL: 3D, or an odd size;
 * NL_ENOMEM.  Plans FFTW: not thread-safe (core/fftw_plan.h). */
int nl_aliasing_measure(const nl_field *f, double *A);

/* Predicted A in [0, 1] for model m on the grid of f (its n and h; the
 * data are not read), negative spectrum values counted as 0.  Errors: those
 * of nl_wk_sample_spectrum (core/wk.h): NL_EINVAL for a model that is not
 * finite on the grid or cannot be evaluated in f's dimension, NL_ENOMEM;
 * not thread-safe (it plans FFTW). */
int nl_aliasing_predict(const nl_model *m, const nl_field *f, double *A);

#ifdef __cplusplus
}
#endif

#endif
