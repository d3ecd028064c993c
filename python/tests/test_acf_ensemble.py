"""The ACF of a synthesised ensemble against the target, within a derived band.

FFT synthesis (synth/fft.h) gives a Gaussian field of ensemble mean 0 whose
covariance is the model's R wrapped on the torus.  With the known mean 0 and
the unbiased divisor (pairs per lag), the estimate at lag l along x is an
average of products x_j x_{j+l}, so its expectation is exactly
R_torus(l) = sum_k R(l + k n); for markov:scale=8 on 256 samples the images
k != 0 add at most exp(-(256 - 16)/8) = 1e-13, far below the band.  The K
fields (seeds 0..K-1) are independent, so the K estimates at a lag are
i.i.d.; their mean has standard error s / sqrt(K), s the sample sd of the K
values.  Each estimate averages ~65000 products and is close to Gaussian, so
(mean - R) / se is Student-t with K - 1 = 31 degrees of freedom:
P(|t| > 5) = 2e-5 per lag, under 4e-4 over the 17 lags (and the seeds are
fixed, so the outcome is deterministic).  The band must also be narrow
enough to mean something: it must reject the neighbouring model
markov:scale=9 at some lag."""
import numpy as np
import pytest

import noiselab

K, SIZE, SPEC = 32, (256, 256), "markov:scale=8"


class Realizations:
    """Seeds 0 .. K-1 of the plan, synthesised when the ensemble asks."""

    def __init__(self, plan):
        self.plan = plan

    def __len__(self):
        return K

    def __getitem__(self, seed):
        return self.plan(seed)


def ensemble(axis):
    plan = noiselab.Plan("fft", acf=SPEC, size=SIZE)
    lag, mean, se = noiselab.ensemble_acf(Realizations(plan), max_lag=16, axis=axis, mean=0.0, unbiased=True)
    target = noiselab.acf(plan(0), max_lag=16, axis=axis, target=SPEC)[2]
    return lag, mean, se, target


@pytest.mark.heavy
def test_ensemble_acf_within_band():
    for axis in ("x", "y"):
        lag, mean, se, target = ensemble(axis)
        np.testing.assert_array_equal(lag, np.arange(17.0))
        np.testing.assert_allclose(target, np.exp(-lag / 8), rtol=1e-12)
        z = (mean - target) / se
        assert np.all(np.abs(z) < 5), (axis, z)
        # the band discriminates: a 12% longer scale falls outside it
        wrong = np.exp(-lag / 9)
        assert np.any(np.abs(mean - wrong) / se > 5), axis
        assert se[0] < 0.02


def test_ensemble_band_fails_for_wrong_spacing():
    """The same check with the field's spacing misdeclared (h = 2: lags
    doubled) must fail: the band is tight enough to see it."""
    plan = noiselab.Plan("fft", acf=SPEC, size=SIZE)
    lag, mean, se = noiselab.ensemble_acf(Realizations(plan), spacing=2.0, max_lag=32, mean=0.0, unbiased=True)
    target = noiselab.acf(plan(0), spacing=2.0, max_lag=32, target=SPEC)[2]
    z = (mean - target) / se
    assert np.any(np.abs(z) > 5)
