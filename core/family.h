/* Model families: one constant descriptor each, one registration list.
 *
 * A family is what a model spec names before its ':' (markov, matern,
 * power, expr, ...).  Its descriptor says everything the library knows of
 * it: the name and the peers' names it also answers to, the formula, its
 * parameters (name, default or required, valid range, role), the 1D
 * profile R(t), the closed-form spectrum where one exists, the dimensions
 * in which it is positive definite, and what a fit needs (transform and
 * start of each parameter).  Parsing (core/model_parse.c), evaluation
 * (core/model_eval.c), `noiselab models`, `check`, the fitters
 * (analysis/fit_param.c), Python's models() and every message that lists
 * families read the registry: a new family is one file under
 * core/families/ holding its descriptor, plus one line in
 * core/families/list.h.
 *
 * Parameters are held by a model by index, in the order of the
 * descriptor's params[] (which is also the order of the spec's keys in
 * messages and of the catalogue's parameter text: required ones first).
 * The anisotropy keys (sep, angle, ratio, zratio) are the model's, not a
 * family's (core/model.h).
 *
 * Descriptors are constant and live for the program; every function here
 * is thread-safe. */
#ifndef NL_FAMILY_H
#define NL_FAMILY_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct nl_model nl_model;

/* Most parameters of one family. */
#define NL_FAMILY_MAX_PARAMS 8

/* What a parameter is to the model. */
typedef enum {
    NL_ROLE_SHAPE = 0,   /* a shape parameter (alpha, nu, omega, d, ...) */
    NL_ROLE_VARIANCE,    /* var: R(0) of the continuous part, in every dimension (power: the
                            integral of S over its band in dim dimensions) */
    NL_ROLE_SCALE,       /* scale: the correlation length (spherical: the range) */
    NL_ROLE_NUGGET,      /* nugget: white noise at lag 0 */
    NL_ROLE_BAND         /* fmin, fmax: the band of |f| outside which S is 0, lower edge
                            first (nl_model_band, core/model.h) */
} nl_param_role;

/* Valid values of a parameter (checked by nl_model_parse). */
typedef enum {
    NL_RANGE_ANY = 0,    /* any finite number */
    NL_RANGE_POSITIVE,   /* > 0 */
    NL_RANGE_NONNEG,     /* >= 0 */
    NL_RANGE_UPTO        /* 0 < value <= hi */
} nl_param_range;

typedef struct {
    const char *name;        /* as written in a spec */
    nl_param_role role;
    double def;              /* default; NAN when the parameter is required */
    const char *def_text;    /* the default as the catalogue prints it (NULL: %g of def) */
    const char *placeholder; /* required: the catalogue's "alpha=A" letter */
    const char *example;     /* required: a value for the "missing parameter" message */
    nl_param_range range;
    double hi;               /* NL_RANGE_UPTO: the upper end */
    const char *why;         /* NL_RANGE_UPTO: why, e.g. "above 2 the ACF is not positive definite" */
    double start;            /* fit: the start value of a shape parameter (divided by the
                                scale when start_per_scale is set: a frequency); of the
                                scale, the factor on the automatic start (analysis/fit.h) */
    int start_per_scale;
    double fit_lo, fit_hi;   /* fit: the range a fitted shape parameter is held to (a fit that
                                ends at either end is flagged "at bound"); both 0: none */
} nl_family_param;

/* Family flags. */
enum {
    NL_FAMILY_SPECTRAL = 1 << 0,  /* defined by its spectrum S, not by R */
    NL_FAMILY_FIT = 1 << 1,       /* R in closed form of the named parameters: `fit` accepts it */
    NL_FAMILY_EXPRESSION = 1 << 2,/* evaluated by muParser: not reentrant, parse not thread-safe */
    NL_FAMILY_ARGUMENT = 1 << 3,  /* the spec's text after ':' is an argument (an expression, a
                                     file), its key=value pairs after a final ';' */
    NL_FAMILY_FILE = 1 << 4,      /* the argument names a file that parsing the spec reads */
    NL_FAMILY_INTRINSIC = 1 << 5, /* intrinsic: a variogram with no covariance; profile is the
                                     generalized covariance -gamma (core/model.h, Intrinsic models) */
    NL_FAMILY_COMPOSITE = 1 << 6  /* a sum or product of structures (core/model.h); never
                                     registered: nl_model_family of such a model */
};

/* A peer's name for a family with the peer's own parameterisation: gstat's
 * `Sph:psill=0.59,range=897`, GSTools' `Gaussian:len_scale=10`,
 * RandomFields' `RMmatern:nu=1.5,scale=2`.  The spec takes the peer's keys
 * (params[], ranges and defaults as for a family's own parameters) and
 * the anisotropy keys; `convert` turns the peer's values into the
 * family's.  A peer name whose parameters are the family's own is a word
 * of nl_family.aliases instead. */
