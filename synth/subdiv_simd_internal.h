/* The 2N x 2N stencils of one row of a 2D subdivision level (eq. (9)),
 * shared by subdiv_synth.c and its SIMD paths subdiv_simd*.c; not
 * installed.
 *
 * Every path gives the same bits: lane l of a vector computes the output of
 * pair i + l with the scalar loop's operations in the scalar loop's order
 * (s = 0, then s += a[k w + q] x[k][i + q] for k, then q; no fused
 * multiply-add: these files are built with -ffp-contract=off). */
#ifndef NL_SYNTH_SUBDIV_SIMD_INTERNAL_H
#define NL_SYNTH_SUBDIV_SIMD_INTERNAL_H

#include "subdiv_internal.h"

#include <stdint.h>

/* One row J of a level being refined (refine_row_2d in subdiv_synth.c). */
typedef struct {
    const double *rows[2 * NL_SUBDIV_MAX_N]; /* source rows j+1-N..j+N, indexed by i + column */
    double *out;                             /* the row, indexed by I */
    const nl_subdiv_class *odd, *even;       /* classes at odd and even I */
    double sd_odd, sd_even;                  /* their displacement deviations */
    const double *dodd, *deven;              /* correlated: displacements by cell i, or NULL */
    long J, oy;                              /* the row and its parity */
    uint64_t seed;
    unsigned lv;
    int N;
} row_job;

/* Whole pairs (2i, 2i + 1), i = i0..i1-1, of row r: odd rows both stencils,
 * even rows the odd one and a copy.  g: the Gaussian numbers of the keys
 * from k0 on (odd rows: the pair of key i at g[2 (i - k0)]; even rows: key
 * i / 2 for both odd points, g[i - 2 k0]); unused (NULL) when r->dodd is
 * set.  Thread-safe. */
typedef void nl_subdiv_pairs_fn(const row_job *r, long i0, long i1, const double *g, long k0);
nl_subdiv_pairs_fn nl_subdiv_pairs_scalar, nl_subdiv_pairs_avx2, nl_subdiv_pairs_avx512;

#endif

/* The kernel, instantiated by each path: SK_W lanes of type SK_VD (SK_W = 1:
 * plain doubles), loads SK_LOAD(p) and stores SK_STORE(p, v) unaligned, and
 * SK_LO(e, o) / SK_HI(e, o) interleaving e and o (lanes e0 o0 e1 o1 ...),
 * SK_EVEN(a, b) / SK_ODD(a, b) the reverse (from the 2 SK_W values a, b). */
#ifdef SK_NAME

/* Lanes i..i+SK_W-1 of the stencil of class a (w x w) over the rows. */
static inline SK_VD SK_(stencil)(const row_job *r, const double *a, int w, long i)
{
    SK_VD s = SK_ZERO;
    for (int k = 0; k < w; k++) {
        const double *x = r->rows[k] + i, *ak = a + k * w;
        for (int q = 0; q < w; q++)
            s += SK_SET1(ak[q]) * SK_LOAD(x + q);
    }
    return s;
}

/* Both stencils of the pair at once (odd rows): one pass of loads serves
 * both, as in the N = 2 loop before vectorisation. */
static inline void SK_(stencil2)(const row_job *r, const double *ae, const double *ao, int w, long i, SK_VD *se,
                                 SK_VD *so)
{
    SK_VD e = SK_ZERO, o = SK_ZERO;
    for (int k = 0; k < w; k++) {
        const double *x = r->rows[k] + i, *pe = ae + k * w, *po = ao + k * w;
        for (int q = 0; q < w; q++) {
            SK_VD v = SK_LOAD(x + q);
            e += SK_SET1(pe[q]) * v;
            o += SK_SET1(po[q]) * v;
        }
    }
    *se = e, *so = o;
}

static inline void SK_(put)(double *out, SK_VD e, SK_VD o)
{
    SK_STORE(out, SK_LO(e, o));
    SK_STORE(out + SK_W, SK_HI(e, o));
}

static inline void SK_(pairs_w)(const row_job *r, long i0, long i1, const double *g, long k0, int w)
{
    const double *ae = r->even->a, *ao = r->odd->a;
    const SK_VD sde = SK_SET1(r->sd_even), sdo = SK_SET1(r->sd_odd);
    double *out = r->out;
    long i = i0;
    for (; i + SK_W <= i1; i += SK_W) {
        SK_VD e, o;
        if (r->oy) {
            SK_(stencil2)(r, ae, ao, w, i, &e, &o);
            if (r->dodd) {
                e += SK_LOAD(r->deven + i);
                o += SK_LOAD(r->dodd + i);
            } else {
                const double *gi = g + 2 * (i - k0);
                SK_VD g0 = SK_LOAD(gi), g1 = SK_LOAD(gi + SK_W);
                e += sde * SK_EVEN(g0, g1);
                o += sdo * SK_ODD(g0, g1);
            }
        } else {
            o = SK_(stencil)(r, ao, w, i);
            o += r->dodd ? SK_LOAD(r->dodd + i) : sdo * SK_LOAD(g + (i - 2 * k0));
            e = SK_LOAD(r->rows[w / 2 - 1] + i + w / 2 - 1);
        }
        SK_(put)(out + 2 * i, e, o);
    }
    for (; i < i1; i++) {
        double se = 0, so = 0;
        for (int k = 0; k < w; k++) {
            const double *x = r->rows[k] + i, *pe = ae + k * w, *po = ao + k * w;
            for (int q = 0; q < w; q++) {
                if (r->oy)
                    se += pe[q] * x[q];
                so += po[q] * x[q];
            }
        }
        if (!r->oy)
            out[2 * i] = r->rows[w / 2 - 1][i + w / 2 - 1];
        else
            out[2 * i] = se + (r->dodd ? r->deven[i] : r->sd_even * g[2 * (i - k0)]);
        out[2 * i + 1] = so + (r->dodd ? r->dodd[i] : r->sd_odd * g[r->oy ? 2 * (i - k0) + 1 : i - 2 * k0]);
    }
}

void SK_NAME(const row_job *r, long i0, long i1, const double *g, long k0)
{
    if (r->N == 2)
        SK_(pairs_w)(r, i0, i1, g, k0, 4); /* constant w: the loops unroll */
    else
        SK_(pairs_w)(r, i0, i1, g, k0, 2 * r->N);
}

#endif
