/* The peers' names for the families (core/family.h, nl_family_alias)
 * against the peers' own evaluations of their models: gstat's
 * variogramLine(covariance = TRUE) and RandomFields' RFcov, run in R (each
 * test prints a skip line when R or the package is absent), and GSTools'
 * cor() as its source writes it (gstools/covmodel/models.py: cor(h) of
 * h = r / len_rescaled, len_rescaled = len_scale / rescale), transcribed
 * here.  Agreement to 1e-10 of the sill: R prints 17 digits; the Matern
 * paths differ only in the Bessel K routine (R's bessel_k against GSL's). */
#include "gstat.h"
#include "util.h"

#include "../core/family.h"
#include "../core/model.h"
#include "../core/nl_error.h"

#include <criterion/criterion.h>
#include <gsl/gsl_sf_bessel.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define NLAG 8
static const double lags[NLAG] = {0, 0.37, 1, 2.2, 4.5, 7.9, 13, 21};
#define LAGS_R "c(0, 0.37, 1, 2.2, 4.5, 7.9, 13, 21)"

/* R of spec at the lags against want[0..NLAG-1], to 1e-10 of R(0). */
static void expect_acf(const char *spec, const double *want)
{
    nl_model *m;
    cr_assert_eq(nl_model_parse(spec, &m), NL_OK, "%s: %s", spec, nl_errmsg());
    for (int i = 0; i < NLAG; i++) {
        double r = nl_model_acf(m, 1, &lags[i]);
        cr_expect(fabs(r - want[i]) <= 1e-10 * want[0], "%s at %g: %.17g, the peer %.17g", spec, lags[i], r,
                  want[i]);
    }
    nl_model_free(m);
}

struct peer_case {
    const char *spec;  /* ours, by the peer's name */
    const char *peer;  /* the peer's model, in R */
};

static void against_r(const char *library, const char *prelude, const char *fn, const struct peer_case *c, size_t n)
{
    char *script = malloc(65536);
    double *v = malloc(n * NLAG * sizeof *v);
    size_t len = (size_t)snprintf(script, 65536, "suppressMessages(library(%s))\n%sh <- " LAGS_R "\n", library,
                                  prelude);
    for (size_t i = 0; i < n; i++)
        len += (size_t)snprintf(script + len, 65536 - len, "cat(sprintf('%%.17g', %s), '\\n')\n", c[i].peer);
    (void)fn;
    cr_assert_eq(gstat_run(script, v, n * NLAG), (long)(n * NLAG), "%s: R failed:\n%s", library, script);
    for (size_t i = 0; i < n; i++)
        expect_acf(c[i].spec, v + i * NLAG);
    free(script);
    free(v);
}

#define VL(m) "variogramLine(" m ", dist_vector = h, covariance = TRUE)$gamma"

Test(family_peers, gstat)
{
    static const struct peer_case c[] = {
        {"Exp:psill=1.7,range=3", VL("vgm(1.7, 'Exp', 3)")},
        {"Sph:psill=1.7,range=9", VL("vgm(1.7, 'Sph', 9)")},
        {"Gau:psill=1.7,range=3", VL("vgm(1.7, 'Gau', 3)")},
        {"Exc:psill=1.7,range=3,kappa=1.3", VL("vgm(1.7, 'Exc', 3, kappa = 1.3)")},
        {"Exc:psill=1.7,range=3", VL("vgm(1.7, 'Exc', 3)")},
        {"Mat:psill=1.7,range=3,kappa=0.7", VL("vgm(1.7, 'Mat', 3, kappa = 0.7)")},
        {"Mat:psill=1.7,range=2,kappa=2.5", VL("vgm(1.7, 'Mat', 2, kappa = 2.5)")},
        {"Ste:psill=1.7,range=3,kappa=1.5", VL("vgm(1.7, 'Ste', 3, kappa = 1.5)")},
        {"Ste:psill=1.7,range=5,kappa=0.4", VL("vgm(1.7, 'Ste', 5, kappa = 0.4)")},
        {"Bes:psill=1.7,range=3", VL("vgm(1.7, 'Bes', 3)")},
        {"Cir:psill=1.7,range=9", VL("vgm(1.7, 'Cir', 9)")},
        {"Pen:psill=1.7,range=9", VL("vgm(1.7, 'Pen', 9)")},
        {"Lin:psill=1.7,range=9", VL("vgm(1.7, 'Lin', 9)")},
        {"Per:psill=1.7,range=9", VL("vgm(1.7, 'Per', 9)")},
        {"Nug:psill=1.7", VL("vgm(1.7, 'Nug', 0)")},
    };
    if (!gstat_available("peer aliases vs gstat's variogramLine"))
        return;
    against_r("gstat", "", "", c, sizeof c / sizeof *c);
}

