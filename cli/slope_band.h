/* A slope fit's band against the band where the field's model has power:
 * a field made from power:d=1 (fmin = 1/1024 by default) holds nothing
 * below fmin but the estimator's leakage and the file's rounding (1e-20
 * and less, where the band holds 1 to 100), and a log-log fit through those ordinates
 * measures them, not the model (a slope of -0.36 for d = 1 over
 * 0.0001:0.4 on 65536 samples). */
#ifndef NL_CLI_SLOPE_BAND_H
#define NL_CLI_SLOPE_BAND_H

/* Exit 2 when F1:F2 of option `opt` (e.g. "--slope") of command cmd
 * reaches outside the radial band of the model spec (nl_model_band in dim
 * dimensions), one line naming the option, the band, the model's fmin or
 * fmax and what was expected.  An empty spec (no recorded model), one
 * that reads a file (image:) or that does not parse: no check, as for a
 * field without provenance. */
void cli_slope_band_check(const char *cmd, const char *opt, double f1, double f2, const char *spec, int dim);

#endif
