/* What the method descriptors share (synth/method.h): the plan header every
 * method's plan begins with, and option look-ups by name. */
#ifndef NL_SYNTH_METHOD_INTERNAL_H
#define NL_SYNTH_METHOD_INTERNAL_H

#include "method.h"

/* The head of every method's plan. */
struct nl_method_plan {
    const nl_method_type *type; /* the method */
    nl_method_grid grid;        /* the grid it was planned for */
    nl_method_options opt;      /* its options (strings not copied: see nl_method_value) */
    void *impl;                 /* the per-method plan (nl_method_plan_impl) */
};

/* Option values by name (0, 0.0 or NULL when unset or absent). */
long nl_method_opt_int(const nl_method_options *o, const char *name);
double nl_method_opt_double(const nl_method_options *o, const char *name);
const char *nl_method_opt_string(const nl_method_options *o, const char *name);
int nl_method_opt_set(const nl_method_options *o, const char *name);

/* A plan of `size` bytes (>= sizeof(nl_method_plan)) with its head filled
 * (its method: o->type); NULL and NL_ENOMEM recorded when out of memory. */
nl_method_plan *nl_method_plan_head(size_t size, const nl_method_grid *g, const nl_method_options *o);

/* EINVAL unless g->dim is one of t's dimensions. */
int nl_method_check_dim(const nl_method_type *t, const nl_method_grid *g);

/* Append to the method string buf (size bytes) at *len; NL_EINVAL when it
 * does not fit. */
int nl_method_append(char *buf, size_t size, size_t *len, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));

/* A report's numbers: appended to r->json as with nl_method_append.  A
 * real is written by nl_method_real into a buffer (NL_METHOD_REAL(x) gives
 * one for the statement): 17 significant digits, ".0" added to an
 * integral value, "nan" when not finite (which no JSON reader accepts). */
int nl_method_json(nl_method_report *r, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
const char *nl_method_real(char buf[32], double x);
#define NL_METHOD_REAL(x) nl_method_real((char[32]){0}, (x))

#endif
