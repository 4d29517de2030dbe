# The CNJ study's figure: packing (1% quantile of the nearest-neighbour distance, in spacings) against RMS
# displacement, neighbour disorder and lattice order; one row per dimension. Lines: uniform jitter at
# half-widths 0.05..0.7 spacings. Points: CNJ runs, one colour per noise basis. Compiled into dfvn-sample
# (src/plot/gnuplot.hpp), which runs it as
#   gnuplot -c cnj_study.gp OUT.png CNJ_STUDY.csv CNJ_STUDY_JITTER.csv DIMS BASES SETTINGS
# Columns used: cnj_study.csv 1 dim, 3 noise, 7 rms_displacement, 10 neighbour_disorder, 11 lattice_order,
# 14 cnj_nn_q01; cnj_study_jitter.csv 1 dim, 3 rms, 4 disorder, 5 order, 7 nn_q01.
array cnj_columns[3] = [7, 10, 11]
array jitter_columns[3] = [3, 4, 5]
array xlabels[3] = ["RMS displacement (spacings)", "neighbour disorder (spacings)", "lattice order (1 = lattice)"]
rows = words(ARG4)
bases = words(ARG5)
set terminal pngcairo size 1500, 300 * rows + 50 font 'sans,9'
set output ARG1
set datafile separator comma
set multiplot layout rows, 3 title "CNJ vs jitter: 1% quantile of the NN distance (spacings) against displacement, disorder and lattice order\n".ARG6 noenhanced
set grid
set key top right noenhanced
set ylabel 'nn q01 (spacings)'
do for [row = 1:rows] {
  d = int(word(ARG4, row))
  do for [col = 1:3] {
    set table $jitter separator comma
    plot ARG3 skip 1 using (column(jitter_columns[col])):7 with table if (real(strcol(1)) == d)
    set table $cnj separator comma
    plot ARG2 skip 1 using (column(cnj_columns[col])):14 with table if (real(strcol(1)) == d && strcol(3) eq word(ARG5, 1))
    do for [b = 2:bases] {
      set print $cnj append
      print ""
      print ""
      unset print
      set table $cnj append separator comma
      plot ARG2 skip 1 using (column(cnj_columns[col])):14 with table if (real(strcol(1)) == d && strcol(3) eq word(ARG5, b))
    }
    unset table
    set title sprintf('%dD', d)
    set xlabel xlabels[col]
    plot $jitter using 1:2 with linespoints linecolor rgb 'black' pointtype 7 pointsize 0.5 title 'jitter', \
         for [b = 1:bases] $cnj index (b - 1) using 1:2 with points pointtype 6 linecolor b title 'CNJ '.word(ARG5, b)
  }
}
unset multiplot
