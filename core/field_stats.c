/* Mean, variance and rms of a field's samples. */
#include "field_stats.h"

#include <math.h>

void nl_field_mean_var(const nl_field *f, double *mean, double *var)
{
    double m = 0, v = 0;
    for (size_t i = 0; i < f->count; i++)
        m += f->data[i] / (double)f->count;
    for (size_t i = 0; i < f->count; i++)
        v += (f->data[i] - m) * (f->data[i] - m) / (double)f->count;
    *mean = m, *var = v;
}

double nl_field_rms(const nl_field *f)
{
    double s = 0;
    for (size_t i = 0; i < f->count; i++)
        s += f->data[i] * f->data[i] / (double)f->count;
    return sqrt(s);
}
