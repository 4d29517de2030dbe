# Bridson, Hourihan and Nordenstam 2007, Figure 1, as `dfvn-sample reproduce constructions` draws it
# (src/reproduce/constructions_files.cpp): streamlines of 2D curl noise in the unit square around a disc
# obstacle at its centre. Compiled into dfvn-sample (src/plot/gnuplot.hpp), which runs it as
#   gnuplot -c curl_obstacle.gp OUT.png LINES.csv RADIUS WIDTH
# LINES.csv: line,x0,x1, one streamline per line index, its points in order. RADIUS: the disc's; WIDTH:
# the ramp's transition width (the dashed circle shows where the obstacle's ramp ends).
set terminal pngcairo size 900, 900 font 'sans,10'
set output ARG1
set datafile separator comma
set size ratio -1
set xrange [0:1]; set yrange [0:1]
set xlabel 'x0'; set ylabel 'x1'
set title "Curl noise around a disc obstacle (Bridson et al. 2007, Figure 1)"
r = real(ARG3); w = real(ARG4)
set object 1 circle at 0.5, 0.5 size r fillstyle solid 1.0 fillcolor rgb 'gray70' front
set object 2 circle at 0.5, 0.5 size r + w fillstyle empty border linecolor rgb 'gray50' dashtype 2 front
set object 3 rectangle from 0, 0 to 1, 1 fillstyle empty border linecolor rgb 'black' front
unset key
# A point whose line index differs from the previous point's is undefined (NaN), which breaks the line
# between two streamlines.
previous = -1
next_y(line, y) = (result = (line == previous ? y : NaN), previous = line, result)
plot ARG2 skip 1 using 2:(next_y($1, $3)) with lines linewidth 1.0 linecolor rgb '#1f77b4'
