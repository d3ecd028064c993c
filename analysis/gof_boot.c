/* The bootstrap goodness-of-fit test under the Gaussian-copula null: null
 * draws by FFT synthesis from each field's own spectrum, p-values and
 * detectable departures (analysis/gof_boot.h). */
#include "gof_boot.h"
#include "gof_boot_internal.h"
#include "../core/gsl_guard_internal.h"
#include "../core/nl_error.h"
#include "../synth/fft.h"

#include <gsl/gsl_cdf.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define Z80 0.8416212335729143
#define KS_MEDIAN 0.8275735551899077 /* median of the Kolmogorov law */
#define KS_Q95 1.3580986393225505    /* its 95% point */

/* Everything one test holds. */
typedef struct {
    const nl_field *const *x; /* the fields */
    size_t K, n, B;           /* fields, samples in all, draws */
    const nl_dist *d;         /* the law */
    int want[NL_GOF_NSTATS];  /* moments tested */
    double *u, *xs;           /* pooled u, and x (NULL: no moment) */
    double *T;                /* B x NL_GOF_NSTATS statistics of the draws */
    double *half;             /* B: F_n(1/2) - 1/2 of the draws */
    nl_synth_fft_plan **plan; /* K null plans */
    nl_field **g;             /* K null fields */
    nl_gof_boot_work w;       /* statistics scratch */
} boot;

const char *nl_gof_boot_name(int stat)
{
    static const char *const names[] = {"ks", "chi2", "mean", "variance", "skewness", "kurtosis"};
    return stat >= 0 && stat < NL_GOF_NSTATS ? names[stat] : NULL;
}

/* splitmix64's finaliser (Steele, Lea and Flood 2014). */
static uint64_t mix(uint64_t z)
{
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
    return z ^ (z >> 31);
}

static uint64_t draw_seed(uint64_t seed, size_t b, size_t k, size_t K)
{
    return mix(mix(seed) + 0x9e3779b97f4a7c15u * ((uint64_t)b * K + k + 1));
}

static int check(const nl_field *const *x, size_t K, const nl_dist *d, size_t draws, size_t bins, size_t *n)
{
    *n = 0;
    if (K == 0)
        return NL_ERROR(NL_EINVAL, "goodness of fit: expected at least one field");
    if (draws < 2)
        return NL_ERROR(NL_EINVAL, "goodness of fit: expected at least 2 null draws, got %zu", draws);
    if (nl_dist_is_function(d))
        return NL_ERROR(NL_EINVAL, "goodness of fit: %s has no CDF (expected a distribution)", nl_dist_spec(d));
    for (size_t k = 0; k < K; k++) {
        size_t bad;
        if (x[k]->count < 2)
            return NL_ERROR(NL_EINVAL, "goodness of fit: field %zu: expected at least 2 samples, got %zu", k,
                            x[k]->count);
        if (nl_field_check_finite(x[k], INFINITY, &bad))
            return NL_EINVAL;
        *n += x[k]->count;
    }
    if (bins < 2 || bins > *n)
        return NL_ERROR(NL_EINVAL, "goodness of fit: expected 2 to %zu chi-square bins, got %zu", *n, bins);
    return NL_OK;
}

static void boot_free(boot *t)
{
    for (size_t k = 0; k < t->K; k++) {
        if (t->plan)
            nl_synth_fft_plan_free(t->plan[k]);
        if (t->g)
            nl_field_free(t->g[k]);
    }
    free(t->plan), free(t->g), free(t->u), free(t->xs), free(t->T), free(t->half);
    nl_gof_boot_work_free(&t->w);
}

/* Scratch, and the null plan of every field; radii into out. */
static int boot_alloc(boot *t, size_t bins, nl_gof_boot *out)
{
    int st, any = t->want[NL_GOF_MEAN] || t->want[NL_GOF_VARIANCE];
    t->u = malloc(t->n * sizeof *t->u), t->xs = any ? malloc(t->n * sizeof *t->xs) : NULL;
    t->T = malloc(t->B * NL_GOF_NSTATS * sizeof *t->T), t->half = malloc(t->B * sizeof *t->half);
    t->plan = calloc(t->K, sizeof *t->plan), t->g = calloc(t->K, sizeof *t->g);
    if (!t->u || (any && !t->xs) || !t->T || !t->half || !t->plan || !t->g)
        return NL_ERROR(NL_ENOMEM, "out of memory for the goodness-of-fit draws of %zu samples", t->n);
    if ((st = nl_gof_boot_work_alloc(t->n, bins, &t->w)))
        return st;
    out->radius_min = INFINITY, out->radius_max = 0;
    for (size_t k = 0; k < t->K; k++) {
        nl_field *S;
        double r, dof;
        if ((st = nl_gof_boot_spectrum(t->x[k], t->d, &S, &r, &dof)))
            return st;
        st = nl_synth_fft_plan_spectrum(S, NL_SYNTH_FFT_CLAMP, &t->plan[k]);
        if (!st)
            t->g[k] = nl_field_alloc(S->dim, S->n, NULL, &st);
        nl_field_free(S);
        if (st)
            return st;
        out->radius_min = fmin(out->radius_min, r), out->radius_max = fmax(out->radius_max, r);
        out->moment_dof += dof;
    }
    return NL_OK;
}

