/* The default octaves of an interpolated noise lattice. */
#include "lattice.h"

#include <math.h>

double nl_synth_lattice_default_cell(const size_t *n) { return (double)n[0] / 4; }

int nl_synth_lattice_default_octaves(double cell0)
{
    int O;
    for (O = 1; cell0 / pow(2, O) >= 2 && O < NL_LATTICE_MAX_OCTAVES; O++)
        ;
    return O;
}
