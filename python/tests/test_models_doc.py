"""docs/models.md is what tools/models-doc.py writes from the family
registry: a family added to the registry appears there once the page is
regenerated (`/usr/bin/python3 tools/models-doc.py docs/models.md`)."""
import os
import runpy

from conftest import TOP


def test_models_page_is_current():
    gen = runpy.run_path(os.path.join(TOP, "tools", "models-doc.py"))
    with open(os.path.join(TOP, "docs", "models.md")) as f:
        assert f.read() == gen["page"](), "docs/models.md is stale: run /usr/bin/python3 tools/models-doc.py docs/models.md"


def test_every_family_is_on_the_page():
    import noiselab
    text = open(os.path.join(TOP, "docs", "models.md")).read()
    for m in noiselab.models():
        assert "## `%s`" % m["name"] in text


def test_registry_families_reach_python():
    """A family of the registry is in models() with its descriptor's
    parameters, and synthesis takes it (gencauchy: both shape parameters
    required, alpha bounded by 2)."""
    import noiselab
    m = {x["name"]: x for x in noiselab.models()}["gencauchy"]
    p = {x["name"]: x for x in m["parameters"]}
    assert m["fit"] and not m["spectral"] and m["max_dim"] is None
    assert p["alpha"]["default"] is None and p["alpha"]["upper"] == 2.0
    assert p["beta"]["default"] is None and p["beta"]["lower_open"]
    assert [x["role"] for x in m["parameters"]] == ["shape", "shape", "scale", "variance", "nugget"]
    f = noiselab.synth("circulant", acf="gencauchy:alpha=1.5,beta=2,scale=4", size=(32, 32), seed=3)
    assert f.shape == (32, 32)


def test_peer_names_reach_python():
    """A peer's name with its own keys (gstat's Sph: psill, range) is in
    models() under its family, and a spec by it is the family's model with
    the peer's parameters converted: the same field, seed for seed."""
    import numpy as np
    import noiselab
    m = {x["name"]: x for x in noiselab.models()}["spherical"]
    sph = {a["name"]: a for a in m["peers"]}["Sph"]
    assert sph["peer"] == "gstat"
    assert [p["name"] for p in sph["parameters"]] == ["psill", "range", "nugget"]
    assert sph["parameters"][1]["default"] is None
    a = noiselab.synth("circulant", acf="Sph:psill=2,range=9", size=(32, 32), seed=3)
    b = noiselab.synth("circulant", acf="spherical:var=2,scale=9", size=(32, 32), seed=3)
    assert np.array_equal(a, b)
    c = noiselab.synth("circulant", acf="Gaussian:len_scale=9", size=(32, 32), seed=3)
    d = noiselab.synth("circulant", acf="gauss:scale=%.17g" % (9 * 2 / np.pi ** 0.5), size=(32, 32), seed=3)
    assert np.allclose(c, d, rtol=0, atol=1e-12)
