#!/usr/bin/env bash
# Figure 4: radial distribution functions, one panel per dimension (rows) and method (columns), with
# the median nearest-neighbour distance as a dashed line.
# Usage: scripts/plot_figure4.sh DIR   (reads DIR/table1.csv and DIR/rdf.csv, writes DIR/figure4.png)
set -euo pipefail
dir=${1:?usage: plot_figure4.sh DIR}
command -v gnuplot >/dev/null || { echo "plot_figure4.sh: gnuplot not found (apt-get install gnuplot-nox)" >&2; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

dims=$(awk -F, 'NR > 1 { print $1 }' "$dir/rdf.csv" | sort -un | tr '\n' ' ')
methods="cnj jitter pds sobol"
rows=$(echo $dims | wc -w)
{
  echo "set terminal pngcairo size 1400,$((260 * rows)) font 'sans,9'"
  echo "set output '$dir/figure4.png'"
  echo "set multiplot layout $rows,4 title 'Radial distribution functions g(r) (edge-corrected); dashed: median nearest-neighbour distance'"
  echo "set key off; set grid; set yrange [0:*]; set xlabel 'r'"
  for d in $dims; do
    for m in $methods; do
      awk -F, -v d="$d" -v m="$m" 'NR > 1 && $1 == d && $2 == m { print $3, $4 }' "$dir/rdf.csv" >"$tmp/$d-$m.dat"
      median=$(awk -F, -v d="$d" -v m="$m" 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "nn_median") c = i }
                                            NR > 1 && $1 == d && $3 == m { print $c }' "$dir/table1.csv")
      echo "set title '${d}D $m (median ${median:0:6})'"
      echo "unset arrow; set arrow from $median, graph 0 to $median, graph 1 nohead dashtype 2 linecolor rgb 'red' linewidth 1.5"
      echo "set label 1 'g = 1' at graph 0.02, first 1.08 textcolor rgb 'gray40'"
      echo "plot '$tmp/$d-$m.dat' using 1:2 with lines linecolor rgb '#1f5fbf' linewidth 1.5, 1 with lines dashtype 3 linecolor rgb 'gray50'"
    done
  done
  echo "unset multiplot"
} >"$tmp/plot.gp"
gnuplot "$tmp/plot.gp"
