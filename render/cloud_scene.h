/* A cloud scene (render/cloud.h) read from a JSON file, the format of
 * noiselab cloud:
 *   {"size": [W, H], "box": [[x0, y0, z0], [x1, y1, z1]],
 *    "points": [[x, y, z, value], ...], "acf": SPEC,
 *    "noise": {"acf": SPEC, "amplitude": a, "period": P, "grid": g, "seed": S},
 *    "threshold": t, "extinction": sigma, "grid": G,
 *    "camera": {"position": [..], "look_at": [..], "fov": degrees},
 *    "sun": [x, y, z],
 *    "kriging": "ordinary" | "simple", "rotation": [ax, ay, az]}
 * and in "noise" also "kind": "grid" | "point", "density": D.
 * Keys with a default (value and accepted range): amplitude 0.3 [0, 100],
 * period 1 [1e-6, 1e6], noise grid 64 [8, 256], seed 1 [0, 1e15],
 * threshold 0.2 [0, 0.99], extinction 8 [0, 1e6], grid 64 [8, 256],
 * fov 40 [1, 170], kriging "ordinary", rotation [0, 0, 0] (degrees, each
 * within +-360), kind "grid" (the periodic FFT volume; "point": sparse-
 * convolution noise evaluated at the ray's samples, which ignores period
 * and grid), density 8 [0.5, 1000] impulses per noise scale^3; the others
 * are required.  W and H are 1 to 8192.  Scenes written before "kriging"
 * existed were simple kriging: add "kriging": "simple" to render them as
 * before. */
#ifndef NL_RENDER_CLOUD_SCENE_H
#define NL_RENDER_CLOUD_SCENE_H

#ifdef __cplusplus
extern "C" {
#endif

#include "cloud.h"

/* Read path into *s (overwritten whole).  On success s owns its points
 * and both models: release them with nl_cloud_scene_free; the shape
 * model's spec (nl_model_spec(s->shape)) is the "acf" string as written.
 * On failure nothing is left allocated and *s holds no pointers.
 * Errors: NL_EINPUT when the file cannot be read, is not a JSON object, or
 * a key is missing, of the wrong type or out of range (the message names
 * the file and the key); those of nl_model_parse for either model
 * (core/model.h); NL_ENOMEM.  Thread-safe. */
int nl_cloud_scene_read(const char *path, nl_cloud_scene *s);

/* Free the points and models that nl_cloud_scene_read put in s and set
 * those pointers to NULL (a scene without them is a no-op). */
void nl_cloud_scene_free(nl_cloud_scene *s);

#ifdef __cplusplus
}
#endif

#endif
