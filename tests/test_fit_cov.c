/* External covariates in the drift from the command line: noiselab
 * variogram --drift sdist against gstat's variogram(log(zinc) ~
 * sqrt(dist), meuse), and noiselab fit --method reml --drift sdist against
 * the restricted likelihood written out in R at the fitted parameters; wls
 * with a covariate fits the residual variogram. */
#include "../core/rng.h"
#include "gstat.h"
#include "util.h"

#include <criterion/criterion.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

/* R's first lines: Meuse (sp's meuse) to meuse.tsv in the scratch folder,
 * x, y, value = log(zinc), sdist = sqrt(dist), 17 digits. */
#define MEUSE_TSV                                                                                                     \
    "suppressMessages(library(sp)); data(meuse)\n"                                                                    \
    "d <- data.frame(x = meuse$x, y = meuse$y, value = log(meuse$zinc), sdist = sqrt(meuse$dist))\n"                  \
    "write.table(format(d, digits = 17), 'meuse.tsv', sep = '\\t', quote = FALSE, row.names = FALSE)\n"

#define MAXBINS 64

/* gstat's residual variogram with the covariate: rows np dist gamma. */
static const char vario_script[] = MEUSE_TSV
    "suppressMessages(library(gstat)); coordinates(meuse) <- ~x + y\n"
    "v <- variogram(log(zinc) ~ sqrt(dist), meuse)\n"
    "cat(sprintf('%.17g %.17g %.17g', v$np, v$dist, v$gamma), sep = '\\n')\n";

/* The same bins, pair counts exactly (the same pairs), distances to 1e-12
 * (the same sums), gammas to 1e-9 relative: the residuals come from two
 * least-squares solvers (R's QR, GSL's SVD), each within ~cond(X) eps =
 * 1e-14 of the exact ones, and each bin sums up to ~2000 squared
 * differences in another order (1e-13).  A residual variogram of a
 * constant mean differs from it by 10-40% per bin, one with sdist
 * scaled or shifted not at all. */
Test(fit_cov, variogram_sdist_equals_gstat)
{
    double r[3 * MAXBINS];
    if (!gstat_available("residual variogram with a covariate"))
        return;
    long m = gstat_run(vario_script, r, 3 * MAXBINS);
    cr_assert(m > 0 && m % 3 == 0, "R failed (%ld numbers)", m);
    json_t *j = run_noiselab_json("variogram meuse.tsv --drift sdist --json");
    json_t *jd = json_object_get(j, "distance"), *jg = json_object_get(j, "gamma"), *jp = json_object_get(j, "pairs");
    cr_assert_eq(json_array_size(jd), (size_t)m / 3, "%zu bins, gstat %ld", json_array_size(jd), m / 3);
    for (size_t k = 0; k < (size_t)m / 3; k++) {
        const double *g = r + 3 * k;
        double np = json_real_value(json_array_get(jp, k)), d = json_real_value(json_array_get(jd, k));
        double gam = json_real_value(json_array_get(jg, k));
        cr_expect_eq(np, g[0], "bin %zu: pairs %g, gstat %g", k, np, g[0]);
        cr_expect(fabs(d - g[1]) <= 1e-9 * g[1], "bin %zu: distance %.17g, gstat %.17g", k, d, g[1]);
        cr_expect(fabs(gam - g[2]) <= 1e-9 * g[2], "bin %zu: gamma %.17g, gstat %.17g", k, gam, g[2]);
    }
    json_decref(j);
}

/* R, in one call: meuse.tsv, then -2 l_REML of spherical + nugget with
 * X = [1, sqrt(dist)] at the parameters held below (the optimum the
 * command reports, 8 digits), by analysis/fit.h's formula written out with
 * base R: (n - p) ln 2 pi + ln|C| + ln|X' C^-1 X| + r' (C^-1 - C^-1 X
 * (X' C^-1 X)^-1 X' C^-1) r with r = z (the projection removes X beta);
 * prints it, the GLS beta (2 numbers), and the lowest -2 l_REML over the
 * 6 points with one parameter moved by a factor 1 -+ 1e-3. */
