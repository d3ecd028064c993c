/* Experiment helper: the macroscopic level of a cloud scene honours its
 * data (Stam and Fiume 1991: "the general shape ... is constrained by ...
 * the interpolation of user-supplied data values").  The scene's points
 * are kriged exactly as `noiselab cloud` does (simple kriging, mean 0,
 * the scene's "acf") and the estimate and its variance are evaluated back
 * at every data point: kriging is an exact interpolator, so the estimate
 * must equal the value and the variance vanish, up to the rounding of a
 * Cholesky solve (bound 1e-9 of the largest value and of R(0)).
 * usage: kriged_at_data SCENE.json -> "points N max_error E max_variance V";
 * exit 1 when a bound fails, 2 on bad input. */
#include "../analysis/krige.h"
#include "../core/model.h"

#include <jansson.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

int main(int argc, char **argv)
{
    json_t *j, *pts;
    nl_model *m;
    nl_krige_plan *kp;
    double *x, *v, err = 0, var = 0, top = 0, r0, zero[3] = {0, 0, 0};
    size_t n;
    if (argc != 2 || !(j = json_load_file(argv[1], 0, NULL)) || !json_is_array(pts = json_object_get(j, "points")) ||
        (n = json_array_size(pts)) < 1 || nl_model_parse(json_string_value(json_object_get(j, "acf")), &m)) {
        fprintf(stderr, "usage: kriged_at_data SCENE.json (a scene with points and acf)\n");
        return 2;
    }
    x = malloc(3 * n * sizeof *x), v = malloc(n * sizeof *v);
    for (size_t i = 0; i < n; i++) {
        for (int a = 0; a < 3; a++)
            x[3 * i + a] = json_number_value(json_array_get(json_array_get(pts, i), (size_t)a));
        v[i] = json_number_value(json_array_get(json_array_get(pts, i), 3));
        top = fmax(top, fabs(v[i]));
    }
    if (nl_krige_plan_alloc(m, 3, n, x, v, 1, 0, 0, &kp))
        return 2;
    r0 = nl_model_acf(m, 3, zero);
    for (size_t i = 0; i < n; i++) {
        double e, s;
        nl_krige_eval(kp, x + 3 * i, &e, &s, NULL);
        err = fmax(err, fabs(e - v[i]));
        var = fmax(var, s);
    }
    printf("points %zu max_error %.2e max_variance %.2e\n", n, err, var);
    nl_krige_plan_free(kp), nl_model_free(m), json_decref(j), free(x), free(v);
    return err <= 1e-9 * top && var <= 1e-9 * r0 ? 0 : 1;
}
