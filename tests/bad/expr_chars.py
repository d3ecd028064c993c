#!/usr/bin/env python3
# Writes tests/bad/expr_chars.cases to stdout: one case per ASCII character
# outside the expression syntax (core/expr_internal.h; libmatheval's scanner,
# used before muParser, echoed such a character to stdout and dropped it).
# python3 tests/bad/expr_chars.py > tests/bad/expr_chars.cases
ok = set("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_.,+-*/^() \t")
T = [
    ('$NL synth fft --acf "expr:exp(-abs(t)%s/8)" --size 64 -o out.tsv', 12),
    ('$NL check --acf "expr:exp(-abs(t)%s/8)" --dim 1 --json', 12),
    ('$NL synth fft --spectrum "spectrum:1/(1+f%s^2)" --size 64 -o out.tsv', 7),
    ('$NL synth fft --spectrum "1/(1+f%s^2)" --size 64 -o out.tsv', 7),
    ('$NL nonlin --acf markov:scale=8 --g "expr:x%s^2" --size 64', 2),
    ('$NL synth sparse --kernel "exp(-r%s)" --size 64 -o out.tsv', 7),
    ('$NL synth sparse --kernel "exp(-r)" --angle "x%s/64" --size 32x32 -o out.exr', 2),
]
print("# Expressions with a character outside the expression syntax (libmatheval's flex scanner,")
print("# used before muParser, echoed it to stdout and dropped it): refused, naming the character")
print("# and its position, with nothing on")
print("# stdout.  One case per such ASCII character (NUL cannot be in an argument), cycling")
print("# through every option that takes an expression.  Generated once by tests/bad/expr_chars.py;\n# RULE EXIT NEEDLE COMMAND.")
k = 0
for c in range(1, 128):
    ch = chr(c)
    if ch in ok:
        continue
    # ';' ends the expression of a model spec (expr:EXPR;nugget=V): it is
    # tried where no model spec is parsed
    tmpl, pos = T[4] if ch == ';' else T[k % len(T)]
    k += ch != ';'
    shown = "'%s'" % ch if 0x20 < c < 0x7f else "\\x%02x" % c
    needle = "character %s at position %d" % (shown, pos)
    cmd = "c=$(printf '\\%03ox'); c=${c%%x}; " % c + tmpl % "$c"
    cmd += " >stdout.txt; rc=$?; [ -s stdout.txt ] && rc=3; rm -f stdout.txt; exit $rc"
    print("2\t2\t%s\t%s" % (needle, cmd))
