/* The Wiener-interpolated noise lattice (synth/lattice.h). */
#include "lattice.h"
#include "fft.h"
#include "../core/gsl_guard_internal.h"
#include "../core/mem.h"
#include "../core/nl_error.h"
#include "method.h"

#include <gsl/gsl_linalg.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define WK NL_LATTICE_WIENER_K
#define WN (2 * WK)

struct nl_synth_lattice_wiener_plan {
    int dim, cell, nw;            /* nw = WN^dim weights per offset */
    size_t n[2], nodes[2];        /* output and lattice sizes (1 beyond dim) */
    double *w;                    /* cell^dim offsets x nw weights, offset (ux, uy) at (uy cell + ux) nw */
    nl_synth_fft_plan *fft;       /* the lattice's FFT synthesis */
    nl_synth_lattice_wiener_info info;
};

/* R at lag (dx, dy) samples. */
static double cov(const nl_model *m, int dim, double dx, double dy)
{
    double lag[3] = {dx, dy, 0};
    return nl_model_acf(m, dim, lag);
}

/* Node q of the neighbourhood at (px, py) samples from the cell's first node. */
static void node_pos(int dim, int cell, int q, double *px, double *py)
{
    *px = (double)(q % WN - WK + 1) * cell;
    *py = dim == 2 ? (double)(q / WN - WK + 1) * cell : 0;
}

/* C = U S V^T once; w(u) = V S^+ U^T r(u) for every offset. */
static int solve_weights(const nl_model *m, nl_synth_lattice_wiener_plan *p)
{
    int dim = p->dim, nw = p->nw, c = p->cell, st = NL_OK;
    size_t noff = dim == 2 ? (size_t)c * (size_t)c : (size_t)c;
    double r0 = cov(m, dim, 0, 0), emean = 0, emax = 0;
    nl_gsl_enter();
    gsl_matrix *U = gsl_matrix_alloc((size_t)nw, (size_t)nw), *V = gsl_matrix_alloc((size_t)nw, (size_t)nw);
    gsl_vector *S = gsl_vector_alloc((size_t)nw), *work = gsl_vector_alloc((size_t)nw);
    gsl_vector *r = gsl_vector_alloc((size_t)nw), *x = gsl_vector_alloc((size_t)nw);
    if (!U || !V || !S || !work || !r || !x) {
        st = NL_ERROR(NL_ENOMEM, "out of memory");
        goto done;
    }
    for (int a = 0; a < nw; a++)
        for (int b = 0; b < nw; b++) {
            double ax, ay, bx, by;
            node_pos(dim, c, a, &ax, &ay), node_pos(dim, c, b, &bx, &by);
            gsl_matrix_set(U, (size_t)a, (size_t)b, cov(m, dim, ax - bx, ay - by));
        }
    for (int a = 0; a < nw * nw; a++)
        if (!isfinite(U->data[a])) {
            st = NL_ERROR(NL_EINVAL, "lattice: %s: R is not finite at a node lag; expected a model with R in closed "
                          "form (the Wiener lattice needs R)", nl_model_spec(m));
            goto done;
        }
    int gst = gsl_linalg_SV_decomp(U, V, S, work);
    if (gst) {
        st = NL_ERROR(NL_EFAIL, "lattice: the SVD of the node covariance failed: %s", nl_gsl_reason(gst));
        goto done;
    }
    p->info.rank = 0;
    for (int a = 0; a < nw; a++)
        if (gsl_vector_get(S, (size_t)a) > 1e-13 * gsl_vector_get(S, 0))
            p->info.rank++;
        else
            gsl_vector_set(S, (size_t)a, 0); /* gsl_linalg_SV_solve skips zero singular values */
    for (size_t o = 0; o < noff; o++) {
        double ux = (double)(o % (size_t)c), uy = dim == 2 ? (double)(o / (size_t)c) : 0, e = r0;
        for (int a = 0; a < nw; a++) {
            double ax, ay;
            node_pos(dim, c, a, &ax, &ay);
            gsl_vector_set(r, (size_t)a, cov(m, dim, ux - ax, uy - ay));
        }
        gsl_linalg_SV_solve(U, V, S, r, x);
        for (int a = 0; a < nw; a++) {
            p->w[o * (size_t)nw + (size_t)a] = gsl_vector_get(x, (size_t)a);
            e -= gsl_vector_get(x, (size_t)a) * gsl_vector_get(r, (size_t)a);
        }
        e = fmax(e, 0) / r0;
        emean += e / (double)noff, emax = fmax(emax, e);
    }
    p->info.mean_error = emean, p->info.max_error = emax;
done:
    gsl_matrix_free(U), gsl_matrix_free(V), gsl_vector_free(S), gsl_vector_free(work), gsl_vector_free(r);
    gsl_vector_free(x);
    nl_gsl_leave();
    return st;
}

static int check_args(const nl_model *m, int dim, const size_t *n, int cell)
{
    double zero[3] = {0, 0, 0}, r0;
    if (dim != 1 && dim != 2)
        return NL_ERROR(NL_EINVAL, "lattice: expected dimension 1 or 2, got %d", dim);
    if (cell < 1 || cell > NL_LATTICE_WIENER_MAX_CELL)
        return NL_ERROR(NL_EINVAL, "--cell: expected 1 to %d samples for the Wiener lattice, got %d",
                        NL_LATTICE_WIENER_MAX_CELL, cell);
    for (int a = 0; a < dim; a++)
        if (n[a] % (size_t)cell || n[a] / (size_t)cell < WN)
            return NL_ERROR(NL_EINVAL, "--size: the Wiener lattice needs each size a multiple of the cell %d with at "
                            "least %d nodes, got %zu", cell, WN, n[a]);
    if (nl_model_nugget(m) != 0) {
        char list[64];
        nl_method_names(NL_METHOD_NUGGET, NULL, ", ", " or ", list, sizeof list);
        return NL_ERROR(NL_EINVAL, "lattice: %s: a nugget is not represented by lattice noise; use %s", nl_model_spec(m), list);
    }
    r0 = nl_model_acf(m, dim, zero);
    if (!(r0 > 0) || !isfinite(r0))
        return NL_ERROR(NL_EINVAL, "lattice: %s: the Wiener lattice needs R in closed form with R(0) > 0, got %g "
                        "(give the autocorrelation, or a power: model)", nl_model_spec(m), r0);
    return NL_OK;
}

