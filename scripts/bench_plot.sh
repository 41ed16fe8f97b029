#!/bin/sh
# Draw DIR/bench.png from DIR/bench.dat (written by scripts/bench_table.py
# from the builds' bench.tsv) with scripts/bench.gp: filled symbols the first
# build's times (-O2), open symbols the second's (-O3 -march=native).
# Without gnuplot: a note, and exit 0 (the table is the result; the plot is
# a picture of it).  Install it with `sh scripts/deps.sh bench` (Debian:
# gnuplot-nox).
set -eu
dir=${1:-build/bench-out}
if ! command -v gnuplot >/dev/null 2>&1; then
  echo "bench: note: gnuplot not found, $dir/bench.png not drawn (install: sh scripts/deps.sh bench, as root)"
  exit 0
fi
# the build labels, for the title (no quotes in them)
b1=$(sed -n 's/^# build1: //p' "$dir/bench.dat" | tr -d "'\"")
b2=$(sed -n 's/^# build2: //p' "$dir/bench.dat" | tr -d "'\"")
gnuplot -e "datafile='$dir/bench.dat'; outfile='$dir/bench.png'; b1='$b1'; b2='$b2'" scripts/bench.gp
echo "bench: wrote $dir/bench.png"
