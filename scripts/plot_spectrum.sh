#!/usr/bin/env bash
# Power spectrum figure: the periodogram (2D: the (k0, k1) plane; 3D: its k2 = 0 slice) on a log
# colour scale, and the radial average with the flat level 1 of uniform random points.
# Usage: scripts/plot_spectrum.sh PREFIX N   (reads PREFIX.csv and PREFIX_radial.csv, writes PREFIX.png)
set -euo pipefail
prefix=${1:?usage: plot_spectrum.sh PREFIX N}
dim=${2:?usage: plot_spectrum.sh PREFIX N}
command -v gnuplot >/dev/null || { echo "plot_spectrum.sh: gnuplot not found (apt-get install gnuplot-nox)" >&2; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
if [[ $dim -eq 3 ]]; then
  awk -F, 'NR > 1 && $3 == 0 { print $1, $2, ($4 > 1e-3 ? $4 : 1e-3) }' "$prefix.csv" >"$tmp/plane.dat"
  slice=" (k2 = 0 slice)"
else
  awk -F, 'NR > 1 { print $1, $2, ($3 > 1e-3 ? $3 : 1e-3) }' "$prefix.csv" >"$tmp/plane.dat"
  slice=""
fi
awk -F, 'NR > 1 { print $1, $2, $3 }' "$prefix""_radial.csv" >"$tmp/radial.dat"
cat >"$tmp/plot.gp" <<GP
set terminal pngcairo size 1300,560 font 'sans,10'
set output '$prefix.png'
set multiplot layout 1,2 title 'Power spectrum of ${dim}D points, averaged over the sets'
set title 'periodogram P(k)$slice, log colour scale'
set xlabel 'k0'; set ylabel 'k1'; set size ratio -1
set logscale cb; set cbrange [0.01:*]; set palette defined (0 'black', 1 '#1f3f9f', 2 '#d62728', 3 'yellow')
plot '$tmp/plane.dat' using 1:2:3 with image notitle
unset logscale cb; set size noratio
set title 'radial average and anisotropy'
set xlabel '|k|'; set ylabel 'P'; set y2label 'anisotropy (dB)'; set ytics nomirror; set y2tics; set grid
plot '$tmp/radial.dat' using 1:2 with lines linewidth 2 linecolor rgb '#1f5fbf' title 'radial mean', \
     1 with lines dashtype 3 linecolor rgb 'gray40' title 'random = 1', \
     '$tmp/radial.dat' using 1:3 axes x1y2 with lines linecolor rgb '#d62728' title 'anisotropy (dB)'
unset multiplot
GP
gnuplot "$tmp/plot.gp"
