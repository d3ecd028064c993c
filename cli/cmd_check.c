/* noiselab check: is a model a valid autocorrelation, how smooth, how singular. */
#include "cli.h"
#include "opt.h"
#include "../analysis/check.h"
#include "../analysis/check_intrinsic.h"
#include "../core/model.h"
#include "../core/nl_error.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static const char help[] =
    "usage: noiselab check --acf SPEC --dim D [--profile-1d[=RMAX]] [--json]\n"
    "       noiselab check --spectrum SPEC --dim D [--json]\n\n"
    "Positive definiteness (the sign of the D-dimensional spectrum, of R times a\n"
    "Gaussian taper too, exact in sign however slowly R decays; the smallest\n"
    "eigenvalue of a covariance matrix; for isotropic models Schoenberg's bound\n"
    "R >= min J0 R(0) in 2D, min sin(x)/x R(0) in 3D, the 3D non-increasing line\n"
    "spectrum, a negative power-law tail r^-b with b <= D, and, for compact\n"
    "support, the edge's asymptotics), smoothness (R''(0), the order of\n"
    "mean-square differentiability, the decay of the line spectrum -- the\n"
    "spectrum of R along a line -- and of the D-dimensional density) and the\n"
    "spacing below which subdivision's matrix is numerically singular.  A model\n"
    "that is not positive definite is told why, with valid neighbours where there\n"
    "is an obvious one.  Models defined by R are sampled; spectral models (power:,\n"
    "spectrum:) are judged from their density (the eigenvalue is then that of the\n"
    "infinite grid of unit spacing, the smallest aliased spectrum value).\n"
    "JSON keys: model, dim, positive_definite, why (null when valid),\n"
    "neighbours, spectral (the path taken), variance, min_spectrum,\n"
    "min_spectrum_k, spectrum_kmax, min_eigenvalue, eigen_grid {side (null:\n"
    "infinite), spacing}, isotropic,\n"
    "isotropic_bound_ok, min_r, min_r_lag, monotone_3d, line_rise_f,\n"
    "differentiable_order (null: infinitely), r2 (null: does not exist),\n"
    "spectral_decay (the line spectrum's b in f^-b; null: faster than any\n"
    "power), density_decay (the D-dimensional density's), band_limited,\n"
    "band_edge, singular_checked, singular_below_spacing (null: never), scale,\n"
    "flags.  Exit status 0 whatever the verdict.\n"
    "--profile-1d (--dim 2): also Lewis 1987 eq. (14) (Matheron): the isotropic 2D\n"
    "correlation C2 made by sweeping the model's 1D profile C1 = R over every\n"
    "direction (turning bands; valid in 2D whenever R is in 1D), at 33 lags from 0\n"
    "to RMAX (default: a quarter of the reported scale): JSON profile_1d {lag, c1,\n"
    "c2, min_c2 (relative to C2(0)), min_c2_lag}.\n";

static const char *why_key[] = {NULL, "negative-integral", "negative-spectrum", "isotropic-bound",
                                "negative-eigenvalue", "line-spectrum-rises", "edge-asymptotics",
                                "negative-tapered-spectrum", "known-not-positive-definite"};

/* A JSON number, or null where it is undefined or unbounded. */
static json_t *num(double v) { return isfinite(v) ? json_real(v) : json_null(); }

static json_t *json_lists(const nl_check *k, const char *nb, json_t **flags)
{
    json_t *a = json_array();
    char buf[4096];
    *flags = json_array();
    if (!k->positive_definite)
        json_array_append_new(*flags, json_string("not-positive-definite"));
    if (k->singular_below > 0)
        json_array_append_new(*flags, json_string("singular"));
    if (!k->isotropic_bound_ok)
        json_array_append_new(*flags, json_string("isotropic-bound"));
    if (!k->monotone_3d)
        json_array_append_new(*flags, json_string("not-monotone-3d"));
    snprintf(buf, sizeof buf, "%s", nb);
    for (char *save = NULL, *s = strtok_r(buf, "\n", &save); s; s = strtok_r(NULL, "\n", &save))
        json_array_append_new(a, json_string(s));
    return a;
}

