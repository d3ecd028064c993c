"""Error paths raise noiselab.Error (a ValueError) with the library's message,
the same line the CLI prints after "noiselab: "; nothing aborts the
interpreter."""
import os
import subprocess
import sys

import numpy as np
import pytest

import noiselab


def cli_message(cli, *args):
    r = cli(*args, check=False)
    assert r.returncode != 0
    assert r.stderr.startswith("noiselab: ")
    return r.stderr[len("noiselab: "):].strip()


def test_cholesky_not_positive_definite(cli, tmp_path):
    with pytest.raises(noiselab.Error) as e:
        noiselab.synth("cholesky", acf="expr:1-abs(t)/3", size=64)
    assert isinstance(e.value, ValueError) and e.value.code == 4  # NL_ENOTPD
    assert "not positive definite" in str(e.value) and "expr:1-abs(t)/3" in str(e.value)
    want = cli_message(cli, "synth", "cholesky", "--acf", "expr:1-abs(t)/3", "--size", "64",
                       "-o", str(tmp_path / "x.exr"))
    assert str(e.value) == want


def test_interpreter_survives():
    """The issue's case in a fresh interpreter: it prints the message and
    goes on to exit 0."""
    code = ("import noiselab\n"
            "try:\n    noiselab.synth('cholesky', acf='expr:1-abs(t)/3', size=64)\n"
            "except noiselab.Error as e:\n    print('Error:', e)\n"
            "print('alive', noiselab.synth('fft', acf='markov:scale=8', size=(64, 64), seed=7).std())\n")
    env = dict(os.environ, PYTHONPATH=os.path.dirname(os.path.dirname(noiselab.__file__)))
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env)
    assert r.returncode == 0, r.stderr
    assert "Error: expr:1-abs(t)/3" in r.stdout and "alive" in r.stdout


@pytest.mark.parametrize("cli_args,call", [
    (["synth", "fft", "--acf", "markov:scale=-1", "--size", "8"],
     lambda: noiselab.synth("fft", acf="markov:scale=-1", size=8)),
    (["synth", "fft", "--acf", "nosuch:scale=1", "--size", "8"],
     lambda: noiselab.synth("fft", acf="nosuch:scale=1", size=8)),
    (["synth", "fft", "--acf", "markov:scale=8", "--size", "48x40"],
     lambda: noiselab.synth("fft", acf="markov:scale=8", size=(40, 48))),
    (["synth", "midpoint", "--spectrum", "power:d=2.5", "--size", "33x33"],
     lambda: noiselab.synth("midpoint", spectrum="power:d=2.5", size=(33, 33))),
    (["synth", "subdiv", "--acf", "gauss:scale=4", "--size", "32x32", "--neighborhood", "auto"],
     lambda: noiselab.synth("subdiv", acf="gauss:scale=4", size=(32, 32), neighborhood="auto")),
    (["synth", "lattice", "--acf", "markov:scale=4", "--size", "32x32"],
     lambda: noiselab.synth("lattice", acf="markov:scale=4", size=(32, 32))),
])
def test_library_messages_match_cli(cli, tmp_path, cli_args, call):
    want = cli_message(cli, *cli_args, "-o", str(tmp_path / "x.exr"))
    with pytest.raises(noiselab.Error) as e:
        call()
    assert str(e.value) == want


def test_read_missing_file(cli):
    with pytest.raises(noiselab.Error) as e:
        noiselab.read("/nonexistent/f.exr")
    assert str(e.value) == cli_message(cli, "acf", "/nonexistent/f.exr")
    assert e.value.code == 2  # NL_EINPUT


def test_read_not_a_field(tmp_path):
    p = tmp_path / "junk.exr"
    p.write_bytes(b"\x76\x2f\x31\x01garbage")
    with pytest.raises(noiselab.Error):
        noiselab.read(str(p))


