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

#ifdef __cplusplus
extern "C" {
#endif

#include <stddef.h>
#include <stdint.h>

#define NL_RANK1_STREAM 600u
#define NL_RANK1_MAX_DIM 4

typedef struct {
    int s;            /* dimension */
    size_t N;         /* points */
    long g[NL_RANK1_MAX_DIM];  /* generator */
    long *k;          /* N * s wave vectors, k_m at k[m * s] (owned; nl_rank1_free) */
    double min_dist;  /* minimum distance between points (figure of merit) */
} nl_rank1_lattice;

/* Conventions for every function below.  A lattice is filled by one of the
 * three constructors and released by nl_rank1_free (it owns L->k; the struct
 * itself is the caller's).  A constructor that fails leaves L->k NULL, so
 * nl_rank1_free is safe either way.  Lattices are read-only after
 * construction: every other function may run concurrently on one lattice.
 * Positions are in [0, 1)^s (times `extent` where a function takes one);
 * arrays are caller-allocated. */

/* Fibonacci lattice at N = F_index (F_1 = F_2 = 1), g = (1, F_{index-1}).
 * NL_EINVAL: index outside 3..34. */
int nl_rank1_fibonacci(int index, nl_rank1_lattice *L);

/* k with F_k = N (k >= 3), or 0 when N is not a Fibonacci number >= 2.
 * Pure; thread-safe. */
int nl_rank1_fibonacci_index(size_t N);

/* Korobov lattice of N points in s dimensions, g = (1, a, a^2, ...) mod N;
 * a <= 0: searched over 2 <= a < min(N, 4096, max(18, 2^33 / (N s))) for
 * the largest minimum distance (ties: smallest a).  The search's work is
 * bounded by NL_RANK1_SEARCH_BUDGET point coordinates, which shortens it
 * from N s > 2^21 on (in 2D above 1048576 points); a candidate's scan stops
 * once it cannot beat the best so far.  Errors as nl_rank1_generator
 * (checked before the search). */
#define NL_RANK1_SEARCH_BUDGET ((size_t)1 << 33)
int nl_rank1_korobov(size_t N, int s, long a, nl_rank1_lattice *L);

/* A lattice with a given generator (s values, g[0] must be 1; reduced mod N).
 * NL_EINVAL: s outside 1..NL_RANK1_MAX_DIM, N outside 2..2^24, g[0] != 1;
 * NL_ETOOBIG: the wave vector search needs more than the memory available
 * (nl_mem_available); NL_ENOMEM. */
int nl_rank1_generator(size_t N, int s, const long *g, nl_rank1_lattice *L);

/* NL_OK, or NL_EINVAL for a degenerate generator (s values, reduced mod
 * N): a component g_a (a >= 1) that is 0 mod N, or two components equal or
 * opposite mod N, which put every point on a plane (x_a = 0, x_a = x_b or
 * x_a + x_b = 0 on the torus).  Pure; thread-safe.  The constructors do not
 * call it (tiny Fibonacci and Korobov lattices are degenerate this way). */
int nl_rank1_check_generator(size_t N, int s, const long *g);

/* Frees L->k and sets it to NULL. */
void nl_rank1_free(nl_rank1_lattice *L);

/* Point n (0 <= n < N) in [0, 1)^s into x (s doubles). */
void nl_rank1_point(const nl_rank1_lattice *L, size_t n, double *x);

/* Euclidean norm |k_m| of the wave vector of residue m (0 <= m < N). */
double nl_rank1_wave_norm(const nl_rank1_lattice *L, size_t m);

/* Variance per wave vector: S(k) for k in Z^s (the caller's spectrum). */
typedef double (*nl_rank1_spectrum)(const long *k, int s, void *ctx);

/* Draw the coefficients c_m (2N doubles, re/im interleaved), calling S for
 * m = 0..N/2 in order (S need not be thread-safe).  NL_EINVAL: S returned a
 * negative, NAN or infinite value (c is then partly written). */
int nl_rank1_coefficients(const nl_rank1_lattice *L, nl_rank1_spectrum S, void *ctx, uint64_t seed, double *c);

/* f(x_n) for n = 0..N-1 from coefficients c (re/im); *imag (may be NULL)
 * receives the largest |imaginary part| (0 up to rounding for a real
 * field).  grad (may be NULL): N * s values, grad[n * s + a] = df/dx_a on a
 * torus of side `extent` (per unit of extent).  NL_ENOMEM (the FFT could
 * not be planned).  Plans FFTW: not thread-safe (core/fftw_plan.h). */
int nl_rank1_synthesize(const nl_rank1_lattice *L, const double *c, double extent, double *f, double *grad,
                     double *imag);

/* Periodic Delaunay triangulation of a 2D lattice by an O(N) scan: the
 * shortest torus vector v1 = x_{n1}, then the shortest v2 = x_{n2} with
 * |det(v1, v2)| = 1/N (a basis), with v2 replaced by -v2 when v1 . v2 < 0
 * so that the parallelogram's short diagonal is v2 - v1.  The 2N triangles
 * are (x_n, x_n + v1, x_n + v2) and (x_n + v1, x_n + v1 + v2, x_n + v2),
 * that is, point indices (n, n + n1, n + n2) and (n + n1, n + n1 + n2,
 * n + n2) mod N, unwrapped by the vectors v1, v2.
 * NL_EINVAL: not 2D, or N < 3; NL_EFAIL: no basis found (not expected for
 * a lattice; kept as a guard). */
int nl_rank1_delaunay(const nl_rank1_lattice *L, size_t *n1, size_t *n2, double *v1, double *v2);

/* The Delaunay triangulation as 2N separate triangles (each with its own
 * unwrapped vertices, so the mesh tiles the torus without seams): triangle
 * t (0 <= t < 2N) is triangle t % 2 of point t / 2 above.  The struct
 * borrows L and f, which must outlive it; nothing to free. */
typedef struct {
    const nl_rank1_lattice *L;  /* the lattice (borrowed) */
    size_t n1, n2;              /* basis point indices (nl_rank1_delaunay) */
    double v1[2], v2[2];        /* basis vectors */
    double extent;              /* positions are multiplied by it */
    const double *f;            /* N heights (borrowed), or NULL: height 0 */
} nl_rank1_mesh;

/* Errors: NL_EINVAL for an extent that is not positive and finite, and
 * those of nl_rank1_delaunay. */
int nl_rank1_mesh_init(const nl_rank1_lattice *L, double extent, const double *f, nl_rank1_mesh *m);

/* Triangle t of mesh (an nl_rank1_mesh *): xyz receives its three vertices
 * x y z, positions times extent and z the height.  The signature is that of
 * nl_obj_triangle (core/io_obj.h).  Thread-safe. */
void nl_rank1_mesh_triangle(const void *mesh, size_t t, double xyz[9]);

/* Linear interpolation of lattice values (and gradients, may be NULL) over
 * the periodic Delaunay triangles onto a W x W periodic image of the unit
 * square (pixel centres (i + 1/2)/W, row-major, x fastest); outputs W*W
 * doubles each (gx, gy may be NULL; both needed for gradients).  Pixels no
 * triangle covers keep their values.  NL_EINVAL: W = 0, f or img NULL, and
 * those of nl_rank1_delaunay.  Thread-safe for distinct outputs. */
int nl_rank1_rasterize(const nl_rank1_lattice *L, const double *f, const double *grad, size_t W, double *img,
                    double *gx, double *gy);

/* The field between the lattice points.  The coefficients define the
 * trigonometric polynomial (Keller, section 3.2)
 *     f(x) = sum_{m != N/2} c_m exp(2 pi i k_m . x) + c_{N/2} cos(2 pi k_{N/2} . x)
 * (x in unit torus coordinates, period 1 on every axis; the N/2 term, for
 * even N, has no partner -k in K_N and is taken as its real part, the
 * value it has at every lattice point), real for the coefficients of
 * nl_rank1_coefficients, equal to nl_rank1_synthesize's values at the
 * lattice points x_n.  Its gradient per unit of a torus of side `extent`
 * is the series of i 2 pi k_m c_m / extent (the N/2 term: -2 pi k c sin(.) /
 * extent). */

/* f (and its gradient, grad may be NULL: count * s values, per unit of
 * extent) at count points x (count * s coordinates) by the direct sum,
 * O(N) per point.  *imag (may be NULL) receives the largest |imaginary
 * part| of the sums (0 up to rounding for a real field).  NL_EINVAL: a
 * coordinate that is not finite or above 1e9 in magnitude, an extent that
 * is not positive and finite.  Thread-safe. */
int nl_rank1_eval(const nl_rank1_lattice *L, const double *c, double extent, size_t count, const double *x, double *f,
                  double *grad, double *imag);

/* f on a W x W grid over the first two coordinates, pixel (i, j) at
 * ((i + 1/2) / W, (j + 1/2) / W) (row-major, x fastest, as
 * nl_rank1_rasterize), the other s - 2 coordinates fixed at `at` (s - 2
 * values; NULL for s = 2): by one complex W x W FFT through the lattice's
 * wave vectors (each c_m times exp(2 pi i sum_{a >= 2} k_a at_a) added at
 * bin (k_0 mod W, k_1 mod W) with the half-pixel phase), so every pixel is
 * the series' value to rounding; the picture is free of aliasing when W >
 * 2 max |k_a| over the two axes.  gx, gy (may be NULL, both or neither):
 * the gradient's first two components per unit of extent, two more FFTs.
 * imag (may be NULL): the largest |imaginary part|.  Errors: NL_EINVAL for
 * s < 2, W outside 2..65536, an extent that is not positive and finite, a
 * fixed coordinate that is not finite or above 1e9; NL_ETOOBIG when the
 * W x W buffer exceeds the memory available; NL_ENOMEM.  Plans FFTW: not
 * thread-safe (core/fftw_plan.h). */
int nl_rank1_grid(const nl_rank1_lattice *L, const double *c, double extent, size_t W, const double *at, double *img,
                  double *gx, double *gy, double *imag);

#ifdef __cplusplus
}
#endif

#endif
