# Power spectrum figure: the periodogram (2D: the (k0, k1) plane; 3D: its k2 = 0 slice) on a log colour
# scale, and the radial average with the flat level 1 of uniform random points and the lattice peak
# marked. Compiled into dfvn-sample (dfvn/plot/gnuplot.hpp), which runs it as
#   gnuplot -c spectrum.gp OUT.png PREFIX.csv PREFIX_radial.csv DIM PEAK WHAT
# PREFIX.csv: k0,k1[,k2],power with k0 varying fastest; PREFIX_radial.csv: frequency,power,anisotropy_db,...
# (anisotropy_db empty where it is not defined); PEAK: the lattice peak frequency n^(1/N); WHAT: the
# input's name, sets and points, for the title.
# The DC term P(0) = n is left out of the colour scale (it would set its top and darken everything
# else): it is drawn in the scale's top colour, and the scale spans the other frequencies' powers.
dim = int(ARG4)
peak = real(ARG5)
power_floor = 1e-3  # the colour scale's floor: a periodogram can be 0 at a frequency
set datafile separator comma
set table $plane separator comma
if (dim == 3) {
  plot ARG2 skip 1 using 1:2:($4 > power_floor ? $4 : power_floor) with table if (real(strcol(3)) == 0)
} else {
  plot ARG2 skip 1 using 1:2:($3 > power_floor ? $3 : power_floor) with table
}
unset table
# The largest power away from k = 0, for the top of the colour scale.
stats $plane using (($1 != 0 || $2 != 0) ? $3 : NaN) nooutput
power_top = STATS_max
set terminal pngcairo size 1300, 620 font 'sans,10'
set output ARG1
set multiplot layout 1, 2 title sprintf("Power spectrum of %s: %dD, averaged over the sets", ARG6, dim) noenhanced
set title 'periodogram P(k)'.(dim == 3 ? ' (k2 = 0 slice)' : '').', log colour scale'
set xlabel 'k0'; set ylabel 'k1'; set size ratio -1
set logscale cb; set cbrange [0.01:power_top]; set palette defined (0 'black', 1 '#1f3f9f', 2 '#d62728', 3 'yellow')
plot $plane using 1:2:($3 < power_top ? $3 : power_top) with image notitle
unset logscale cb; set size noratio
stats ARG3 skip 1 using 1 nooutput
if (peak <= STATS_max) {
  set arrow 1 from peak, graph 0 to peak, graph 1 nohead dashtype 2 linecolor rgb 'gray40'
  set label 1 sprintf('lattice peak %.3g', peak) at peak, graph 0.95 offset character 0.5, 0 left textcolor rgb 'gray40'
} else {  # a --spectrum-frequency below the peak: say where it is
  set label 1 sprintf('lattice peak %.3g: beyond |k| = %d', peak, STATS_max) at graph 0.02, graph 0.95 left textcolor rgb 'gray40'
}

set title 'radial average and anisotropy'
set xlabel '|k|'; set ylabel 'P'; set grid
set key outside below center horizontal  # clear of the curves
set bmargin 6
# The anisotropy is empty where a shell's power is constant (identical points): draw it where it exists.
stats ARG3 skip 1 using (valid(3) ? 1 : 0) nooutput
if (STATS_sum > 0) {
  set y2label 'anisotropy (dB)'; set ytics nomirror; set y2tics
  plot ARG3 skip 1 using 1:2 with lines linewidth 2 linecolor rgb '#1f5fbf' title 'radial mean', \
       1 with lines dashtype 3 linecolor rgb 'gray40' title 'random = 1', \
       ARG3 skip 1 using 1:3 axes x1y2 with lines linecolor rgb '#d62728' title 'anisotropy (dB)'
} else {
  plot ARG3 skip 1 using 1:2 with lines linewidth 2 linecolor rgb '#1f5fbf' title 'radial mean (constant: no anisotropy)', \
       1 with lines dashtype 3 linecolor rgb 'gray40' title 'random = 1'
}
unset multiplot
