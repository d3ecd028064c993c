"""An expression with a character outside the expression syntax raises
noiselab.Error naming it, and nothing reaches the program's stdout (libmatheval's
scanner, used before muParser, echoed the character there and dropped it)."""
import os
import subprocess
import sys

import pytest

import noiselab

BAD = [c for c in map(chr, range(1, 128))
       if not (c.isalnum() or c in "_.+-*/^() \t")]


def test_error_names_the_character():
    with pytest.raises(noiselab.Error) as e:
        noiselab.synth("fft", acf="expr:exp(-abs(t)/8)?", size=64)
    assert "unexpected character '?' at position 15" in str(e.value)


def test_stdout_stays_empty():
    """Every such character through acf=, spectrum= and shaping's expr:, in a
    fresh interpreter whose stdout is compared byte for byte."""
    code = ("import noiselab\n"
            "bad = [c for c in map(chr, range(1, 128)) if not (c.isalnum() or c in '_.+-*/^() \\t')]\n"
            "n = 0\n"
            "for c in bad:\n"
            "    for kw in (dict(acf='expr:exp(-abs(t)%s/8)' % c), dict(spectrum='spectrum:1/(1+f%s^2)' % c)):\n"
            "        try:\n"
            "            noiselab.synth('fft', size=64, **kw)\n"
            "        except noiselab.Error:\n"
            "            n += 1\n"
            "import sys\n"
            "sys.stderr.write('%d\\n' % n)\n")
    env = dict(os.environ, PYTHONPATH=os.path.dirname(os.path.dirname(noiselab.__file__)))
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, env=env)
    assert r.returncode == 0, r.stderr
    assert r.stdout == b""
    assert int(r.stderr.split()[-1]) == 2 * len(BAD)
