"""noiselab from Python: random fields with a prescribed autocorrelation or
spectrum, synthesised and measured by libnoiselab.

Every number comes from the C library (through cffi); arrays are numpy
float64, C order, shape N (1D), (ny, nx) (2D, the EXR's rows) or
(nz, ny, nx): x, the fastest axis in memory, is the last numpy axis.
Fields the library makes are returned as arrays over its memory (no copy).

    >>> import noiselab
    >>> f = noiselab.synth("fft", acf="markov:scale=8", size=(64, 64), seed=7)
    >>> plan = noiselab.Plan("fft", acf="markov:scale=8", size=(512, 512))
    >>> fields = [plan(seed) for seed in range(100)]
    >>> lag, r = noiselab.acf(f, max_lag=16)
    >>> m = noiselab.Model("markov:scale=8")
    >>> m.acf([0, 8]), m.spectrum(0.01), m.periodogram_target(256)

Errors raise noiselab.Error (a ValueError) with the library's one-line
message; a bad argument (a wrong type, None, 2.7 for an integer, a number
out of range, NaN, a string that does not encode, an array of the wrong
shape or not finite) raises it too, before the library is called, with a
message naming the argument, what was expected and what came.  cffi releases the GIL around every C call: threads run in
parallel, and one Plan may be called from several threads.  The library is
found through $NOISELAB_LIB, then the build/ folder of the source tree next
to this package, then the installed libnoiselab.so.1.
"""
from ._ffi import LIBRARY_PATH, Error
from ._synth import METHODS, Plan, methods, synth
from ._io import formats, models, read, version, write
from ._analysis import acf, check_model, coeffs, hist, krige, moments, nonlin, psd, shape, variogram
from ._krige import CondSim, condsim
from ._sample import sample
from ._krige_flavours import Krige, fit  # Krige with block=, transform=, indicator=; fit with variogram=
from ._ensemble import ensemble_acf, ensemble_hist, ensemble_psd
from ._model import Model
from ._dist import Dist, band_chisq, welch_edf

check = check_model  # noiselab.check, as the CLI's verb

__version__ = version()
__all__ = ["Error", "Plan", "synth", "read", "write", "formats", "models", "version", "acf", "psd", "hist", "moments",
           "check", "check_model", "coeffs", "nonlin", "shape", "krige", "Krige", "CondSim", "condsim", "sample",
           "variogram", "fit", "METHODS", "methods",
           "ensemble_acf", "ensemble_psd", "ensemble_hist", "Model", "Dist", "band_chisq", "welch_edf",
           "LIBRARY_PATH"]
