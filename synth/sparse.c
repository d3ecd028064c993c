/* Sparse convolution on the lattice: kernels and gather evaluation. */
#include "sparse.h"
#include "sparse_internal.h"
#include "../core/autocorr.h"
#include "../core/fftw_plan.h"
#include "../core/expr_internal.h"
#include "../core/mem.h"
#include "../core/nl_error.h"
#include "../core/rng.h"
#include "../core/wk.h"
#include "fft.h"
#include "method.h"

#include <complex.h>
#include <fftw3.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void nl_synth_sparse_plan_free(nl_synth_sparse_plan *p)
{
    if (!p)
        return;
    nl_expr_free(p->angle);
    free(p->angle_expr);
    nl_sparse_bands_clear(p);
    free(p->h);
    free(p);
}

int nl_sparse_default_cell(int radius)
{
    int c;
    for (c = 4; c < radius; c *= 2)
        ;
    return c;
}

static size_t table_size(int dim, int R) { return dim == 1 ? (size_t)(2 * R + 1) : (size_t)(2 * R + 1) * (2 * R + 1); }

/* Finish a plan: scale h so that the variance is `variance`, fill info. */
static int finish(nl_synth_sparse_plan *p, double variance)
{
    size_t n = table_size(p->dim, p->radius);
    double s2 = 0, s4 = 0, lambda = p->density / pow(p->cell, p->dim), k;
    for (size_t i = 0; i < n; i++)
        s2 += p->h[i] * p->h[i];
    if (!isfinite(s2))
        return NL_ERROR(NL_EINVAL, "sparse: the kernel's energy overflows (%g); expected smaller kernel values", s2);
    if (!(s2 > 0))
        return NL_ERROR(NL_EINVAL, "sparse: the kernel is zero everywhere within the radius %d", p->radius);
    k = sqrt(variance / (lambda * s2));
    s2 = 0;
    for (size_t i = 0; i < n; i++) {
        p->h[i] *= k;
        s2 += p->h[i] * p->h[i];
        s4 += p->h[i] * p->h[i] * p->h[i] * p->h[i];
    }
    p->info.radius = p->radius;
    p->info.cell = p->cell;
    p->info.density = p->density;
    p->info.kernel_energy = s2;
    p->info.variance = lambda * s2;
    p->info.kurtosis = 3 * s4 / (lambda * s2 * s2);
    return NL_OK;
}

static int new_plan(int dim, int radius, int cell, double density, nl_synth_sparse_plan **out)
{
    nl_synth_sparse_plan *p;
    *out = NULL;
    if (dim != 1 && dim != 2)
        return NL_ERROR(NL_EINVAL, "sparse: expected dimension 1 or 2, got %d", dim);
    if (!(density > 0) || !isfinite(density) || density > 1e6)
        return NL_ERROR(NL_EINVAL, "density: expected a positive number of impulses per cell (at most 1e6), got %g",
                        density);
    if (radius < 1 || radius > 4096)
        return NL_ERROR(NL_EINVAL, "radius: expected 1 to 4096 samples, got %d", radius);
    if (cell < 0 || cell > 4096)
        return NL_ERROR(NL_EINVAL, "cell: expected 1 to 4096 samples, got %d", cell);
    {
        size_t nt = table_size(dim, radius);
        int st = nl_size_check(1, &nt, sizeof(double), 1, NULL);
        if (st)
            return st;
    }
    p = calloc(1, sizeof *p);
    if (!p || !(p->h = calloc(table_size(dim, radius), sizeof *p->h))) {
        free(p);
        return NL_ERROR(NL_ENOMEM, "out of memory for the kernel");
    }
    p->dim = dim;
    p->radius = radius;
    p->cell = cell > 0 ? cell : nl_sparse_default_cell(radius);
    p->density = density;
    *out = p;
    return NL_OK;
}

/* The model's kernel on a periodic grid of mm samples per axis: g =
 * IDFT(sqrt(lambda_k)) / M (real parts), its energy in *total; the
 * positive-definiteness rule of FFT synthesis (synth/fft.h) on lambda_k:
 * the fraction of the spectrum's mass that is negative goes to
 * info->clamp_error, NL_ENOTPD above NL_SYNTH_FFT_CLAMP_TOL unless
 * NL_SYNTH_FFT_CLAMP. */
