/* Ordinary kriging of a few scattered values (Stam and Fiume): the plan
 * factorises the covariance of the data once, then estimates anywhere.
 * Checks that kriging interpolates: at a data point the estimate is the
 * datum and the kriging variance is zero (to rounding).
 * Build: cc krige.c $(pkg-config --cflags --libs noiselab) */
#include <noiselab.h>

#include <math.h>
#include <stdio.h>

int main(void)
{
    static const double pts[5][2] = {{0.1, 0.2}, {0.8, 0.3}, {0.5, 0.5}, {0.2, 0.9}, {0.7, 0.8}};
    static const double val[5] = {1.3, -0.4, 0.7, 2.1, 0.2};
    nl_model *m = NULL;
    nl_krige_plan *plan = NULL;
    int ok = 1;

    int st = nl_model_parse("gauss:scale=0.3", &m);
    if (st == NL_OK)
        st = nl_krige_plan_alloc(m, 2, 5, &pts[0][0], val, 0, 0.0, 0, &plan);
    for (int i = 0; st == NL_OK && i < 5; i++) { /* at the data */
        double est, var;
        st = nl_krige_eval(plan, pts[i], &est, &var, NULL);
        if (st == NL_OK && (fabs(est - val[i]) > 1e-8 || fabs(var) > 1e-8))
            ok = 0;
    }
    for (int i = 0; st == NL_OK && i <= 4; i++) { /* along the diagonal */
        double x[2] = {0.25 * i, 0.25 * i}, est, var;
        st = nl_krige_eval(plan, x, &est, &var, NULL);
        if (st == NL_OK)
            printf("(%.2f, %.2f)\testimate %.4f\tvariance %.4f\n", x[0], x[1], est, var);
    }
    if (st != NL_OK)
        fprintf(stderr, "krige: %s\n", nl_errmsg());
    else if (!ok)
        fprintf(stderr, "krige: the estimate at a data point is not the datum\n");
    nl_krige_plan_free(plan);
    nl_model_free(m);
    return st == NL_OK && ok ? 0 : 1;
}
