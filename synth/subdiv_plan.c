/* Subdivision plans: the coefficients of every level and the coarse FFT plan
 * made once, then executed for any number of seeds (Lewis 1987). */
#include "subdiv_internal.h"
#include "fft.h"
#include "../core/autocorr.h"
#include "../core/taper_internal.h"
#include "../core/nl_error.h"
#include "../core/rng.h"

#include <limits.h>
#include <math.h>
#include <omp.h>
#include <stdlib.h>

struct nl_subdiv_plan {
    nl_subdiv_coeffs *c;       /* the levels' coefficients */
    int owns;                  /* c is freed with the plan */
    const nl_model *m;         /* the model (NULL for midpoint); borrowed, only read by alloc */
    int dim;                   /* 1 or 2 */
    size_t n[2];               /* output size (n[1] = 1 in 1D) */
    size_t cn[2];              /* coarse size n / 2^levels */
    int allow_not_pd;          /* negative variances become 0 instead of NL_ENOTPD */
    int nonperiodic;           /* a window of the infinite field */
    int image;                 /* the coarse level is given to nl_subdiv_plan_execute_image */
    nl_synth_fft_plan *coarse; /* periodic level 0 of m at spacing s_0; NULL: independent values */
    nl_subdiv_info info;       /* what nl_subdiv_plan_info returns */
};

void nl_subdiv_options_default(nl_subdiv_options *o)
{
    *o = (nl_subdiv_options){.levels = 0, .N = 2, .tol = 1e-4, .nmax = 0, .random_seed = 1};
}

int nl_subdiv_default_levels(int dim, const size_t *n, long min)
{
    int L = 0;
    for (;;) {
        int ok = 1;
        for (int a = 0; a < dim; a++)
            if ((long)n[a] % (2L << L) != 0 || (long)n[a] / (2L << L) < min)
                ok = 0;
        if (!ok || L >= 30)
            return L;
        L++;
    }
}

int nl_subdiv_image_levels(int dim, const size_t *image_n, const size_t *n, int levels, int *out)
{
    int Li = 0;
    while ((image_n[0] << Li) < n[0])
        Li++;
    if ((image_n[0] << Li) != n[0] || (dim == 2 && (image_n[1] << Li) != n[1]))
        return NL_ERROR(NL_EINVAL, "--seed-image: a %zu%s%.0zu image refines to a power-of-two multiple of its "
                        "size, not to --size %zu%s%.0zu", image_n[0], dim == 2 ? "x" : "",
                        dim == 2 ? image_n[1] : (size_t)0, n[0], dim == 2 ? "x" : "", dim == 2 ? n[1] : (size_t)0);
    if (levels && levels != Li)
        return NL_ERROR(NL_EINVAL, "--levels: the seed image fixes %d levels, got %d", Li, levels);
    if (Li < 1)
        return NL_ERROR(NL_EINVAL, "--seed-image: the %zu%s%.0zu image is already as large as --size %zu%s%.0zu; "
                        "expected a smaller image", image_n[0], dim == 2 ? "x" : "", dim == 2 ? image_n[1] : (size_t)0,
                        n[0], dim == 2 ? "x" : "", dim == 2 ? n[1] : (size_t)0);
    *out = Li;
    return NL_OK;
}

void nl_subdiv_plan_free(nl_subdiv_plan *p)
{
    if (!p)
        return;
    if (p->owns)
        nl_subdiv_coeffs_free(p->c);
    nl_synth_fft_plan_free(p->coarse);
    free(p);
}

/* The periodic set-up: the size check, the levels' positive definiteness
 * and, with a model, the FFT plan of level 0 (in this order, as the
 * one-shot nl_subdiv_synth_periodic reports them). */
static int check_periodic_size(int dim, const size_t *n, int L)
{
    size_t c0 = n[0] >> L, c1 = dim == 2 ? n[1] >> L : 2;
    if ((c0 << L) != n[0] || (dim == 2 && (c1 << L) != n[1]) || c0 < 2 || c1 < 2)
        return NL_ERROR(NL_EINVAL, "size: expected each size a multiple of 2^%d = %ld with at least 2 coarse "
                        "samples, got %zu%s%.0zu", L, 1L << L, n[0], dim == 2 ? "x" : "", dim == 2 ? n[1] : (size_t)0);
    return NL_OK;
}