static int model_kernel(const nl_model *m, int dim, const double *hh, const size_t *mm, unsigned flags,
                        fftw_complex **out, double *total, nl_synth_sparse_info *info)
{
    size_t M = mm[0] * mm[1];
    double cellh = hh[0] * (dim == 2 ? hh[1] : 1), neg = 0, pos = 0, lmin = INFINITY;
    nl_field *S;
    fftw_complex *g;
    fftw_plan fp;
    int dims[2], st;
    *out = NULL;
    /* the sampled spectrum and the complex kernel are alive together */
    if ((st = nl_size_check(dim, mm, sizeof(double) + sizeof(fftw_complex), 1, NULL))) {
        char why[256];
        snprintf(why, sizeof why, "%s", nl_errmsg());
        return NL_ERROR(st, "radius: the kernel's FFT grid (%zu samples per axis) does not fit: %s", mm[0], why);
    }
    S = nl_field_alloc(dim, mm, hh, &st);
    if (!S)
        return st;
    if ((st = nl_wk_sample_spectrum(m, S))) {
        nl_field_free(S);
        return st;
    }
    for (size_t i = 0; i < M; i++) {
        double l = S->data[i] / cellh;
        if (!isfinite(l)) {
            nl_field_free(S);
            return NL_ERROR(NL_EINVAL, "%s: the sampled spectrum is not finite (%g) at frequency index %zu of the "
                            "kernel's grid: the model's values are too large", nl_model_spec(m), l, i);
        }
        if (l < 0)
            neg -= l, info->negatives++;
        else
            pos += l;
        lmin = fmin(lmin, l);
    }
    info->clamp_error = pos > 0 ? neg / pos : INFINITY;
    if (!(pos > 0))
        st = NL_ERROR(NL_ENOTPD, "%s: the sampled spectrum has no positive part on the kernel's grid",
                      nl_model_spec(m));
    else if (info->clamp_error > NL_SYNTH_FFT_CLAMP_TOL && !(flags & NL_SYNTH_FFT_CLAMP))
        st = NL_ERROR(NL_ENOTPD,
                      "%s: not positive definite on the kernel's grid: min spectrum %.3g; zeroing the %zu negative "
                      "values would change the covariance by up to %.2g of R(0), above %.0e (use --clamp to accept)",
                      nl_model_spec(m), lmin * cellh, info->negatives, info->clamp_error, NL_SYNTH_FFT_CLAMP_TOL);
    g = st ? NULL : nl_alloc(M * sizeof(fftw_complex));
    for (int a = 0; a < dim; a++)
        dims[a] = (int)mm[dim - 1 - a];
    fp = g ? fftw_plan_dft(dim, dims, g, g, FFTW_BACKWARD, nl_fftw_flags(M)) : NULL;
    if (!fp) {
        nl_free(g), nl_field_free(S);
        return st ? st : NL_ERROR(NL_ENOMEM, "sparse: cannot plan the kernel FFT");
    }
    for (size_t i = 0; i < M; i++)
        g[i] = sqrt(fmax(S->data[i] / cellh, 0));
    fftw_execute(fp);
    fftw_destroy_plan(fp);
    nl_field_free(S);
    *total = 0;
    for (size_t i = 0; i < M; i++) {
        double v = creal(g[i]) / (double)M;
        g[i] = v;
        *total += v * v;
    }
    *out = g;
    return NL_OK;
}

static double kernel_value(const fftw_complex *g, const size_t *mm, long i, long j)
{
    return creal(g[((j + (long)mm[1]) % (long)mm[1]) * mm[0] + (size_t)((i + (long)mm[0]) % (long)mm[0])]);
}

/* The smallest box keeping all but NL_SPARSE_ENERGY_TOL of the energy. */
static int auto_radius(const fftw_complex *g, const size_t *mm, int dim, double total)
{
    int R;
    for (R = 1; R < (int)mm[0] / 4; R++) {
        double in = 0;
        for (long j = dim == 2 ? -R : 0; j <= (dim == 2 ? R : 0); j++)
            for (long i = -R; i <= R; i++) {
                double v = kernel_value(g, mm, i, j);
                in += v * v;
            }
        if (in >= (1 - NL_SPARSE_ENERGY_TOL) * total)
            break;
    }
    return R;
}