static int randomfields_available(void)
{
    if (system("Rscript -e 'suppressMessages(library(RandomFields))' >/dev/null 2>&1") == 0)
        return 1;
    fprintf(stderr, "skip: peer aliases vs RFcov: Rscript with RandomFields is not installed "
                    "(Debian: r-cran-randomfields)\n");
    return 0;
}

#define RF(m) "RFcov(" m ", x = h)"

Test(family_peers_slow, randomfields)
{
    static const struct peer_case c[] = {
        {"RMexp:var=1.7,scale=3", RF("RMexp(var = 1.7, scale = 3)")},
        {"RMgauss:var=1.7,scale=3", RF("RMgauss(var = 1.7, scale = 3)")},
        {"RMspheric:var=1.7,scale=9", RF("RMspheric(var = 1.7, scale = 9)")},
        {"RMcircular:var=1.7,scale=9", RF("RMcircular(var = 1.7, scale = 9)")},
        {"RMcubic:var=1.7,scale=9", RF("RMcubic(var = 1.7, scale = 9)")},
        {"RMstable:alpha=0.8,var=1.7,scale=3", RF("RMstable(alpha = 0.8, var = 1.7, scale = 3)")},
        {"RMmatern:nu=1.5,var=1.7,scale=3", RF("RMmatern(nu = 1.5, var = 1.7, scale = 3)")},
        {"RMwhittle:nu=0.7,var=1.7,scale=3", RF("RMwhittle(nu = 0.7, var = 1.7, scale = 3)")},
        {"RMgencauchy:alpha=1.3,beta=0.6,var=1.7,scale=3", RF("RMgencauchy(alpha = 1.3, beta = 0.6, var = 1.7, "
                                                              "scale = 3)")},
        {"RMnugget:var=1.7", RF("RMnugget(var = 1.7)")},
    };
    if (!randomfields_available())
        return;
    against_r("RandomFields", "RFoptions(spConform = FALSE, printlevel = 0)\n", "", c, sizeof c / sizeof *c);
}

/* GSTools' cor() (gstools/covmodel/models.py) with its rescale factor:
 * Gaussian sqrt(pi)/2, the others 1. */
static double gstools_cor(const char *model, double h, double shape)
{
    if (strcmp(model, "Gaussian") == 0) {
        double x = h * sqrt(M_PI) / 2;
        return exp(-x * x);
    }
    if (strcmp(model, "Exponential") == 0)
        return exp(-h);
    if (strcmp(model, "Stable") == 0)
        return exp(-pow(h, shape));
    if (strcmp(model, "Matern") == 0) {
        double x = sqrt(shape) * h;
        return h == 0 ? 1 : exp((1 - shape) * M_LN2 - lgamma(shape) + shape * log(x)) * gsl_sf_bessel_Knu(shape, x);
    }
    h = fmin(h, 1);
    if (strcmp(model, "Cubic") == 0)
        return 1 - 7 * h * h + 8.75 * pow(h, 3) - 3.5 * pow(h, 5) + 0.75 * pow(h, 7);
    if (strcmp(model, "Linear") == 0)
        return 1 - h;
    if (strcmp(model, "Circular") == 0)
        return h < 1 ? 2 / M_PI * (acos(h) - h * sqrt(1 - h * h)) : 0;
    if (strcmp(model, "Spherical") == 0)
        return 1 - 1.5 * h + 0.5 * h * h * h;
    return NAN;
}

