/* The grid's place in a field's record: nl_meta_origin and
 * nl_meta_set_origin (core/provenance.h).  One representation,
 * noiselab.origin in samples, with the older "extent=" of maps and the
 * extent of georeferenced files (nl_meta.extent) still read. */
#include "provenance.h"
#include "nl_error.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The cell centres of an extent "a:b[,c:d[,e:f]]" of cell edges. */
static int legacy_extent(const char *e, int dim, const size_t *n, double *h, double *origin)
{
    const char *s = e;
    for (int d = 0; d < dim; d++) {
        char *end;
        const char *b;
        double lo = strtod(s, &end), hi;
        if (end == s || *end != ':' || !isfinite(lo))
            return NL_ERROR(NL_EINPUT, "extent \"%.60s\": expected a:b per axis", e);
        hi = strtod(b = end + 1, &end);
        if (end == b || !(hi > lo) || !isfinite(hi - lo))
            return NL_ERROR(NL_EINPUT, "extent \"%.60s\": expected a:b per axis with a < b", e);
        h[d] = (hi - lo) / (double)n[d];
        origin[d] = lo + 0.5 * h[d];
        s = end + (*end == ',');
    }
    return NL_OK;
}

int nl_meta_origin(const nl_meta *m, int dim, const size_t *n, double *h, double *origin)
{
    nl_meta only = {0};
    nl_provenance p;
    int st;
    for (int d = 0; d < 3; d++)
        origin[d] = 0;
    if (!m)
        return NL_OK;
    if (!m->origin[0] && m->extent[0]) /* a georeferenced file's (GDAL formats) */
        return legacy_extent(m->extent, dim < 2 ? dim : 2, n, h, origin);
    if (!m->origin[0] && strstr(m->method, "extent="))
        return legacy_extent(strstr(m->method, "extent=") + 7, dim, n, h, origin);
    memcpy(only.origin, m->origin, sizeof only.origin);
    if ((st = nl_provenance_parse(&only, NL_PROV_ORIGIN, &p)))
        return st;
    for (int d = 0; d < p.norigin && d < dim; d++)
        origin[d] = p.origin[d] * h[d];
    return NL_OK;
}

int nl_meta_set_origin(nl_meta *m, int dim, const double *h, const double *origin)
{
    nl_provenance p;
    nl_meta kv;
    int st;
    if (dim < 1 || dim > 3)
        return NL_ERROR(NL_EINVAL, "origin: expected 1 to 3 axes, got %d", dim);
    nl_provenance_init(&p);
    p.nspacing = p.norigin = dim;
    for (int d = 0; d < dim; d++) {
        double x = origin[d] / h[d];
        if (!(h[d] > 0) || !isfinite(h[d]) || !isfinite(origin[d]) || !isfinite(x))
            return NL_ERROR(NL_EINVAL, "origin: axis %d: expected a finite origin and a positive finite spacing, "
                            "got %g and %g", d, origin[d], h[d]);
        p.h[d] = h[d];
        p.origin[d] = fabs(x - nearbyint(x)) <= 1e-9 * fmax(1, fabs(x)) ? nearbyint(x) : x;
    }
    if ((st = nl_provenance_format(&p, &kv)))
        return st;
    memcpy(m->spacing, kv.spacing, sizeof m->spacing);
    memcpy(m->origin, kv.origin, sizeof m->origin);
    return NL_OK;
}