void nl_synth_sparse_options_default(nl_synth_sparse_options *o)
{
    *o = (nl_synth_sparse_options){.radius = 0, .cell = 0, .density = 1, .flags = 0};
}

int nl_synth_sparse_plan_model(const nl_model *m, int dim, const double *h, const nl_synth_sparse_options *o,
                               nl_synth_sparse_plan **out)
{
    int radius = o->radius, cell = o->cell;
    double density = o->density;
    unsigned flags = o->flags;
    size_t mm[2], span;
    double hh[2] = {h ? h[0] : 1, h && dim == 2 ? h[1] : 1};
    double total = 0, kept = 0, zero[2] = {0, 0}, r0;
    nl_synth_sparse_info info = {0};
    fftw_complex *g;
    int st, R = radius;
    *out = NULL;
    if (dim != 1 && dim != 2)
        return NL_ERROR(NL_EINVAL, "sparse: expected dimension 1 or 2, got %d", dim);
    if (radius > 4096)
        return NL_ERROR(NL_EINVAL, "radius: expected 1 to 4096 samples, got %d", radius);
    if (nl_model_nugget(m) != 0) {
        char list[64];
        nl_method_names(NL_METHOD_NUGGET, NULL, ", ", " or ", list, sizeof list);
        return NL_ERROR(NL_EINVAL, "sparse: %s: a nugget is not represented by shot noise (its kernel would need a "
                        "spike of white noise); use %s", nl_model_spec(m), list);
    }
    /* periodic grid for h = IDFT(sqrt(lambda)) / N: large enough that the
     * kernel has decayed where it wraps */
    span = radius > 0 ? (size_t)(4 * radius + 4) : (dim == 1 ? 8192 : 512);
    for (mm[0] = 64; mm[0] < span; mm[0] *= 2)
        ;
    mm[1] = dim == 2 ? mm[0] : 1;
    if ((st = nl_synth_check_cell(dim, hh)) || (st = model_kernel(m, dim, hh, mm, flags, &g, &total, &info)))
        return st;
    if (R <= 0)
        R = auto_radius(g, mm, dim, total);
    if ((st = new_plan(dim, R, cell, density, out))) {
        nl_free(g);
        return st;
    }
    for (long j = dim == 2 ? -R : 0; j <= (dim == 2 ? R : 0); j++)
        for (long i = -R; i <= R; i++) {
            double v = kernel_value(g, mm, i, j);
            (*out)->h[(size_t)(dim == 2 ? (j + R) * (2 * R + 1) : 0) + (size_t)(i + R)] = v;
            kept += v * v;
        }
    nl_free(g);
    (*out)->info.truncated = total > 0 ? 1 - kept / total : 0;
    (*out)->info.clamp_error = info.clamp_error;
    (*out)->info.negatives = info.negatives;
    /* h * h = R within the box: the variance R(0) less the truncated energy
     * (a spectrum model without a closed-form R(0): the kernel's energy) */
    r0 = nl_model_acf(m, dim, zero);
    st = finish(*out, (isnan(r0) ? total : r0) * (1 - (*out)->info.truncated));
    if (st) {
        nl_synth_sparse_plan_free(*out);
        *out = NULL;
    }
    return st;
}

int nl_synth_sparse_plan_expr(const char *expr, int dim, const nl_synth_sparse_options *o,
                              nl_synth_sparse_plan **out)
{
    int radius = o->radius, cell = o->cell;
    double density = o->density;
    static const char *const names[] = {"x", "y", "t", "r"};
    nl_expr *ev;
    const char *bad;
    int st;
    *out = NULL;
    if ((st = nl_expr_create("kernel", expr, &ev)))
        return st;
    if ((bad = nl_expr_bind(ev, names, 4))) {
        st = NL_ERROR(NL_EINVAL, "kernel: unknown variable \"%s\" in \"%s\" (expected x, y, t, r)", bad, expr);
        nl_expr_free(ev);
        return st;
    }
    if ((st = new_plan(dim, radius, cell, density, out))) {
        nl_expr_free(ev);
        return st;
    }
    for (int j = dim == 2 ? -radius : 0; j <= (dim == 2 ? radius : 0); j++)
        for (int i = -radius; i <= radius; i++) {
            double v[4] = {i, j, i, hypot(i, j)};
            double y = nl_expr_eval(ev, v);
            if (!isfinite(y)) {
                nl_expr_free(ev);
                nl_synth_sparse_plan_free(*out);
                *out = NULL;
                return NL_ERROR(NL_EINVAL, "kernel: \"%s\" is not finite at (%d, %d)", expr, i, j);
            }
            (*out)->h[(size_t)(dim == 2 ? (j + radius) * (2 * radius + 1) : 0) + (size_t)(i + radius)] = y;
        }
    nl_expr_free(ev);
    if ((st = finish(*out, 1.0))) {
        nl_synth_sparse_plan_free(*out);
        *out = NULL;
    }
    return st;
}