/* The data's statistics into T (u = F(x), x pooled). */
static void data_stats(boot *t, double *T)
{
    double half;
    for (size_t k = 0, o = 0; k < t->K; o += t->x[k++]->count)
        for (size_t i = 0; i < t->x[k]->count; i++) {
            double v = t->x[k]->data[i];
            t->u[o + i] = fmin(fmax(nl_dist_cdf(t->d, v), 0), 1);
            if (t->xs)
                t->xs[o + i] = v;
        }
    nl_gof_boot_stats(t->u, t->xs, t->want, &t->w, T, &half);
}

/* Draw b: one null field per input, u = Phi(g), x = F^-1(u). */
static int draw(boot *t, uint64_t seed, size_t b)
{
    for (size_t k = 0, o = 0; k < t->K; o += t->g[k++]->count) {
        const nl_field *g = t->g[k];
        double *u = t->u + o, *xs = t->xs ? t->xs + o : NULL;
        int st = nl_synth_fft_execute(t->plan[k], draw_seed(seed, b, k, t->K), t->g[k]);
        if (st)
            return st;
#pragma omp parallel for if (g->count >= 65536) schedule(static)
        for (size_t i = 0; i < g->count; i++) {
            u[i] = 0.5 * erfc(-g->data[i] / M_SQRT2); /* Phi, as GSL's to rounding, faster */
            /* as nl_dist_transform, without computing Phi twice */
            if (xs)
                xs[i] = nl_dist_quantile(t->d, fmin(fmax(u[i], 1e-300), 1 - 1e-16));
        }
    }
    nl_gof_boot_stats(t->u, t->xs, t->want, &t->w, t->T + b * NL_GOF_NSTATS, t->half + b);
    return NL_OK;
}

