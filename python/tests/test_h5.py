"""HDF5 fields from Python: the same file as the command line's, read back
bit for bit, provenance kept, bad input raising."""
import numpy as np
import pytest

import noiselab


def test_write_read_double_bit_for_bit(tmp_path):
    a = noiselab.synth("fft", acf="markov:scale=4", size=(48, 64), seed=7)
    p = tmp_path / "a.h5"
    noiselab.write(p, a, precision="double", model="markov:scale=4", method="fft", seed="7")
    b, m = noiselab.read(p, meta=True)
    assert np.array_equal(a, b)
    assert m["model"] == "markov:scale=4" and m["seed"] == "7" and m["size"] == "64x48"


def test_single_is_float32_of_the_cli(cli, tmp_path):
    """The CLI's float32 .h5 holds our float64 field rounded to float32."""
    p = tmp_path / "c.h5"
    r = cli("synth", "subdiv", "--acf", "markov:scale=8", "--size", "96x64", "--seed", "3", "-o", str(p))
    assert r.returncode == 0, r.stderr
    a = noiselab.synth("subdiv", acf="markov:scale=8", size=(64, 96), seed=3)
    assert np.array_equal(noiselab.read(p), a.astype(np.float32).astype(np.float64))


def test_errors(tmp_path):
    with pytest.raises(noiselab.Error, match="not a readable HDF5 file"):
        (tmp_path / "x.h5").write_text("not hdf5")
        noiselab.read(tmp_path / "x.h5")
    with pytest.raises(noiselab.Error, match="precision"):
        noiselab.write(tmp_path / "y.exr", np.zeros((4, 4)), precision="double")
    with pytest.raises(noiselab.Error, match="cannot create"):
        noiselab.write(tmp_path / "no" / "z.h5", np.zeros((4, 4)))
