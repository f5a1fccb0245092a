# Shared gnuplot style of granmix figures, copied into every figure script (compare/figure_style.hpp.in):
# paper-like axes, one colour per species (styles 1-8; 9 is black for totals, means and guides).
set datafile separator "\t"
set datafile commentschars "#"
set datafile columnheaders
set grid lc rgb "#e4e4e4" lw 0.8
set border lw 1.2
set tics nomirror out scale 0.6
set mxtics default
# No blank disc around a symbol: gnuplot clears one behind the points of error bars, a halo on a shaded band.
set pointintervalbox 0.01
set style line 1 lc rgb "#1f4e9c" lw 2
set style line 2 lc rgb "#c0392b" lw 2
set style line 3 lc rgb "#27ae60" lw 2
set style line 4 lc rgb "#8e44ad" lw 2
set style line 5 lc rgb "#d35400" lw 2
set style line 6 lc rgb "#16a085" lw 2
set style line 7 lc rgb "#7f8c8d" lw 2
set style line 8 lc rgb "#b7950b" lw 2
set style line 9 lc rgb "#000000" lw 2 dt 2
