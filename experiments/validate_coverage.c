/* How often do validate's 95% intervals hold the true error, and how often
 * does its z test raise a false alarm?  K independent ensembles (first
 * seeds 1, 1 + M, 1 + 2M, ...) of one model and method in 1D; the true
 * largest error over the tested lags is 0 for the exact methods (fft,
 * circulant, sparse up to its kernel's truncation) and subdivision's
 * exact-ACF error for subdiv (analysis/subdiv_exact.h).
 *
 * usage: validate_coverage SPEC METHOD N M K [DIM]  (N^DIM grid, DIM 1 by default)
 *   prints, tab-separated: ensembles, coverage of the effect-size interval
 *   (nominal >= 0.95), false alarms of the z test at 1e-3 (exact methods;
 *   nominal <= 0.001), the share of intervals excluding 0 (the resolution of
 *   a real error), for subdiv the coverage of 0 by its interval against
 *   its own exact ACF, and the coverage of 0 by the spectrum's largest band
 *   error (nominal >= 0.95 for the exact methods). */
#include "../analysis/validate.h"
#include "../core/model.h"
#include "../core/nl_error.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static nl_validate_result res;

static int method_of(const char *name)
{
    for (int k = 0; k < nl_validate_method_count(); k++)
        if (strcmp(name, nl_validate_method_name(k)) == 0)
            return k;
    return -1;
}

int main(int argc, char **argv)
{
    nl_model *m;
    nl_validate_options o;
    int meth = argc == 6 || argc == 7 ? method_of(argv[2]) : -1, dim = argc == 7 ? atoi(argv[6]) : 1;
    size_t n[3], K, cover = 0, alarms = 0, resolved = 0, exact_cover = 0, spectrum_cover = 0, runs = 0;
    if (meth < 0 || nl_model_parse(argv[1], &m)) {
        fprintf(stderr, "usage: validate_coverage SPEC fft|circulant|subdiv|sparse N M K [DIM]\n%s\n", nl_errmsg());
        return 2;
    }
    n[0] = n[1] = n[2] = strtoul(argv[3], NULL, 10), K = strtoul(argv[5], NULL, 10);
    nl_validate_options_default(&o);
    o.realizations = strtoul(argv[4], NULL, 10);
    for (size_t k = 0; k < K; k++) {
        const nl_validate_method_result *r = &res.method[meth];
        double truth;
        o.seed = 1 + k * o.realizations;
        if (nl_validate_init(m, dim, n, 1, &o, &res) || nl_validate_method(m, meth, &o, &res) || !r->ran) {
            fprintf(stderr, "validate_coverage: %s\n", r->ran ? nl_errmsg() : r->why);
            return 1;
        }
        truth = res.method[meth].have_exact ? res.exact_effect : 0;
        runs++;
        cover += r->all.effect.lo <= truth && truth <= r->all.effect.hi;
        alarms += !r->pass;
        resolved += r->all.effect.lo > 0;
        exact_cover += r->have_exact && r->vs_exact.effect.lo == 0;
        spectrum_cover += r->spectrum_error.lo == 0;
    }
    printf("ensembles\tcoverage\tz_alarms\texcluding_0\texact_coverage\tspectrum_coverage\ttrue_error\n"
           "%zu\t%.3f\t%.3f\t%.3f\t%.3f\t%.3f\t%.4g\n", runs, (double)cover / runs, (double)alarms / runs,
           (double)resolved / runs, (double)exact_cover / runs, (double)spectrum_cover / runs,
           res.method[meth].have_exact ? res.exact_effect : 0.0);
    nl_model_free(m);
    return 0;
}