static const double held[3] = {0.12729056, 429.23813, 0.064155477}; /* var, scale (range), nugget */
static const char reml_script[] = MEUSE_TSV
    "z <- log(meuse$zinc); n <- length(z); X <- cbind(1, sqrt(meuse$dist)); p <- ncol(X)\n"
    "D <- as.matrix(dist(cbind(meuse$x, meuse$y)))\n"
    "m2l <- function(q, out = FALSE) {\n"
    "  h <- pmin(D / q[2], 1); C <- q[1] * (1 - 1.5 * h + 0.5 * h^3) + diag(q[3], n)\n"
    "  L <- chol(C); Ci <- chol2inv(L); M <- t(X) %%*%% Ci %%*%% X\n"
    "  P <- Ci - Ci %%*%% X %%*%% solve(M, t(X) %%*%% Ci)\n"
    "  f <- (n - p) * log(2 * pi) + 2 * sum(log(diag(L))) + as.numeric(determinant(M)$modulus) +\n"
    "       as.numeric(t(z) %%*%% P %%*%% z)\n"
    "  if (out) cat(sprintf('%%.17g', c(f, solve(M, t(X) %%*%% Ci %%*%% z))), '\\n')\n"
    "  f\n"
    "}\n"
    "q <- c(%.17g, %.17g, %.17g); invisible(m2l(q, TRUE))\n"
    "lo <- Inf; for (k in 1:3) for (s in c(-1, 1)) { e <- q; e[k] <- e[k] * (1 + s * 1e-3); lo <- min(lo, m2l(e)) }\n"
    "cat(sprintf('%%.17g', lo), '\\n')\n";

/* The command's REML fit with the range held at its optimum (the full
 * search takes 2 s; python/tests/test_fit_cov_py.py compares it with the
 * Python package's): var and nugget equal the held ones to 1e-4 relative
 * (the simplex stops within 1e-5 in log units); -2 l equals R's at the
 * held parameters to 1e-7 relative (at an optimum a 1e-5 error in the
 * parameters moves -2 l by ~1e-8; the same formula, another
 * factorisation); the coefficients (the drift's terms, named 1 and sdist)
 * equal R's GLS beta to 1e-4 relative (they move with the parameters at
 * first order); and R's -2 l a step of 1e-3 away in any parameter is not
 * lower (the held point is a minimum: the command's is the optimum). */
Test(fit_cov, reml_sdist_equals_r_restricted_likelihood)
{
    char buf[4096];
    double r[4];
    if (!gstat_available("REML with a covariate vs R"))
        return;
    snprintf(buf, sizeof buf, reml_script, held[0], held[1], held[2]);
    cr_assert_eq(gstat_run(buf, r, 4), 4, "R's restricted likelihood");
    cr_expect(r[3] >= r[0] - 1e-9, "R: -2 l %.12g a step away, %.12g at the optimum", r[3], r[0]);
    json_t *j = run_noiselab_json("fit meuse.tsv --model spherical --nugget --method reml --drift sdist "
                                  "--fix scale=429.23813 --json");
    json_t *par = json_object_get(j, "parameters"), *dr = json_object_get(j, "drift");
    static const char *names[] = {"var", "scale", "nugget"}, *terms[] = {"1", "sdist"};
    cr_assert_eq(json_real_value(json_object_get(par, "scale")), held[1], "the range not held");
    for (int k = 0; k < 3; k += 2) {
        double v = json_real_value(json_object_get(par, names[k]));
        cr_expect(fabs(v / held[k] - 1) < 1e-4, "%s %.10g, expected %.10g", names[k], v, held[k]);
    }
    double obj = json_real_value(json_object_get(j, "objective"));
    fprintf(stderr, "meuse REML ~ sqrt(dist): -2 l %.10f (R %.10f), beta %.8g %.8g\n", obj, r[0], r[1], r[2]);
    cr_expect(fabs(obj - r[0]) <= 1e-7 * fabs(r[0]), "-2 l %.12g, R %.12g", obj, r[0]);
    cr_assert_eq(json_array_size(dr), 2, "drift: %zu terms", json_array_size(dr));
    for (int k = 0; k < 2; k++) {
        json_t *t = json_array_get(dr, (size_t)k);
        double v = json_real_value(json_object_get(t, "value"));
        cr_expect_str_eq(json_string_value(json_object_get(t, "term")), terms[k]);
        cr_expect(fabs(v - r[1 + k]) <= 1e-4 * fabs(r[1 + k]), "%s: %.10g, R %.10g", terms[k], v, r[1 + k]);
        cr_expect(json_real_value(json_object_get(t, "se")) > 0, "%s: no standard error", terms[k]);
    }
    cr_expect(json_is_true(json_object_get(j, "converged")), "not converged");
    json_decref(j);
}