static int plan_periodic(nl_subdiv_plan *p)
{
    const nl_subdiv_coeffs *c = p->c;
    const int dim = p->dim;
    double h[2] = {c->spacing0, c->spacing0};
    int st;
    p->cn[0] = p->n[0] >> c->levels;
    p->cn[1] = dim == 2 ? p->n[1] >> c->levels : 1;
    if ((st = check_periodic_size(dim, p->n, c->levels)))
        return st;
    if ((st = nl_subdiv_check_levels(c, p->allow_not_pd)))
        return st;
    if (p->m)
        return nl_synth_fft_plan_alloc(p->m, dim, p->cn, h, p->allow_not_pd ? NL_SYNTH_FFT_CLAMP : 0, &p->coarse);
    return NL_OK;
}

static nl_subdiv_plan *plan_new(nl_subdiv_coeffs *c, int owns, const nl_model *m, int dim, const size_t *n)
{
    nl_subdiv_plan *p = calloc(1, sizeof *p);
    if (!p) {
        if (owns)
            nl_subdiv_coeffs_free(c);
        return NULL;
    }
    p->c = c, p->owns = owns, p->m = m, p->dim = dim;
    p->n[0] = n[0], p->n[1] = dim == 2 ? n[1] : 1;
    p->info.levels = c ? c->levels : 0;
    p->info.spacing0 = c ? c->spacing0 : NAN;
    p->info.variance = c ? c->r0 : NAN;
    p->info.coarse_correlation = NAN;
    return p;
}

/* The coefficients for `o`, levels L at s_0 = h 2^L, randomised if asked. */
static int coeffs_for(const nl_model *m, int dim, int L, double h, const nl_subdiv_options *o, nl_subdiv_coeffs **c)
{
    int st = nl_subdiv_coeffs_alloc_rule(m, dim, L, ldexp(h, L), o->N, o->stop, o->tol,
                                         o->nmax ? o->nmax : dim == 1 ? 16 : 6, c);
    if (st)
        return st;
    if (o->random_nb) {
        if (dim != 2)
            st = NL_ERROR(NL_EINVAL, "--random-neighborhoods: expected a 2D --size, got %dD", dim);
        else
            st = nl_subdiv_coeffs_randomize(*c, m, o->random_nb, o->random_seed);
    }
    if (!st && o->displacements) {
        if (o->taps < 0 || o->taps > NL_SUBDIV_MAX_TAPS)
            st = NL_ERROR(NL_EINVAL, "--taps: expected 1 to %d, got %d", NL_SUBDIV_MAX_TAPS, o->taps);
        else
            st = nl_subdiv_coeffs_correlate(*c, m, o->taps ? o->taps : dim == 1 ? 4 : 2, o->displacements);
    }
    if (st) {
        nl_subdiv_coeffs_free(*c);
        *c = NULL;
    }
    return st;
}

int nl_subdiv_plan_alloc(const nl_model *m, int dim, const size_t *n, double h, const nl_subdiv_options *o,
                         nl_subdiv_plan **out)
{
    nl_subdiv_coeffs *c;
    nl_subdiv_plan *p;
    int L = o->levels, st;
    *out = NULL;
    if (dim != 1 && dim != 2)
        return NL_ERROR(NL_EINVAL, "subdivision: expected a 1D or 2D grid, got %dD", dim);
    if (m && (st = nl_model_check_stationary(m, "subdivision")))
        return st;
    if (!L)
        L = o->nonperiodic ? 6 : nl_subdiv_default_levels(dim, n, 8);
    if (L < 1)
        return NL_ERROR(NL_EINVAL, "--size: expected a size divisible by 2 with at least 16 samples for "
                        "subdivision, got %zu", n[0]);
    /* the size first: the coefficients can cost seconds */
    if (!o->nonperiodic && !o->image && (st = check_periodic_size(dim, n, L)))
        return st;
    /* the coefficients first: they name a lag where R is not finite */
    if ((st = coeffs_for(m, dim, L, h, o, &c)))
        return st;
    if (!(p = plan_new(c, 1, m, dim, n)))
        return NL_ERROR(NL_ENOMEM, "out of memory");
    p->allow_not_pd = o->allow_not_pd;
    p->nonperiodic = o->nonperiodic;
    p->image = o->image;
    if (o->nonperiodic) {
        double lag[2] = {c->spacing0, 0}, zero[2] = {0, 0};
        p->info.coarse_correlation = nl_model_acf(m, dim, lag) / nl_model_acf(m, dim, zero);
        st = nl_subdiv_check_levels(c, 0);
    } else if (!o->image) {
        st = plan_periodic(p);
    }
    p->m = NULL;
    if (st) {
        nl_subdiv_plan_free(p);
        return st;
    }
    *out = p;
    return NL_OK;
}

