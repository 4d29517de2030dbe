# Integration error figure of one dimension: one log-log panel per Genz family, the RMS relative error
# (bars: its standard error) against the number of points per method, and the Monte Carlo rate n^-1/2
# as a dotted guide through random's first point. Compiled into dfvn-sample (src/plot/gnuplot.hpp),
# which runs it as
#   gnuplot -c integration.gp OUT.png INTEGRATION.csv DIM METHODS GUIDES SETTINGS
# INTEGRATION.csv: columns dim,family,method,grid,mean_points,rms_relative_error,standard_error,...
# METHODS: the methods to draw ("cnj jitter ..."). GUIDES: per family in the order of `families`, the
# guide's point "n e", or "- -" for none. SETTINGS: the realizations and seeds, for the title.
array families[6] = ["oscillatory", "product_peak", "corner_peak", "gaussian", "continuous", "discontinuous"]
array codes[7] = ["cnj", "jitter", "pds", "sobol", "random", "halton", "lhs"]
array colours[7] = ["#d62728", "#1f77b4", "#2ca02c", "#9467bd", "#7f7f7f", "#ff7f0e", "#8c564b"]
d = int(ARG3)
methods = words(ARG4)
array colour[methods]
do for [i = 1:methods] {
  colour[i] = 'black'
  do for [j = 1:7] { if (codes[j] eq word(ARG4, i)) { colour[i] = colours[j] } }
}
set terminal pngcairo size 1500, 900 font 'sans,9'
set output ARG1
set datafile separator comma
set multiplot layout 2, 3 title sprintf("Integration error, %dD: RMS relative error (bars: standard error) against points; dotted: n^{-1/2}\n%s", d, ARG6)
set logscale xy
set grid
set format y '10^{%L}'
set xlabel 'points'
set ylabel 'RMS relative error'
set key bottom left font 'sans,8'
do for [f = 1:6] {
  # One datablock, one index (blocks separated by two blank lines) per method.
  set table $cells separator comma
  plot ARG2 skip 1 using 5:6:7 with table if (real(strcol(1)) == d && strcol(2) eq families[f] && strcol(3) eq word(ARG4, 1))
  do for [i = 2:methods] {
    set print $cells append
    print ""
    print ""
    unset print
    set table $cells append separator comma
    plot ARG2 skip 1 using 5:6:7 with table if (real(strcol(1)) == d && strcol(2) eq families[f] && strcol(3) eq word(ARG4, i))
  }
  unset table
  n0 = word(ARG5, 2 * f - 1)
  e0 = word(ARG5, 2 * f)
  set title families[f] noenhanced
  if (n0 eq '-') {
    plot for [i = 1:methods] $cells index (i - 1) using 1:2:3 with yerrorlines title word(ARG4, i) noenhanced \
         linecolor rgb colour[i] linewidth 1.5 pointtype 7 pointsize 0.6
  } else {
    plot for [i = 1:methods] $cells index (i - 1) using 1:2:3 with yerrorlines title word(ARG4, i) noenhanced \
         linecolor rgb colour[i] linewidth 1.5 pointtype 7 pointsize 0.6, \
         real(e0) * (real(n0) / x) ** 0.5 with lines dashtype 3 linecolor rgb 'gray40' notitle
  }
}
unset multiplot
