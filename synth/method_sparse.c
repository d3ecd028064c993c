/* sparse as a method descriptor (synth/method.h over synth/sparse.h).  Its
 * nl_method_plan_impl is the nl_synth_sparse_plan. */
#include "method_internal.h"
#include "fft.h"
#include "sparse.h"
#include "../core/io.h"
#include "../core/nl_error.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

typedef struct {
    nl_method_plan head; /* impl: the nl_synth_sparse_plan */
    nl_field *img;       /* the exemplar read from its file, or NULL */
} sparse_plan;

/* The radius of an expression kernel when none is given. */
#define EXPR_RADIUS 16

static const nl_method_option options[] = {
    {"density", NL_METHOD_DOUBLE, NL_METHOD_OPEN, 0, HUGE_VAL, NULL, "a positive number", "1", "impulses per cell"},
    {"radius", NL_METHOD_INT, 0, 1, 4096, NULL, NULL, NULL, "the kernel's radius in samples (default: automatic)"},
    {"cell", NL_METHOD_INT, 0, 1, 2147483647, NULL, NULL, NULL, "the impulse cell in samples (default: the radius)"},
    {"wrap", NL_METHOD_FLAG, NL_METHOD_NO_WINDOW, 0, 0, NULL, NULL, NULL, "a periodic tile"},
    {"kernel", NL_METHOD_STRING, NL_METHOD_REPLACES_MODEL | NL_METHOD_SUFFIX | NL_METHOD_EXPRESSION, 0, 0, NULL, NULL,
     NULL, "the kernel, an expression in x, y (t, r)"},
    {"exemplar", NL_METHOD_STRING, NL_METHOD_REPLACES_MODEL | NL_METHOD_FILE | NL_METHOD_SUFFIX, 0, 0, NULL, NULL,
     NULL, "a 2D image whose Hann-windowed centre is the kernel (texture resynthesis)"},
    {"angle", NL_METHOD_STRING, NL_METHOD_SUFFIX | NL_METHOD_EXPRESSION, 0, 0, NULL, NULL, NULL,
     "an expression in x, y rotating the kernel with position"},
};

/* A model kernel.  The kernel's FFT grid depends on whether the radius was
 * automatic, and a field records the radius it used: regenerating
 * (NL_METHOD_OPT_RECORDED), the automatic radius is tried first and kept
 * when it is the recorded one, so that the field comes back bit for bit. */
static int model_plan(const nl_model *m, const nl_method_grid *g, const nl_method_options *o,
                      nl_synth_sparse_plan **p)
{
    unsigned fl = o->flags & NL_METHOD_OPT_CLAMP ? NL_SYNTH_FFT_CLAMP : 0;
    int radius = (int)nl_method_opt_int(o, "radius"), cell = (int)nl_method_opt_int(o, "cell");
    double density = nl_method_opt_double(o, "density");
    if ((o->flags & NL_METHOD_OPT_RECORDED) && radius) {
        nl_synth_sparse_info info;
        if (!nl_synth_sparse_plan_model(m, g->dim, g->h, &(nl_synth_sparse_options){0, cell, density, fl}, p)) {
            nl_synth_sparse_plan_info(*p, &info);
            if (info.radius == radius)
                return NL_OK;
            nl_synth_sparse_plan_free(*p);
        }
    }
    return nl_synth_sparse_plan_model(m, g->dim, g->h, &(nl_synth_sparse_options){radius, cell, density, fl}, p);
}

static int exemplar_plan(sparse_plan *sp, const nl_method_grid *g, const nl_method_options *o)
{
    const nl_method_value *v = nl_method_options_get(o, "exemplar");
    const nl_field *img = v->field;
    int st;
    if (!img && (st = nl_field_read(v->s, &sp->img, NULL)))
        return st;
    img = img ? img : sp->img;
    if (g->dim != 2)
        return NL_ERROR(NL_EINVAL, "--exemplar: expected a 2D image and a 2D --size, got %dD %s and a %dD --size",
                        img->dim, v->s, g->dim);
    return nl_synth_sparse_plan_exemplar(img, &(nl_synth_sparse_options){(int)nl_method_opt_int(o, "radius"),
                                         (int)nl_method_opt_int(o, "cell"), nl_method_opt_double(o, "density"), 0},
                                         (nl_synth_sparse_plan **)&sp->head.impl);
}

