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
