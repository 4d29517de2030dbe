#!/usr/bin/env bash
# Integration error figures: for each dimension N, DIR/integration_<N>d.png with one log-log panel per
# Genz family: RMS relative error (with its standard error) against the number of points, per method,
# and the Monte Carlo rate n^-1/2 as a dotted guide.
# Usage: scripts/plot_integration.sh DIR   (reads DIR/integration.csv)
set -euo pipefail
dir=${1:?usage: plot_integration.sh DIR}
command -v gnuplot >/dev/null || { echo "plot_integration.sh: gnuplot not found (apt-get install gnuplot-nox)" >&2; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

csv="$dir/integration.csv"
dims=$(awk -F, 'NR > 1 { print $1 }' "$csv" | sort -un | tr '\n' ' ')
families="oscillatory product_peak corner_peak gaussian continuous discontinuous"
methods=$(awk -F, 'NR > 1 && !seen[$3]++ { print $3 }' "$csv" | tr '\n' ' ')
declare -A colour=([cnj]='#d62728' [jitter]='#1f77b4' [pds]='#2ca02c' [sobol]='#9467bd' [random]='#7f7f7f'
                   [halton]='#ff7f0e' [lhs]='#8c564b')
for d in $dims; do
  {
    echo "set terminal pngcairo size 1500,900 font 'sans,9'"
    echo "set output '$dir/integration_${d}d.png'"
    echo "set multiplot layout 2,3 title '${d}D: RMS relative integration error over realizations (bars: standard error); dotted: n^{-1/2}'"
    echo "set logscale xy; set grid; set format y '10^{%L}'; set xlabel 'points'; set ylabel 'RMS relative error'"
    echo "set key bottom left font 'sans,8'"
    for f in $families; do
      plots=()
      for m in $methods; do
        awk -F, -v d="$d" -v f="$f" -v m="$m" 'NR > 1 && $1 == d && $2 == f && $3 == m { print $5, $6, $7 }' "$csv" >"$tmp/$d-$f-$m.dat"
        plots+=("'$tmp/$d-$f-$m.dat' using 1:2:3 with yerrorlines title '$m' linecolor rgb '${colour[$m]:-black}' linewidth 1.5 pointtype 7 pointsize 0.6")
      done
      # The n^-1/2 guide through random's first point.
      first=$(awk 'NR == 1 { print $1, $2 }' "$tmp/$d-$f-random.dat" 2>/dev/null || true)
      if [[ -n $first ]]; then
        read -r n0 e0 <<<"$first"
        plots+=("$e0 * ($n0 / x) ** 0.5 with lines dashtype 3 linecolor rgb 'gray40' notitle")
      fi
      echo "set title '$f' noenhanced"
      (IFS=,; echo "plot ${plots[*]}")
    done
    echo "unset multiplot"
  } >"$tmp/plot-$d.gp"
  gnuplot "$tmp/plot-$d.gp"
done