static int kernel_plan(sparse_plan *sp, const nl_model *m, const nl_method_grid *g, const nl_method_options *o)
{
    const char *kernel = nl_method_opt_string(o, "kernel"), *angle = nl_method_opt_string(o, "angle");
    int radius = (int)nl_method_opt_int(o, "radius"), cell = (int)nl_method_opt_int(o, "cell"), st;
    double density = nl_method_opt_double(o, "density");
    int given = (m != NULL) + (kernel != NULL) + nl_method_opt_set(o, "exemplar");
    if (given != 1)
        return NL_ERROR(NL_EINVAL, "synth sparse: expected exactly one kernel: --acf/--spectrum SPEC, --kernel EXPR "
                        "or --exemplar FILE");
    /* an explicit radius: the work is known before the kernel is made */
    if ((radius || kernel) &&
        (st = nl_synth_sparse_check_work(g->dim, g->n, radius ? radius : EXPR_RADIUS, cell, density,
                                               angle ? NL_SYNTH_SPARSE_ANGLE : 0)))
        return st;
    if (m)
        st = model_plan(m, g, o, (nl_synth_sparse_plan **)&sp->head.impl);
    else if (kernel)
        st = nl_synth_sparse_plan_expr(kernel, g->dim, &(nl_synth_sparse_options){radius ? radius : EXPR_RADIUS, cell,
                                       density, 0}, (nl_synth_sparse_plan **)&sp->head.impl);
    else
        st = exemplar_plan(sp, g, o);
    if (!st && angle)
        st = nl_synth_sparse_set_angle(sp->head.impl, angle);
    return st;
}

static void plan_free(nl_method_plan *p)
{
    nl_synth_sparse_plan_free(p->impl);
    nl_field_free(((sparse_plan *)p)->img);
    free(p);
}

static int plan(const nl_model *m, const nl_method_grid *g, const nl_method_options *o, nl_method_plan **out)
{
    sparse_plan *sp = (sparse_plan *)nl_method_plan_head(sizeof *sp, g, o);
    int st;
    *out = NULL;
    if (!sp)
        return NL_ENOMEM;
    if ((st = kernel_plan(sp, m, g, o)))
        plan_free(&sp->head);
    else
        *out = &sp->head;
    return st;
}

static int execute(nl_method_plan *p, uint64_t seed, nl_field *f)
{
    int wrap = (int)nl_method_opt_int(&p->opt, "wrap");
    return nl_synth_sparse_execute(p->impl, seed, wrap ? NL_SYNTH_SPARSE_WRAP : 0, wrap ? NULL : p->grid.origin, f);
}

static int execute_slab(nl_method_plan *p, uint64_t seed, size_t s0, nl_field *f)
{
    long o[2] = {p->grid.origin[0], p->grid.origin[1]};
    if (nl_method_opt_int(&p->opt, "wrap"))
        return nl_synth_sparse_execute_slab(p->impl, seed, NL_SYNTH_SPARSE_WRAP, p->grid.n, s0, f);
    o[p->grid.dim - 1] += (long)s0;
    return nl_synth_sparse_execute(p->impl, seed, 0, o, f);
}

