"""One Plan called from 4 threads gives the serial fields, bit for bit.

cffi releases the GIL around each C call, so the executes really overlap
(fft, circulant, subdiv only read their plan; cholesky's calls are
serialised by the plan's lock, its workspace being in the plan)."""
from concurrent.futures import ThreadPoolExecutor

import numpy as np
import pytest

import noiselab


@pytest.mark.parametrize("method,size", [("fft", (128, 96)), ("circulant", (40, 40)), ("cholesky", (32, 32)),
                                         ("subdiv", (64, 64)), ("sparse", (48, 48)), ("midpoint", (64, 64)),
                                         ("lattice", (64, 64)), ("faulting", (64, 64))])
def test_plan_across_threads(method, size):
    model = {"midpoint": dict(spectrum="power:d=2.5"), "lattice": dict(spectrum="power:d=3"), "faulting": {}}
    plan = noiselab.Plan(method, size=size, **model.get(method, dict(acf="gauss:scale=3")))
    seeds = list(range(48))
    serial = [plan(s) for s in seeds]
    with ThreadPoolExecutor(max_workers=4) as ex:
        parallel = list(ex.map(plan, seeds))
    for s, a, b in zip(seeds, serial, parallel):
        assert np.array_equal(a, b), (method, s)
    assert not np.array_equal(serial[0], serial[1])


def test_one_shot_calls_across_threads():
    """synth, acf and psd plan FFTW (not thread-safe in C): from threads they
    serialise on the package's lock and still agree with serial calls."""
    def work(seed):
        f = noiselab.synth("fft", acf="markov:scale=4", size=(64, 64), seed=seed)
        return f, noiselab.acf(f)[1], noiselab.psd(f, welch=16)[1]
    serial = [work(s) for s in range(12)]
    with ThreadPoolExecutor(max_workers=4) as ex:
        parallel = list(ex.map(work, range(12)))
    for a, b in zip(serial, parallel):
        for x, y in zip(a, b):
            assert np.array_equal(x, y)


def test_out_refills_an_array():
    plan = noiselab.Plan("fft", acf="markov:scale=4", size=(64, 80))
    a = plan(1)
    b = plan(2, out=a)
    assert b is a and np.array_equal(a, plan(2))
    with pytest.raises(noiselab.Error):
        plan(3, out=np.zeros((80, 64)))
    with pytest.raises(noiselab.Error):
        plan(3, out=a[:, ::2])
    c = plan(5)
    c.setflags(write=False)
    with pytest.raises(noiselab.Error):
        plan(3, out=c)
