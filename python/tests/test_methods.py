"""The synthesis methods come from the library's registry (synth/method.h):
noiselab.methods() lists what each can do and takes, Plan checks options
against the method's table, and the method string is the library's."""
import pytest

import noiselab


def test_methods_are_the_registry():
    ms = noiselab.methods()
    assert tuple(m["name"] for m in ms) == noiselab.METHODS
    by = {m["name"]: m for m in ms}
    assert "levels" in by["subdiv"]["options"] and "levels" in by["midpoint"]["options"]
    assert by["subdiv"]["options"]["displacements"]["choices"] == ("independent", "correlated")
    assert by["sparse"]["options"]["radius"]["range"] == (1, 4096)
    assert "distributed" in by["fft"]["capabilities"] and "window" in by["sparse"]["capabilities"]
    assert by["faulting"]["dims"] == (1, 2) and by["fft"]["dims"] == (1, 2, 3)
    assert "no_model" in by["faulting"]["capabilities"]


def test_options_are_checked_by_the_table():
    with pytest.raises(noiselab.Error, match="unknown option"):
        noiselab.Plan("midpoint", size=64, H=0.5, octaves=3)
    with pytest.raises(noiselab.Error, match="levels: expected 1 to 30"):
        noiselab.Plan("subdiv", acf="gauss:scale=4", size=64, levels=31)
    with pytest.raises(noiselab.Error, match="expected independent or correlated"):
        noiselab.Plan("subdiv", acf="gauss:scale=4", size=64, displacements="both")
    with pytest.raises(noiselab.Error, match="Hurst exponent"):
        noiselab.Plan("midpoint", size=64, H=1.5)


def test_method_string_is_the_library_describe():
    p = noiselab.Plan("subdiv", acf="gauss:scale=4", size=128, levels=3, neighborhood="auto", tol="variance:1e-3")
    assert p.method == "subdiv:levels=3,neighborhood=auto,tol=variance:0.001,periodic"
    assert noiselab.Plan("faulting", size=32, density=2.0).method == "faulting:density=2"