int nl_synth_sparse_plan_image(const nl_field *img, const nl_synth_sparse_options *o, nl_synth_sparse_plan **out)
{
    int cell = o->cell;
    double density = o->density;
    size_t w = img->n[0], hgt = img->dim == 2 ? img->n[1] : 1;
    int R = (int)((w > hgt ? w : hgt) / 2), st;
    double mean = 0, var = 0;
    *out = NULL;
    if (img->dim != 2)
        return NL_ERROR(NL_EINVAL, "exemplar: expected a 2D image, got %dD", img->dim);
    if ((st = new_plan(2, R, cell, density, out)))
        return st;
    for (size_t i = 0; i < img->count; i++)
        mean += img->data[i] / (double)img->count;
    for (size_t i = 0; i < img->count; i++)
        var += (img->data[i] - mean) * (img->data[i] - mean) / (double)img->count;
    if (!(var > 0)) {
        nl_synth_sparse_plan_free(*out);
        *out = NULL;
        return NL_ERROR(NL_EINVAL, "exemplar: the %zux%zu image is constant (%g); expected a texture", w, hgt, mean);
    }
    for (size_t j = 0; j < hgt; j++)
        for (size_t i = 0; i < w; i++) {
            /* Hann window over the exemplar, centred in the table */
            double wx = 0.5 * (1 - cos(2 * M_PI * ((double)i + 0.5) / (double)w));
            double wy = 0.5 * (1 - cos(2 * M_PI * ((double)j + 0.5) / (double)hgt));
            long ti = (long)i - (long)w / 2 + R, tj = (long)j - (long)hgt / 2 + R;
            (*out)->h[(size_t)tj * (size_t)(2 * R + 1) + (size_t)ti] = (img->data[j * w + i] - mean) * wx * wy;
        }
    if ((st = finish(*out, var))) {
        nl_synth_sparse_plan_free(*out);
        *out = NULL;
    }
    return st;
}

int nl_synth_sparse_set_angle(nl_synth_sparse_plan *p, const char *expr)
{
    static const char *const xy[] = {"x", "y"};
    const char *bad;
    char *copy;
    int st;
    if (p->dim != 2)
        return NL_ERROR(NL_EINVAL, "angle: a rotated kernel needs a 2D field, got %dD", p->dim);
    copy = strdup(expr);
    if (!copy)
        return NL_ERROR(NL_ENOMEM, "out of memory");
    nl_expr_free(p->angle);
    p->angle = NULL;
    free(p->angle_expr);
    p->angle_expr = copy;
    if ((st = nl_expr_create("angle", copy, &p->angle)))
        return st;
    if ((bad = nl_expr_bind(p->angle, xy, 2))) {
        st = NL_ERROR(NL_EINVAL, "angle: unknown variable \"%s\" in \"%s\" (expected x, y)", bad, expr);
        nl_expr_free(p->angle);
        p->angle = NULL;
        return st;
    }
    return NL_OK;
}

void nl_synth_sparse_plan_info(const nl_synth_sparse_plan *p, nl_synth_sparse_info *info) { *info = p->info; }

