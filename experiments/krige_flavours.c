/* Do the kriging flavours keep their promises on fields of a known model?
 * K Gaussian fields Y (circulant embedding, exact, G x G nodes of unit
 * spacing, seeds 1..K, model SPEC), each sampled at N distinct nodes drawn
 * by seeded uniforms; Z = exp(Y) is the lognormal field.  From each field:
 *   - 36 blocks of 4 x 4 nodes: block kriging of Y with --block-points 4
 *     (its 16 points are the block's nodes), so the block kriging variance
 *     is the expected squared error of the nodes' mean: the standardised
 *     errors' variance should be 1 (point kriging of Y at 64 other nodes
 *     alongside);
 *   - the same 64 nodes: trans-Gaussian kriging (log) of Z, against the
 *     back-transforms exp(pred) and exp(pred + var / 2) of the ordinary
 *     kriging of Y: the bias of each;
 *   - indicator kriging of Z at the thresholds exp(q sigma), q = -1, 0, 1
 *     (each with a Markov model of the field's scale and variance p (1 -
 *     p)): the mean probability against the frequency, and the Brier score
 *     against the marginal's p (1 - p).
 * Each quantity is averaged within a field, then over the K independent
 * fields: mean and standard error (sd / sqrt K).
 *
 * usage: krige_flavours SPEC SIGMA2 SCALE G N K
 *   prints quantity, mean, standard error (tab-separated). */
#include "../analysis/krige_flavours.h"
#include "../core/model.h"
#include "../core/nl_error.h"
#include "../core/rng.h"
#include "../synth/circulant.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { NB = 36, NT = 64, NQ = 3, NV = 9 + 3 * NQ };

static const char *const names[NV] = {
    "block_z_mean", "block_z_var", "point_z_var", "tg_bias", "exp_pred_bias", "exp_pred_var2_bias", "tg_rmse",
    "exp_pred_var2_rmse", "ik_corrected_share", "ik_p1_mean", "ik_p1_freq", "ik_p1_brier", "ik_p2_mean",
    "ik_p2_freq", "ik_p2_brier", "ik_p3_mean", "ik_p3_freq", "ik_p3_brier"};

/* N distinct data nodes and NT distinct target nodes (none a datum). */
static void draw(size_t g, size_t n, uint64_t seed, double *pts, size_t *idx, size_t *tgt)
{
    unsigned char *used = calloc(g * g, 1);
    size_t k = 0;
    for (uint64_t i = 0; k < n + NT; i++) {
        size_t j = (size_t)(nl_rng_uniform(seed, 91, i) * (double)(g * g)) % (g * g);
        if (used[j])
            continue;
        used[j] = 1;
        if (k < n)
            idx[k] = j, pts[2 * k] = (double)(j % g), pts[2 * k + 1] = (double)(j / g);
        else
            tgt[k - n] = j;
        k++;
    }
    free(used);
}

