# The commands of a Markdown page, one per line: "LINE<TAB>COMMAND".
# A command is a line of an indented code block (four spaces, after a blank
# line); fenced blocks (``` ... ```) are not commands (the C example is built
# by tools/test-install.sh). An HTML comment "<!-- doc-test: skip ... -->"
# just before a block (blank lines allowed between) skips that block; the
# comment says why.
BEGIN { fence = 0; inblock = 0; prevblank = 1; skip = 0 }
/^[ \t]*```/ { fence = !fence; inblock = 0; prevblank = 0; next }
fence { next }
/^<!-- doc-test: skip/ { skip = 1; prevblank = 0; next }
/^    / && (inblock || prevblank) {
    inblock = 1
    line = substr($0, 5)
    if (!skip && line !~ /^[ \t]*$/)
        printf "%d\t%s\n", NR, line
    prevblank = 0
    next
}
/^[ \t]*$/ { prevblank = 1; next }
{ if (inblock) skip = 0; inblock = 0; prevblank = 0 }