int nl_synth_lattice_wiener_plan_alloc(const nl_model *m, int dim, const size_t *n, int cell, unsigned flags,
                                       nl_synth_lattice_wiener_plan **out)
{
    nl_synth_lattice_wiener_plan *p;
    double hl[3] = {cell, cell, cell}, zero[3] = {0, 0, 0};
    size_t noff, count;
    int st;
    nl_synth_fft_info fi;
    *out = NULL;
    if ((st = check_args(m, dim, n, cell)) || (st = nl_size_check(dim, n, sizeof(double), 1, &count)))
        return st;
    if (!(p = calloc(1, sizeof *p)))
        return NL_ERROR(NL_ENOMEM, "out of memory");
    p->dim = dim, p->cell = cell, p->nw = dim == 2 ? WN * WN : WN;
    for (int a = 0; a < 2; a++)
        p->n[a] = a < dim ? n[a] : 1, p->nodes[a] = a < dim ? n[a] / (size_t)cell : 1;
    noff = dim == 2 ? (size_t)cell * (size_t)cell : (size_t)cell;
    if (!(p->w = nl_alloc(noff * (size_t)p->nw * sizeof *p->w))) {
        free(p);
        return NL_ERROR(NL_ENOMEM, "out of memory");
    }
    if ((st = nl_synth_fft_plan_alloc(m, dim, p->nodes, hl,
                                      flags & NL_SYNTH_LATTICE_CLAMP ? NL_SYNTH_FFT_CLAMP : 0, &p->fft)) ||
        (st = solve_weights(m, p))) {
        nl_synth_lattice_wiener_plan_free(p);
        return st;
    }
    nl_synth_fft_plan_info(p->fft, &fi);
    p->info.cell = cell;
    p->info.nodes[0] = p->nodes[0], p->info.nodes[1] = p->nodes[1];
    p->info.variance = nl_model_acf(m, dim, zero);
    p->info.negatives = fi.negatives;
    *out = p;
    return NL_OK;
}

void nl_synth_lattice_wiener_plan_info(const nl_synth_lattice_wiener_plan *p, nl_synth_lattice_wiener_info *info)
{
    *info = p->info;
}

void nl_synth_lattice_wiener_weights(const nl_synth_lattice_wiener_plan *p, const int *u, double *w)
{
    size_t o = (size_t)u[0] + (p->dim == 2 ? (size_t)u[1] * (size_t)p->cell : 0);
    memcpy(w, p->w + o * (size_t)p->nw, (size_t)p->nw * sizeof *w);
}

int nl_synth_lattice_wiener_execute(const nl_synth_lattice_wiener_plan *p, uint64_t seed, nl_field *out,
                                    double **lattice)
{
    int dim = p->dim, st, c = p->cell;
    size_t nx = p->n[0], ny = p->n[1], lx = p->nodes[0], ly = p->nodes[1];
    double hl[3] = {c, c, c};
    nl_field *L;
    if (lattice)
        *lattice = NULL;
    if (out->dim != dim || out->n[0] != nx || (dim == 2 && out->n[1] != ny))
        return NL_ERROR(NL_EINVAL, "lattice: the output field does not match the plan's grid");
    if (!(L = nl_field_alloc(dim, p->nodes, hl, &st)))
        return st;
    if ((st = nl_synth_fft_execute(p->fft, seed, L))) {
        nl_field_free(L);
        return st;
    }
#pragma omp parallel for schedule(static) if (out->count > 65536)
    for (size_t j = 0; j < ny; j++) {
        size_t cj = j / (size_t)c, uy = j % (size_t)c;
        for (size_t i = 0; i < nx; i++) {
            size_t ci = i / (size_t)c, ux = i % (size_t)c;
            const double *w = p->w + (ux + uy * (size_t)c) * (size_t)p->nw;
            double s = 0;
            for (int dy = 0; dy < (dim == 2 ? WN : 1); dy++) {
                size_t jj = dim == 2 ? (cj + ly + (size_t)dy - (WK - 1)) % ly : 0;
                for (int dx = 0; dx < WN; dx++)
                    s += w[dy * WN + dx] * L->data[jj * lx + (ci + lx + (size_t)dx - (WK - 1)) % lx];
            }
            out->data[j * nx + i] = s;
        }
    }
    if (lattice) {
        if (!(*lattice = nl_alloc(L->count * sizeof **lattice))) {
            nl_field_free(L);
            return NL_ERROR(NL_ENOMEM, "out of memory");
        }
        memcpy(*lattice, L->data, L->count * sizeof **lattice);
    }
    nl_field_free(L);
    return NL_OK;
}

void nl_synth_lattice_wiener_plan_free(nl_synth_lattice_wiener_plan *p)
{
    if (!p)
        return;
    nl_synth_fft_plan_free(p->fft);
    nl_free(p->w);
    free(p);
}
