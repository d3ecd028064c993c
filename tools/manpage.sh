#!/bin/sh
# noiselab(1) on stdout, made from the help texts of the command and of each
# subcommand, so the manual says what `--help` says.
# usage: tools/manpage.sh BIN VERSION
set -eu
bin=$1
version=$2

# Roff-safe text: backslashes and minus signs escaped, a leading . or ' kept literal.
esc() { sed -e 's/\\/\\e/g' -e 's/-/\\-/g' -e "s/^[.']/\\\\\\&&/"; }

help=$("$bin" --help)
cmds=$(printf '%s\n' "$help" | sed -n '/^commands:/,/^$/s/^  \([a-z][a-z0-9]*\) .*/\1/p')
[ -n "$cmds" ] || { echo "manpage.sh: no commands in \`$bin --help\`" >&2; exit 1; }

cat <<HEAD
.TH NOISELAB 1 "" "noiselab $version" "User Commands"
.SH NAME
noiselab \\- synthesise random fields with a prescribed autocorrelation or spectrum, and measure them
.SH SYNOPSIS
.B noiselab
.I COMMAND
.RI [ OPTIONS ]
.br
.B noiselab
.I COMMAND
.B \\-\\-help
.br
.B noiselab \\-\\-version
.SH DESCRIPTION
.nf
HEAD
printf '%s\n' "$help" | esc
echo ".fi"
echo ".SH COMMANDS"
for c in $cmds; do
    echo ".SS $c"
    echo ".nf"
    "$bin" "$c" --help | esc
    echo ".fi"
done
cat <<'TAIL'
.SH EXIT STATUS
0 on success, 2 for bad usage or input (one line on stderr naming the value and
what was expected), 1 for a failure while running.  No partial output file is
left behind.
.SH ENVIRONMENT
.TP
.B NOISELAB_FFTW
\fBestimate\fR or \fBmeasure\fR: the FFTW planner for every transform size.
.TP
.B NOISELAB_MEMORY_LIMIT
bytes: lowers the memory ceiling requests are checked against.
.TP
.B NOISELAB_PROGRESS_AFTER
seconds after which long work shows its progress on a terminal (default 1).
.SH FILES
.TP
.I $XDG_CACHE_HOME/noiselab/fftw\-wisdom
FFTW plans kept between runs (\fI~/.cache/noiselab/\fR by default).
.SH SEE ALSO
The C library: \fB#include <noiselab.h>\fR, \fBpkg\-config \-\-cflags \-\-libs noiselab\fR;
the installed examples in \fIshare/doc/noiselab/examples\fR.
TAIL
