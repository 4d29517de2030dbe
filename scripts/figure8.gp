# Figure 8 of `dfvn-sample reproduce figure8` (src/reproduce/figure8.cpp): curl noise jittering animated,
# drop mode (the 2023 method) against the conformant field. Top: particles inside the domain per frame,
# 2D and 3D. Bottom: the 2D tracks of the particles nearest the boundary in frame 0, drop and conformant
# (a gap where a particle is outside). Compiled into dfvn-sample (src/plot/gnuplot.hpp), which runs it as
#   gnuplot -c figure8.gp OUT.png FRAMES.csv TRACKS.csv DROP_IDS CONFORMANT_IDS
# FRAMES.csv: dimension,mode,lattice,frame,phase,inside,...; TRACKS.csv: dimension,mode,particle,frame,x0,x1;
# *_IDS: the particles of the tracks, space-separated.
set terminal pngcairo size 1200, 1000 font 'sans,10'
set output ARG1
set datafile separator comma
set multiplot layout 2, 2 title 'Figure 8: CNJ animated, drop mode (2023) against the conformant field'
set grid
set key bottom right
set xlabel 'frame'; set ylabel 'particles inside'
do for [d = 2:3] {
  set title sprintf('%dD: particles inside the domain per frame', d)
  plot ARG2 skip 1 using 4:(strcol(2) eq 'drop' && $1 == d ? $6 : NaN) with lines linewidth 1.5 linecolor rgb '#d62728' title 'drop (2023)', \
       ARG2 skip 1 using 4:(strcol(2) eq 'conformant' && $1 == d ? $6 : NaN) with lines linewidth 1.5 linecolor rgb '#1f77b4' title 'conformant'
}
unset grid
set size ratio -1
set xrange [-0.02:1.02]; set yrange [-0.02:1.02]
set xlabel 'x0'; set ylabel 'x1'
set object 1 rectangle from 0, 0 to 1, 1 fillstyle empty border linecolor rgb 'gray40' behind
set key outside bottom center horizontal
array modes[2] = ['drop', 'conformant']
do for [m = 1:2] {
  ids = m == 1 ? ARG4 : ARG5
  set title sprintf('2D tracks near the boundary, %s', modes[m])
  plot for [t = 1:words(ids)] ARG3 skip 1 using (strcol(2) eq modes[m] && $3 == int(word(ids, t)) ? $5 : NaN):6 \
       with lines linewidth 1.2 title sprintf('particle %s', word(ids, t))
}
unset multiplot
