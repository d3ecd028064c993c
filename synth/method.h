/* Synthesis methods as descriptors: one registry lists every method, each
 * a constant nl_method_type saying what it is and can do (dimensions,
 * whether it needs a model, periodic or windowed, distributed, conditionable,
 * exact), which options it takes (an option table) and how to plan, execute
 * and describe it, with one signature for every method.  Everything that
 * lists, parses, checks or exposes methods (noiselab synth, validate, the
 * distributed runs, conditioning, Python) iterates the registry
 * (nl_method_count, nl_method_at, nl_method_find) and tests capabilities.
 *
 * A method is one descriptor in synth/method_<name>.c plus one line in
 * synth/method_registry.c; the descriptors call the per-method plans
 * (synth/fft.h, subdiv.h, ...), so fields are bit for bit those of the
 * per-method functions.
 *
 * Options travel in one generic object, nl_method_options: a typed value
 * for each row of the method's option table.  An option's name is its
 * command-line name (--name), its Python keyword (with '_' for '-') and its
 * key in the method string describe writes (the provenance noiselab.method,
 * "name:key=value,...|key=value", read back by synth --from).
 *
 * Thread safety: the registry and the descriptors are constant; plans follow
 * the per-method plans' rules (the executes only read the plan, except
 * cholesky's, whose plan holds its workspace: one thread at a time per
 * plan; sparse with a kernel expression evaluates it per call with
 * muParser, whose expressions are not reentrant). */
#ifndef NL_SYNTH_METHOD_H
#define NL_SYNTH_METHOD_H

#include "../core/field.h"
#include "../core/model.h"

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Capabilities (nl_method_type.caps). */
enum {
    NL_METHOD_MODEL = 1u << 0,         /* needs a model (--acf, --spectrum) unless a model-replacing option is given */
    NL_METHOD_NO_MODEL = 1u << 1,      /* takes no model at all */
    NL_METHOD_PERIODIC = 1u << 2,      /* the field is periodic (by default) */
    NL_METHOD_WINDOW = 1u << 3,        /* can make a window of an infinite field at an origin */
    NL_METHOD_DISTRIBUTED = 1u << 4,   /* runs distributed (slabs; fft/circulant through mpi/fft.h) */
    NL_METHOD_CONDITIONABLE = 1u << 5, /* conditional simulation (synth --condition) */
    NL_METHOD_EXACT = 1u << 6,         /* the covariance is exactly the model's on the grid */
    NL_METHOD_CLAMP = 1u << 7,         /* honours NL_METHOD_OPT_CLAMP (a model not positive definite) */
    NL_METHOD_SERIAL = 1u << 8,        /* one execute at a time per plan (the plan holds its workspace) */
    NL_METHOD_TORUS = 1u << 9,         /* distributed: white noise filtered on the periodic grid by FFTW-MPI */
    NL_METHOD_EMBEDDING = 1u << 10,    /* distributed: the same on a circulant embedding of the grid */
    NL_METHOD_VALIDATED = 1u << 11,    /* run by validate (analysis/validate.h), also once per other choice
                                          of each CHOICE option */
    NL_METHOD_SUBDIVISION = 1u << 12,  /* the plan is an nl_subdiv_plan (nl_method_plan_impl): its exact
                                          expected ACF is known (analysis/subdiv_exact.h) */
    NL_METHOD_NUGGET = 1u << 13,       /* represents a model's nugget (white noise added at lag 0) */
    NL_METHOD_INTRINSIC = 1u << 14     /* simulates intrinsic models (core/model.h); the others are refused
                                          by nl_method_plan_alloc */
};

/* nl_method_names: list the exact methods first, each group in the
 * registry's order (the order validate runs them). */
#define NL_METHOD_EXACT_FIRST (1u << 30)

/* Option types. */
typedef enum {
    NL_METHOD_INT,    /* integer in min..max; `words` may name 0 ("auto") */
    NL_METHOD_DOUBLE, /* finite number in min..max (open bounds: NL_METHOD_OPEN); `words` lists
                         optional prefixes "a:|b:", the index given in i */
    NL_METHOD_CHOICE, /* one of `words` ("a|b"), its index in i */
    NL_METHOD_FLAG,   /* given or not (i = 1) */
    NL_METHOD_STRING  /* text (an expression or a file name) */
} nl_method_opt_type;

/* Option row flags (a method's messages about its model: model_conflict
 * when a model is given to a NL_METHOD_NO_MODEL method or with a
 * model-replacing option; model_missing when a model is needed and none,
 * or two, are given). */