/* Eq. (14) at 33 lags from 0 to rmax (0: the check's scale / 4): a table,
 * or profile_1d in o. */
static void profile_1d(const nl_model *m, const nl_check *k, double rmax, json_t *o)
{
    enum { NL = 33 };
    double r[NL], c1[NL], c2[NL], lo = INFINITY, lolag = 0;
    int given = rmax > 0;
    if (!given)
        rmax = k->scale / 4;
    for (int i = 0; i < NL; i++) {
        r[i] = rmax * ((double)i / (NL - 1)); /* no overflow for rmax near DBL_MAX */
        c1[i] = nl_model_acf(m, 1, &r[i]);
    }
    int st = nl_check_matheron_2d(m, NL, r, c2);
    if (st)
        cli_die(nl_error_is_input(st) ? 2 : 1, "--profile-1d: RMAX %g%s: %s", rmax,
                given ? "" : " (a quarter of the scale; set --profile-1d=RMAX)", nl_errmsg());
    for (int i = 0; i < NL; i++)
        if (c2[i] < lo)
            lo = c2[i], lolag = r[i];
    if (o) {
        json_object_set_new(o, "profile_1d", json_pack("{s:o,s:o,s:o,s:f,s:f}", "lag", cli_json_array(r, NL), "c1",
                                                       cli_json_array(c1, NL), "c2", cli_json_array(c2, NL),
                                                       "min_c2", lo / c2[0], "min_c2_lag", lolag));
        return;
    }
    printf("  eq. (14), the 2D isotropic correlation swept from the 1D profile (min C2/C2(0) %.4f at lag %.3g):\n"
           "  %-12s %-12s %s\n", lo / c2[0], lolag, "lag", "C1 = R", "C2");
    for (int i = 0; i < NL; i++)
        printf("  %-12.6g %-12.6g %.6g\n", r[i], c1[i], c2[i]);
}

/* m non-NULL: with eq. (14) (--profile-1d). */
static void print_json(const char *spec, const nl_check *k, const char *nb, const nl_model *m, double rmax)
{
    json_t *fl, *nbs = json_lists(k, nb, &fl);
    json_t *grid = json_pack("{s:o,s:o}", "side", k->eig_side ? json_integer((json_int_t)k->eig_side) : json_null(),
                             "spacing", num(k->eig_spacing));
    json_t *o = json_pack("{s:s,s:i,s:b,s:o,s:o,s:b,s:o,s:o,s:o,s:o,s:o,s:o}", "model", spec, "dim", k->dim,
                          "positive_definite", k->positive_definite, "why",
                          why_key[k->why] ? json_string(why_key[k->why]) : json_null(), "neighbours", nbs,
                          "spectral", k->spectral, "variance", num(k->variance), "min_spectrum", num(k->min_spectrum),
                          "min_spectrum_k", num(k->min_spectrum_k), "spectrum_kmax", num(k->spectrum_kmax),
                          "min_eigenvalue", num(k->min_eigenvalue), "eigen_grid", grid);
    json_object_update_new(
        o, json_pack("{s:b,s:b,s:o,s:o,s:b,s:o,s:o,s:o,s:o,s:o,s:b,s:o,s:b,s:o,s:o,s:o}", "isotropic", k->isotropic,
                     "isotropic_bound_ok", k->isotropic_bound_ok, "min_r", num(k->min_r), "min_r_lag",
                     num(k->min_r_lag), "monotone_3d", k->monotone_3d, "line_rise_f", num(k->line_rise_f),
                     "differentiable_order",
                     k->differentiable_order < 0 ? json_null() : json_integer(k->differentiable_order), "r2",
                     num(k->r2), "spectral_decay", num(k->spectral_decay), "density_decay", num(k->density_decay),
                     "band_limited", k->band_limited, "band_edge", num(k->band_edge), "singular_checked",
                     k->singular_checked, "singular_below_spacing",
                     k->singular_below > 0 ? json_real(k->singular_below) : json_null(), "scale", num(k->scale),
                     "flags", fl));
    if (m)
        profile_1d(m, k, rmax, o);
    cli_json_print(o);
}