Test(family_peers, gstools)
{
    static const struct {
        const char *model;
        double shape;  /* alpha or nu; 0: none */
    } c[] = {{"Gaussian", 0}, {"Exponential", 0}, {"Stable", 0.7}, {"Matern", 0.6}, {"Matern", 2.5},
             {"Cubic", 0},    {"Linear", 0},      {"Circular", 0},  {"Spherical", 0}};
    for (size_t i = 0; i < sizeof c / sizeof *c; i++) {
        char spec[128];
        double want[NLAG], var = 1.7, len = strcmp(c[i].model, "Matern") && strcmp(c[i].model, "Gaussian") &&
                                                   strcmp(c[i].model, "Exponential") &&
                                                   strcmp(c[i].model, "Stable")
                                               ? 9
                                               : 3;
        int n = snprintf(spec, sizeof spec, "%s:var=%g,len_scale=%g", c[i].model, var, len);
        if (c[i].shape > 0)
            snprintf(spec + n, sizeof spec - (size_t)n, ",%s=%g", strcmp(c[i].model, "Stable") ? "nu" : "alpha",
                     c[i].shape);
        for (int k = 0; k < NLAG; k++)
            want[k] = var * gstools_cor(c[i].model, lags[k] / len, c[i].shape);
        expect_acf(spec, want);
    }
}

/* Every peer alias: found by its name with its family, its required keys
 * required, its ranges enforced with the key's name in the message. */
Test(family_peers, registry)
{
    size_t npeers = 0;
    for (size_t i = 0; i < nl_family_count(); i++) {
        const nl_family *f = nl_family_get(i), *g = NULL;
        for (size_t k = 0; k < f->npeers; k++) {
            const nl_family_alias *a = &f->peers[k];
            char spec[256];
            size_t len = (size_t)snprintf(spec, sizeof spec, "%s:", a->name);
            nl_model *m;
            npeers++;
            cr_assert_eq(nl_family_find_peer(a->name, strlen(a->name), &g), a, "%s", a->name);
            cr_assert_eq(g, f, "%s", a->name);
            cr_assert_null(nl_family_find(a->name, strlen(a->name)), "%s is also a family's name", a->name);
            cr_assert(a->peer && a->formula && a->convert && a->nparams <= NL_FAMILY_MAX_PARAMS, "%s", a->name);
            for (size_t q = 0; q < a->nparams; q++)
                if (isnan(a->params[q].def))
                    len += (size_t)snprintf(spec + len, sizeof spec - len, "%s=%s,", a->params[q].name,
                                            a->params[q].example);
            spec[len - 1] = len > strlen(a->name) + 1 ? 0 : spec[len - 1];
            if (spec[len - 1] == ':')
                spec[len - 1] = 0;
            cr_assert_eq(nl_model_parse(spec, &m), NL_OK, "%s: %s", spec, nl_errmsg());
            cr_assert_eq(nl_model_family(m), f, "%s", spec);
            nl_model_free(m);
            for (size_t q = 0; q < a->nparams; q++) {
                if (a->params[q].range == NL_RANGE_ANY)
                    continue;
                char bad[300];
                snprintf(bad, sizeof bad, "%s%s%s=-1", spec, strchr(spec, ':') ? "," : ":", a->params[q].name);
                cr_assert_eq(nl_model_parse(bad, &m), NL_EINVAL, "%s accepted", bad);
                cr_assert(strstr(nl_errmsg(), a->params[q].name) && strstr(nl_errmsg(), a->name), "%s: %s", bad,
                          nl_errmsg());
            }
        }
    }
    cr_assert_geq(npeers, 15, "%zu peer aliases", npeers);
}