int nl_synth_sparse_plan_exemplar(const nl_field *img, const nl_synth_sparse_options *o, nl_synth_sparse_plan **out)
{
    int radius = o->radius;
    nl_field *crop = NULL;
    double mean;
    int st;
    *out = NULL;
    if (img->dim != 2)
        return NL_ERROR(NL_EINVAL, "--exemplar: expected a 2D image, got %dD", img->dim);
    if (radius) {
        /* the central 2R x 2R window of the exemplar */
        size_t w = 2 * (size_t)radius, n[2] = {w, w};
        if (w > img->n[0] || w > img->n[1])
            return NL_ERROR(NL_EINVAL, "--radius: %d needs a %zux%zu window, larger than the %zux%zu exemplar",
                            radius, w, w, img->n[0], img->n[1]);
        if (!(crop = nl_field_alloc(2, n, NULL, &st)))
            return st;
        for (size_t j = 0; j < w; j++)
            for (size_t i = 0; i < w; i++)
                crop->data[j * w + i] = img->data[(j + (img->n[1] - w) / 2) * img->n[0] + i + (img->n[0] - w) / 2];
        img = crop;
    }
    mean = nl_field_mean(img);
    st = nl_synth_sparse_plan_image(img, o, out);
    nl_field_free(crop);
    if (!st)
        (*out)->info.mean = mean;
    return st;
}

void nl_sparse_impulses_free(nl_sparse_impulses *im)
{
    free(im->start), free(im->px), free(im->py), free(im->a), free(im->c), free(im->s);
}

static uint64_t cell_id(long cx, long cy) { return ((uint64_t)(uint32_t)cy << 32) | (uint32_t)cx; }

int nl_sparse_impulses_make(const nl_synth_sparse_plan *p, uint64_t seed, long cx0, long cx1, long cy0, long cy1,
                            nl_sparse_impulses *im)
{
    return nl_sparse_impulses_make_periodic(p, seed, cx0, cx1, cy0, cy1, NULL, im);
}

static long wrap_cell(long c, const long *per, int a) { return per ? ((c % per[a]) + per[a]) % per[a] : c; }

int nl_sparse_impulses_make_periodic(const nl_synth_sparse_plan *p, uint64_t seed, long cx0, long cx1, long cy0,
                                     long cy1, const long *per, nl_sparse_impulses *im)
{
    size_t ncell, total = 0, cap;
    memset(im, 0, sizeof *im);
    im->cx0 = cx0, im->cy0 = cy0, im->ncx = cx1 - cx0 + 1, im->ncy = cy1 - cy0 + 1;
    ncell = (size_t)im->ncx * (size_t)im->ncy;
    {
        /* offsets per cell, and five arrays per impulse (about density per cell) */
        double want = p->density * (double)ncell * 1.5 + 64;
        size_t n2[2] = {ncell + 1, 1}, ni = want < 1e18 ? (size_t)want : SIZE_MAX / 64;
        int st = nl_size_check(1, n2, sizeof(size_t), 1, NULL);
        if (!st && (st = nl_size_check(1, &ni, 2 * sizeof(long) + 3 * sizeof(double), 1, NULL))) {
            char why[256];
            snprintf(why, sizeof why, "%s", nl_errmsg());
            return NL_ERROR(st, "density: %.3g impulses per cell over %zu cells do not fit: %s", p->density, ncell,
                            why);
        }
        if (st)
            return st;
    }
    im->start = malloc((ncell + 1) * sizeof *im->start);
    cap = (size_t)(p->density * (double)ncell * 1.5) + 64;
    im->px = malloc(cap * sizeof *im->px), im->py = malloc(cap * sizeof *im->py);
    im->a = malloc(cap * sizeof *im->a), im->c = malloc(cap * sizeof *im->c), im->s = malloc(cap * sizeof *im->s);
    if (!im->start || !im->px || !im->py || !im->a || !im->c || !im->s) {
        nl_sparse_impulses_free(im);
        return NL_ERROR(NL_ENOMEM, "out of memory for %zu cells of impulses", ncell);
    }
    for (long ky = cy0; ky <= cy1; ky++)
        for (long kx = cx0; kx <= cx1; kx++) {
            /* the cell's canonical index: its impulses and their positions */
            const long cx = wrap_cell(kx, per, 0), cy = p->dim == 2 ? wrap_cell(ky, per, 1) : ky;
            uint64_t id = cell_id(cx, p->dim == 2 ? cy : 0);
            unsigned long k, K = nl_rng_poisson(seed, NL_SPARSE_STREAM, id, 0, p->density);
            im->start[(ky - cy0) * im->ncx + (kx - cx0)] = total;
            for (k = 0; k < K; k++) {
                if (total == cap) {
                    cap *= 2;
                    long *nx = realloc(im->px, cap * sizeof *nx), *ny = realloc(im->py, cap * sizeof *ny);
                    double *na = realloc(im->a, cap * sizeof *na), *nc = realloc(im->c, cap * sizeof *nc),
                           *ns = realloc(im->s, cap * sizeof *ns);
                    if (nx) im->px = nx;
                    if (ny) im->py = ny;
                    if (na) im->a = na;
                    if (nc) im->c = nc;
                    if (ns) im->s = ns;
                    if (!nx || !ny || !na || !nc || !ns) {
                        nl_sparse_impulses_free(im);
                        return NL_ERROR(NL_ENOMEM, "out of memory for impulses");
                    }
                }
                im->px[total] = cx * p->cell +
                                (long)(nl_rng_uniform2(seed, NL_SPARSE_STREAM + 1, id, (uint32_t)k) * p->cell);
                im->py[total] = p->dim == 2 ? cy * p->cell + (long)(nl_rng_uniform2(seed, NL_SPARSE_STREAM + 2, id,
                                                                                   (uint32_t)k) * p->cell)
                                            : 0;
                im->a[total] = nl_rng_gauss2(seed, NL_SPARSE_STREAM + 3, id, (uint32_t)k);
                im->c[total] = 1, im->s[total] = 0;
                if (p->angle) {
                    double v[2] = {(double)im->px[total], (double)im->py[total]};
                    double th = nl_expr_eval(p->angle, v);
                    if (!isfinite(th)) {
                        nl_sparse_impulses_free(im);
                        return NL_ERROR(NL_EINVAL, "angle: \"%s\" is not finite (%g) at the impulse (x %g, y %g)",
                                        p->angle_expr, th, v[0], v[1]);
                    }
                    im->c[total] = cos(th), im->s[total] = sin(th);
                }
                total++;
            }
        }
    im->start[ncell] = total;
    return NL_OK;
}

