# Does a command's output (file 2) agree with what the page shows (file 1,
# "LINE<TAB>TEXT" from extract.awk)?  Prints the first disagreement and exits 1.
# A shown line "..." stands for any number of output lines (none included);
# otherwise the shown lines are consecutive output lines, the first at the top
# of the output and the last at its end unless "..." comes before or after.
# Two lines agree when they split into the same text and numbers: the text
# between numbers equal (runs of blanks count as one, ends trimmed), and each
# shown number equal to the printed one rounded to the digits shown (1.038
# is the printed value rounded to 3 decimals, 2.5e-07 to 1 decimal of its
# mantissa, 12 to an integer).
function norm(s) { gsub(/[ \t]+/, " ", s); sub(/^ /, "", s); sub(/ $/, "", s); return s }
function split_line(s, tok,    n, pre) {
    n = 0
    while (match(s, /[-+]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][-+]?[0-9]+)?/)) {
        pre = substr(s, 1, RSTART - 1)
        tok[++n] = "t" norm(pre)
        tok[++n] = "n" substr(s, RSTART, RLENGTH)
        s = substr(s, RSTART + RLENGTH)
    }
    tok[++n] = "t" norm(s)
    return n
}
function rounded(x, shown,    m, d, f, r) {
    m = shown; sub(/[eE].*/, "", m)
    d = index(m, ".") ? length(m) - index(m, ".") : 0
    f = (shown ~ /[eE]/) ? "%." d "e" : "%." d "f"
    r = sprintf(f, x + 0)
    if (r ~ /^-[0.]*([eE].*)?$/) r = substr(r, 2) # -0.000 is 0.000
    return r
}
function agree(want, got,    nw, ng, w, g, i) {
    nw = split_line(want, w); ng = split_line(got, g)
    if (nw != ng) return 0
    for (i = 1; i <= nw; i++) {
        if (substr(w[i], 1, 1) == "t") { if (w[i] != g[i]) return 0 }
        else if (rounded(substr(g[i], 2), substr(w[i], 2)) != rounded(substr(w[i], 2), substr(w[i], 2))) return 0
    }
    return 1
}
function fail(l, why) { printf "line %d: %s\n", l, why; exit 1 }
function shown(k) { return "\"" w[k] "\"" }
function printed(p) { return p >= 1 && p <= nout ? "\"" out[p] "\"" : "nothing" }
# the first line of segment s that disagrees when it starts at output line p; 0 if none
function at(s, p,    k) {
    for (k = first[s]; k <= lastl[s]; k++)
        if (p + k - first[s] > nout || !agree(w[k], out[p + k - first[s]])) return k
    return 0
}
FNR == NR {
    l = $0; sub(/\t.*/, "", l)
    w[++nw] = substr($0, length(l) + 2); wl[nw] = l
    dots[nw] = w[nw] ~ /^[ \t]*\.\.\.[ \t]*$/
    next
}
{ out[++nout] = $0 }
END {
    for (i = 1; i <= nw; i++) {
        if (dots[i]) continue
        if (i == 1 || dots[i - 1]) first[++ns] = i
        lastl[ns] = i
    }
    lead = !dots[1]; trail = !dots[nw]
    p = 1
    for (s = 1; s <= ns; s++) {
        if (s == 1 && lead) {
            if ((k = at(s, 1))) fail(wl[k], "shows " shown(k) ", the command printed " printed(k - first[s] + 1))
            q = 1
        } else if (s == ns && trail) {
            q = nout - (lastl[s] - first[s])
            if (q < p) q = p
            if ((k = at(s, q))) fail(wl[k], "shows " shown(k) " at the end, the command printed " printed(q + k - first[s]))
        } else {
            for (q = p; q <= nout && at(s, q); q++) ;
            if (q > nout) fail(wl[first[s]], "shows " shown(first[s]) " (and what follows it), which the command did not print")
        }
        p = q + lastl[s] - first[s] + 1
        if (s == ns && trail && p <= nout) fail(wl[lastl[s]], "ends here, the command printed more: " printed(p))
    }
}
