/* noiselab-mpi's distributed analysis: the slab of an .h5 field read
 * collectively (mpi/h5.h) and the estimators of mpi/analysis.h on it, over
 * every process of the run. */
#include "h5_analysis.h"
#include "../core/mem.h"
#include "../core/nl_error.h"
#include "../core/provenance.h"
#include "../mpi/analysis.h"
#include "../mpi/dist.h"
#include "../mpi/h5.h"

#include <stdlib.h>

static nl_mpi_slab slab_of(const cli_slab *s)
{
    nl_mpi_slab x = {.comm = MPI_COMM_WORLD, .dim = s->dim, .s0 = s->s0, .ns = s->ns, .data = s->data};
    for (int a = 0; a < 3; a++)
        x.n[a] = s->n[a], x.h[a] = s->h[a];
    return x;
}

static int read_slab(const char *path, cli_slab *s)
{
    nl_meta meta;
    int st;
    s->data = NULL;
    st = nl_mpi_h5_read_slab(path, MPI_COMM_WORLD, &s->dim, s->n, s->h, &meta, &s->s0, &s->ns, &s->data);
    if (!st && !(st = nl_meta_origin(&meta, s->dim, s->n, s->h, s->origin)))
        s->origin[s->dim - 1] += (double)s->s0 * s->h[s->dim - 1];
    return st;
}

static void slab_free(cli_slab *s)
{
    nl_free(s->data);
    s->data = NULL;
}

static int acf(const cli_slab *s, double mean, int unbiased, int radial, int axis, size_t nl, double *lag,
               double *val)
{
    nl_mpi_slab x = slab_of(s);
    size_t *cnt;
    int st;
    if (!radial)
        return nl_mpi_acf_axis(&x, mean, unbiased, axis, nl - 1, lag, val);
    cnt = malloc(nl * sizeof *cnt);
    st = nl_mpi_agree(MPI_COMM_WORLD, cnt ? NL_OK : NL_ERROR(NL_ENOMEM, "out of memory for %zu lags", nl));
    if (!st)
        st = nl_mpi_acf_radial(&x, mean, unbiased, nl, lag, val, cnt);
    free(cnt);
    return st;
}

static int psd(const cli_slab *s, double mean, double *freq, double *val, size_t *nf, size_t nsec, double flo,
               double fhi, double *sector, double *aniso, const double *band, nl_slope *sl)
{
    nl_mpi_slab x = slab_of(s);
    nl_mpi_psd_more more = {.nsec = nsec, .flo = flo, .fhi = fhi, .sector = sector, .slope = band != NULL};
    size_t *cnt = malloc(nl_mpi_psd_profile_size(s->dim, s->n, s->h) * sizeof *cnt);
    int st = nl_mpi_agree(MPI_COMM_WORLD, cnt ? NL_OK : NL_ERROR(NL_ENOMEM, "out of memory for the profile"));
    if (band)
        more.fmin = band[0], more.fmax = band[1];
    if (!st)
        st = nl_mpi_psd(&x, mean, freq, val, cnt, nf, &more);
    if (!st && sector)
        *aniso = more.aniso;
    if (!st && band)
        *sl = more.sl;
    free(cnt);
    return st;
}

static int hist(const cli_slab *s, size_t bins, nl_moments *m, double *edges, double *counts)
{
    nl_mpi_slab x = slab_of(s);
    int st = nl_mpi_moments(&x, m);
    return st ? st : nl_mpi_hist(&x, bins, edges, counts);
}

void cli_h5_analysis_hooks(cli_h5_hooks *h)
{
    h->read_slab = read_slab, h->slab_free = slab_free;
    h->acf = acf, h->psd = psd, h->hist = hist;
}
