/* subdiv as a method descriptor (synth/method.h over synth/subdiv.h).  Its
 * nl_method_plan_impl is the nl_subdiv_plan. */
#include "method_internal.h"
#include "subdiv.h"
#include "../core/io.h"
#include "../core/nl_error.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

typedef struct {
    nl_method_plan head; /* impl: the nl_subdiv_plan */
    nl_field *img;       /* the seed image read from its file, or NULL */
    const nl_field *seed;/* the seed image used, or NULL */
} subdiv_plan;

static const nl_method_option options[] = {
    {"levels", NL_METHOD_INT, 0, 1, 30, NULL, NULL, NULL, "levels of refinement"},
    {"neighborhood", NL_METHOD_INT, 0, 1, 2147483647, "auto", NULL, "2", "half-width of the neighbourhood, or auto"},
    {"tol", NL_METHOD_DOUBLE, NL_METHOD_OPEN, 0, HUGE_VAL, "variance:|improvement:",
     "a positive number, variance:NUMBER or improvement:NUMBER", "1e-4", "auto: the neighbourhood's stopping rule"},
    {"nonperiodic", NL_METHOD_FLAG, NL_METHOD_MAKES_WINDOW, 0, 0, NULL, NULL, NULL,
     "a window of an infinite, spatially consistent field"},
    {"seed-image", NL_METHOD_STRING, NL_METHOD_FILE | NL_METHOD_SUFFIX, 0, 0, NULL, NULL, NULL,
     "start from this image as the coarse level"},
    {"random-neighborhoods", NL_METHOD_INT, 0, 1, 256, NULL, NULL, NULL,
     "2D: random quadrilateral neighbourhoods per point class"},
    {"displacements", NL_METHOD_CHOICE, 0, 0, 0, "independent|correlated", "independent or correlated",
     "independent", "new points displaced independently or together"},
    {"taps", NL_METHOD_INT, 0, 1, NL_SUBDIV_MAX_TAPS, NULL, NULL, NULL, "correlated: the filter's half-width"},
    {"max-neighborhood", NL_METHOD_INT, 0, 1, 64, NULL, NULL, NULL,
     "auto: the largest half-width tried (default 16 in 1D, 6 in 2D)"},
};

static void to_options(const nl_method_options *mo, nl_subdiv_options *o)
{
    const nl_method_value *tol = nl_method_options_get(mo, "tol");
    nl_subdiv_options_default(o);
    o->levels = (int)nl_method_opt_int(mo, "levels");
    o->N = (int)nl_method_opt_int(mo, "neighborhood");
    o->tol = tol->d;
    o->stop = tol->i == 0 ? NL_SUBDIV_STOP_VARIANCE : NL_SUBDIV_STOP_IMPROVEMENT;
    o->nonperiodic = (int)nl_method_opt_int(mo, "nonperiodic");
    o->allow_not_pd = (mo->flags & NL_METHOD_OPT_CLAMP) != 0;
    o->random_nb = (int)nl_method_opt_int(mo, "random-neighborhoods");
    o->displacements = nl_method_opt_int(mo, "displacements") ? NL_SUBDIV_DISP_ERROR : NL_SUBDIV_DISP_INDEPENDENT;
    o->taps = (int)nl_method_opt_int(mo, "taps");
    o->nmax = (int)nl_method_opt_int(mo, "max-neighborhood");
}

/* The seed image (read unless given read) and the levels it needs. */
static int seed_image(subdiv_plan *sp, const nl_method_grid *g, nl_subdiv_options *o)
{
    const nl_method_value *v = nl_method_options_get(&sp->head.opt, "seed-image");
    int st;
    if (!v->set)
        return NL_OK;
    if (!(sp->seed = v->field)) {
        if ((st = nl_field_read(v->s, &sp->img, NULL)))
            return st;
        sp->seed = sp->img;
    }
    if (sp->seed->dim != g->dim)
        return NL_ERROR(NL_EINVAL, "--seed-image: %s is %dD, expected %dD like --size", v->s, sp->seed->dim, g->dim);
    if ((st = nl_subdiv_image_levels(g->dim, sp->seed->n, g->n, o->levels, &o->levels)))
        return st;
    o->image = !o->nonperiodic;
    return NL_OK;
}

static void plan_free(nl_method_plan *p)
{
    subdiv_plan *sp = (subdiv_plan *)p;
    nl_subdiv_plan_free(p->impl);
    nl_field_free(sp->img);
    free(p);
}

