# Figure 5 (Table 2): labelled montage of the image-warping reproduction. Top row: the original and the
# warp at the figure times (1000 RK4 steps each); second and third rows: t = 0.5 with 64 and 512 steps,
# Euler and RK4, without and with one reprojection step. Compiled into dfvn-sample
# (src/plot/gnuplot.hpp), which runs it as
#   gnuplot -c figure5.gp OUT.png DIR WIDTH HEIGHT TIMES RMSE SETTINGS
# DIR: the folder of the PNG images (source.png, time-<t>.png, euler-64.png, ...). WIDTH, HEIGHT: their
# size in pixels. TIMES: up to three figure times as they appear in the file names ("0.05 0.2 0.5").
# RMSE: the eight bottom panels' RMSE as printed, in the order of `variants`. SETTINGS: the noise,
# frequency, speed, time, seed and size, for the title.
array variants[4] = ["euler-%d.png", "euler-%d-newton1.png", "rk4-%d.png", "rk4-%d-newton1.png"]
array labels[4] = ["t = 0.5: Euler %d", "Euler %d + reprojection", "RK4 %d", "RK4 %d + reprojection"]
dir = ARG2
tile_w = 360
tile_h = tile_w * int(ARG4) / int(ARG3) + 40
set terminal pngcairo size 4 * tile_w, 3 * tile_h + 50 font 'sans,10'
set output ARG1
set multiplot layout 3, 4 title "Figure 5: an image warped along 2D DFVN (RMSE against 2048 RK4 steps, 8-bit units, from float values)\n".ARG7 noenhanced
unset key; unset tics; unset border; unset colorbox
set size ratio -1
set margins 1, 1, 1, 3
set title 'original' noenhanced
plot dir.'/source.png' binary filetype=png with rgbimage
times = words(ARG5) < 3 ? words(ARG5) : 3
do for [i = 1:times] {
  set title sprintf('t = %s (RK4, 1000 steps)', word(ARG5, i)) noenhanced
  plot dir.'/time-'.word(ARG5, i).'.png' binary filetype=png with rgbimage
}
do for [i = times + 1:3] { set multiplot next }
do for [row = 1:2] {
  steps = row == 1 ? 64 : 512
  do for [col = 1:4] {
    set title sprintf(labels[col], steps).' (RMSE '.word(ARG6, 4 * (row - 1) + col).')' noenhanced
    plot dir.'/'.sprintf(variants[col], steps) binary filetype=png with rgbimage
  }
}
unset multiplot
