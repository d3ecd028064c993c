/* Sparse convolution internals shared by sparse.c (lattice execution) and
 * sparse_bands.c (band-limited kernels, evaluation at points). */
#ifndef NL_SYNTH_SPARSE_INTERNAL_H
#define NL_SYNTH_SPARSE_INTERNAL_H

#include "sparse.h"

struct nl_synth_sparse_plan {
    int dim;            /* 1 or 2 */
    int radius;         /* R: table covers offsets -R..R per axis */
    int cell;           /* C */
    double density;     /* impulses per cell */
    double *h;          /* (2R+1)^dim kernel table, x fastest */
    struct nl_expr *angle; /* theta(x, y) (core/expr_internal.h) or NULL */
    char *angle_expr;   /* its text, for messages */
    nl_synth_sparse_info info;
    int nbands;                               /* band-limited tables 1..nbands (0: none) */
    double *band[NL_SPARSE_BANDS_MAX + 1];    /* band[l]: h blurred by sigma 2^(l-1); band[0] unused */
    int band_radius[NL_SPARSE_BANDS_MAX + 1]; /* half-width of band[l] */
};

/* The impulses of the cells cx0..cx1 x cy0..cy1 (absolute cell indices). */
typedef struct {
    long cx0, cy0, ncx, ncy;  /* cell range */
    size_t *start;            /* ncx * ncy + 1 offsets into the arrays */
    long *px, *py;            /* absolute lattice positions */
    double *a, *c, *s;        /* amplitude, cos and sin of the kernel angle */
} nl_sparse_impulses;

/* Draws the impulses of the cells (NL_OK, NL_EINVAL for an angle not finite
 * at an impulse, NL_ETOOBIG/NL_ENOMEM); freed by nl_sparse_impulses_free. */
int nl_sparse_impulses_make(const nl_synth_sparse_plan *p, uint64_t seed, long cx0, long cx1, long cy0, long cy1,
                            nl_sparse_impulses *im);
void nl_sparse_impulses_free(nl_sparse_impulses *im);

/* nl_sparse_impulses_make with per[a] > 0 (NULL: none) the cells per axis
 * of a periodic tile: cell (kx, ky) of the range holds the impulses of its
 * canonical cell (kx mod per[0], ky mod per[1]), at that cell's positions
 * (px, py within 0 .. per[a] cell - 1), so a range may run past the tile. */
int nl_sparse_impulses_make_periodic(const nl_synth_sparse_plan *p, uint64_t seed, long cx0, long cx1, long cy0,
                                     long cy1, const long *per, nl_sparse_impulses *im);

/* Bilinear lookup of a (2R+1)^2 table at a non-integer offset; 0 outside. */
double nl_sparse_table_at(const double *h, int R, double u, double v);

/* Floor division, and the default cell of a radius. */
long nl_sparse_floordiv(long a, long b);
int nl_sparse_default_cell(int radius);

/* Frees the band tables (nbands = 0). */
void nl_sparse_bands_clear(nl_synth_sparse_plan *p);

#endif
