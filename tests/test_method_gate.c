/* Every synthesis method refuses a model that `noiselab check` finds
 * invalid, through the registry's test after each plan
 * (nl_model_sign_check, core/taper_internal.h), where its own grid would
 * not see it: a negative power-law tail (whose integral a finite periodic
 * grid sums to a positive number) and an edge singularity (Askey's
 * (1-r)_+^nu below nu = (d+1)/2, whose negative lobes lie at 1e-12 of the
 * peak); and it accepts their valid neighbours and --clamp. */
#include "util.h"

#include <criterion/criterion.h>
#include <stdio.h>
#include <string.h>

static char out[4096], err[4096];

static int synth(const char *method, const char *spec, const char *size, const char *extra)
{
    char args[1024];
    snprintf(args, sizeof args, "synth %s --acf '%s' --size %s --seed 1 %s -o gate.exr", method, spec, size, extra);
    return run_noiselab(args, out, sizeof out, err, sizeof err);
}

Test(method_gate_slow, refuses_what_check_refuses)
{
    static const struct {
        const char *spec, *size;
        int valid;
    } c[] = {
        {"expr:exp(-r)-0.05/(1+r^2)", "64x64", 0},        /* tail -0.05 r^-2, b = d: int R = -infinity */
        {"expr:exp(-r)+0.05/(1+r^2)", "64x64", 1},
        {"expr:step(1-r/4)*abs(1-r/4)^1.9", "16x16x16", 0}, /* Askey nu = 1.9 < 2 in 3D */
        {"expr:step(1-r/4)*abs(1-r/4)^2.1", "16x16x16", 1},
    };
    static const char *const methods[] = {"fft", "circulant", "cholesky"};
    for (size_t i = 0; i < sizeof c / sizeof *c; i++)
        for (size_t k = 0; k < sizeof methods / sizeof *methods; k++) {
            int rc = synth(methods[k], c[i].spec, c[i].size, "");
            if (c[i].valid) {
                cr_expect_eq(rc, 0, "%s %s: %s", methods[k], c[i].spec, err);
                continue;
            }
            cr_expect_eq(rc, 2, "%s %s accepted", methods[k], c[i].spec);
            cr_expect(strstr(err, "not positive definite in"), "%s %s: %s", methods[k], c[i].spec, err);
        }
    /* subdivision (1D and 2D) and --clamp */
    cr_expect_eq(synth("subdiv", "expr:exp(-r)-0.05/(1+r^2)", "64x64", ""), 2, "subdiv accepted the negative tail");
    cr_expect_eq(synth("subdiv", "expr:exp(-r)+0.05/(1+r^2)", "64x64", ""), 0, "%s", err);
    cr_expect_eq(synth("fft", "expr:exp(-r)-0.05/(1+r^2)", "64x64", "--clamp"), 0, "--clamp: %s", err);
}
