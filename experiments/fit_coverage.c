/* Do fitted parameters' standard errors describe their spread?  K fields of
 * a known model (circulant embedding, exact, on a G x G grid of unit
 * spacing, seeds 1..K), N distinct grid nodes drawn from each (seeded
 * uniform draws, so the data are exact samples of the field), the model's
 * family fitted by ML (nl_fit_ml) and by WLS on the Matheron variogram with
 * Cressie's weights (nl_fit_variogram, gstat's default width and cutoff).
 *
 * ML also reports 95% profile-likelihood intervals (nl_fit_options.intervals)
 * of every free parameter ("all"), of the scale alone ("scale") or none.
 * Fields are made one after another; fits run in parallel (OpenMP), each
 * field's results kept in its slot, so the output does not depend on the
 * number of threads.
 *
 * usage: fit_coverage SPEC FAMILY NUGGET(0|1) G N K [all|scale|none]
 *   prints per method and parameter, tab-separated: method, parameter,
 *   true value, fits that succeeded, mean estimate, sd of the estimates,
 *   mean reported standard error, coverage of the Wald interval est +-
 *   1.96 se, coverage of the log-scale interval est exp(+-1.96 se / est),
 *   fits with a profile interval and its coverage ("-" where none). */
#include "../analysis/fit.h"
#include "../analysis/variogram.h"
#include "../core/io_points.h"
#include "../core/model.h"
#include "../core/nl_error.h"
#include "../core/rng.h"
#include "../synth/circulant.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { METHODS = 2 };

typedef struct {
    double sum, sum2, se, cover, cover_log;  /* over successful fits with a standard error */
    int n;                                   /* such fits */
    int pn, pcover;                          /* fits with a profile interval, those covering */
} tally;

/* One field's data and fits. */
typedef struct {
    nl_points p;               /* the sampled nodes */
    nl_fit_result r[METHODS];  /* ML, WLS */
    int st;                    /* NL_OK when both fits succeeded */
} slot;

/* N distinct nodes of the G x G field, drawn by seeded uniforms. */
static void sample_nodes(const nl_field *f, size_t g, size_t n, uint64_t seed, nl_points *p)
{
    unsigned char *used = calloc(g * g, 1);
    size_t k = 0;
    for (uint64_t i = 0; k < n; i++) {
        size_t idx = (size_t)(nl_rng_uniform(seed, 77, i) * (double)(g * g)) % (g * g);
        if (used[idx])
            continue;
        used[idx] = 1;
        p->pts[2 * k] = (double)(idx % g);
        p->pts[2 * k + 1] = (double)(idx / g);
        p->val[k] = f->data[idx];
        k++;
    }
    free(used);
}

static void add(tally *t, double truth, const nl_fit_result *r, size_t q)
{
    double est = r->param[q].value, se = r->param[q].se;
    if (isfinite(se)) {
        t->n++;
        t->sum += est;
        t->sum2 += est * est;
        t->se += se;
        t->cover += fabs(est - truth) <= 1.96 * se;
        t->cover_log += fabs(log(est / truth)) <= 1.96 * se / est;
    }
    if (!isnan(r->param[q].lower) && !isnan(r->param[q].upper)) {
        t->pn++;
        t->pcover += r->param[q].lower <= truth && truth <= r->param[q].upper;
    }
}

static int fit_both(const nl_points *p, const nl_fit_options *o, nl_fit_result r[METHODS])
{
    nl_variogram_options vo;
    nl_variogram *v;
    int st;
    nl_variogram_options_default(&vo);
    if ((st = nl_variogram_points(p, &vo, &v)))
        return st;
    st = nl_fit_variogram(v->distance, v->gamma, v->pairs, v->nbins, 2, o, &r[1]);
    nl_variogram_free(v);
    if (!st) {
        nl_fit_options ml = *o;
        double start[NL_FAMILY_MAX_PARAMS];
        for (size_t k = 0; k < r[1].np; k++)
            start[k] = r[1].param[k].value;  /* ML starts from the WLS fit */
        ml.start = start;
        st = nl_fit_ml(p->pts, p->val, p->n, 2, &ml, &r[0]);
    }
    return st;
}

