/* Centred views of wrapped spectra and ACF estimates. */
#include "fftshift.h"
#include "../core/nl_error.h"

#include <math.h>

int nl_fftshift_alloc(const nl_field *P, nl_field **out)
{
    int st;
    nl_field *C = nl_field_alloc(P->dim, P->n, P->h, &st);
    const size_t *n = P->n;
    *out = NULL;
    if (!C)
        return st;
    for (size_t k = 0; k < n[2]; k++)
        for (size_t j = 0; j < n[1]; j++)
            for (size_t i = 0; i < n[0]; i++)
                C->data[(((k + n[2] / 2) % n[2]) * n[1] + (j + n[1] / 2) % n[1]) * n[0] + (i + n[0] / 2) % n[0]] =
                    P->data[(k * n[1] + j) * n[0] + i];
    *out = C;
    return NL_OK;
}

int nl_acf_centred_alloc(const nl_field *full, nl_field **out)
{
    size_t cn[3] = {1, 1, 1};
    int st;
    nl_field *C;
    *out = NULL;
    for (int a = 0; a < full->dim; a++) {
        if (full->n[a] % 2)
            return NL_ERROR(NL_EINVAL, "centred ACF: expected an even axis (2 n samples), got %zu", full->n[a]);
        cn[a] = full->n[a] - 1;
    }
    if (!(C = nl_field_alloc(full->dim, cn, full->h, &st)))
        return st;
    for (size_t k = 0; k < cn[2]; k++)
        for (size_t j = 0; j < cn[1]; j++)
            for (size_t i = 0; i < cn[0]; i++) {
                size_t idx[3] = {i, j, k}, src[3];
                for (int a = 0; a < 3; a++) {
                    long l = a < full->dim ? (long)idx[a] - (long)(full->n[a] / 2 - 1) : 0;
                    src[a] = (size_t)(l < 0 ? l + (long)full->n[a] : l);
                }
                C->data[(k * cn[1] + j) * cn[0] + i] =
                    full->data[(src[2] * full->n[1] + src[1]) * full->n[0] + src[0]];
            }
    *out = C;
    return NL_OK;
}

double nl_fftshift_log10_floor(nl_field *f, double rel)
{
    double mx = 0;
    for (size_t q = 0; q < f->count; q++)
        mx = fmax(mx, f->data[q]);
    for (size_t q = 0; q < f->count; q++)
        f->data[q] = log10(fmax(f->data[q], mx * rel));
    return mx;
}