int nl_subdiv_midpoint_hurst(const nl_model *m, int dim, double *H)
{
    double d = NAN;
    /* f^-d with d = 2H + E (E = 1 or 2) */
    if (nl_model_family(m) != &nl_family_power || nl_model_param(m, "d", &d))
        return NL_ERROR(NL_EINVAL, "synth midpoint: expected --H or a power:d=D model, got \"%s\"", nl_model_spec(m));
    *H = (d - dim) / 2;
    if (!(*H > 0 && *H < 1))
        return NL_ERROR(NL_EINVAL, "synth midpoint: power:d=%g gives H = %g in %dD; expected %d < d < %d", d, *H,
                        dim, dim, dim + 2);
    return NL_OK;
}

int nl_subdiv_plan_alloc_midpoint(int dim, const size_t *n, double h, int levels, double H, double sigma2,
                                  double vscale, nl_subdiv_plan **out)
{
    nl_subdiv_coeffs *c;
    nl_subdiv_plan *p;
    int L = levels ? levels : nl_subdiv_default_levels(dim, n, 2), st;
    *out = NULL;
    if ((st = nl_subdiv_coeffs_midpoint(dim, L, ldexp(h, L), H, sigma2, vscale, &c)))
        return st;
    if (!(p = plan_new(c, 1, NULL, dim, n)))
        return NL_ERROR(NL_ENOMEM, "out of memory");
    if ((st = plan_periodic(p))) {
        nl_subdiv_plan_free(p);
        return st;
    }
    *out = p;
    return NL_OK;
}

const nl_subdiv_coeffs *nl_subdiv_plan_coeffs(const nl_subdiv_plan *p) { return p->c; }

void nl_subdiv_plan_info(const nl_subdiv_plan *p, nl_subdiv_info *info) { *info = p->info; }

/* Level 0 of a periodic plan for `seed` into coarse (p->cn samples). */
static int coarse_level(const nl_subdiv_plan *p, uint64_t seed, nl_field *coarse)
{
    if (p->coarse)
        return nl_synth_fft_execute(p->coarse, seed, coarse);
    for (size_t j = 0; j < p->cn[1]; j++)
        for (size_t i = 0; i < p->cn[0]; i++)
            coarse->data[j * p->cn[0] + i] =
                sqrt(p->c->r0) * nl_rng_gauss(seed, NL_SUBDIV_STREAM, rng_index(p->dim, (long)i, (long)j));
    return NL_OK;
}

static int check_field(const nl_subdiv_plan *p, const nl_field *f)
{
    if (f->dim != p->dim)
        return NL_ERROR(NL_EINVAL, "subdivision: a %dD plan cannot fill a %dD field", p->dim, f->dim);
    if (f->n[0] != p->n[0] || (p->dim == 2 && f->n[1] != p->n[1]))
        return NL_ERROR(NL_EINVAL, "subdivision: the output field (%zu%s%.0zu) does not match the plan's grid "
                        "(%zu%s%.0zu)", f->n[0], p->dim == 2 ? "x" : "", p->dim == 2 ? f->n[1] : (size_t)0,
                        p->n[0], p->dim == 2 ? "x" : "", p->dim == 2 ? p->n[1] : (size_t)0);
    return NL_OK;
}

static int execute_periodic(const nl_subdiv_plan *p, uint64_t seed, nl_field *f)
{
    double h[2] = {p->c->spacing0, p->c->spacing0};
    nl_field *coarse;
    int st;
    coarse = nl_field_alloc(p->dim, p->cn, h, &st);
    if (!coarse)
        return st;
    st = coarse_level(p, seed, coarse);
    if (!st)
        st = nl_subdiv_refine_periodic(p->c, coarse, seed, p->allow_not_pd, f);
    nl_field_free(coarse);
    return st;
}