double nl_sparse_table_at(const double *h, int R, double u, double v)
{
    int w = 2 * R + 1;
    double fu = floor(u), fv = floor(v), au = u - fu, av = v - fv, s = 0;
    for (int dv = 0; dv <= 1; dv++)
        for (int du = 0; du <= 1; du++) {
            long i = (long)fu + du, j = (long)fv + dv;
            if (i < -R || i > R || j < -R || j > R)
                continue;
            s += (du ? au : 1 - au) * (dv ? av : 1 - av) * h[(size_t)(j + R) * (size_t)w + (size_t)(i + R)];
        }
    return s;
}

int nl_synth_sparse_check_work(int dim, const size_t *n, int radius, int cell, double density, unsigned flags)
{
    double reach = flags & NL_SYNTH_SPARSE_ANGLE ? ceil(radius * M_SQRT2) + 1 : radius;
    double C = cell > 0 ? cell : nl_sparse_default_cell(radius);
    double count = 1, cells = 1, per = 2 * reach / C + 2, work;
    for (int a = 0; a < dim; a++) {
        count *= (double)n[a];
        cells *= ((double)n[a] + 2 * reach) / C + 2;
    }
    /* the impulses drawn, and those each sample gathers from the cells within reach */
    work = cells * density + count * pow(per, dim) * (density + 1);
    if (work > NL_SPARSE_WORK_MAX)
        return NL_ERROR(NL_ETOOBIG, "sparse: about %.2g impulse evaluations (radius %d, cell %g, density %g, %.0f "
                        "samples), above %.0e; expected a smaller radius or density, or a larger cell", work, radius, C,
                        density, count, NL_SPARSE_WORK_MAX);
    return NL_OK;
}

long nl_sparse_floordiv(long a, long b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }

