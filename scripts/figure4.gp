# Figure 4 (Table 1): radial distribution functions g(r), one row per dimension, one column per method,
# the median nearest-neighbour distance dashed. Compiled into dfvn-sample (src/plot/gnuplot.hpp), which
# runs it as
#   gnuplot -c figure4.gp OUT.png RDF.csv DIMS MEDIANS XMAX NOTE
# RDF.csv: columns dim,method,r,g. DIMS: the dimensions, e.g. "3 4 5". MEDIANS: per dimension the four
# methods' median NN distances in the order of `codes`, as they are to be printed. XMAX: per dimension the
# largest r of its row (the row shares its x range). NOTE: a line under the title.
# Numbers in the `if` filters are read with real(strcol(n)): gnuplot 5.4 parses only the `using` columns as numbers.
array codes[4] = ["cnj", "jitter", "pds", "sobol"]
array names[4] = ["Curl noise jittering", "Jittering", "Poisson disk", "Sobol"]
rows = words(ARG3)
set terminal pngcairo size 1400, 260 * rows + 40 font 'sans,9'
set output ARG1
set datafile separator comma
set multiplot layout rows, 4 title "Figure 4: radial distribution functions g(r) under the paper's protocol, each set normalised by its own density (points over the box it fills),\nedge-corrected; dashed: median nearest-neighbour distance; ".ARG6 noenhanced
set key off
set grid
# One y range for every panel, from the data: the panels compare at a glance.
stats ARG2 skip 1 using 4 nooutput
g_max = STATS_max > 1 ? STATS_max : 1
set yrange [0:1.05 * g_max]
set xlabel 'r'
set ylabel 'g(r)'
set rmargin 8  # room for the g = 1 label, right of the frame and off every curve
do for [row = 1:rows] {
  d = int(word(ARG3, row))
  x_max = real(word(ARG5, row))
  set xrange [0:x_max]
  x_step = x_max > 0.3 ? 0.1 : 0.05  # readable tick labels in 1400 / 4 pixels
  set xtics x_step
  do for [col = 1:4] {
    median_text = word(ARG4, 4 * (row - 1) + col)
    set table $panel separator comma
    plot ARG2 skip 1 using 3:4 with table if (real(strcol(1)) == d && strcol(2) eq codes[col])
    unset table
    set title sprintf("%dD %s (median %s)", d, names[col], median_text) noenhanced
    set arrow 1 from real(median_text), graph 0 to real(median_text), graph 1 nohead dashtype 2 linecolor rgb 'red' linewidth 1.5
    set label 1 'g = 1' at graph 1, first 1 offset character 0.6, 0 left textcolor rgb 'gray40'
    plot $panel using 1:2 with lines linecolor rgb '#1f5fbf' linewidth 1.5, \
         1 with lines dashtype 3 linecolor rgb 'gray50'
  }
}
unset multiplot
