/* noiselab validate: the verdict as JSON, and the report in DIR. */
#include "validate_report.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#define NM NL_VALIDATE_METHODS
#define ND NL_VALIDATE_DIRS

/* The exit status (cmd_validate.c's help): the model's validity, then each
 * method against its own claim (nl_validate_claim). */
int cli_validate_status(const cli_validate *v)
{
    int judged = 0, unresolved = 0;
    if (!v->k.positive_definite)
        return 4;
    for (int meth = 0; meth < NM; meth++) {
        int verdict;
        nl_validate_claim(&v->r, meth, &verdict);
        if (verdict == NL_VALIDATE_OFF)
            return 3;
        unresolved |= verdict == NL_VALIDATE_UNRESOLVED;
        judged += verdict >= 0;
    }
    return unresolved ? 5 : judged ? 0 : 3;
}

const char *cli_validate_claim_name(int claim)
{
    return claim == NL_VALIDATE_CLAIM_MODEL ? "model" : claim == NL_VALIDATE_CLAIM_OWN ? "own exact ACF" : "none";
}

double cli_validate_to_resolve(const nl_validate_result *res, const nl_validate_method_result *r)
{
    double half = r->all.effect.hi - r->all.effect.est, gap = fabs(res->tolerance - r->all.effect.est);
    if (!r->ran || r->verdict != NL_VALIDATE_UNRESOLVED || !(gap > 0))
        return 0;
    return ceil((double)res->realizations * (half / gap) * (half / gap));
}

/* A JSON number, or null where it is undefined. */
static json_t *num(double x) { return isfinite(x) ? json_real(x) : json_null(); }

static json_t *interval(const nl_validate_interval *i)
{
    return json_pack("{s:o,s:o,s:o}", "estimate", num(i->est), "lo", num(i->lo), "hi", num(i->hi));
}

static json_t *lag_json(const long *l, int dim)
{
    json_t *a = json_array();
    for (int k = 0; k < dim; k++)
        json_array_append_new(a, json_integer(l[k]));
    return a;
}

static json_t *effect_json(const nl_validate_effect *e, int dim)
{
    return json_pack("{s:o,s:o,s:o,s:o}", "effect", interval(&e->effect), "worst_lag", lag_json(e->worst, dim),
                     "max_abs_z", num(e->zmax), "detectable", num(e->detectable));
}

static json_t *array(const double *x, size_t n)
{
    json_t *a = json_array();
    for (size_t i = 0; i < n; i++)
        json_array_append_new(a, num(x[i]));
    return a;
}

static json_t *spectrum_json(const nl_validate_result *res, const nl_validate_method_result *r)
{
    json_t *b = json_array();
    for (size_t k = 0; k < res->nbands; k++)
        json_array_append_new(b, json_pack("{s:o,s:o,s:o}", "mean", num(r->band_mean[k]), "se", num(r->band_se[k]),
                                           "relative_error", interval(&r->band_error[k])));
    return json_pack("{s:s,s:o,s:o}", "expected",
                     nl_validate_method_periodic((int)(r - res->method)) ? "periodic" : "fejer",
                     "max_relative_error", interval(&r->spectrum_error), "bands", b);
}

static json_t *method_json(const cli_validate *v, int meth)
{
    const nl_validate_result *res = &v->r;
    const nl_validate_method_result *r = &res->method[meth];
    json_t *o, *dirs = json_object(), *acf = json_object();
    if (!r->ran)
        return json_pack("{s:b,s:s,s:s,s:o}", "ran", 0, "refused",
                         v->k.positive_definite ? r->why : "the model is not positive definite", "verdict",
                         "refused", "seconds", num(r->seconds));
    for (int d = 0; d < ND; d++)
        if (res->nlag[d]) {
            json_object_set_new(dirs, nl_validate_dir_name(d), effect_json(&r->dir[d], v->dim));
            json_object_set_new(acf, nl_validate_dir_name(d), json_pack("{s:o,s:o}", "mean", array(r->mean[d], res->nlag[d]),
                                                                        "se", array(r->se[d], res->nlag[d])));
        }
    o = json_pack("{s:b,s:s,s:o,s:o,s:b,s:o,s:o}", "ran", 1, "verdict", nl_validate_verdict_name(r->verdict),
                  "seconds", num(r->seconds), "effect", effect_json(&r->all, v->dim), "error_detected", !r->pass,
                  "variance_ratio", interval(&r->variance), "directions", dirs);
    if (r->verdict == NL_VALIDATE_UNRESOLVED)
        json_object_set_new(o, "realizations_to_resolve", num(cli_validate_to_resolve(res, r)));
    if (res->nmap)
        json_object_set_new(o, "map", effect_json(&r->map, v->dim));
    if (r->have_exact)
        json_object_set_new(o, "vs_exact", effect_json(&r->vs_exact, v->dim));
    {
        int verdict, claim = nl_validate_claim(&v->r, meth, &verdict);
        json_object_set_new(o, "claim", json_string(cli_validate_claim_name(claim)));
        json_object_set_new(o, "claim_verdict",
                            verdict >= 0 ? json_string(nl_validate_verdict_name(verdict)) : json_null());
    }
    json_object_set_new(o, "spectrum", spectrum_json(res, r));
    json_object_set_new(o, "acf", acf);
    return o;
}

