#!/bin/sh
# Draw DIR/bench.png from DIR/bench.dat (written by build/bench) with
# scripts/bench.gp.  Without gnuplot: a note, and exit 0 (the table is the
# result; the plot is a picture of it).  Install it with
# `sh scripts/deps.sh bench` (Debian: gnuplot-nox).
set -eu
dir=${1:-build/bench-out}
if ! command -v gnuplot >/dev/null 2>&1; then
  echo "bench: note: gnuplot not found, $dir/bench.png not drawn (install: sh scripts/deps.sh bench, as root)"
  exit 0
fi
gnuplot -e "datafile='$dir/bench.dat'; outfile='$dir/bench.png'" scripts/bench.gp
echo "bench: wrote $dir/bench.png"
