/* The registration list of model families: one line each, in the order of
 * `noiselab models` (core/family.h).  NL_FAMILY(id) names the descriptor
 * nl_family_<id> defined in core/families/<id>.c. */
NL_FAMILY(markov)
NL_FAMILY(gauss)
NL_FAMILY(markaussian)
NL_FAMILY(oscillatory)
NL_FAMILY(gauss_osc)
NL_FAMILY(matern)
NL_FAMILY(spherical)
NL_FAMILY(gencauchy)
NL_FAMILY(power)
NL_FAMILY(expr)
NL_FAMILY(spectrum)
NL_FAMILY(image)
