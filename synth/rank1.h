/* Random fields on rank-1 lattices (Keller 2001).
 *
 * Lattice: x_n = (n / N) g mod 1, n = 0..N-1, in [0, 1)^s, s = 1..4
 * (generator g with g_0 = 1).  Fibonacci (s = 2): N = F_k, g = (1, F_{k-1}).
 * Korobov: g = (1, a, a^2, ...) mod N, with a chosen to maximise the
 * figure of merit: the minimum distance between lattice points on the
 * torus (ties: the smallest a).
 *
 * Wave vectors (Keller, eq. (2) and section 3.3): for every residue m, a
 * k_m in Z^s with k_m . g = m (mod N) of minimal Euclidean norm.  The
 * candidates are enumerated in shells of growing |k|_1 (within a shell in
 * lexicographic order of the coordinates, each from -|k|_1 upwards), and a
 * residue keeps the first candidate of smallest norm (the tie rule).
 * Termination: (m, 0, ..., 0) reaches every residue within |k|_1 <= N, and
 * a shell |k|_1 = L only holds vectors of norm >= L / sqrt(s), so the
 * search stops at the first shell with L / sqrt(s) above the largest
 * minimal norm found.  For a real field the set is made symmetric: the
 * vectors for 1 <= m < N/2 are kept and k_{N-m} = -k_m (same norm).
 *
 * Synthesis (one complex FFT of length N, FFTW): Fourier coefficients
 * c_m = sqrt(S(k_m) / 2) (xi + i eta) with independent standard normals
 * from (seed, NL_RANK1_STREAM, m), c_{N-m} = conj(c_m), c_0 and c_{N/2} real
 * with variance S; then f(x_n) = sum_m c_m exp(2 pi i m n / N).  S(k) is
 * the variance carried by wave vector k (the spectral density times the
 * cell 1 / extent^s), so Var f = sum_m S(k_m).  The gradient uses the
 * coefficients i 2 pi k_m c_m / extent, one FFT per component. */
#ifndef NL_SYNTH_RANK1_H
#define NL_SYNTH_RANK1_H

#include <stddef.h>
#include <stdint.h>

#define NL_RANK1_STREAM 600u
#define NL_RANK1_MAX_DIM 4

typedef struct {
    int s;            /* dimension */
    size_t N;         /* points */
    long g[NL_RANK1_MAX_DIM];  /* generator */
    long *k;          /* N * s wave vectors, k_m at k[m * s] */
    double min_dist;  /* minimum distance between points (figure of merit) */
} nl_rank1_lattice;

/* Fibonacci lattice at N = F_index (index >= 3). */
int nl_rank1_fibonacci(int index, nl_rank1_lattice *L);

/* Korobov lattice of N points in s dimensions, a searched (a = 0: search). */
int nl_rank1_korobov(size_t N, int s, long a, nl_rank1_lattice *L);

/* A lattice with a given generator (g[0] must be 1). */
int nl_rank1_generator(size_t N, int s, const long *g, nl_rank1_lattice *L);

void nl_rank1_free(nl_rank1_lattice *L);

/* Point n in [0, 1)^s. */
void nl_rank1_point(const nl_rank1_lattice *L, size_t n, double *x);

/* Variance per wave vector: S(k) for k in Z^s (the caller's spectrum). */
typedef double (*nl_rank1_spectrum)(const long *k, int s, void *ctx);

/* Draw the coefficients c_m (2N doubles, re/im interleaved). */
int nl_rank1_coefficients(const nl_rank1_lattice *L, nl_rank1_spectrum S, void *ctx, uint64_t seed, double *c);

/* f(x_n) for n = 0..N-1 from coefficients c (re/im); *imag receives the
 * largest |imaginary part| (0 up to rounding for a real field). grad (may
 * be NULL): N * s values, the gradient on a torus of side `extent`. */
int nl_rank1_synthesize(const nl_rank1_lattice *L, const double *c, double extent, double *f, double *grad,
                     double *imag);

/* Periodic Delaunay triangulation of a 2D lattice by an O(N) scan: the
 * shortest torus vector v1 = x_{n1}, then the shortest v2 = x_{n2} with
 * |det(v1, v2)| = 1/N (a basis), with v2 replaced by -v2 when v1 . v2 < 0
 * so that the parallelogram's short diagonal is v2 - v1.  The 2N triangles
 * are (x_n, x_n + v1, x_n + v2) and (x_n + v1, x_n + v1 + v2, x_n + v2),
 * that is, point indices (n, n + n1, n + n2) and (n + n1, n + n1 + n2,
 * n + n2) mod N, unwrapped by the vectors v1, v2. */
int nl_rank1_delaunay(const nl_rank1_lattice *L, size_t *n1, size_t *n2, double *v1, double *v2);

/* Linear interpolation of lattice values (and gradients, may be NULL) over
 * the periodic Delaunay triangles onto a W x W periodic image of the unit
 * square (pixel centres (i + 1/2)/W); outputs W*W doubles each. */
int nl_rank1_rasterize(const nl_rank1_lattice *L, const double *f, const double *grad, size_t W, double *img,
                    double *gx, double *gy);

#endif