@pytest.mark.parametrize("call,words", [
    (lambda: noiselab.synth("nosuch", acf="markov", size=8), "unknown method"),
    (lambda: noiselab.synth("fft", size=8), "exactly one of acf or spectrum"),
    (lambda: noiselab.synth("fft", acf="power:d=2", size=8), "is a spectrum model"),
    (lambda: noiselab.synth("fft", acf="markov", size=1), "at least 2 samples"),
    (lambda: noiselab.synth("fft", acf="markov", size=(2, 2, 2, 2)), "1 to 3 axes"),
    (lambda: noiselab.synth("fft", acf="markov", size=8, seed=-1), "seed"),
    (lambda: noiselab.synth("fft", acf="markov", size=8, seed=2 ** 64), "seed"),
    (lambda: noiselab.synth("fft", acf="markov", size=8, spacing=0), "spacing"),
    (lambda: noiselab.synth("fft", acf="markov", size=8, spacing=float("nan")), "spacing"),
    (lambda: noiselab.synth("fft", acf="markov", size=(8, 8), spacing=(1, 2, 3)), "spacing"),
    (lambda: noiselab.synth("fft", acf="markov", size=8, levels=3), "unknown option"),
    (lambda: noiselab.synth("subdiv", acf="markov", size=(8, 8, 8)), "1D or 2D"),
    (lambda: noiselab.synth("fft", acf="mark\0ov", size=8), "NUL"),
    (lambda: noiselab.acf(np.array([1.0, np.nan, 2.0])), "finite"),
    (lambda: noiselab.acf(np.zeros((2, 2, 2, 2))), "1 to 3 axes"),
    (lambda: noiselab.acf(np.zeros(0)), "at least one sample"),
    (lambda: noiselab.acf(np.ones(16), axis="y"), "axis"),
    (lambda: noiselab.acf(np.ones(16), max_lag=16), "max_lag"),
    (lambda: noiselab.acf(np.ones(16), target="markov:scale=0"), "scale"),
    (lambda: noiselab.psd(np.ones(16), welch=32), ""),
    (lambda: noiselab.psd(np.ones(16), welch=2), "welch"),
    (lambda: noiselab.psd(np.array([1e300, -1e300] * 8)), ""),
    (lambda: noiselab.hist(np.ones(16), bins=0), "bins"),
    (lambda: noiselab.shape(np.ones(16), "uniform"), ""),
    (lambda: noiselab.shape(np.arange(16.0), "nosuch"), ""),
    (lambda: noiselab.krige(np.zeros((3, 2)), np.zeros(2), "markov", np.zeros((1, 2))), "values"),
    (lambda: noiselab.krige(np.zeros((3, 2)), np.zeros(3), "markov", np.zeros((1, 3))), "at"),
    (lambda: noiselab.krige(np.zeros((3, 4)), np.zeros(3), "markov", np.zeros((1, 4))), "points"),
    (lambda: noiselab.krige(np.array([[0.0], [np.inf]]), np.zeros(2), "markov", np.zeros((1, 1))), "finite"),
    (lambda: noiselab.variogram(np.zeros((3, 2)), np.zeros(3), width=-1), "width"),
    (lambda: noiselab.fit(field=np.random.default_rng(1).normal(size=(8, 8)), model="nosuch"), ""),
    (lambda: noiselab.write("/nonexistent/dir/f.exr", np.zeros((4, 4))), ""),
    (lambda: noiselab.write("f.tsv", np.zeros((4, 4))), "does not hold 2D"),
    (lambda: noiselab.write("f.exr", np.full(4, 1e300)), "float32"),
    (lambda: noiselab.write("f.exr", np.zeros(4), colour="red"), "unknown provenance"),
    (lambda: noiselab.check(acf="markov", dim=4), "dim"),
    (lambda: noiselab.coeffs("markov:scale=2", dim=3), "dim"),
    (lambda: noiselab.nonlin("markov:scale=2", "uniform", terms=1), "terms"),
])
def test_bad_input_raises(call, words, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    with pytest.raises(noiselab.Error) as e:
        call()
    assert words in str(e.value)
    assert str(e.value)  # a message, always


@pytest.mark.heavy
def test_clean_exit_after_threaded_fft():
    """The interpreter exits cleanly after FFTW ran on OpenMP threads: the
    library must stay mapped while their idle workers live (cffi would
    dlclose it at exit; before the fix about 1 exit in 30 crashed)."""
    code = ("import noiselab\n"
            "p = noiselab.Plan('fft', acf='markov:scale=8', size=(1024, 1024))\n"
            "f = p(1)\n")
    env = dict(os.environ, PYTHONPATH=os.path.dirname(os.path.dirname(noiselab.__file__)))
    env.pop("NOISELAB_FFTW", None)
    env["NOISELAB_FFTW"] = "estimate"
    codes = [subprocess.run([sys.executable, "-c", code], env=env, capture_output=True).returncode
             for _ in range(40)]
    assert codes == [0] * 40, codes
