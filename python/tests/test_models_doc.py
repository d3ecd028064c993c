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
