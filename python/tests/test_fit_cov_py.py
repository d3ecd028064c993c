"""fit's external covariates from the command line (fit DATA.tsv --drift
COLUMN) against the Python package's fit(covariates=): Meuse's log(zinc)
with sqrt(dist), gstat's log(zinc) ~ sqrt(dist), REML with a spherical
model and a nugget (the full search: the profile over the range, whose
likelihood has several valleys).  Both start from the same wls fit and run
the same library calls: the CLI's JSON (10 significant digits) equals the
Python numbers to 1e-9 relative, and its spec string is the same."""
import json
import shutil
import subprocess

import numpy as np
import pytest

import noiselab


@pytest.fixture(scope="module")
def meuse(tmp_path_factory):
    """(points, log zinc, sqrt dist, path of the TSV x, y, value, sdist)."""
    if not shutil.which("Rscript"):
        pytest.skip("Rscript is not installed (Meuse comes from R's sp)")
    path = tmp_path_factory.mktemp("meuse") / "meuse.tsv"
    r = subprocess.run(["Rscript", "-e", "suppressMessages(library(sp)); data(meuse); d <- data.frame(x = meuse$x, "
                        "y = meuse$y, value = log(meuse$zinc), sdist = sqrt(meuse$dist)); write.table(format(d, "
                        "digits = 17), '%s', sep = '\\t', quote = FALSE, row.names = FALSE)" % path],
                       capture_output=True)
    if r.returncode != 0:
        pytest.skip("R's sp package is not installed")
    t = np.loadtxt(path, skiprows=1)
    return np.ascontiguousarray(t[:, :2]), t[:, 2].copy(), t[:, 3].copy(), str(path)


@pytest.mark.heavy
def test_reml_sdist_equals_python(cli, meuse):
    pts, z, sdist, path = meuse
    j = json.loads(cli("fit", path, "--model", "spherical", "--nugget", "--method", "reml", "--drift", "sdist",
                       "--json").stdout)
    r = noiselab.fit(pts, z, model="spherical", nugget=True, method="reml", covariates=sdist)
    assert r["spec"] == j["model"]
    np.testing.assert_allclose(r["objective"], j["objective"], rtol=1e-9)
    for name, v in r["parameters"].items():
        np.testing.assert_allclose(v, j["parameters"][name], rtol=1e-9, err_msg=name)
        np.testing.assert_allclose(r["intervals"][name], j["intervals"][name], rtol=1e-9, err_msg=name)
    assert [d["term"] for d in j["drift"]] == ["1", "sdist"]
    np.testing.assert_allclose(r["drift"], [d["value"] for d in j["drift"]], rtol=1e-9)
    np.testing.assert_allclose(r["drift_se"], [d["se"] for d in j["drift"]], rtol=1e-9)
    # the optimum of tests/test_fit_cov.c (R's restricted likelihood there)
    np.testing.assert_allclose([j["parameters"][k] for k in ("var", "scale", "nugget")],
                               [0.12729056, 429.23813, 0.064155477], rtol=1e-4)
