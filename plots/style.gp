# Shared gnuplot style of granmix figures: paper-like axes, one colour per species,
# theory as lines (DSMC symbols with error bars join with the compare tool).
set terminal pngcairo size 800,600 enhanced font "DejaVu Sans,12"
set datafile separator "\t"
set datafile commentschars "#"
set datafile columnheaders
set key top left box opaque
set grid lc rgb "#dddddd"
set style line 1 lc rgb "#1f4e9c" lw 2
set style line 2 lc rgb "#c0392b" lw 2
set style line 3 lc rgb "#27ae60" lw 2
set style line 4 lc rgb "#8e44ad" lw 2
set style line 9 lc rgb "#000000" lw 2 dt 2