static int plan(const nl_model *m, const nl_method_grid *g, const nl_method_options *mo, nl_method_plan **out)
{
    subdiv_plan *sp;
    nl_subdiv_options o;
    int st;
    *out = NULL;
    to_options(mo, &o);
    if (o.random_nb && o.displacements)
        return NL_ERROR(NL_EINVAL, "--displacements correlated: expected the standard neighbourhoods, got "
                        "--random-neighborhoods %d (random neighbourhoods have no common error covariance)",
                        o.random_nb);
    if (o.taps && o.displacements != NL_SUBDIV_DISP_ERROR)
        return NL_ERROR(NL_EINVAL, "--taps %d: expected --displacements correlated (independent displacements have "
                        "no filter)", o.taps);
    for (int a = 1; a < g->dim; a++)
        if (g->h[a] != g->h[0])
            return NL_ERROR(NL_EINVAL, "--spacing: subdivision needs the same spacing on every axis, got %g and %g",
                            g->h[0], g->h[a]);
    if (!(sp = (subdiv_plan *)nl_method_plan_head(sizeof *sp, g, mo)))
        return NL_ENOMEM;
    if ((st = seed_image(sp, g, &o)) ||
        (st = nl_subdiv_plan_alloc(m, g->dim, g->n, g->h[0], &o, (nl_subdiv_plan **)&sp->head.impl))) {
        plan_free(&sp->head);
        return st;
    }
    *out = &sp->head;
    return NL_OK;
}

static int execute(nl_method_plan *p, uint64_t seed, nl_field *f)
{
    const subdiv_plan *sp = (const subdiv_plan *)p;
    if (nl_method_opt_int(&p->opt, "nonperiodic"))
        return nl_subdiv_plan_execute_window(p->impl, seed, p->grid.origin, f);
    if (sp->seed)
        return nl_subdiv_plan_execute_image(p->impl, sp->seed, seed, f);
    return nl_subdiv_plan_execute(p->impl, seed, f);
}

static int execute_slab(nl_method_plan *p, uint64_t seed, size_t s0, nl_field *f)
{
    const subdiv_plan *sp = (const subdiv_plan *)p;
    long o[2] = {p->grid.origin[0], p->grid.origin[1]};
    o[p->grid.dim - 1] += (long)s0;
    if (nl_method_opt_int(&p->opt, "nonperiodic"))
        return nl_subdiv_synth_window(nl_subdiv_plan_coeffs(p->impl), seed, o, f);
    if (sp->seed)
        return nl_subdiv_plan_execute_image_slab(p->impl, sp->seed, seed, s0, f);
    return nl_subdiv_plan_execute_slab(p->impl, seed, s0, f);
}

static int describe(const nl_method_plan *p, char *buf, size_t size)
{
    const nl_subdiv_coeffs *c = nl_subdiv_plan_coeffs(p->impl);
    const nl_method_value *tol = nl_method_options_get(&p->opt, "tol");
    const char *img = nl_method_opt_string(&p->opt, "seed-image");
    long N = nl_method_opt_int(&p->opt, "neighborhood"), nonper = nl_method_opt_int(&p->opt, "nonperiodic");
    long rnb = nl_method_opt_int(&p->opt, "random-neighborhoods");
    nl_subdiv_info info;
    char nb[24] = "auto";
    size_t len = 0;
    int st;
    nl_subdiv_plan_info(p->impl, &info);
    if (N)
        snprintf(nb, sizeof nb, "%ld", N);
    st = nl_method_append(buf, size, &len, "subdiv:levels=%d,neighborhood=%s,tol=%s%g%s%s", info.levels, nb,
                          tol->i == 0 ? "variance:" : "", tol->d, nonper ? ",nonperiodic" : ",periodic",
                          img ? ",seed-image" : "");
    if (!st && rnb)
        st = nl_method_append(buf, size, &len, ",random-neighborhoods=%ld", rnb);
    if (!st && nl_method_opt_set(&p->opt, "max-neighborhood"))
        st = nl_method_append(buf, size, &len, ",max-neighborhood=%ld", nl_method_opt_int(&p->opt, "max-neighborhood"));
    if (!st && c->level[0].filt)
        st = nl_method_append(buf, size, &len, ",displacements=correlated,taps=%d", c->level[0].taps);
    if (!st && nonper)
        st = nl_method_append(buf, size, &len, ",origin=%ld:%ld", p->grid.origin[0], p->grid.origin[1]);
    if (!st && img)
        st = nl_method_append(buf, size, &len, "|seed-image=%s", img);
    return st;
}

