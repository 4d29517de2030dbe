#!/usr/bin/env bash
# Figure 5: labelled montage of the Table 2 reproduction. Top row: the original and the warp at the times
# of DIR/timeline.csv (1000 RK4 steps each); second and third rows: t = 0.5 with 64 and 512 steps.
# Usage: scripts/plot_figure5.sh DIR   (reads DIR/*.png, DIR/table2.csv and DIR/timeline.csv, writes DIR/figure5.png)
set -euo pipefail
dir=${1:?usage: plot_figure5.sh DIR}
command -v gnuplot >/dev/null || { echo "plot_figure5.sh: gnuplot not found (apt-get install gnuplot-nox)" >&2; exit 1; }
read -r width height < <(awk -F, 'NR == 2 { print $7, $8 }' "$dir/table2.csv")
rmse() { awk -F, -v i="$1" -v s="$2" -v r="$3" 'NR > 1 && $1 == i && $2 == s && $3 == r { printf "%.4g", $4 }' "$dir/table2.csv"; }
panel() {  # file title
  echo "set title \"$2\""
  echo "plot '$dir/$1' binary filetype=png with rgbimage"
}
tile_w=360
tile_h=$((tile_w * height / width + 40))
{
  echo "set terminal pngcairo size $((4 * tile_w)),$((3 * tile_h + 30)) font 'sans,10'"
  echo "set output '$dir/figure5.png'"
  echo "set multiplot layout 3,4 title 'Image warping along 2D DFVN (RMSE against 2048 RK4 steps, 8-bit units, from float values)'"
  echo "unset key; unset tics; unset border; unset colorbox; set size ratio -1; set margins 1,1,1,3"
  panel source.png "original"
  shown=1
  while IFS=, read -r time steps file; do
    [[ $time == time ]] && continue
    ((shown < 4)) || break
    panel "$file" "t = $time (RK4, $steps steps)"
    shown=$((shown + 1))
  done < "$dir/timeline.csv"
  for ((; shown < 4; shown++)); do echo "set multiplot next"; done
  for steps in 64 512; do
    panel "euler-$steps.png" "t = 0.5: Euler $steps (RMSE $(rmse euler $steps 0))"
    panel "euler-$steps-newton1.png" "Euler $steps + reprojection (RMSE $(rmse euler $steps 1))"
    panel "rk4-$steps.png" "RK4 $steps (RMSE $(rmse rk4 $steps 0))"
    panel "rk4-$steps-newton1.png" "RK4 $steps + reprojection (RMSE $(rmse rk4 $steps 1))"
  done
  echo "unset multiplot"
} | gnuplot
