/* Private layout of nl_model, shared by the files of the model layer. */
#ifndef NL_MODEL_INTERNAL_H
#define NL_MODEL_INTERNAL_H

#include "model.h"

struct nl_model {
    nl_model_kind kind;  /* which family */
    char *spec;          /* the spec as given */
    double var;          /* sill of the continuous part for R models; target variance for power */
    double nugget;       /* white-noise variance added at lag 0 exactly (R models) */
    double scale;        /* correlation length */
    double alpha;        /* markaussian exponent */
    double omega;        /* oscillation frequency, radians per unit lag */
    double nu;           /* Matern smoothness */
    double d;            /* power-law spectral exponent */
    double fmin, fmax;   /* power-law band, cycles per unit length */
    int sep;             /* separable product over axes */
    double angle;        /* ellipsoid rotation about z, radians */
    double cosa, sina;   /* cos and sin of angle, set after parsing */
    double ratio;        /* y length over x length */
    double zratio;       /* z length over x length */
    int aniso_given;     /* sep, angle, ratio or zratio was given */
    void *eval;          /* libmatheval evaluator (expr:, spectrum:) */
    double *table;       /* image: empirical ACF, wrapped lags, tw x th */
    size_t tw, th;       /* image: table size */
};

/* Load an exemplar and tabulate its empirical autocorrelation. */
int nl_model_image_load(nl_model *m, const char *path);

/* Bilinear lookup of the image table at lag (dx, dy) in pixels; 0 beyond
 * the half-size of the exemplar. */
double nl_model_image_acf(const nl_model *m, double dx, double dy);

/* R of the power model at distance r by quadrature (model_hankel.c). */
double nl_model_power_acf(const nl_model *m, int dim, double r);

#endif
