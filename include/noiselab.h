/* noiselab: random fields with a prescribed autocorrelation or spectrum,
 * synthesised and measured.  The one header a program includes:
 *
 *     #include <noiselab.h>
 *     cc app.c $(pkg-config --cflags --libs noiselab)
 *
 * It pulls in every public module header, installed as
 * <noiselab/core/...>, <noiselab/synth/...>, <noiselab/analysis/...> and
 * <noiselab/render/...>; each states its contract (sizes, layout, units,
 * normalisation, ownership, NL_E* codes, thread safety) next to the function.
 *
 * Errors: a function that can fail returns NL_OK or an NL_E* status code
 * (core/nl_error.h) and leaves a one-line message for nl_errmsg().  The
 * library never prints, exits or aborts.
 *
 * Version: NL_VERSION_STRING is the version compiled against, nl_version()
 * the one running (core/version.h). */
#ifndef NOISELAB_H
#define NOISELAB_H

/* The C headers the module headers use, outside the extern "C" block so a
 * C++ program gets its own declarations of them. */
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#ifdef __cplusplus
extern "C" {
#endif

#include "noiselab/core/version.h"
#include "noiselab/core/nl_error.h"
#include "noiselab/core/field.h"
#include "noiselab/core/field_stats.h"
#include "noiselab/core/mem.h"
#include "noiselab/core/family.h"
#include "noiselab/core/model.h"
#include "noiselab/core/dist.h"
#include "noiselab/core/rng.h"
#include "noiselab/core/wk.h"
#include "noiselab/core/field_sample.h"
#include "noiselab/core/io_coords.h"
#include "noiselab/core/autocorr.h"
#include "noiselab/core/autocorr_plan.h"
#include "noiselab/core/fftw_plan.h"
#include "noiselab/core/io.h"
#include "noiselab/core/format.h"
#include "noiselab/core/provenance.h"
#include "noiselab/core/io_obj.h"
#include "noiselab/core/io_points.h"
#include "noiselab/core/io_table.h"
#include "noiselab/core/spindex.h"

#include "noiselab/synth/fft.h"
#include "noiselab/synth/circulant.h"
#include "noiselab/synth/intrinsic.h"
#include "noiselab/synth/cholesky.h"
#include "noiselab/synth/subdiv.h"
#include "noiselab/synth/midpoint.h"
#include "noiselab/synth/sparse.h"
#include "noiselab/synth/sparse_point.h"
#include "noiselab/synth/faulting.h"
#include "noiselab/synth/lattice.h"
#include "noiselab/synth/shape.h"
#include "noiselab/synth/rank1.h"
#include "noiselab/synth/ocean.h"
#include "noiselab/synth/method.h"
#include "noiselab/synth/rank1_model.h"

#include "noiselab/analysis/variogram.h"
#include "noiselab/analysis/krige_local.h"
#include "noiselab/analysis/acf.h"
#include "noiselab/analysis/bands.h"
#include "noiselab/analysis/psd.h"
#include "noiselab/analysis/welch.h"
#include "noiselab/analysis/radial.h"
#include "noiselab/analysis/fftshift.h"
#include "noiselab/analysis/spectral.h"
#include "noiselab/analysis/verdict.h"
#include "noiselab/analysis/validate.h"
#include "noiselab/analysis/slope.h"
#include "noiselab/analysis/hist.h"
#include "noiselab/analysis/gof.h"
#include "noiselab/analysis/gof_dep.h"
#include "noiselab/analysis/gof_boot.h"
#include "noiselab/analysis/ensemble.h"
#include "noiselab/analysis/check.h"
#include "noiselab/analysis/check_intrinsic.h"
#include "noiselab/analysis/nonlin.h"
#include "noiselab/analysis/krige.h"
#include "noiselab/analysis/krige_flavours.h"
#include "noiselab/analysis/creases.h"
#include "noiselab/analysis/aliasing.h"
#include "noiselab/analysis/subdiv_exact.h"
#include "noiselab/analysis/condsim.h"
#include "noiselab/analysis/fit.h"

#include "noiselab/render/terrain.h"
#include "noiselab/render/shade.h"
#include "noiselab/render/cloud.h"
#include "noiselab/render/cloud_scene.h"
#include "noiselab/render/colorbar.h"

#ifdef __cplusplus
}
#endif

#endif
