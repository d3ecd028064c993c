/* Mean and standard error over realizations, column by column. */
#include "ensemble.h"
#include "../core/nl_error.h"

#include <math.h>

int nl_ensemble_mean_se(const double *v, size_t K, size_t m, double *mean, double *se)
{
    if (K < 2 || m == 0)
        return NL_ERROR(NL_EINVAL, "ensemble: expected at least 2 realizations of at least 1 value, got %zu of %zu",
                        K, m);
    for (size_t i = 0; i < m; i++) {
        double s = 0, ss = 0;
        for (size_t r = 0; r < K; r++)
            s += v[r * m + i];
        s /= (double)K;
        for (size_t r = 0; r < K; r++)
            ss += (v[r * m + i] - s) * (v[r * m + i] - s);
        mean[i] = isfinite(s) ? s : NAN;
        if (se)
            se[i] = isfinite(s) && isfinite(ss) ? sqrt(ss / ((double)(K - 1) * (double)K)) : NAN;
    }
    return NL_OK;
}