/* Each level's neighbourhood, largest variance and flags. */
static int report_levels(const nl_subdiv_coeffs *c, nl_method_report *r)
{
    int st = nl_method_json(r, "[");
    for (int k = 0; k < c->levels && !st; k++) {
        const nl_subdiv_level *l = &c->level[k];
        unsigned fl = 0;
        double v = 0;
        char buf[128];
        for (int j = 0; j < l->nclass; j++)
            fl |= l->cls[j].flags, v = fmax(v, l->cls[j].variance);
        nl_subdiv_flag_names(fl, buf, sizeof buf);
        st = nl_method_json(r, "%s{\"level\": %d, \"spacing\": %s, \"N\": %d, \"max_variance\": %s, \"flags\": \"%s\"",
                            k ? ", " : "", k, NL_METHOD_REAL(l->spacing), l->N, NL_METHOD_REAL(v), buf);
        if (!st && l->filt)
            st = nl_method_json(r, ", \"taps\": %d, \"filter_error\": %s", l->taps, NL_METHOD_REAL(l->filt_error));
        if (!st)
            st = nl_method_json(r, "}");
    }
    return st ? st : nl_method_json(r, "]");
}

static int report(const nl_method_plan *p, const nl_model *m, uint64_t seed, const nl_field *f, nl_method_report *r)
{
    const nl_subdiv_coeffs *c = nl_subdiv_plan_coeffs(p->impl);
    nl_subdiv_info info;
    int st;
    (void)m, (void)seed, (void)f;
    nl_subdiv_plan_info(p->impl, &info);
    nl_subdiv_flag_names(c->flags, r->flags, sizeof r->flags);
    r->sd = sqrt(c->r0);
    st = nl_method_json(r, "{\"spacing0\": %s, \"variance\": %s, \"levels\": ", NL_METHOD_REAL(info.spacing0),
                        NL_METHOD_REAL(c->r0));
    if (!st)
        st = report_levels(c, r);
    if (!st && nl_method_opt_int(&p->opt, "nonperiodic"))
        st = nl_method_json(r, ", \"coarse_correlation\": %s", NL_METHOD_REAL(info.coarse_correlation));
    return st ? st : nl_method_json(r, "}");
}

const nl_method_type nl_method_subdiv = {
    .name = "subdiv",
    .summary = "generalized stochastic subdivision (Lewis 1987)",
    .noun = "subdivision",
    .help =
        "generalized stochastic subdivision (Lewis 1987), 1D or 2D:\n"
        "--levels L          levels of refinement (default: down to a coarse grid\n"
        "                    of 8 samples, or 6 levels with --nonperiodic)\n"
        "--neighborhood N|auto  half-width of the neighbourhood (default 2: 4 or 4x4)\n"
        "--tol [variance:]E  auto: grow N until (7) improves by < E R(0) (1e-4), or is < E R(0)\n"
        "--nonperiodic       a window of an infinite, spatially consistent field\n"
        "--origin X[,Y]      the window's first sample, in output samples (default 0)\n"
        "--seed-image FILE   start from this image as the coarse level (kept exactly)\n"
        "--random-neighborhoods K  2D: K random quadrilateral neighbourhoods per\n"
        "                    point class, one drawn per point (against diagonal bias)\n"
        "--displacements independent|correlated  independent: Lewis's, each new\n"
        "                    point displaced on its own (eq. 7); correlated: the new\n"
        "                    points of a level displaced together, with the covariance\n"
        "                    of their estimation errors, by a filter of white noise\n"
        "                    (default independent)\n"
        "--taps M            correlated: the filter's half-width in cells (default 4 in\n"
        "                    1D, 2 in 2D; at most 16)",
    .dims = 3,
    .caps = NL_METHOD_MODEL | NL_METHOD_PERIODIC | NL_METHOD_WINDOW | NL_METHOD_DISTRIBUTED |
            NL_METHOD_CONDITIONABLE | NL_METHOD_CLAMP | NL_METHOD_VALIDATED | NL_METHOD_SUBDIVISION,
    .options = options, .noptions = (int)(sizeof options / sizeof *options),
    .plan = plan, .execute = execute, .execute_slab = execute_slab, .describe = describe, .report = report,
    .free = plan_free,
};