/* Expression-valued keys follow '|', as they may hold commas. */
static int describe(const nl_method_plan *p, char *buf, size_t size)
{
    const char *kernel = nl_method_opt_string(&p->opt, "kernel"), *ex = nl_method_opt_string(&p->opt, "exemplar");
    const char *angle = nl_method_opt_string(&p->opt, "angle");
    int wrap = (int)nl_method_opt_int(&p->opt, "wrap");
    const long *org = p->grid.origin;
    nl_synth_sparse_info info;
    size_t len = 0;
    int st;
    nl_synth_sparse_plan_info(p->impl, &info);
    st = nl_method_append(buf, size, &len, "sparse:radius=%d,cell=%d,density=%.17g", info.radius, info.cell,
                          info.density);
    if (!st && (wrap || org[0] || org[1]))
        st = wrap ? nl_method_append(buf, size, &len, ",wrap")
                  : nl_method_append(buf, size, &len, ",origin=%ld:%ld", org[0], org[1]);
    if (!st && kernel)
        st = nl_method_append(buf, size, &len, "|kernel=%s", kernel);
    if (!st && ex)
        st = nl_method_append(buf, size, &len, "|exemplar=%s", ex);
    if (!st && angle)
        st = nl_method_append(buf, size, &len, "|angle=%s", angle);
    return st;
}

/* Flags: a clamped spectrum, and a kernel that loses more than TRUNC_FLAG
 * of its energy at the radius (the variance is then R(0) less that
 * fraction; the report gives it as truncated_energy). */
#define TRUNC_FLAG 1e-3

static int report(const nl_method_plan *p, const nl_model *m, uint64_t seed, const nl_field *f, nl_method_report *r)
{
    nl_synth_sparse_info i;
    int k = 0, st;
    (void)m, (void)seed, (void)f;
    nl_synth_sparse_plan_info(p->impl, &i);
    if (i.clamp_error > NL_SYNTH_FFT_CLAMP_TOL)
        k = snprintf(r->flags, sizeof r->flags, "clamped");
    if (i.truncated > TRUNC_FLAG)
        snprintf(r->flags + k, sizeof r->flags - (size_t)k, "%struncated=%.2g", k ? "," : "", i.truncated);
    r->sd = sqrt(i.variance);
    r->offset = i.mean;
    st = nl_method_json(r, "{\"radius\": %d, \"cell\": %d, \"density\": %s, \"variance\": %s, \"excess_kurtosis\": %s, "
                        "\"truncated_energy\": %s", i.radius, i.cell, NL_METHOD_REAL(i.density),
                        NL_METHOD_REAL(i.variance), NL_METHOD_REAL(i.kurtosis), NL_METHOD_REAL(i.truncated));
    if (!st && i.clamp_error > NL_SYNTH_FFT_CLAMP_TOL)
        st = nl_method_json(r, ", \"clamp_error\": %s", NL_METHOD_REAL(i.clamp_error));
    return st ? st : nl_method_json(r, "}");
}

const nl_method_type nl_method_sparse = {
    .name = "sparse",
    .summary = "sparse convolution (Lewis GI '86): Poisson impulses in cells convolved with a kernel",
    .noun = "sparse convolution",
    .help =
        "sparse convolution (Lewis GI '86): Poisson impulses in cells, convolved with\n"
        "a kernel: the model's (R = h * h), --kernel EXPR in x, y (t, r), or --exemplar\n"
        "FILE (Hann-windowed, for texture resynthesis); --density D impulses per\n"
        "cell (default 1), --cell C and --radius R in samples, --wrap for a periodic\n"
        "tile, --origin X[,Y] for a window of the infinite field, --angle EXPR in\n"
        "x, y rotating the kernel with position; the report predicts the excess\n"
        "kurtosis 3 sum h^4 / (lambda (sum h^2)^2); a kernel losing more than 1e-3\n"
        "of its energy at the radius is flagged truncated=FRACTION",
    .dims = 3,
    .caps = NL_METHOD_MODEL | NL_METHOD_WINDOW | NL_METHOD_DISTRIBUTED | NL_METHOD_CLAMP | NL_METHOD_VALIDATED,
    .options = options, .noptions = (int)(sizeof options / sizeof *options),
    .model_conflict = "expected exactly one kernel: --acf/--spectrum SPEC, --kernel EXPR or --exemplar FILE",
    .model_missing = "expected exactly one kernel: --acf/--spectrum SPEC, --kernel EXPR or --exemplar FILE",
    .plan = plan, .execute = execute, .execute_slab = execute_slab, .describe = describe, .report = report,
    .free = plan_free,
};