static int cmp(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* The q-quantile of v[0..B-1] (sorted in place), linear between order statistics. */
static double quantile(double *v, size_t B, double q)
{
    double p = q * (double)(B - 1), f = floor(p);
    size_t i = (size_t)f;
    qsort(v, B, sizeof *v, cmp);
    return i + 1 < B ? v[i] + (p - f) * (v[i + 1] - v[i]) : v[B - 1];
}

/* The scale on which a moment's null is nearly symmetric: the log of the
 * variance (a sum of squares, skewed like a chi-square) and of the kurtosis
 * + 3 = m4 / m2^2 >= 1; the mean and the skewness as they are. */
static double sym(int s, double x)
{
    return s == NL_GOF_VARIANCE ? log(x) : s == NL_GOF_KURTOSIS ? log(x + 3) : x;
}

static void mean_sd(const double *v, size_t B, double *m, double *sd)
{
    double a = 0, ss = 0;
    for (size_t b = 0; b < B; b++)
        a += v[b];
    a /= (double)B;
    for (size_t b = 0; b < B; b++)
        ss += (v[b] - a) * (v[b] - a);
    *m = a, *sd = sqrt(ss / (double)(B - 1));
}

/* Mean, sd and rank p of statistic s over the draws; v receives the draws'
 * values.  Moments: *lm and *ls are the mean and sd on the symmetric scale,
 * where the rank p is two-sided. */
static void summarise(const boot *t, int s, double T, double *v, nl_gof_boot_stat *o, double *lm, double *ls)
{
    double above = 0;
    int moment = s >= NL_GOF_MEAN;
    for (size_t b = 0; b < t->B; b++)
        v[b] = t->T[b * NL_GOF_NSTATS + s];
    mean_sd(v, t->B, &o->null_mean, &o->null_sd);
    if (moment) {
        for (size_t b = 0; b < t->B; b++)
            v[b] = sym(s, v[b]);
        mean_sd(v, t->B, lm, ls);
    }
    for (size_t b = 0; b < t->B; b++)
        above += moment ? fabs(v[b] - *lm) >= fabs(sym(s, T) - *lm) : v[b] >= T;
    o->tested = 1, o->value = T, o->p_rank = (1 + above) / (double)(t->B + 1);
}

/* The approximate p-values (header: t, Satterthwaite, Kolmogorov). */
static void p_values(const boot *t, double *v, const double *lm, const double *ls, nl_gof_boot *out)
{
    nl_gof_boot_stat *ks = &out->stat[NL_GOF_KS], *c = &out->stat[NL_GOF_CHI2];
    double var, med, d = 0;
    for (int s = NL_GOF_MEAN; s < NL_GOF_NSTATS; s++) {
        nl_gof_boot_stat *o = &out->stat[s];
        if (!o->tested)
            continue;
        o->p = ls[s] > 0 ? 2 * gsl_cdf_tdist_Q(fabs(sym(s, o->value) - lm[s]) / ls[s], out->moment_dof)
                         : sym(s, o->value) == lm[s];
    }
    var = c->null_sd * c->null_sd;
    out->chi2_scale = var / (2 * c->null_mean), out->chi2_dof = 2 * c->null_mean * c->null_mean / var;
    c->p = var > 0 ? gsl_cdf_chisq_Q(c->value / out->chi2_scale, out->chi2_dof) : c->value <= c->null_mean;
    summarise(t, NL_GOF_KS, ks->value, v, ks, &d, &d);
    out->ks_q95 = quantile(v, t->B, 0.95);
    med = quantile(v, t->B, 0.5);
    if (out->ks_q95 > med) {
        out->ks_n_eff = pow((KS_Q95 - KS_MEDIAN) / (out->ks_q95 - med), 2);
        out->ks_shift = med - KS_MEDIAN / sqrt(out->ks_n_eff);
    } else
        out->ks_n_eff = pow(KS_MEDIAN / med, 2), out->ks_shift = 0;
    ks->p = nl_gof_ks_tail(sqrt(out->ks_n_eff) * (ks->value - out->ks_shift));
}

/* Verdict and detectable departures (header: power); ls_var: the sd of the
 * log variance over the draws. */
static void verdict(const boot *t, double ls_var, nl_gof_boot *out)
{
    const nl_gof_boot_stat *v = &out->stat[NL_GOF_VARIANCE];
    double pmin = INFINITY, hm = 0, hs = 0;
    out->tests = 0;
    for (int s = 0; s < NL_GOF_NSTATS; s++)
        if (out->stat[s].tested) {
            out->tests++;
            if (out->stat[s].p < pmin)
                pmin = out->stat[s].p, out->p_from = s;
        }
    out->p = fmin(1, pmin * (double)out->tests);
    out->var_ratio_lo = out->var_ratio_hi = NAN;
    if (v->tested) {
        /* the quantiles of the t law the variance test uses */
        double shift = (gsl_cdf_tdist_Pinv(0.975, out->moment_dof) + gsl_cdf_tdist_Pinv(0.8, out->moment_dof)) * ls_var;
        out->var_ratio_hi = exp(shift), out->var_ratio_lo = exp(-shift);
    }
    for (size_t b = 0; b < t->B; b++)
        hm += t->half[b];
    hm /= (double)t->B;
    for (size_t b = 0; b < t->B; b++)
        hs += (t->half[b] - hm) * (t->half[b] - hm);
    out->ks_detectable = out->ks_q95 + Z80 * sqrt(hs / (double)(t->B - 1));
}

static int run(boot *t, uint64_t seed, size_t bins, nl_gof_boot *out)
{
    double T[NL_GOF_NSTATS], lm[NL_GOF_NSTATS] = {0}, ls[NL_GOF_NSTATS] = {0}, *v;
    double (*law[])(const nl_dist *) = {nl_dist_mean, nl_dist_variance, nl_dist_skewness, nl_dist_kurtosis};
    int st;
    memset(out, 0, sizeof *out);
    for (int s = 0; s < NL_GOF_NSTATS; s++)
        out->stat[s].expected = s >= NL_GOF_MEAN ? law[s - NL_GOF_MEAN](t->d) : NAN;
    /* a moment's normal law needs the moment of twice its order: the
     * variance for the mean, the kurtosis for the others */
    for (int s = 0; s < NL_GOF_NSTATS; s++) {
        int need = s == NL_GOF_MEAN ? NL_GOF_VARIANCE : NL_GOF_KURTOSIS;
        t->want[s] = s < NL_GOF_MEAN || (isfinite(out->stat[s].expected) && isfinite(out->stat[need].expected));
    }
    if ((st = boot_alloc(t, bins, out)))
        return st;
    data_stats(t, T);
    for (size_t b = 0; b < t->B; b++)
        if ((st = draw(t, seed, b)))
            return st;
    if (!(v = malloc(t->B * sizeof *v)))
        return NL_ERROR(NL_ENOMEM, "out of memory for %zu draws", t->B);
    for (int s = 0; s < NL_GOF_NSTATS; s++) {
        nl_gof_boot_stat *o = &out->stat[s];
        /* a constant field has no skewness or kurtosis: not tested */
        if (t->want[s] && !isnan(T[s]))
            summarise(t, s, T[s], v, o, &lm[s], &ls[s]);
        else
            o->value = o->null_mean = o->null_sd = o->p = o->p_rank = NAN;
    }
    p_values(t, v, lm, ls, out);
    verdict(t, ls[NL_GOF_VARIANCE], out);
    free(v);
    out->n = t->n, out->fields = t->K, out->draws = t->B, out->bins = bins;
    return NL_OK;
}

int nl_gof_boot_test(const nl_field *const *x, size_t K, const nl_dist *d, size_t draws, uint64_t seed, size_t bins,
                     nl_gof_boot *out)
{
    boot t = {.x = x, .K = K, .B = draws, .d = d};
    nl_gof_boot r;
    int st = check(x, K, d, draws, bins, &t.n);
    if (st)
        return st;
    nl_gsl_enter();
    st = run(&t, seed, bins, &r);
    nl_gsl_leave();
    boot_free(&t);
    if (!st)
        *out = r;
    return st;
}