int nl_subdiv_plan_execute(const nl_subdiv_plan *p, uint64_t seed, nl_field *f)
{
    static const long zero[2] = {0, 0};
    int st;
    if (p->image)
        return NL_ERROR(NL_EINVAL, "subdivision: a plan for a given coarse level executes with "
                        "nl_subdiv_plan_execute_image");
    if ((st = check_field(p, f)))
        return st;
    return p->nonperiodic ? nl_subdiv_synth_window(p->c, seed, zero, f) : execute_periodic(p, seed, f);
}

int nl_subdiv_plan_execute_window(const nl_subdiv_plan *p, uint64_t seed, const long *origin, nl_field *f)
{
    int st;
    if (!p->nonperiodic)
        return NL_ERROR(NL_EINVAL, "subdivision: a window needs a plan made with the nonperiodic option");
    static const long zero[2] = {0, 0};
    if ((st = check_field(p, f)))
        return st;
    return nl_subdiv_synth_window(p->c, seed, origin ? origin : zero, f);
}

int nl_subdiv_plan_execute_image(const nl_subdiv_plan *p, const nl_field *image, uint64_t seed, nl_field *f)
{
    const int dim = p->dim;
    size_t step = (size_t)1 << p->c->levels;
    double mean;
    nl_field *work;
    int st;
    if (p->nonperiodic)
        return NL_ERROR(NL_EINVAL, "subdivision: a seed image needs a periodic plan");
    if ((st = check_field(p, f)))
        return st;
    if (image->dim != dim)
        return NL_ERROR(NL_EINVAL, "subdivision: a %dD seed image for a %dD plan", image->dim, dim);
    /* refine the zero-mean image: the model is of a zero-mean field */
    mean = nl_field_mean(image);
    work = nl_field_alloc(image->dim, image->n, image->h, &st);
    if (!work)
        return st;
    for (size_t i = 0; i < image->count; i++)
        work->data[i] = image->data[i] - mean;
    st = nl_subdiv_refine_periodic(p->c, work, seed, p->allow_not_pd, f);
    nl_field_free(work);
    if (st)
        return st;
    for (size_t i = 0; i < f->count; i++)
        f->data[i] += mean;
    /* the seed samples are the data, bit for bit (not (v - mean) + mean) */
    for (size_t j = 0; j < image->n[1]; j++)
        for (size_t i = 0; i < image->n[0]; i++)
            f->data[(dim == 2 ? j * step * f->n[0] : 0) + i * step] = image->data[j * image->n[0] + i];
    return NL_OK;
}

int nl_subdiv_synth_periodic(const nl_subdiv_coeffs *c, const nl_model *m, uint64_t seed, int allow_not_pd,
                             nl_field *f)
{
    nl_subdiv_plan *p;
    int st;
    if (f->dim != c->dim)
        return NL_ERROR(NL_EINVAL, "subdivision: a %dD plan cannot fill a %dD field", c->dim, f->dim);
    /* a plan borrowing c: the coefficients stay the caller's */
    if (!(p = plan_new((nl_subdiv_coeffs *)c, 0, m, c->dim, f->n)))
        return NL_ERROR(NL_ENOMEM, "out of memory");
    p->allow_not_pd = allow_not_pd;
    st = plan_periodic(p);
    p->m = NULL;
    if (!st)
        st = execute_periodic(p, seed, f);
    nl_subdiv_plan_free(p);
    return st;
}

/* The slab field f for a slab from s0 (nl_subdiv_plan_execute_slab). */
static int check_slab(const nl_subdiv_plan *p, size_t s0, const nl_field *f)
{
    const int s = p->dim - 1;
    if (f->dim != p->dim)
        return NL_ERROR(NL_EINVAL, "subdivision: a %dD plan cannot fill a %dD slab", p->dim, f->dim);
    if (p->dim == 2 && f->n[0] != p->n[0])
        return NL_ERROR(NL_EINVAL, "slab: expected rows of %zu samples, as the plan's, got %zu", p->n[0], f->n[0]);
    if (f->n[s] < 1 || s0 > p->n[s] || f->n[s] > p->n[s] - s0)
        return NL_ERROR(NL_EINVAL, "slab: %zu %s from %zu leave the plan's %zu; expected at least one, within it",
                        f->n[s], p->dim == 2 ? "rows" : "samples", s0, p->n[s]);
    return NL_OK;
}

