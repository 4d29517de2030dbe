# A square image over the unit square with axes and a title: the figures drawn as pixels by the library
# (reproduce bridson's wake and ring). Compiled into dfvn-sample (dfvn/plot/gnuplot.hpp), which runs it as
#   gnuplot -c titled.gp OUT.png IMAGE.png TITLE SETTINGS XLABEL YLABEL SIDE
# IMAGE.png: SIDE x SIDE pixels over [0,1]^2, its first row at the top. TITLE, SETTINGS: the title's two
# lines. XLABEL, YLABEL: the axes' names.
set terminal pngcairo size 900, 960 font 'sans,12'
set output ARG1
set title ARG3."\n".ARG4 noenhanced font 'sans,12'
set size ratio -1
set xrange [0:1]; set yrange [0:1]
set xlabel ARG5 noenhanced; set ylabel ARG6 noenhanced
set xtics 0.25; set ytics 0.25
unset key; unset colorbox
plot ARG2 binary filetype=png dx=1.0/real(ARG7) dy=1.0/real(ARG7) with rgbimage