typedef struct {
    const char *name;              /* as written in a spec, e.g. "Sph" */
    const char *peer;              /* whose name it is: "gstat", "GSTools", "RandomFields" */
    const char *formula;           /* R in the peer's parameters, as the peer documents it */
    size_t nparams;
    const nl_family_param *params; /* the peer's keys: name, default (NAN: required), range */
    /* From the peer's values q[0..nparams-1] to the family's parameters
     * p[] (by index of the family's params[]; p holds the family's
     * defaults). */
    void (*convert)(const double *q, double *p);
} nl_family_alias;

typedef struct nl_family {
    const char *name;          /* as written in a spec */
    const char *aliases;       /* other names a spec may use (the peers'), space separated; "" none */
    const char *argument;      /* NL_FAMILY_ARGUMENT: the catalogue's name for it (EXPR, FILE) */
    const char *usage;         /* NL_FAMILY_ARGUMENT: the catalogue's text for the argument */
    const char *formula;       /* R or S, as `noiselab models` prints it */
    unsigned flags;            /* NL_FAMILY_* */
    int max_dim;               /* not positive definite beyond this dimension, whatever the
                                  parameters (0: no such limit) */
    const char *validity;      /* what is known of its validity by dimension, one sentence */
    size_t nparams;
    const nl_family_param *params;
    /* NL_FAMILY_ARGUMENT: read the argument into m (NL_OK or a status with
     * a message); NULL otherwise. */
    int (*parse_argument)(nl_model *m, const char *arg);
    /* Cross-parameter checks beyond each parameter's range (NULL: none). */
    int (*check)(const nl_model *m);
    /* The 1D profile R1(t) at the signed lag t, continuous part, variance
     * included (NULL for spectral families). */
    double (*profile)(const nl_model *m, double t);
    /* R at a lag vector where the ellipsoid construction of core/model.h
     * does not apply (power: quadrature; image: its table); NULL: generic. */
    double (*acf)(const nl_model *m, int dim, const double *lag);
    /* R of the rotated and stretched lag components (u, v, w), r their
     * norm, where R is not a function of r alone (expressions); NULL:
     * profile(r). */
    double (*acf_stretched)(const nl_model *m, double u, double v, double w, double r);
    /* The closed-form spectrum at f[0..dim-1] (continuous part), NAN where
     * none is known in dim; NULL: none. */
    double (*spectrum)(const nl_model *m, int dim, const double *f);
    /* Is R (or S) a function of |lag| alone when no anisotropy key is
     * given?  NULL: yes. */
    int (*isotropic)(const nl_model *m);
    /* Dimension checks beyond max_dim: NL_OK, NL_ENOTPD where the family
     * is known not to be positive definite in dim with these parameters
     * (e.g. askey with nu < (d+1)/2), NL_EINVAL for other reasons; NULL:
     * none. */
    int (*check_dim)(const nl_model *m, int dim);
    /* d^2 R / dt^2 of the 1D profile at t; NULL: not known (NAN). */
    double (*acf_d2)(const nl_model *m, double t);
    /* The peers' names with their own parameterisations (none: 0, NULL). */
    size_t npeers;
    const nl_family_alias *peers;
} nl_family;

/* The registered families, in registration order (core/families/list.h). */
size_t nl_family_count(void);
const nl_family *nl_family_get(size_t i);

/* The family a spec's name (before ':', len bytes) names, by name or
 * alias; NULL when none. */
const nl_family *nl_family_find(const char *name, size_t len);

/* The peer alias a spec's name (len bytes) names, with its family in
 * *fam; NULL (and *fam untouched) when none. */
const nl_family_alias *nl_family_find_peer(const char *name, size_t len, const nl_family **fam);

/* The index of a parameter of f by name, or -1. */
int nl_family_param_index(const nl_family *f, const char *name);

/* The index of f's first parameter of a role, or -1. */
int nl_family_role_index(const nl_family *f, nl_param_role role);

/* The names of the families that have every flag of `with` and none of
 * `without`, as a list for a message: "a, b, c" with `last` (e.g. " or ")
 * before the last one, argument families written "expr:".  Writes at most
 * size bytes; returns the length the whole list needs. */
size_t nl_family_names(unsigned with, unsigned without, const char *last, char *buf, size_t size);

/* The family of a model. */
const nl_family *nl_model_family(const nl_model *m);

/* Families the library refers to by identity. */
extern const nl_family nl_family_expr;
extern const nl_family nl_family_spectrum;
extern const nl_family nl_family_image;
extern const nl_family nl_family_power;
extern const nl_family nl_family_gauss;

#ifdef __cplusplus
}
#endif

#endif