/* Why the model is not positive definite, in words the user can act on. */
static void print_why(const nl_check *k, const char *nb)
{
    static const char *whole[] = {"", "line", "plane", "space"};
    int d = k->dim;
    switch (k->why) {
    case NL_CHECK_NEG_INTEGRAL:
        printf("  why                    the integral of R over the %s is negative (the %dD spectrum at k = 0 is "
               "%.3g times its largest magnitude): no field has this covariance\n", whole[d], d, k->min_spectrum);
        break;
    case NL_CHECK_NEG_SPECTRUM:
        printf("  why                    its %dD spectrum (the density over %dD frequencies) is negative at |k| = "
               "%.3g cycles per unit (%.3g times its largest magnitude): no field has this covariance\n", d, d,
               k->min_spectrum_k, k->min_spectrum);
        break;
    case NL_CHECK_BOUND:
        printf("  why                    R falls to %.3f R(0) at lag %.3g, below the %.4f R(0) an isotropic covariance "
               "allows in %dD (Schoenberg 1938)\n", k->min_r, k->min_r_lag, nl_check_isotropic_bound(d), d);
        break;
    case NL_CHECK_NEG_EIGENVALUE:
        printf("  why                    the covariance matrix of a grid of %zu^%d points spaced %.3g has a negative "
               "eigenvalue (%.3g R(0)): sampled there, no field has it\n", k->eig_side, d, k->eig_spacing,
               k->min_eigenvalue);
        break;
    case NL_CHECK_LINE_RISES:
        printf("  why                    its line spectrum (of R along a line) rises at f = %.3g; an isotropic 3D "
               "covariance needs it non-increasing\n", k->line_rise_f);
        break;
    case NL_CHECK_NEG_TAPERED:
        printf("  why                    the %dD spectrum of R times a Gaussian taper (positive for every valid R, "
               "however slowly R decays) is negative at |k| = %.3g cycles per unit (%.3g times its largest "
               "magnitude): no field has this covariance\n", d, k->min_spectrum_k, k->min_spectrum);
        break;
    case NL_CHECK_EDGE:
        printf("  why                    R vanishes beyond a lag with an edge singularity that its behaviour at lag 0 "
               "does not outweigh: its %dD spectrum oscillates in sign at high |k| (beyond the frequencies "
               "sampled): no field has this covariance\n", d);
        break;
    default: break;
    }
    if (k->why == NL_CHECK_VALID)
        return;
    if (!*nb)
        printf("  valid neighbours       none obvious\n");
    for (const char *p = nb; *p;) {
        const char *e = strchr(p, '\n');
        int n = e ? (int)(e - p) : (int)strlen(p);
        printf("  %-22s %.*s\n", p == nb ? "valid neighbours" : "", n, p);
        p += n + (e != NULL);
    }
}

static void print_eigen(const nl_check *k)
{
    if (!isfinite(k->min_eigenvalue))
        printf("  min eigenvalue / R(0)  not computed (the integral of S, R(0), is not positive)\n");
    else if (k->eig_side)
        printf("  min eigenvalue / R(0)  %.3g (the %zu x %zu covariance matrix of a %zu-point grid per axis, "
               "spacing %.3g)\n", k->min_eigenvalue, (size_t)pow((double)k->eig_side, k->dim),
               (size_t)pow((double)k->eig_side, k->dim), k->eig_side, k->eig_spacing);
    else
        printf("  min eigenvalue / R(0)  %.3g (the covariance of the infinite grid of unit spacing: the smallest "
               "aliased spectrum%s)\n", k->min_eigenvalue,
               k->min_eigenvalue == 0 ? "; 0 where S vanishes on part of the band" : "");
}

