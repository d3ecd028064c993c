"""The Python code blocks of README.md (its "Python" section) and of
docs/python.md run as shown (in a scratch folder).  The plotting block needs
matplotlib, which the tests do not: it is skipped without it."""
import os
import re

import numpy as np

import pytest

from conftest import TOP


def blocks(page):
    text = open(os.path.join(TOP, page)).read()
    return re.findall(r"^```python\n(.*?)^```", text, re.S | re.M)


def test_readme_python_example(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    (code,) = blocks("README.md")
    assert len(code.strip().splitlines()) == 5
    exec(compile(code, "README.md", "exec"), {})
    assert os.path.getsize("f.exr") > 0


def test_python_page(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    errors, kriging, ensemble, plot = blocks("docs/python.md")[:4]
    ns = {}
    exec(compile(errors, "docs/python.md", "exec"), ns)
    exec(compile(kriging, "docs/python.md", "exec"), ns)
    assert np.abs(ns["at_data"] - ns["vals"]).max() < 1e-6
    exec(compile(ensemble, "docs/python.md", "exec"), ns)
    assert np.max(np.abs(ns["mean"] - ns["target"]) / ns["se"]) < 5
    pytest.importorskip("matplotlib")
    exec(compile(plot, "docs/python.md", "exec"), ns)
    assert os.path.getsize("acf-ensemble.png") > 0


@pytest.mark.parametrize("which", ["acf-band", "periodogram-welch", "nonlinearity"])
def test_model_demos(tmp_path, monkeypatch, which):
    """The three demonstrations of "The model itself": each short (at most
    15 lines, imports included) and each asserting what it shows."""
    monkeypatch.chdir(tmp_path)
    demos = blocks("docs/python.md")[4:7]
    code = demos[["acf-band", "periodogram-welch", "nonlinearity"].index(which)]
    assert len(code.strip().splitlines()) <= 15
    assert "assert" in code
    exec(compile(code, "docs/python.md", "exec"), {})