int nl_subdiv_plan_execute_slab(const nl_subdiv_plan *p, uint64_t seed, size_t s0, nl_field *f)
{
    double h[2] = {p->c->spacing0, p->c->spacing0};
    nl_field *coarse;
    int st;
    if (p->image)
        return NL_ERROR(NL_EINVAL, "subdivision: a plan for a given coarse level executes slabs with "
                        "nl_subdiv_plan_execute_image_slab");
    if ((st = check_slab(p, s0, f)))
        return st;
    if (p->nonperiodic) {
        const long origin[2] = {p->dim == 2 ? 0 : (long)s0, (long)s0};
        return nl_subdiv_synth_window(p->c, seed, origin, f);
    }
    if (!(coarse = nl_field_alloc(p->dim, p->cn, h, &st)))
        return st;
    st = coarse_level(p, seed, coarse);
    if (!st)
        st = nl_subdiv_refine_slab(p->c, coarse, seed, p->allow_not_pd, s0, f);
    nl_field_free(coarse);
    return st;
}

int nl_subdiv_plan_execute_image_slab(const nl_subdiv_plan *p, const nl_field *image, uint64_t seed, size_t s0,
                                      nl_field *f)
{
    const int dim = p->dim;
    const size_t step = (size_t)1 << p->c->levels, ns = f->n[dim - 1];
    double mean;
    nl_field *work;
    int st;
    if (p->nonperiodic || !p->image)
        return NL_ERROR(NL_EINVAL, "subdivision: a seed-image slab needs a plan made with the image option");
    if ((st = check_slab(p, s0, f)))
        return st;
    if (image->dim != dim)
        return NL_ERROR(NL_EINVAL, "subdivision: a %dD seed image for a %dD plan", image->dim, dim);
    if (image->n[0] * step != p->n[0] || (dim == 2 && image->n[1] * step != p->n[1]))
        return NL_ERROR(NL_EINVAL, "subdivision: the seed image (%zu%s%.0zu) is not the plan's grid over 2^%d",
                        image->n[0], dim == 2 ? "x" : "", dim == 2 ? image->n[1] : (size_t)0, p->c->levels);
    /* as nl_subdiv_plan_execute_image: the zero-mean image refined, the
     * mean added back, the image's own samples restored */
    mean = nl_field_mean(image);
    if (!(work = nl_field_alloc(image->dim, image->n, image->h, &st)))
        return st;
    for (size_t i = 0; i < image->count; i++)
        work->data[i] = image->data[i] - mean;
    st = nl_subdiv_refine_slab(p->c, work, seed, p->allow_not_pd, s0, f);
    nl_field_free(work);
    if (st)
        return st;
    for (size_t i = 0; i < f->count; i++)
        f->data[i] += mean;
    for (size_t j = 0; j < image->n[1]; j++)
        for (size_t i = 0; i < image->n[0]; i++) {
            size_t y = dim == 2 ? j * step : i * step;
            if (y >= s0 && y < s0 + ns)
                f->data[dim == 2 ? (y - s0) * f->n[0] + i * step : y - s0] = image->data[j * image->n[0] + i];
        }
    return NL_OK;
}

/* The coarse level's bytes: its field, and the scratch of its FFT (an odd
 * first axis: the half grid; even: a column and 8-row blocks per thread,
 * synth/fft.c), or the image's zero-mean copy. */
static size_t coarse_bytes(const nl_subdiv_plan *p)
{
    const size_t count = p->cn[0] * p->cn[1], rows = p->cn[1], h0 = p->cn[0] / 2 + 1, z = 2 * sizeof(double);
    size_t b = count * sizeof(double);
    if (p->coarse)
        b += p->cn[0] % 2 ? rows * h0 * z : rows * z + (size_t)omp_get_max_threads() * 8 * h0 * z;
    return b;
}

size_t nl_subdiv_plan_slab_bytes(const nl_subdiv_plan *p, size_t ns)
{
    size_t levels, coarse;
    if (ns > (size_t)LONG_MAX / 2)
        return SIZE_MAX;
    levels = nl_subdiv_slab_bytes(p->c, (long)p->n[0], (long)ns, p->nonperiodic);
    if (p->nonperiodic)
        return levels;
    coarse = coarse_bytes(p);
    return levels > SIZE_MAX - coarse ? SIZE_MAX : levels + coarse;
}