enum {
    NL_METHOD_OPEN = 1u << 0,         /* DOUBLE: min and max excluded */
    NL_METHOD_REPLACES_MODEL = 1u << 1, /* given, it stands in for the model (midpoint H, sparse kernel) */
    NL_METHOD_FILE = 1u << 2,         /* STRING: a field's file name (value.field may hold it read) */
    NL_METHOD_SUFFIX = 1u << 3,       /* recorded after '|' (its value may hold commas) */
    NL_METHOD_MAKES_WINDOW = 1u << 4, /* FLAG: given, the field is a window at the grid's origin */
    NL_METHOD_NO_WINDOW = 1u << 5,    /* FLAG: given, the field is periodic and has no origin */
    NL_METHOD_EXPRESSION = 1u << 6    /* STRING: an expression evaluated per execute by muParser (not
                                         thread-safe: calls of such plans must be serialised) */
};

/* One row of an option table. */
typedef struct {
    const char *name;          /* --name, Python name (with '_'), provenance key */
    nl_method_opt_type type;   /* how its value is read */
    unsigned flags;            /* NL_METHOD_OPEN, _REPLACES_MODEL, _FILE, _SUFFIX, _MAKES_WINDOW, _NO_WINDOW */
    double min, max;           /* INT, DOUBLE: the valid range */
    const char *words;         /* CHOICE: "a|b" (the first the default); INT: the word for 0; DOUBLE: prefixes */
    const char *expect;        /* DOUBLE, CHOICE: what a bad value's message says was expected */
    const char *def;           /* the default as text, or NULL: unset */
    const char *help;          /* one line */
} nl_method_option;

/* The most options a method may have. */
#define NL_METHOD_MAX_OPTIONS 12

/* A value of one option. */
typedef struct {
    int set;                   /* 0 unset, 1 the row's default, 2 given */
    long i;                    /* INT, FLAG (1), CHOICE (index), DOUBLE (prefix index, -1: none) */
    double d;                  /* DOUBLE */
    const char *s;             /* STRING: not copied, the caller keeps it alive */
    const nl_field *field;     /* STRING with NL_METHOD_FILE: the field already read, or NULL (read s) */
} nl_method_value;

typedef struct nl_method_type nl_method_type;

/* The options of one method: a value per row of its table. */
typedef struct {
    const nl_method_type *type;           /* the method */
    unsigned flags;                       /* NL_METHOD_OPT_CLAMP, NL_METHOD_OPT_RECORDED */
    nl_method_value v[NL_METHOD_MAX_OPTIONS]; /* by the type's option table */
} nl_method_options;

/* Option object flags. */
enum {
    NL_METHOD_OPT_CLAMP = 1u << 0,    /* synthesise a model that is not positive definite (--clamp) */
    NL_METHOD_OPT_RECORDED = 1u << 1  /* the options are a field's record (--from): automatic choices that
                                         depend on how they were asked are made as recorded */
};

/* The grid of a synthesis: dim 1..3, n[a] samples at spacing h[a] (unused
 * axes 1 and 1), and for NL_METHOD_WINDOW methods the window's origin
 * (recorded as origin=X:Y). */
typedef struct {
    int dim;        /* 1..3 */
    size_t n[3];    /* samples per axis */
    double h[3];    /* spacing per axis (lag units of the model) */
    long origin[2]; /* a windowed method's first sample, in samples (0, 0 by default) */
} nl_method_grid;

typedef struct nl_method_plan nl_method_plan;

/* What a plan reports of itself and of a field it made (nl_method_report_of). */
typedef struct {
    char method[4096]; /* the method string (nl_method_describe) */
    char flags[256];   /* what the method flagged, comma-separated ("clamped", "truncated=0.0012"); "" none */
    double sd;         /* the field's scale: a preview spans offset +- 3 sd */
    double offset;     /* the preview's centre */
    char json[8192];   /* the method's numbers as the text of one JSON object (reals with 17 significant
                          digits and a '.' or exponent; a non-finite one written nan), or "": none */
} nl_method_report;

/* A method.  plan: made once from the model (NULL for NL_METHOD_NO_MODEL or
 * a model-replacing option), grid and options (g and o are copied; the
 * strings o holds, m and the fields of NL_METHOD_FILE options must outlive
 * the plan); execute: one
 * realization of the whole grid for a seed; execute_slab (NULL when not
 * distributed): rows s0 .. s0 + f->n[dim - 1] - 1 of the slowest axis, the
 * same bits as the whole field's; describe: the method string with every
 * option that shapes the field; report (NULL: none beyond the method
 * string) fills flags, sd, offset and json of r for the field f made with
 * seed, or for the plan alone when f is NULL (nl_method_report_of has set
 * r's method and defaults); free.  Each int returns NL_OK or an NL_E* code
 * with its message (core/nl_error.h). */
