#!/usr/bin/env bash
# The CNJ study's figure: packing (1% quantile of the nearest-neighbour distance, in spacings) against
# RMS displacement, neighbour disorder and lattice order; one row per dimension. Lines: uniform jitter
# at half-widths 0.05..0.7 spacings. Points: CNJ runs, one colour per noise basis.
# Usage: scripts/plot_cnj_study.sh DIR   (reads DIR/cnj_study.csv and DIR/cnj_study_jitter.csv, writes DIR/cnj_study.png)
set -euo pipefail
dir=${1:?usage: plot_cnj_study.sh DIR}
command -v gnuplot >/dev/null || { echo "plot_cnj_study.sh: gnuplot not found (apt-get install gnuplot-nox)" >&2; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

dims=$(awk -F, 'NR > 1 { print $1 }' "$dir/cnj_study.csv" | sort -un | tr '\n' ' ')
bases=$(awk -F, 'NR > 1 { print $3 }' "$dir/cnj_study.csv" | sort -u | tr '\n' ' ')
rows=$(echo $dims | wc -w)
# columns of cnj_study.csv: 7 rms_displacement, 10 neighbour_disorder, 11 lattice_order, 14 cnj_nn_q01;
# of cnj_study_jitter.csv: 3 rms, 4 disorder, 5 order, 7 nn_q01
{
  echo "set terminal pngcairo size 1500,$((300 * rows)) font 'sans,9'"
  echo "set output '$dir/cnj_study.png'"
  echo "set multiplot layout $rows,3 title 'CNJ vs jitter: 1% quantile of the NN distance (spacings) against displacement, disorder and lattice order'"
  echo "set grid; set key top right; set ylabel 'nn q01 (spacings)'"
  for d in $dims; do
    awk -F, -v d="$d" 'NR > 1 && $1 == d { print $3, $4, $5, $7 }' "$dir/cnj_study_jitter.csv" >"$tmp/jitter-$d.dat"
    for b in $bases; do
      awk -F, -v d="$d" -v b="$b" 'NR > 1 && $1 == d && $3 == b { print $7, $10, $11, $14 }' "$dir/cnj_study.csv" >"$tmp/cnj-$d-$b.dat"
    done
    col=1
    for x in "RMS displacement (spacings)" "neighbour disorder (spacings)" "lattice order (1 = lattice)"; do
      echo "set title '${d}D'; set xlabel '$x'"
      plot="plot '$tmp/jitter-$d.dat' using $col:4 with linespoints linecolor rgb 'black' pointtype 7 pointsize 0.5 title 'jitter'"
      colour=1
      for b in $bases; do
        plot="$plot, '$tmp/cnj-$d-$b.dat' using $col:4 with points pointtype 6 linecolor $colour title 'CNJ $b'"
        colour=$((colour + 1))
      done
      echo "$plot"
      col=$((col + 1))
    done
  done
  echo "unset multiplot"
} >"$tmp/plot.gp"
gnuplot "$tmp/plot.gp"