/* K fields sampled at n nodes each into slots (sequential: one plan). */
static int make_data(const nl_synth_circulant_plan *plan, size_t g, size_t n, size_t K, slot *s)
{
    size_t gn[2] = {g, g};
    int st;
    nl_field *f = nl_field_alloc(2, gn, NULL, &st);
    if (!f)
        return st;
    for (size_t k = 0; k < K; k++) {
        s[k].p = (nl_points){2, n, malloc(2 * n * sizeof(double)), malloc(n * sizeof(double))};
        if (!s[k].p.pts || !s[k].p.val || (st = nl_synth_circulant_execute(plan, k + 1, f)))
            break;
        sample_nodes(f, g, n, k + 1, &s[k].p);
    }
    nl_field_free(f);
    return st;
}

static void print_table(const nl_model *m, tally t[METHODS][NL_FAMILY_MAX_PARAMS], const nl_fit_result *r)
{
    static const char *names[METHODS] = {"ml", "wls-cressie"};
    printf("method\tparameter\ttrue\tfits\tmean\tsd\tmean_se\tcoverage\tcoverage_log\tprofile_fits\tprofile_coverage\n");
    for (int a = 0; a < METHODS; a++)
        for (size_t q = 0; q < r[a].np; q++) {
            tally *x = &t[a][q];
            double truth, mean = x->sum / x->n;
            if (!x->n || nl_model_param(m, r[a].param[q].name, &truth))
                continue;
            printf("%s\t%s\t%g\t%d\t%.4g\t%.4g\t%.4g\t%.3f\t%.3f\t", names[a], r[a].param[q].name, truth, x->n, mean,
                   sqrt(fmax(0, x->sum2 / x->n - mean * mean) * x->n / (x->n - 1)), x->se / x->n,
                   x->cover / x->n, x->cover_log / x->n);
            if (x->pn)
                printf("%d\t%.3f\n", x->pn, (double)x->pcover / x->pn);
            else
                printf("-\t-\n");
        }
}

int main(int argc, char **argv)
{
    static const char *const iv[] = {"none", "all", "scale"};
    nl_model *m;
    nl_synth_circulant_plan *plan;
    nl_fit_options o = {0};
    size_t g, n, K, gn[2];
    tally t[METHODS][NL_FAMILY_MAX_PARAMS] = {{{0}}};
    slot *s;
    int st, failed = 0, last = -1;
    if (argc != 7 && argc != 8) {
        fprintf(stderr, "usage: fit_coverage SPEC FAMILY NUGGET(0|1) G N K [all|scale|none]\n");
        return 2;
    }
    g = strtoul(argv[4], NULL, 10), n = strtoul(argv[5], NULL, 10), K = strtoul(argv[6], NULL, 10);
    gn[0] = gn[1] = g;
    o.family = argv[2];
    o.nugget = atoi(argv[3]);
    o.intervals = NL_FIT_INTERVALS_ALL;
    for (int i = 0; argc == 8 && i < 3; i++)
        if (strcmp(argv[7], iv[i]) == 0)
            o.intervals = (nl_fit_intervals)i;
    if (!(s = calloc(K, sizeof *s)) || (st = nl_model_parse(argv[1], &m)) ||
        (st = nl_synth_circulant_plan_alloc(m, 2, gn, NULL, 0, 8, &plan)) || (st = make_data(plan, g, n, K, s))) {
        fprintf(stderr, "fit_coverage: %s\n", s ? nl_errmsg() : "out of memory");
        return 1;
    }
#pragma omp parallel for schedule(dynamic)
    for (size_t k = 0; k < K; k++)
        s[k].st = fit_both(&s[k].p, &o, s[k].r);
    for (size_t k = 0; k < K; k++) {
        if (s[k].st) {
            failed++;
            continue;
        }
        last = (int)k;
        for (int a = 0; a < METHODS; a++)
            for (size_t q = 0; q < s[k].r[a].np; q++) {
                double truth;
                if (!s[k].r[a].param[q].fixed && !nl_model_param(m, s[k].r[a].param[q].name, &truth))
                    add(&t[a][q], truth, &s[k].r[a], q);
            }
    }
    if (last >= 0)
        print_table(m, t, s[last].r);
    if (failed)
        printf("# %d of %zu fits failed\n", failed, K);
    for (size_t k = 0; k < K; k++) {
        free(s[k].p.pts), free(s[k].p.val);
        for (int a = 0; a < METHODS; a++)
            nl_fit_result_free(&s[k].r[a]);
    }
    free(s);
    nl_synth_circulant_plan_free(plan);
    nl_model_free(m);
    return 0;
}
