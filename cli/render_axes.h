/* render --axes: a 2D field drawn by gnuplot with axes in length units and
 * a colour bar (cli/render_axes.c). */
#ifndef CLI_RENDER_AXES_H
#define CLI_RENDER_AXES_H

#include "../core/field.h"

enum { CLI_AXES_GRID = 0, CLI_AXES_LAGS = 1 };

/* x (2D) into the PNG tmp, grey from lo to hi with its colour bar, titled
 * name; kind CLI_AXES_GRID puts sample (0, 0) at the origin and row 0 at
 * the top (as render draws it), CLI_AXES_LAGS the centre sample at lag
 * (0, 0) with lag y up (a centred ACF or spectrum map).  Exits on error. */
void cli_render_axes(const nl_field *x, double lo, double hi, int kind, const char *name, const char *tmp);

#endif
