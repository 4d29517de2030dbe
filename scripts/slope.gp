# Figures 9 and 10 (Section 5.5): particle traces over the height field of the surface the 2D field is
# lifted onto, with axes, the slope direction, the mean drift and the spread's principal direction.
# Compiled into dfvn-sample (dfvn/plot/gnuplot.hpp), which runs it as
#   gnuplot -c slope.gp OUT.png TRACES.png TITLE "SX SY" "DX DY" ANGLE SETTINGS SIDE
# TRACES.png: the traces drawn over the height field (lighter = lower) on the unit square, y up. SX SY: the
# plane's slope, grad h. DX DY: the mean displacement. ANGLE: the principal direction of the
# displacements' spread, degrees from x. TITLE, SETTINGS: the two lines of the title. SIDE: the PNG's side.
# Numbers are read by eval, not real(): gnuplot 5.4's real("1e-300") refuses an exponent without a point.
eval "sx = 1.0 * (".word(ARG4, 1).")"; eval "sy = 1.0 * (".word(ARG4, 2).")"
eval "dx = 1.0 * (".word(ARG5, 1).")"; eval "dy = 1.0 * (".word(ARG5, 2).")"
eval "angle_deg = 1.0 * (".ARG6.")"
angle = angle_deg * pi / 180
set terminal pngcairo size 1000, 1120 font 'sans,12'
set output ARG1
set title ARG3."\n".ARG7 noenhanced font 'sans,12'
set size ratio -1
set xrange [0:1]; set yrange [0:1]
set xlabel 'x'; set ylabel 'y'
set xtics 0.25; set ytics 0.25
set key outside below center vertical maxrows 3 font 'sans,11'
unset colorbox
len = 0.22
slope_len = sqrt(sx * sx + sy * sy); drift_len = sqrt(dx * dx + dy * dy)
ux = slope_len > 0 ? sx / slope_len : 0; uy = slope_len > 0 ? sy / slope_len : 0
px = cos(angle); py = sin(angle)
set arrow 1 from 0.5, 0.5 to 0.5 + len * ux, 0.5 + len * uy lc rgb '#d62728' lw 4 head filled size 0.03, 20 front
# The mean drift at its true length (the displacement in the square's units).
set arrow 2 from 0.5, 0.5 to 0.5 + dx, 0.5 + dy lc rgb '#1f77b4' lw 4 head filled size 0.03, 20 front
set arrow 3 from 0.5 - 0.3 * px, 0.5 - 0.3 * py to 0.5 + 0.3 * px, 0.5 + 0.3 * py nohead lc rgb '#2ca02c' lw 3 dt 2 front
plot ARG2 binary filetype=png dx=1.0/real(ARG8) dy=1.0/real(ARG8) with rgbimage notitle, \
     NaN with lines lc rgb '#d62728' lw 4 title sprintf('slope direction grad h = (%g, %g)', sx, sy), \
     NaN with lines lc rgb '#1f77b4' lw 4 title sprintf('mean drift over t, to scale: (%.3g, %.3g), %.3g long', dx, dy, drift_len), \
     NaN with lines lc rgb '#2ca02c' lw 3 dt 2 title sprintf('principal direction of the spread, %.1f deg from x', angle_deg)