static void print_smooth(const nl_check *k)
{
    char dens[128] = "";
    int d = k->dim;
    if (d > 1 && isfinite(k->density_decay))
        snprintf(dens, sizeof dens, "; %dD density ~ |k|^-%.2f", d, k->density_decay);
    else if (d > 1 && isnan(k->density_decay))
        snprintf(dens, sizeof dens, "; %dD density's decay not estimated (anisotropic)", d);
    if (k->band_limited)
        printf("  differentiable         infinitely (band-limited: the %dD density is 0 above |k| = %.3g%s%.2f "
               "below)\n", d, k->band_edge, isfinite(k->density_decay) ? " and ~ |k|^-" : "",
               isfinite(k->density_decay) ? k->density_decay : 0.0);
    else if (k->differentiable_order < 0)
        printf("  differentiable         infinitely (the spectrum decays faster than any power)\n");
    else if (isfinite(k->spectral_decay))
        printf("  differentiable         %d times (line spectrum of R along x ~ f^-%.2f%s)\n",
               k->differentiable_order, k->spectral_decay, dens);
    else /* the spectral fit saw no power law, but R has a kink at lag 0 */
        printf("  differentiable         %d times (R has a kink at lag 0)\n", k->differentiable_order);
    if (isfinite(k->r2))
        printf("  R''(0)                 %.6g\n", k->r2);
    else if (k->r2 < 0)
        printf("  R''(0)                 unbounded below (%s)\n",
               k->spectral ? "the moment of f^2 S diverges" : "a kink at lag 0");
    else
        printf("  R''(0)                 not computed (the integral of S, R(0), is not positive)\n");
}

static void print_text(const char *spec, const nl_check *k, const char *nb, const char *known)
{
    int d = k->dim;
    printf("%s in %dD: %s\n", spec, d, k->positive_definite ? "positive definite" : "NOT positive definite");
    if (k->why == NL_CHECK_KNOWN) {
        printf("  why                    %s\n", known);
        print_why(k, nb);
        return;
    }
    print_why(k, nb);
    printf("  min spectrum / max     %.3g (the %dD density, %s to |k| = %.3g cycles per unit along each axis)\n",
           k->min_spectrum, d, k->spectral ? "scanned" : "sampled", k->spectrum_kmax);
    if (k->spectral)
        printf("  variance R(0)          %.6g (the integral of S)\n", k->variance);
    print_eigen(k);
    if (k->isotropic && isfinite(k->min_r))
        printf("  min R / R(0)           %.4f at lag %.3g (isotropic bound %.4f in %dD: %s)\n", k->min_r, k->min_r_lag,
               nl_check_isotropic_bound(d), d, k->isotropic_bound_ok ? "ok" : "violated");
    if (d == 3 && k->isotropic && !k->spectral)
        printf("  3D line spectrum       %s\n", k->monotone_3d ? "non-increasing" : "rises");
    print_smooth(k);
    if (!k->singular_checked)
        printf("  subdivision            not checked (a spectrum: model's R is not sampled)\n");
    else if (k->singular_below > 0)
        printf("  numerically singular below spacing %.3g (subdivision, N = 2, along x)\n", k->singular_below);
    else
        printf("  never numerically singular (down to spacing %.3g; subdivision, N = 2, along x)\n",
               ldexp(k->scale, -24));
}

/* The command's options. */
typedef struct {
    const char *spec; /* --acf or --spectrum */
    int dim, json;    /* --dim, --json */
    int prof;         /* --profile-1d given */
    double rmax;      /* its largest lag (0: the default) */
} opts_t;

