/* The image: model, the empirical autocorrelation of an exemplar. */
#include "autocorr.h"
#include "io.h"
#include "model_internal.h"
#include "nl_error.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Lewis 1987, eq. (15): R(y, x) = 1/N^2 sum p[r, c] p[r + y, c + x], with the
 * exemplar's mean removed first (a zero-mean process is modelled). */
int nl_model_image_load(nl_model *m, const char *path)
{
    nl_field *img, *c;
    int st = nl_field_read(path, &img, NULL);
    if (st)
        return st;
    if (img->dim == 3) {
        nl_field_free(img);
        return NL_ERROR(NL_EINVAL, "image: %s: expected a 1D or 2D exemplar, got a 3D field", path);
    }
    st = nl_autocorr_sums(img, nl_field_mean(img), &c);
    if (!st) {
        for (size_t i = 0; i < c->count; i++)
            c->data[i] /= (double)img->count;
        m->tw = c->n[0];
        m->th = c->n[1];
        m->table = malloc(c->count * sizeof *m->table);
        if (m->table)
            memcpy(m->table, c->data, c->count * sizeof *m->table);
        else
            st = NL_ERROR(NL_ENOMEM, "out of memory");
        nl_field_free(c);
        if (!st && !(m->table[0] > 0))
            st = NL_ERROR(NL_EINVAL, "image: %s: the exemplar is constant (variance 0)", path);
    }
    nl_field_free(img);
    return st;
}

static double at(const nl_model *m, long i, long j)
{
    long hw = (long)m->tw / 2, hh = (long)m->th / 2;
    if (i <= -hw || i >= hw || (m->th > 1 && (j <= -hh || j >= hh)) || (m->th == 1 && j != 0))
        return 0.0;
    if (i < 0)
        i += (long)m->tw;
    if (j < 0)
        j += (long)m->th;
    return m->table[(size_t)j * m->tw + (size_t)i];
}

double nl_model_image_acf(const nl_model *m, double dx, double dy)
{
    double fx = floor(dx), fy = floor(dy), ax = dx - fx, ay = dy - fy;
    long i = (long)fx, j = (long)fy;
    return (1 - ay) * ((1 - ax) * at(m, i, j) + ax * at(m, i + 1, j)) +
           ay * ((1 - ax) * at(m, i, j + 1) + ax * at(m, i + 1, j + 1));
}
