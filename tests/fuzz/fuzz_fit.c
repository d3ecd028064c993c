/* libFuzzer target 10 (fit): the fitters on a small hostile point set.
 * The bytes are decoded into up to 15 points in 1 to 3 dimensions whose
 * coordinates and values are ordinary numbers or, half of the time, from a
 * table of hostile finite ones (0, -0, denormals, 1e-300, 1e154, 1e300,
 * ...; a point may repeat the place of the one before), a family of the registry that `fit` accepts, a nugget
 * or not, one parameter fixed or not, a weighting, a method (wls, ml, reml)
 * and the profile intervals wanted; then the library's fits run as the
 * command line runs them (the variogram, WLS, then ML or REML from WLS's
 * answer) under a small work budget.
 *
 * The checker traps (__builtin_trap, a crash libFuzzer records) when
 *   - a fit refuses with an empty nl_errmsg();
 *   - a fit returns NL_OK with a non-finite objective, value or mean
 *     (ML), a standard error that is NaN though the parameter is neither
 *     flagged nor fixed, or a profile interval of width 0 or not holding
 *     its value.
 * FUZZ_DEBUG=1 in the environment prints the decoded case on stderr. */
#include "../../analysis/fit.h"
#include "../../analysis/variogram.h"
#include "../../core/family.h"
#include "../../core/io_points.h"
#include "../../core/nl_error.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    const uint8_t *p; /* the bytes left */
    size_t n;         /* how many */
} bytes;

static unsigned take(bytes *b)
{
    if (!b->n)
        return 0;
    b->n--;
    return *b->p++;
}

static const double nums[] = {0,   -0.0, 1,      0.5,    2.385, -3.25,   1e-8,    5e-324, 2.2250738585072014e-308,
                              1e-300, 1e-154, 1e154, -1e154, 1e300, 1e308, 1e-3, 7, 0.25, 100, 4096};

/* A number of the table (high bit set) or an ordinary one, 0 to 9.3 */
static double pick(bytes *b)
{
    unsigned v = take(b);
    return v & 0x80 ? nums[(v & 0x7f) % (sizeof nums / sizeof *nums)] : v * 0.0731;
}

static void check(int st, const char *what)
{
    const char *e = nl_errmsg();
    if (getenv("FUZZ_DEBUG"))
        fprintf(stderr, "  %s: %s\n", what, st ? e : "ok");
    if (st != NL_OK && (!e || !*e)) {
        fprintf(stderr, "fuzz: %s refused (status %d) with an empty message\n", what, st);
        __builtin_trap();
    }
}

static void fail(const char *what, const nl_fit_param *q, const char *why)
{
    fprintf(stderr, "fuzz: %s: %s = %g (se %g, %g to %g, flags %u): %s\n", what, q->name, q->value, q->se, q->lower,
            q->upper, q->flags, why);
    __builtin_trap();
}

/* What a fit that returned NL_OK must hold. */
static void check_result(const nl_fit_result *r, int ml, const char *what)
{
    if (!isfinite(r->objective) || (ml && !isfinite(r->mean))) {
        fprintf(stderr, "fuzz: %s: objective %g, mean %g\n", what, r->objective, r->mean);
        __builtin_trap();
    }
    for (size_t k = 0; k < r->np; k++) {
        const nl_fit_param *q = &r->param[k];
        if (!isfinite(q->value))
            fail(what, q, "value not finite");
        if (isnan(q->se) && !q->flags && !q->fixed)
            fail(what, q, "no standard error and no flag");
        if (!isnan(q->lower) && !isnan(q->upper) && !(q->upper > q->lower && q->lower <= q->value &&
                                                      q->value <= q->upper))
            fail(what, q, "interval of width 0 or not holding the value");
    }
}

/* The k-th family that fit accepts (in registry order, cycling). */
static const char *family(unsigned k)
{
    size_t nfit = 0;
    for (size_t i = 0; i < nl_family_count(); i++)
        nfit += (nl_family_get(i)->flags & NL_FAMILY_FIT) != 0;
    k %= (unsigned)nfit;
    for (size_t i = 0; i < nl_family_count(); i++)
        if ((nl_family_get(i)->flags & NL_FAMILY_FIT) && k-- == 0)
            return nl_family_get(i)->name;
    return "markov";
}

static void run_fits(const nl_points *p, nl_fit_options *o, int method)
{
    nl_variogram_options vo;
    nl_variogram *v = NULL;
    nl_fit_result r = {0};
    int st;
    nl_variogram_options_default(&vo);
    if ((st = nl_fit_check_options(o, p->dim)) || (st = nl_variogram_points(p, &vo, &v))) {
        check(st, "options or variogram");
        return;
    }
    st = nl_fit_variogram(v->distance, v->gamma, v->pairs, v->nbins, p->dim, o, &r);
    nl_variogram_free(v);
    check(st, "nl_fit_variogram");
    if (st)
        return;
    check_result(&r, 0, "nl_fit_variogram");
    if (method) {
        double start[NL_FAMILY_MAX_PARAMS + 2];
        for (size_t k = 0; k < r.np && k < sizeof start / sizeof *start; k++)
            start[k] = r.param[k].value;
        nl_fit_result_free(&r);
        o->start = start;
        o->likelihood = method == 2 ? NL_FIT_REML : NL_FIT_ML;
        st = nl_fit_ml(p->pts, p->val, p->n, p->dim, o, &r);
        check(st, "nl_fit_ml");
        if (!st)
            check_result(&r, 1, "nl_fit_ml");
        o->start = NULL;
    }
    nl_fit_result_free(&r);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    bytes b = {data, size};
    double pts[15 * 3], val[15];
    nl_points p = {1 + (int)(take(&b) % 3), 2 + take(&b) % 14, pts, val};
    nl_fit_options o = {0};
    unsigned how = take(&b), fix = take(&b);
    int method = (int)(how % 3);
    static const char *const fixable[] = {"var", "scale", "nugget", "nu", "alpha", "beta", "omega"};
    for (size_t i = 0; i < p.n; i++) {
        int same = i > 0 && (take(&b) & 7) == 0;
        for (int a = 0; a < p.dim; a++)
            pts[i * (size_t)p.dim + (size_t)a] = same ? pts[(i - 1) * (size_t)p.dim + (size_t)a] : pick(&b);
        val[i] = pick(&b);
    }
    o.family = family(take(&b));
    o.nugget = (how >> 2) & 1;
    o.weights = (nl_fit_weights)((how >> 3) & 3);
    o.intervals = (nl_fit_intervals)(((how >> 5) & 3) % 3);
    o.max_work = 1e9; /* a few hundred evaluations of 15 data */
    if (fix & 1) {
        o.nfix = 1;
        o.fix_name[0] = fixable[(fix >> 1) % (sizeof fixable / sizeof *fixable)];
        o.fix_value[0] = fabs(pick(&b));
    }
    if (getenv("FUZZ_DEBUG"))
        fprintf(stderr, "fit: %zu points in %dD, %s, nugget %d, method %d, weights %d, intervals %d, fix %s\n", p.n,
                p.dim, o.family, o.nugget, method, (int)o.weights, (int)o.intervals, o.nfix ? o.fix_name[0] : "-");
    run_fits(&p, &o, method);
    return 0;
}
