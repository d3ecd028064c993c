/* The variance per wave vector of a model on a torus of side `extent`,
 * shared by noiselab lattice and noiselab ocean. */
#ifndef NL_CLI_RANK1_SPEC_H
#define NL_CLI_RANK1_SPEC_H

#include "../core/model.h"

typedef struct {
    const nl_model *m;  /* the model */
    int s;              /* dimension */
    double extent;      /* torus side */
} nl_rank1_model_ctx;

/* S(k / extent) / extent^s: the closed-form spectrum of spectral models
 * (s <= 3), or the Hankel transform (eq. 13) of isotropic R. */
double cli_rank1_model_spectrum(const long *k, int s, void *ctx);

/* NL_OK when the model can give a spectrum in s dimensions. */
int cli_rank1_model_check(const nl_model *m, int s);

#endif