/* wls with --drift c fits the variogram of the drift's residuals: the same
 * parameters as fitting the table that noiselab variogram --drift c writes
 * (17 digits: the same bins to rounding; the fits stop within ~1e-8 of one
 * minimum: 1e-6 relative; the nugget, at 0, to 1e-6 of var), and not those of the plain variogram (the
 * covariate carries most of the values' variance here: var moves by a
 * factor ~10). */
Test(fit_cov, wls_fits_the_residual_variogram)
{
    char text[80 * 80 + 64], plain_text[60 * 80 + 64];
    size_t len = (size_t)snprintf(text, sizeof text, "x\ty\tvalue\tc\n");
    size_t plen = (size_t)snprintf(plain_text, sizeof plain_text, "x\ty\tvalue\n");
    for (int i = 0; i < 80; i++) {
        double x = 10 * nl_rng_uniform(9, 1, (uint64_t)i), y = 10 * nl_rng_uniform(9, 2, (uint64_t)i);
        double c = 4 * nl_rng_uniform(9, 3, (uint64_t)i), e = nl_rng_uniform(9, 4, (uint64_t)i) - 0.5;
        double z = 1.5 * c + sin(2.3 * x + 1) * cos(1.9 * y) + 0.3 * e;
        len += (size_t)snprintf(text + len, sizeof text - len, "%.17g\t%.17g\t%.17g\t%.17g\n", x, y, z, c);
        plen += (size_t)snprintf(plain_text + plen, sizeof plain_text - plen, "%.17g\t%.17g\t%.17g\n", x, y, z);
    }
    scratch_file("c.tsv", text);
    scratch_file("p.tsv", plain_text);
    char out[256], err[512];
    cr_assert_eq(run_noiselab("variogram c.tsv --drift c -o v.tsv", out, sizeof out, err, sizeof err), 0, "%s", err);
    json_t *a = run_noiselab_json("fit c.tsv --model markov --nugget --drift c --json");
    json_t *b = run_noiselab_json("fit --variogram v.tsv --model markov --nugget --json");
    json_t *plain = run_noiselab_json("fit p.tsv --model markov --nugget --json");
    static const char *names[] = {"var", "scale", "nugget"};
    double sill = json_real_value(json_object_get(json_object_get(b, "parameters"), "var"));
    for (int k = 0; k < 3; k++) {
        double va = json_real_value(json_object_get(json_object_get(a, "parameters"), names[k]));
        double vb = json_real_value(json_object_get(json_object_get(b, "parameters"), names[k]));
        /* the nugget ends at 0 (its search's floor) here: compared on the sill's scale */
        cr_expect(fabs(va - vb) <= 1e-6 * (k == 2 ? sill : fabs(vb)), "%s: %.10g, from the table %.10g", names[k], va,
                  vb);
    }
    double va = json_real_value(json_object_get(json_object_get(a, "parameters"), "var"));
    double vp = json_real_value(json_object_get(json_object_get(plain, "parameters"), "var"));
    cr_expect(vp > 3 * va, "var %g with the covariate, %g without: expected the covariate to take most", va, vp);
    json_decref(a), json_decref(b), json_decref(plain);
}
