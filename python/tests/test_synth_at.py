"""synth --condition ... --at PTS.tsv -o OUT.tsv (the realizations at a
table's points, columns sim1..simK) against Krige.simulate(at=): the same
plan, seeds and draws, so the same bits (the table prints 17 significant
digits, which read back exactly)."""
import numpy as np

import noiselab

SPEC = "markov:scale=0.8"
DATA = np.array([[1.3, 2.2], [4.75, 6.1], [7.9, 1.05], [3.3, 7.6], [6.2, 4.4]])
VALUES = np.array([0.4, -1.1, 0.9, 1.6, -0.2])
AT = np.array([[0.25, 0.25], [5.0, 5.0], [1.3, 2.2], [9.99, 0.01], [2.625, 7.125]])


def table(path):
    rows = [ln.split("\t") for ln in open(path).read().splitlines() if ln and not ln.startswith("#")]
    return rows[0], rows[1:]


def test_cli_at_is_krige_simulate_bit_for_bit(cli, tmp_path):
    d, p, o = tmp_path / "d.tsv", tmp_path / "p.tsv", tmp_path / "o.tsv"
    d.write_text("x\ty\tvalue\n" + "".join("%r\t%r\t%r\n" % (a, b, v) for (a, b), v in zip(DATA, VALUES)))
    p.write_text("id\tx\ty\n" + "".join("%d\t%r\t%r\n" % (101 + i, a, b) for i, (a, b) in enumerate(AT)))
    for method, extra in (("fft", ()), ("circulant", ("--nmax", "3"))):
        cli("synth", method, "--acf", SPEC, "--size", "20x16", "--condition", d, "--extent", "0:10,0:8", "--at", p,
            "--seed", 7, "--realizations", 3, "-o", o, *extra)
        head, rows = table(o)
        assert head == ["id", "x", "y", "sim1", "sim2", "sim3"]
        assert [r[0] for r in rows] == [str(101 + i) for i in range(len(AT))]
        got = np.array([[float(c) for c in r[3:]] for r in rows]).T
        k = noiselab.Krige(DATA, VALUES, SPEC, nmax=int(extra[1]) if extra else None)
        _, z = k.simulate(method, (16, 20), "0:10,0:8", seed=7, realizations=3, at=AT)
        assert np.array_equal(got, z), (method, got - z)
        np.testing.assert_allclose(got[:, 2], VALUES[0], rtol=0, atol=1e-12)  # the third point is a datum (to rounding)
