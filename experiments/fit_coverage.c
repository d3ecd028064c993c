/* Do fitted parameters' standard errors describe their spread?  K fields of
 * a known model (circulant embedding, exact, on a G x G grid of unit
 * spacing, seeds 1..K), N distinct grid nodes drawn from each (seeded
 * uniform draws, so the data are exact samples of the field), the model's
 * family fitted by ML (nl_fit_ml) and by WLS on the Matheron variogram with
 * Cressie's weights (nl_fit_variogram, gstat's default width and cutoff).
 *
 * usage: fit_coverage SPEC FAMILY NUGGET(0|1) G N K
 *   prints per method and parameter, tab-separated: method, parameter,
 *   true value, fits that succeeded, mean estimate, sd of the estimates,
 *   mean reported standard error, coverage of the Wald interval est +-
 *   1.96 se, coverage of the log-scale interval est exp(+-1.96 se / est). */
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
    double sum, sum2, se, cover, cover_log;  /* over successful fits */
    int n;                                   /* successful fits */
} tally;

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

static void add(tally *t, double truth, double est, double se)
{
    t->n++;
    t->sum += est;
    t->sum2 += est * est;
    t->se += se;
    t->cover += fabs(est - truth) <= 1.96 * se;
    t->cover_log += fabs(log(est / truth)) <= 1.96 * se / est;
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
        ml.start = r[1].value;  /* ML starts from the WLS fit */
        st = nl_fit_ml(p->pts, p->val, p->n, 2, &ml, &r[0]);
    }
    return st;
}

int main(int argc, char **argv)
{
    static const char *names[METHODS] = {"ml", "wls-cressie"};
    nl_model *m;
    nl_synth_circulant_plan *plan;
    nl_fit_options o = {0};
    size_t g, n, K, gn[2];
    tally t[METHODS][NL_FIT_MAX_PARAMS] = {{{0}}};
    nl_fit_result r[METHODS];
    int st, failed = 0;
    if (argc != 7) {
        fprintf(stderr, "usage: fit_coverage SPEC FAMILY NUGGET(0|1) G N K\n");
        return 2;
    }
    g = strtoul(argv[4], NULL, 10), n = strtoul(argv[5], NULL, 10), K = strtoul(argv[6], NULL, 10);
    gn[0] = gn[1] = g;
    o.family = argv[2];
    o.nugget = atoi(argv[3]);
    if ((st = nl_model_parse(argv[1], &m)) || (st = nl_synth_circulant_plan_alloc(m, 2, gn, NULL, 0, 8, &plan))) {
        fprintf(stderr, "fit_coverage: %s\n", nl_errmsg());
        return 1;
    }
    {
        nl_field *f = nl_field_alloc(2, gn, NULL, &st);
        nl_points p = {2, n, malloc(2 * n * sizeof(double)), malloc(n * sizeof(double))};
        for (size_t k = 0; k < K; k++) {
            if (nl_synth_circulant_execute(plan, k + 1, f))
                return 1;
            sample_nodes(f, g, n, k + 1, &p);
            if (fit_both(&p, &o, r)) {
                failed++;
                continue;
            }
            for (int a = 0; a < METHODS; a++)
                for (size_t q = 0; q < r[a].np; q++) {
                    double truth;
                    if (!r[a].fixed[q] && !nl_model_param(m, r[a].name[q], &truth) && isfinite(r[a].se[q]))
                        add(&t[a][q], truth, r[a].value[q], r[a].se[q]);
                }
        }
        nl_field_free(f);
        free(p.pts);
        free(p.val);
    }
    printf("method\tparameter\ttrue\tfits\tmean\tsd\tmean_se\tcoverage\tcoverage_log\n");
    for (int a = 0; a < METHODS; a++)
        for (size_t q = 0; q < r[a].np; q++) {
            tally *x = &t[a][q];
            double truth, mean = x->sum / x->n;
            if (!x->n || nl_model_param(m, r[a].name[q], &truth))
                continue;
            printf("%s\t%s\t%g\t%d\t%.4g\t%.4g\t%.4g\t%.3f\t%.3f\n", names[a], r[a].name[q], truth, x->n, mean,
                   sqrt(fmax(0, x->sum2 / x->n - mean * mean) * x->n / (x->n - 1)), x->se / x->n,
                   x->cover / x->n, x->cover_log / x->n);
        }
    if (failed)
        printf("# %d of %zu fits failed\n", failed, K);
    nl_synth_circulant_plan_free(plan);
    nl_model_free(m);
    return 0;
}
