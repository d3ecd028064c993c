"""Shared set-up of the noiselab Python tests.

FFTW plans: the CLI and this process must plan alike for the fields to be
bit-identical (measured and estimated plans agree only to rounding,
core/fftw_plan.h), so both plan with FFTW_ESTIMATE and no wisdom, as the C
tests do.  The variable is read by the library at its first plan, after
this module runs."""
import os
import subprocess
import sys

import pytest

os.environ["NOISELAB_FFTW"] = "estimate"

TOP = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
# the package of this tree, whatever else is installed
sys.path.insert(0, os.path.join(TOP, "python"))


def pytest_configure(config):
    config.addinivalue_line("markers", "heavy: tens of seconds: run by make test-slow, not make test")


def cli_path():
    return os.environ.get("NOISELAB") or os.path.join(TOP, "bin", "noiselab")


@pytest.fixture(scope="session")
def cli():
    """Run the command line: cli(args...) -> CompletedProcess (text)."""
    path = cli_path()
    if not os.access(path, os.X_OK):
        pytest.skip("no noiselab program at %s (make, or set NOISELAB)" % path)

    def run(*args, check=True):
        r = subprocess.run([path] + [str(a) for a in args], capture_output=True, text=True)
        if check and r.returncode != 0:
            raise AssertionError("noiselab %s: exit %d: %s" % (" ".join(map(str, args)), r.returncode, r.stderr))
        return r
    return run