struct nl_method_type {
    const char *name;                       /* "fft", ... */
    const char *summary;                    /* one line */
    const char *noun;                       /* what messages call it: "subdivision", "sparse convolution" */
    const char *help;                       /* synth --help's paragraph: lines joined by '\n' */
    unsigned dims;                          /* bit d - 1 set: dD grids (1u << 0 | 1u << 1: 1D and 2D) */
    unsigned caps;                          /* NL_METHOD_* capabilities */
    const nl_method_option *options;        /* the option table */
    int noptions;                           /* its rows, at most NL_METHOD_MAX_OPTIONS */
    const char *model_conflict;             /* why a model conflicts with the options given, or NULL */
    const char *model_missing;              /* what to give when the model is missing, or NULL: a model */
    int (*plan)(const nl_model *m, const nl_method_grid *g, const nl_method_options *o, nl_method_plan **out);
    int (*execute)(nl_method_plan *p, uint64_t seed, nl_field *f);
    int (*execute_slab)(nl_method_plan *p, uint64_t seed, size_t s0, nl_field *f);
    int (*describe)(const nl_method_plan *p, char *buf, size_t size);
    int (*report)(const nl_method_plan *p, const nl_model *m, uint64_t seed, const nl_field *f,
                  nl_method_report *r);
    void (*free)(nl_method_plan *p);
};

/* The registry: methods 0 .. nl_method_count() - 1 in their documented
 * order; nl_method_at(i) NULL out of range; nl_method_find(name) the method
 * of that name or NULL. */
int nl_method_count(void);
const nl_method_type *nl_method_at(int i);
const nl_method_type *nl_method_find(const char *name);
/* The registry with its exact methods (NL_METHOD_EXACT) first, each group
 * in the registry's order: method i of 0 .. nl_method_count() - 1, NULL
 * out of range.  Validate runs methods, and capability messages name them,
 * in this order. */
const nl_method_type *nl_method_ranked(int i);

/* Is `name` reserved for a method not in this version?  1 or 0. */
int nl_method_planned(const char *name);

/* The method names joined: "a, b or c" with `sep` (", ") between them and
 * `last` (" or ") before the last one, into buf (size bytes, NUL-terminated, truncated if short).
 * Only methods with every capability in `caps` are listed (0: all), in the
 * registry's order or, with NL_METHOD_EXACT_FIRST in caps, the exact
 * methods first (nl_method_ranked); opt != NULL: only those taking that
 * option.  Returns the number listed. */
int nl_method_names(unsigned caps, const char *opt, const char *sep, const char *last, char *buf, size_t size);

/* The row of option `name` in t's table, or -1. */
int nl_method_option_index(const nl_method_type *t, const char *name);

/* o := t's defaults (every row with a default set; flags 0). */
void nl_method_options_default(const nl_method_type *t, nl_method_options *o);

/* Set option `name` from its text (as on the command line; a FLAG takes ""
 * or NULL).  Returns NL_OK, or NL_EINVAL naming label (e.g. "--levels") and
 * what was expected: an option t does not have, a value out of its range. */
int nl_method_options_set(nl_method_options *o, const char *name, const char *text, const char *label);

/* The value of option `name` (NULL when t has no such option) and whether
 * it was given or defaulted. */
const nl_method_value *nl_method_options_get(const nl_method_options *o, const char *name);
int nl_method_options_given(const nl_method_options *o, const char *name);

/* Plan t for m on g with o (o->type must be t): t->plan.  Returns as t->plan;
 * an intrinsic model (core/model.h) for a method without
 * NL_METHOD_INTRINSIC is refused (NL_EINVAL, nl_model_check_stationary). */
int nl_method_plan_alloc(const nl_method_type *t, const nl_model *m, const nl_method_grid *g,
                         const nl_method_options *o, nl_method_plan **out);
/* A realization into f (the plan's grid); slab: rows s0.. of the slowest
 * axis (NL_EINVAL when the method has no slab execute). */
int nl_method_execute(nl_method_plan *p, uint64_t seed, nl_field *f);
int nl_method_execute_slab(nl_method_plan *p, uint64_t seed, size_t s0, nl_field *f);
/* The method string (what synth records as noiselab.method) into buf;
 * NL_EINVAL when it does not fit. */
int nl_method_describe(const nl_method_plan *p, char *buf, size_t size);
/* What the plan p (made for model m, NULL when it has none) reports of
 * itself and of the field f it made for seed (f NULL: of the plan alone,
 * without the numbers of a field): r->method by nl_method_describe, then no
 * flags, sd the field's root mean square (1 if 0 or no field), offset 0 and
 * no json unless the method's report says otherwise.
 * Returns NL_OK, or NL_EINVAL (the method string or the json does not fit). */
int nl_method_report_of(const nl_method_plan *p, const nl_model *m, uint64_t seed, const nl_field *f,
                        nl_method_report *r);
/* The plan's method, and the per-method plan under it (nl_synth_fft_plan *
 * for fft, nl_subdiv_plan * for subdiv and midpoint unless miller, ...:
 * see each synth/method_<name>.c), owned by p. */
const nl_method_type *nl_method_plan_type(const nl_method_plan *p);
void *nl_method_plan_impl(const nl_method_plan *p);
void nl_method_plan_free(nl_method_plan *p);

#ifdef __cplusplus
}
#endif

#endif
