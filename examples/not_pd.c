/* A covariance that is not positive definite gets a status, not an abort:
 * R(t) = 1 - |t|/3 grows negative without bound, so its covariance matrix
 * on 64 samples has negative eigenvalues and its Cholesky factorisation
 * fails.  This program leaves GSL's error handler as it is (the default
 * one aborts); the library turns GSL's error into NL_ENOTPD.
 * Exit status 0 when the plan returns NL_ENOTPD, 1 otherwise.
 * Build: cc not_pd.c $(pkg-config --cflags --libs noiselab) */
#include <noiselab.h>

#include <stdio.h>

int main(void)
{
    const size_t n[1] = {64};
    nl_model *m = NULL;
    nl_synth_cholesky_plan *plan = NULL;

    int st = nl_model_parse("expr:1-abs(t)/3", &m);
    if (st == NL_OK)
        st = nl_synth_cholesky_plan_alloc(m, 1, n, NULL, &plan);
    printf("status %d (%s): %s\n", st, st == NL_ENOTPD ? "NL_ENOTPD, as expected" : "expected NL_ENOTPD",
           st == NL_OK ? "" : nl_errmsg());
    nl_synth_cholesky_plan_free(plan);
    nl_model_free(m);
    return st == NL_ENOTPD ? 0 : 1;
}
