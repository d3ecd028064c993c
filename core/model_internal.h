/* Private layout of nl_model, shared by the files of the model layer and
 * the family descriptors (core/families/). */
#ifndef NL_MODEL_INTERNAL_H
#define NL_MODEL_INTERNAL_H

#include "family.h"
#include "model.h"

struct nl_model {
    const nl_family *fam;             /* which family */
    char *spec;                       /* the spec as given */
    double p[NL_FAMILY_MAX_PARAMS];   /* the family's parameters, by index (fam->params) */
    double var;                       /* p[var] (the sill of the continuous part), 1 when none */
    double scale;                     /* p[scale], 1 when none */
    double nugget;                    /* p[nugget], 0 when none */
    int sep;             /* separable product over axes */
    double angle;        /* ellipsoid rotation about z, radians */
    double cosa, sina;   /* cos and sin of angle, set after parsing */
    double ratio;        /* y length over x length */
    double zratio;       /* z length over x length */
    int aniso_given;     /* sep, angle, ratio or zratio was given */
    struct nl_expr *eval; /* the compiled expression (expr:, spectrum:; core/expr_internal.h) */
    double *table;       /* image: empirical ACF, wrapped lags, tw x th */
    size_t tw, th;       /* image: table size */
    struct nl_model **terms; /* sum or product (fam: nl_family_sum, _product): its terms */
    size_t nterms;           /* terms (0: one structure) */
};

/* The family descriptors of a sum and a product of structures
 * (core/model_sum.c); not in the registry: specs never name them. */
extern const nl_family nl_family_sum;
extern const nl_family nl_family_product;

/* Does spec hold '+' or '*' between structures (core/model.h, "Sums and
 * products")?  NL_OK with *yes set, or NL_EINVAL for parentheses. */
int nl_model_spec_is_composite(const char *spec, int *yes);

/* Parse a sum or product of structures into a new model. */
int nl_model_parse_composite(const char *spec, nl_model **out);

/* R of a sum or product: the terms' R added or multiplied. */
double nl_model_composite_acf(const nl_model *m, int dim, const double *lag);

/* Is w (len bytes) one of the space-separated words of list? (core/family.c) */
int nl_model_word_in(const char *list, const char *w, size_t len);

/* The value of the family's parameter `name` (which it must have). */
double nl_model_p(const nl_model *m, const char *name);

/* Load an exemplar and tabulate its empirical autocorrelation. */
int nl_model_image_load(nl_model *m, const char *path);

/* Bilinear lookup of the image table at lag (dx, dy) in pixels; 0 beyond
 * the half-size of the exemplar. */
double nl_model_image_acf(const nl_model *m, double dx, double dy);

/* R of the power model at distance r by quadrature (model_hankel.c). */
double nl_model_power_acf(const nl_model *m, int dim, double r);

/* "k=v,k=v,sep" into m: the family's keys and the anisotropy keys
 * (model_parse.c; used by argument families after their ';'). */
int nl_model_parse_params(nl_model *m, const char *s);

#endif
