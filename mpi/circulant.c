/* Distributed circulant embedding: distributed FFT synthesis on the
 * embedding grid, cropped (synth/circulant.h). */
#include "fft.h"
#include "dist.h"
#include "../core/mem.h"
#include "../core/nl_error.h"
#include "../synth/circulant_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

struct nl_mpi_circulant_plan {
    MPI_Comm comm;          /* the processes (not owned) */
    int dim;                /* 2 or 3 */
    size_t n[3];            /* output grid */
    size_t m[3];            /* embedding */
    double h[3];            /* spacing */
    const nl_model *model;  /* while planning only (not kept) */
    nl_mpi_fft_plan *fft;   /* the embedding's synthesis */
    nl_synth_circulant_info info;
};

void nl_mpi_circulant_plan_free(nl_mpi_circulant_plan *p)
{
    if (!p)
        return;
    nl_mpi_fft_plan_free(p->fft);
    free(p);
}

/* The distributed plan of an embedding (nl_synth_circulant_try_fn). */
static int try_mpi(void *ctx, const size_t *mm, nl_synth_fft_info *fi)
{
    nl_mpi_circulant_plan *p = ctx;
    int st;
    nl_mpi_fft_plan_free(p->fft);
    p->fft = NULL;
    if ((st = nl_mpi_fft_plan_alloc(p->comm, p->model, p->dim, mm, p->h, NL_SYNTH_FFT_CLAMP, &p->fft)))
        return st;
    nl_mpi_fft_plan_info(p->fft, fi);
    memcpy(p->m, mm, sizeof p->m);
    return NL_OK;
}

/* The embedding of nl_synth_circulant_plan_alloc: every process decides
 * alike, the plans' sums being reduced over all of them. */
int nl_mpi_circulant_plan_alloc(MPI_Comm comm, const nl_model *m, int dim, const size_t *n, const double *h,
                                unsigned flags, int max_factor, nl_mpi_circulant_plan **out)
{
    nl_mpi_circulant_plan *p = calloc(1, sizeof *p);
    int st = p ? NL_OK : NL_ERROR(NL_ENOMEM, "out of memory");
    *out = NULL;
    if ((st = nl_mpi_agree(comm, st)))
        return st;
    p->comm = comm, p->dim = dim, p->model = m;
    for (int a = 0; a < 3; a++) {
        p->n[a] = a < dim ? n[a] : 1;
        p->h[a] = a < dim && h ? h[a] : 1;
        p->m[a] = 1;
    }
    st = nl_synth_circulant_embed(m, dim, p->n, p->h, flags, max_factor, try_mpi, p, &p->info);
    p->model = NULL;
    if (st) {
        nl_mpi_circulant_plan_free(p);
        return st;
    }
    *out = p;
    return NL_OK;
}

void nl_mpi_circulant_local(const nl_mpi_circulant_plan *p, size_t *s0, size_t *ns)
{
    size_t e0, en, N = p->n[p->dim - 1];
    nl_mpi_fft_local(p->fft, &e0, &en);
    *s0 = e0 < N ? e0 : N;
    *ns = e0 < N ? (e0 + en < N ? en : N - e0) : 0;
}

void nl_mpi_circulant_plan_info(const nl_mpi_circulant_plan *p, nl_synth_circulant_info *info) { *info = p->info; }

int nl_mpi_circulant_execute(const nl_mpi_circulant_plan *p, uint64_t seed, double *out)
{
    size_t e0, en, s0, ns, rows, mrow = p->m[0], nrow = p->n[0];
    double *w;
    int st;
    nl_mpi_fft_local(p->fft, &e0, &en);
    nl_mpi_circulant_local(p, &s0, &ns);
    w = nl_alloc((en ? en : 1) * p->m[0] * (p->dim == 3 ? p->m[1] : 1) * sizeof *w);
    /* the synthesis is collective: agree on the buffer first */
    st = w ? NL_OK : NL_ERROR(NL_ENOMEM, "out of memory for the embedding");
    if ((st = nl_mpi_agree(p->comm, st)))
        goto done;
    if ((st = nl_mpi_fft_execute(p->fft, seed, w)))
        goto done;
    /* crop: rows below n of the slowest axis, the first n samples of the others */
    rows = p->dim == 3 ? p->n[1] : 1;
    for (size_t q = 0; q < ns; q++)
        for (size_t j = 0; j < rows; j++)
            memcpy(out + (q * rows + j) * nrow, w + (q * (p->dim == 3 ? p->m[1] : 1) + j) * mrow,
                   nrow * sizeof *out);
done:
    nl_free(w);
    return st;
}