/* The lags, targets, bands and subdivision's exact ACF. */
static json_t *setup_json(const cli_validate *v)
{
    const nl_validate_result *res = &v->r;
    json_t *lags = json_object(), *target = json_object(), *bands = json_array(), *exact = json_object();
    for (int d = 0; d < ND; d++)
        if (res->nlag[d]) {
            json_object_set_new(lags, nl_validate_dir_name(d), json_integer((json_int_t)res->nlag[d]));
            json_object_set_new(target, nl_validate_dir_name(d), array(res->target[d], res->nlag[d]));
            if (res->have_exact)
                json_object_set_new(exact, nl_validate_dir_name(d), array(res->exact[d], res->nlag[d]));
        }
    json_object_set_new(lags, "map", json_integer((json_int_t)res->nmap));
    for (size_t b = 0; b < res->nbands; b++)
        json_array_append_new(bands, json_pack("{s:o,s:o,s:o,s:o}", "f_lo", num(res->band_lo[b]), "f_hi",
                                               num(res->band_hi[b]), "expected_periodic", num(res->band_periodic[b]),
                                               "expected_fejer", num(res->band_fejer[b])));
    if (res->have_exact) {
        json_object_set_new(exact, "effect_vs_target", num(res->exact_effect));
        json_object_set_new(exact, "worst_lag", lag_json(res->exact_worst, v->dim));
    }
    return json_pack("{s:o,s:o,s:o,s:o}", "lags", lags, "target", target, "bands", bands, "subdiv_exact",
                     res->have_exact ? exact : (json_decref(exact), json_null()));
}

json_t *cli_validate_json(const cli_validate *v)
{
    const nl_validate_result *res = &v->r;
    json_t *o, *methods = json_object(), *size = json_array();
    for (int a = 0; a < v->dim; a++)
        json_array_append_new(size, json_integer((json_int_t)res->n[a]));
    o = json_pack("{s:s,s:s,s:i,s:o,s:I,s:b,s:o,s:o,s:I,s:o,s:o,s:s}", "model", nl_model_spec(v->m), "given_as",
                  v->spectral ? "spectrum" : "acf", "dim", v->dim, "size", size, "realizations",
                  (json_int_t)res->realizations, "positive_definite", v->k.positive_definite, "tolerance",
                  num(res->tolerance), "alpha", num(res->alpha), "lags_tested", (json_int_t)res->ntests, "threshold",
                  num(res->threshold), "ci_factor", num(res->ci_factor), "verdict_uses", "target");
    json_t *setup = setup_json(v);
    json_object_update(o, setup);
    json_decref(setup);
    for (int meth = 0; meth < NM; meth++)
        json_object_set_new(methods, nl_validate_method_name(meth), method_json(v, meth));
    /* JSON integers are signed 64-bit: a larger seed is given as its decimal string */
    if (res->seed > (uint64_t)INT64_MAX) {
        char buf[32];
        snprintf(buf, sizeof buf, "%llu", (unsigned long long)res->seed);
        json_object_set_new(o, "first_seed", json_string(buf));
    } else
        json_object_set_new(o, "first_seed", json_integer((json_int_t)res->seed));
    json_object_set_new(o, "methods", methods);
    json_object_set_new(o, "exit_status", json_integer(cli_validate_status(v)));
    return o;
}
