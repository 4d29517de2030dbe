# The animation strip of `dfvn-sample animate` (src/animate/animation_files.cpp): a few frames side by
# side, each particle at its position in that frame with a short trail of its previous positions.
# Compiled into dfvn-sample (src/plot/gnuplot.hpp), which runs it as
#   gnuplot -c animation.gp OUT.png TRAILS.csv DIM FRAMES DOMAIN TITLE
# TRAILS.csv: panel,frame,particle,x0,x1[,x2],to_x0,to_x1[,to_x2]: one trail segment per row, from the
# particle's position in frame - 1 to the one in frame (segments with an end outside the domain are left
# out); the rows with frame = the panel's frame hold the particle's position shown (to_*). DIM 2 or 3 (3D
# drawn as an oblique view of the cube); FRAMES the panels' frame numbers, space-separated; DOMAIN cube
# or ball; TITLE the figure's title.
dim = int(ARG3)
panels = words(ARG4)
set terminal pngcairo size 330 * panels + 40, 380 font 'sans,9'
set output ARG1
set datafile separator comma
set multiplot layout 1, panels title ARG6 noenhanced
unset key
if (dim == 2) {
  set size ratio -1
  set xrange [0:1]; set yrange [0:1]
  set xtics 0.5; set ytics 0.5
  if (ARG5 eq 'ball') { set object 1 circle at 0.5, 0.5 size 0.5 front fillstyle empty border linecolor rgb 'gray40' }
  do for [p = 1:panels] {
    set title sprintf('frame %s', word(ARG4, p))
    f = int(word(ARG4, p))
    plot ARG2 skip 1 using ($1 == p ? $4 : NaN):5:($6 - $4):($7 - $5) with vectors nohead linecolor rgb '#9ecae1', \
         ARG2 skip 1 using ($1 == p && $2 == f ? $6 : NaN):7 with points pointtype 7 pointsize 0.35 linecolor rgb '#08306b'
  }
} else {
  set view 62, 28, 1.0, 1.0
  set view equal xyz
  set xyplane at 0
  set xrange [0:1]; set yrange [0:1]; set zrange [0:1]
  set xtics 0.5; set ytics 0.5; set ztics 0.5
  set border 4095
  do for [p = 1:panels] {
    set title sprintf('frame %s', word(ARG4, p))
    f = int(word(ARG4, p))
    splot ARG2 skip 1 using ($1 == p ? $4 : NaN):5:6:($7 - $4):($8 - $5):($9 - $6) with vectors nohead linecolor rgb '#9ecae1', \
          ARG2 skip 1 using ($1 == p && $2 == f ? $7 : NaN):8:9 with points pointtype 7 pointsize 0.3 linecolor rgb '#08306b'
  }
}
unset multiplot
