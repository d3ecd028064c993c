/* Philox4x32-10 counter-based Gaussian numbers. */
#include "rng.h"
#include "gsl_guard_internal.h"

#include <gsl/gsl_cdf.h>
#include <math.h>
#include <Random123/philox.h>
#include <Random123/u01fixedpt.h>

static philox4x32_ctr_t block2(uint64_t seed, uint32_t stream, uint64_t index, uint32_t sub)
{
    philox4x32_ctr_t c = {{(uint32_t)index, (uint32_t)(index >> 32), stream, sub}};
    philox4x32_key_t k = {{(uint32_t)seed, (uint32_t)(seed >> 32)}};
    return philox4x32(c, k);
}

static uint64_t join(uint32_t lo, uint32_t hi) { return ((uint64_t)hi << 32) | lo; }

double nl_rng_uniform(uint64_t seed, uint32_t stream, uint64_t index)
{
    return nl_rng_uniform2(seed, stream, index, 0);
}

double nl_rng_gauss(uint64_t seed, uint32_t stream, uint64_t index)
{
    return nl_rng_gauss2(seed, stream, index, 0);
}

double nl_rng_uniform2(uint64_t seed, uint32_t stream, uint64_t index, uint32_t sub)
{
    philox4x32_ctr_t r = block2(seed, stream, index, sub);
    return u01fixedpt_open_open_64_double(join(r.v[0], r.v[1]));
}

double nl_rng_gauss2(uint64_t seed, uint32_t stream, uint64_t index, uint32_t sub)
{
    philox4x32_ctr_t r = block2(seed, stream, index, sub);
    double u1 = u01fixedpt_open_open_64_double(join(r.v[0], r.v[1]));
    double u2 = u01fixedpt_open_open_64_double(join(r.v[2], r.v[3]));
    /* Box and Muller (1958) */
    return sqrt(-2.0 * log(u1)) * cos(2.0 * M_PI * u2);
}

void nl_rng_gauss_pair(uint64_t seed, uint32_t stream, uint64_t index, double g[2])
{
    philox4x32_ctr_t r = block2(seed, stream, index, 0);
    double u1 = u01fixedpt_open_open_64_double(join(r.v[0], r.v[1]));
    double u2 = u01fixedpt_open_open_64_double(join(r.v[2], r.v[3]));
    double rad = sqrt(-2.0 * log(u1)), s, c;
    sincos(2.0 * M_PI * u2, &s, &c);
    g[0] = rad * c;
    g[1] = rad * s;
}

unsigned long nl_rng_poisson(uint64_t seed, uint32_t stream, uint64_t index, uint32_t sub, double mean)
{
    double u = nl_rng_uniform2(seed, stream, index, sub);
    unsigned long lo = 0, hi = (unsigned long)(mean + 20 * sqrt(mean) + 20);
    if (!(mean > 0))
        return 0;
    nl_gsl_enter();
    while (lo < hi) {
        unsigned long mid = lo + (hi - lo) / 2;
        if (gsl_cdf_poisson_P((unsigned)mid, mean) < u)
            lo = mid + 1;
        else
            hi = mid;
    }
    nl_gsl_leave();
    return lo;
}