/* One field's averages into v (NV). */
static int one_field(const nl_model *m, const nl_model *const *mi, const double *thr, const double *pq,
                     const nl_field *f, size_t n, uint64_t seed, double *v)
{
    size_t g = f->n[0], *idx = malloc(n * sizeof *idx), tgt[NT], nc;
    double *pts = malloc(2 * n * sizeof *pts), *y = malloc(n * sizeof *y), *z = malloc(n * sizeof *z);
    double bx[2 * NB], tx[2 * NT], be[NB], bv[NB], pe[NT], pv[NT], te[NT], tv[NT], cdf[NT * NQ];
    nl_krige_local_options o = {.drift = NL_DRIFT_CONSTANT};
    nl_krige_block blk = {{4, 4}, 4};
    nl_krige_local *ky = NULL, *kl = NULL;
    int st;
    draw(g, n, seed, pts, idx, tgt);
    for (size_t i = 0; i < n; i++)
        y[i] = f->data[idx[i]], z[i] = exp(y[i]);
    for (int b = 0; b < NB; b++) /* blocks at nodes 4 + 10 i .. 7 + 10 i on each axis */
        bx[2 * b] = 5.5 + 10 * (b % 6), bx[2 * b + 1] = 5.5 + 10 * (b / 6);
    for (int t = 0; t < NT; t++)
        tx[2 * t] = (double)(tgt[t] % g), tx[2 * t + 1] = (double)(tgt[t] / g);
    if ((st = nl_krige_local_alloc(m, 2, n, pts, y, &o, &ky)) || (st = nl_krige_block_eval(ky, &blk, NB, bx, be, bv)) ||
        (st = nl_krige_local_eval(ky, NT, tx, pe, pv)) || (st = nl_krige_local_alloc(m, 2, n, pts, y, &o, &kl)) ||
        (st = nl_krige_tg_eval(kl, NULL, 0, NT, tx, te, tv)) ||
        (st = nl_krige_indicator(mi, NQ, thr, 2, n, pts, z, &o, NULL, NT, tx, NULL, cdf, &nc)))
        goto out;
    memset(v, 0, NV * sizeof *v);
    for (int b = 0; b < NB; b++) {
        double mean = 0, e;
        for (int j = 0; j < 16; j++)
            mean += f->data[(size_t)(bx[2 * b + 1] - 1.5 + j / 4) * g + (size_t)(bx[2 * b] - 1.5 + j % 4)] / 16;
        e = (mean - be[b]) / sqrt(bv[b]);
        v[0] += e / NB, v[1] += e * e / NB;
    }
    for (int t = 0; t < NT; t++) {
        double yt = f->data[tgt[t]], zt = exp(yt), e2 = exp(pe[t] + pv[t] / 2);
        v[2] += (yt - pe[t]) * (yt - pe[t]) / pv[t] / NT;
        v[3] += (zt - te[t]) / NT, v[4] += (zt - exp(pe[t])) / NT, v[5] += (zt - e2) / NT;
        v[6] += (zt - te[t]) * (zt - te[t]) / NT, v[7] += (zt - e2) * (zt - e2) / NT;
        for (int q = 0; q < NQ; q++) {
            double p = cdf[t * NQ + q], ind = zt <= thr[q];
            v[9 + 3 * q] += p / NT, v[10 + 3 * q] += ind / NT, v[11 + 3 * q] += (ind - p) * (ind - p) / NT;
        }
    }
    v[6] = sqrt(v[6]), v[7] = sqrt(v[7]), v[8] = (double)nc / NT;
    (void)pq;
out:
    nl_krige_local_free(ky), nl_krige_local_free(kl);
    free(idx), free(pts), free(y), free(z);
    return st;
}

int main(int argc, char **argv)
{
    if (argc != 7) {
        fprintf(stderr, "usage: krige_flavours SPEC SIGMA2 SCALE G N K\n");
        return 2;
    }
    double s2 = atof(argv[2]), scale = atof(argv[3]), thr[NQ], pq[NQ];
    size_t g = strtoul(argv[4], NULL, 10), n = strtoul(argv[5], NULL, 10), K = strtoul(argv[6], NULL, 10);
    size_t gn[2] = {g, g};
    nl_model *m, *mi[NQ];
    nl_synth_circulant_plan *plan;
    int st;
    if ((st = nl_model_parse(argv[1], &m)) || (st = nl_synth_circulant_plan_alloc(m, 2, gn, NULL, 0, 8, &plan))) {
        fprintf(stderr, "krige_flavours: %s\n", nl_errmsg());
        return 1;
    }
    for (int q = 0; q < NQ; q++) {
        char spec[128];
        thr[q] = exp((q - 1) * sqrt(s2)), pq[q] = 0.5 * erfc(-(q - 1) / sqrt(2.0));
        snprintf(spec, sizeof spec, "markov:var=%.6f,scale=%g", pq[q] * (1 - pq[q]), scale);
        if ((st = nl_model_parse(spec, &mi[q])))
            return 1;
    }
    double (*v)[NV] = calloc(K, sizeof *v);
    nl_field *f = nl_field_alloc(2, gn, NULL, &st);
    for (size_t k = 0; k < K && f; k++)
        if ((st = nl_synth_circulant_execute(plan, k + 1, f)) ||
            (st = one_field(m, (const nl_model *const *)mi, thr, pq, f, n, k + 1, v[k]))) {
            fprintf(stderr, "krige_flavours: field %zu: %s\n", k + 1, nl_errmsg());
            return 1;
        }
    printf("quantity\tmean\tse\n");
    for (int j = 0; j < NV; j++) {
        double s = 0, s2v = 0;
        for (size_t k = 0; k < K; k++)
            s += v[k][j], s2v += v[k][j] * v[k][j];
        double mean = s / (double)K, sd = sqrt(fmax(0, (s2v - s * mean) / (double)(K - 1)));
        printf("%s\t%.5g\t%.3g\n", names[j], mean, sd / sqrt((double)K));
    }
    for (int q = 0; q < NQ; q++)
        printf("# threshold %d: exp(%+d sigma) = %.5g, P(Z <= t) = %.4f, p (1 - p) = %.4f\n", q + 1, q - 1, thr[q],
               pq[q], pq[q] * (1 - pq[q]));
    free(v), nl_field_free(f), nl_synth_circulant_plan_free(plan), nl_model_free(m);
    for (int q = 0; q < NQ; q++)
        nl_model_free(mi[q]);
    return 0;
}
