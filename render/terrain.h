/* Perspective views of height fields: a small landscape renderer in the
 * manner of the pictures in Lewis (1987) and Lewis (1986): a terrain lit
 * by the sun with cast shadows, coloured by height and slope, seen from a
 * camera above it, fading into distance haze under a sky gradient, with
 * optional water below a level.
 *
 * Method: one ray per image column marched over the ground plane in steps
 * that grow with distance (front to back, keeping the highest row drawn so
 * far, so hidden terrain costs nothing); heights are bilinear between
 * samples; 2 x 2 supersampling.  Clouds: a second field on a horizontal
 * plane above the camera, white where it exceeds its mean by more than
 * half a standard deviation, fully so from two (GI '86, Fig. 5).  Pitch shifts the rows (the horizon
 * moves by focal tan(pitch)) rather than rotating the camera: exact at
 * pitch 0, close up to the 30 degrees allowed.  Shadows: a sample is in shadow when the
 * terrain rises above the ray toward the sun within 256 samples.
 *
 * Units: positions and distances in samples of the field; heights are the
 * field's values times zscale (samples per field unit). */
#ifndef NL_RENDER_TERRAIN_H
#define NL_RENDER_TERRAIN_H

#ifdef __cplusplus
extern "C" {
#endif

#include "../core/field.h"

#include <stdint.h>

typedef struct {
    size_t width, height;  /* picture size in pixels */
    double zscale;         /* heights in samples per unit of the field */
    double cam[3];         /* camera x, y (samples) and height above the terrain under it
                              (above the mean height when outside an untiled field) */
    double azimuth;        /* viewing direction, degrees from +x toward +y */
    double pitch;          /* degrees below the horizon, at most 30 either way */
    double fov;            /* horizontal field of view, degrees */
    double sun[2];         /* sun azimuth and elevation, degrees */
    double haze;           /* distance (samples) at which haze covers 63% */
    double water;          /* water level in field units; NAN: no water */
    int tile;              /* repeat the field periodically beyond its edges */
    int palette;           /* NL_RENDER_LAND or NL_RENDER_SEA */
    const nl_field *clouds; /* NULL, or a 2D field drawn as clouds on a plane
                               above the camera (tiled, one sample per
                               cloud_scale samples of the terrain) */
    double cloud_height;   /* the plane's height above the camera, samples */
    double cloud_scale;    /* terrain samples per cloud sample */
} nl_render_view;

enum { NL_RENDER_LAND = 0, NL_RENDER_SEA = 1 };

/* Default view of field f: camera behind the middle of the lower (y = 0)
 * edge, 0.15 n above the terrain there, looking along +y, 10 degrees down.
 * Fills every member of *v (no clouds, no water); thread-safe. */
void nl_render_view_default(const nl_field *f, nl_render_view *v);

/* Render f (2D) into rgb (width * height * 3 bytes, rows top to bottom,
 * R G B per pixel; the caller's buffer).  f and v (and v->clouds) are only
 * read.  Errors: NL_EINVAL for a field that is not 2D or smaller than 3 x 3,
 * or a view with bad numbers (fov outside (0, 170), zscale or haze <= 0,
 * |pitch| > 30, sun elevation outside (0, 90], an empty picture, clouds
 * that are not 2D or a cloud plane that is not positive); NL_ETOOBIG for a
 * picture or field whose work arrays overflow; NL_ENOMEM.  Reentrant; runs
 * its own OpenMP loops. */
int nl_render_terrain(const nl_field *f, const nl_render_view *v, uint8_t *rgb);

#ifdef __cplusplus
}
#endif

#endif