int nl_synth_sparse_execute(const nl_synth_sparse_plan *p, uint64_t seed, unsigned flags, const long *origin,
                            nl_field *out)
{
    const int dim = p->dim, R = p->radius, C = p->cell, w = 2 * R + 1, wrap = (flags & NL_SYNTH_SPARSE_WRAP) != 0;
    const long reach = p->angle ? (long)ceil(R * M_SQRT2) + 1 : R;
    long nx = (long)out->n[0], ny = dim == 2 ? (long)out->n[1] : 1, ox = 0, oy = 0;
    long cx0, cx1, cy0 = 0, cy1 = 0;
    nl_sparse_impulses im;
    int st;
    if (out->dim != dim)
        return NL_ERROR(NL_EINVAL, "sparse: a %dD kernel cannot fill a %dD field", dim, out->dim);
    if (wrap) {
        if (origin)
            return NL_ERROR(NL_EINVAL, "sparse: a periodic tile has no origin");
        if (nx % C || (dim == 2 && ny % C))
            return NL_ERROR(NL_EINVAL, "size: a periodic tile must be a multiple of the cell size %d, got %ld%s%.0ld",
                            C, nx, dim == 2 ? "x" : "", dim == 2 ? ny : 0L);
        if (2 * reach + 1 > nx || (dim == 2 && 2 * reach + 1 > ny))
            return NL_ERROR(NL_EINVAL, "radius: the kernel (%ld samples across) is larger than the tile", 2 * reach + 1);
        cx0 = 0, cx1 = nx / C - 1;
        if (dim == 2)
            cy0 = 0, cy1 = ny / C - 1;
    } else {
        if (origin)
            ox = origin[0], oy = dim == 2 ? origin[1] : 0;
        if (ox < -NL_SPARSE_ORIGIN_MAX || ox > NL_SPARSE_ORIGIN_MAX - nx || oy < -NL_SPARSE_ORIGIN_MAX ||
            oy > NL_SPARSE_ORIGIN_MAX - ny)
            return NL_ERROR(NL_EINVAL, "origin: the window (%ld, %ld) + %ldx%ld leaves +-%ld samples", ox, oy, nx, ny,
                            NL_SPARSE_ORIGIN_MAX);
        cx0 = nl_sparse_floordiv(ox - reach, C), cx1 = nl_sparse_floordiv(ox + nx - 1 + reach, C);
        if (dim == 2)
            cy0 = nl_sparse_floordiv(oy - reach, C), cy1 = nl_sparse_floordiv(oy + ny - 1 + reach, C);
    }
    if ((st = nl_synth_sparse_check_work(dim, out->n, R, C, p->density, p->angle ? NL_SYNTH_SPARSE_ANGLE : 0)))
        return st;
    if ((st = nl_sparse_impulses_make(p, seed, cx0, cx1, cy0, cy1, &im)))
        return st;
#pragma omp parallel for schedule(dynamic, 8) if (out->count > 65536)
    for (long j = 0; j < ny; j++)
        for (long i = 0; i < nx; i++) {
            long X = ox + i, Y = oy + j;
            long a0 = nl_sparse_floordiv(X - reach, C), a1 = nl_sparse_floordiv(X + reach, C);
            long b0 = dim == 2 ? nl_sparse_floordiv(Y - reach, C) : 0;
            long b1 = dim == 2 ? nl_sparse_floordiv(Y + reach, C) : 0;
            double s = 0;
            for (long b = b0; b <= b1; b++)
                for (long a = a0; a <= a1; a++) {
                    long ca = wrap ? ((a % (im.ncx)) + im.ncx) % im.ncx : a - im.cx0;
                    long cb = wrap ? ((b % (im.ncy)) + im.ncy) % im.ncy : b - im.cy0;
                    size_t c = (size_t)(cb * im.ncx + ca);
                    for (size_t k = im.start[c]; k < im.start[c + 1]; k++) {
                        long dx = X - im.px[k], dy = dim == 2 ? Y - im.py[k] : 0;
                        if (wrap) {
                            /* the image of the impulse in the cell a, b */
                            dx = X - (im.px[k] + (a - ca) * C);
                            if (dim == 2)
                                dy = Y - (im.py[k] + (b - cb) * C);
                        }
                        if (!p->angle) {
                            if (dx < -R || dx > R || dy < -R || dy > R)
                                continue;
                            s += im.a[k] * p->h[(size_t)(dim == 2 ? (dy + R) * w + (dx + R) : dx + R)];
                        } else {
                            s += im.a[k] * nl_sparse_table_at(p->h, R, im.c[k] * (double)dx + im.s[k] * (double)dy,
                                                     -im.s[k] * (double)dx + im.c[k] * (double)dy);
                        }
                    }
                }
            out->data[j * nx + i] = s;
        }
    nl_sparse_impulses_free(&im);
    for (size_t i = 0; p->info.mean != 0 && i < out->count; i++)
        out->data[i] += p->info.mean;
    return NL_OK;
}