static const cli_opt rows[] = {
    CLI_OPT_MODEL(opts_t, spec, .need = "a model (see noiselab models)"),
    CLI_OPT_DIMS(opts_t, dim, 3, .need = "1, 2 or 3"), CLI_OPT_JSON(opts_t, json),
    CLI_POSITIVE("profile-1d", opts_t, rmax, CLI_GIVEN(opts_t, prof), .flags = CLI_OPTIONAL, .what = "largest lag"),
    {0}};

/* An intrinsic model: its variogram's validity (analysis/check_intrinsic.h). */
static void check_intrinsic(const char *spec, const nl_model *m, int dim, int json)
{
    nl_check_intrinsic k;
    int st = nl_check_intrinsic_model(m, dim, &k);
    if (st)
        cli_die_status(st);
    if (json) {
        cli_json_print(json_pack("{s:s,s:i,s:b,s:b,s:f,s:f,s:o,s:o,s:f,s:f}", "model", spec, "dim", dim, "intrinsic", 1,
                                 "conditionally_negative_definite", k.valid, "alpha", k.alpha, "c", k.c,
                                 "spectrum_coefficient", num(k.spectrum_coef), "min_spectrum", num(k.min_spectrum),
                                 "hurst", k.hurst, "fractal_dimension", k.fractal_dimension));
        return;
    }
    printf("%s in %dD: intrinsic (a variogram, no covariance): gamma = %g |h|^%g%s\n", spec, dim, k.c, k.alpha,
           k.nugget > 0 ? " + nugget" : "");
    printf("  conditionally negative definite: %s (c |h|^alpha is a variogram in every dimension for "
           "0 < alpha <= 2; fractional Brownian field, H = %g)\n", k.valid ? "yes" : "NO", k.hurst);
    if (isfinite(k.spectrum_coef))
        printf("  generalized spectrum: S(f) = %.6g |f|^-%g, positive (smallest over |f| in 1e-3..1e3: %.3g)\n",
               k.spectrum_coef, dim + k.alpha, k.min_spectrum);
    else
        printf("  generalized spectrum: all at f = 0 (alpha = 2: a random plane)\n");
    printf("  fractal dimension of a realization's graph: %g; mean-square differentiable: %s\n",
           k.fractal_dimension, k.alpha < 2 ? "no" : "yes (linear)");
}

int cli_cmd_check(int argc, char **argv)
{
    opts_t a = {0};
    int st;
    nl_model *m;
    nl_check k;
    char nb[4096], known[4096] = "";
    if (cli_opt_parse("check", help, rows, &a, argc, argv))
        return 0;
    cli_no_operands("check", argc, argv);
    cli_opt_need("check", rows, &a);
    if (a.prof && a.dim != 2)
        cli_die(2, "check: --profile-1d: expected --dim 2 (eq. (14) is the 2D sweep), got --dim %d", a.dim);
    if (!(st = nl_model_parse(a.spec, &m)) && a.prof && nl_model_is_spectral(m))
        cli_die(2, "check: --profile-1d: expected a model defined by R (eq. (14) sweeps R(t)), got %s", a.spec);
    if (!st && nl_model_is_intrinsic(m)) {
        if (a.prof)
            cli_die(2, "check: --profile-1d: expected a model with a covariance, got the intrinsic %s", a.spec);
        check_intrinsic(a.spec, m, a.dim, a.json);
        nl_model_free(m);
        return 0;
    }
    if (st || (st = nl_check_model(m, a.dim, &k)))
        cli_die_status(st);
    if (k.why == NL_CHECK_KNOWN) /* the reason, before another call replaces the message */
        snprintf(known, sizeof known, "%s", nl_errmsg());
    if ((st = nl_check_neighbours(m, &k, nb, sizeof nb)))
        cli_die_status(st);
    if (a.json)
        print_json(a.spec, &k, nb, a.prof ? m : NULL, a.rmax);
    else
        print_text(a.spec, &k, nb, known);
    if (a.prof && !a.json)
        profile_1d(m, &k, a.rmax, NULL);
    nl_model_free(m);
    return 0;
}
