# Time (ns per box) versus max excess over the exact bound, one labelled
# point per plotted row of bench/bench.c: filled the first build (b1, -O2),
# open the second (b2, -O3 -march=native) when there is one.  Usage:
#   gnuplot -e "datafile='build/bench-out/bench.dat'; outfile='build/bench-out/bench.png'" scripts/bench.gp
# bench.dat (written by scripts/bench_table.py): one block per row,
# separated by two blank lines; each block is a header line whose 6th field
# is the row's title, then one line: row ns_per_box max_excess y_plotted
# proven label ns_per_box_2 (proven: 1 certbox, 0 unsound round-to-nearest
# baseline, 2 exact GMP; y_plotted is the max excess floored at 0.01, so
# that the exact row shows on the log scale; ns_per_box_2 is NaN without a
# second build).
if (!exists("datafile")) datafile = "build/bench-out/bench.dat"
if (!exists("outfile")) outfile = "build/bench-out/bench.png"
if (!exists("b1")) b1 = "build 1"
if (!exists("b2")) b2 = "build 2"
if (strstrt(GPVAL_TERMINALS, "pngcairo") > 0) {
    set terminal pngcairo size 1400,1000 font ",10" noenhanced
} else {
    set terminal png size 1400,1000 noenhanced
}
set output outfile

stats datafile using 2 nooutput
nb = STATS_blocks
array P[nb]
do for [i = 1:nb] {
    stats datafile index (i - 1) using 5 nooutput
    P[i] = STATS_min
}
pt_of(p) = p == 1 ? 7 : (p == 0 ? 5 : 9)
pt2_of(p) = p == 1 ? 6 : (p == 0 ? 4 : 8)
lc_of(p) = p == 1 ? "#1a7f37" : (p == 0 ? "#cf222e" : "#0969da")

set title sprintf("certbox bench: time per box vs max excess over the exact bound\nfilled: %s   open: %s (same row, same excess)\ngreen: proven (certbox)   red: unsound round-to-nearest baselines   blue: exact (GMP), drawn at 0.01\nsphere rows 6a, 6b: units of u(|t|+sqrt s)+eta, against the exact sphere bound; binary32 rows: u = 2^-24", b1, b2)
set logscale x 10
set logscale y 10
set xlabel "time per box (ns, median of the rounds; log scale)"
set ylabel "max excess over the exact bound (units of u S + eta; log scale)"
set format y "%.0e"
set grid xtics ytics
set key below box maxrows 5 height 1.5
set offsets graph 0.05, graph 0.1, graph 0.1, graph 0.1
plot for [i = 1:nb] datafile index (i - 1) using 2:4 with points pt pt_of(P[i]) ps 1.8 \
         lc rgb lc_of(P[i]) title columnhead(6), \
     for [i = 1:nb] datafile index (i - 1) using 7:4 with points pt pt2_of(P[i]) ps 1.8 \
         lc rgb lc_of(P[i]) notitle, \
     for [i = 1:nb] datafile index (i - 1) using 2:4:6 with labels left offset 1.0,0.6 \
         font ",11" tc rgb lc_of(P[i]) notitle
