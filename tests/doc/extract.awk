# The commands of a Markdown page and the output it shows, one per line:
# "LINE<TAB>c<TAB>COMMAND" and "LINE<TAB>o<TAB>OUTPUT LINE".
# A command is a line of an indented code block (four spaces, after a blank
# line); fenced blocks (``` ... ```) are not commands (the C example is built
# by tools/test-install.sh). An HTML comment "<!-- doc-test: skip ... -->"
# just before a block (blank lines allowed between) skips that block; the
# comment says why. "<!-- doc-test: output -->" just before a block makes it
# the output of the command before it (its blank lines kept, as lines).
BEGIN { fence = 0; inblock = 0; prevblank = 1; skip = 0; output = 0; blanks = 0 }
/^[ \t]*```/ { fence = !fence; inblock = 0; prevblank = 0; next }
fence { next }
/^<!-- doc-test: skip/ { skip = 1; prevblank = 0; next }
/^<!-- doc-test: output/ { output = 1; inblock = 0; blanks = 0; prevblank = 0; next }
/^    / && (inblock || prevblank) {
    inblock = 1
    line = substr($0, 5)
    if (output) {
        for (; blanks > 0; blanks--)
            printf "%d\to\t\n", NR - blanks
        printf "%d\to\t%s\n", NR, line
    } else if (!skip && line !~ /^[ \t]*$/)
        printf "%d\tc\t%s\n", NR, line
    prevblank = 0
    next
}
/^[ \t]*$/ { prevblank = 1; if (inblock && output) blanks++; next }
{ if (inblock) { skip = 0; output = 0 } inblock = 0; prevblank = 0; blanks = 0 }
