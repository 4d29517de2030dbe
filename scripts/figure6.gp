# Figure 6 (Section 5.3): a texture warped on the unit sphere, as one titled montage. Top row: the source
# and the warp at increasing t (projected RK4); bottom row: the error of each compared setting against
# the reference on one log scale (the largest error of any setting white, five decades below it black),
# so that what projection removes is visible. Compiled into dfvn-sample (dfvn/plot/gnuplot.hpp), which runs it as
#   gnuplot -c figure6.gp OUT.png DIR WIDTH HEIGHT TIMES RMSE LARGEST SETTINGS
# DIR: the folder of source.png, time-<t>.png and error-<setting>.png (equirectangular maps, longitude
# across, latitude down). WIDTH, HEIGHT: their size in pixels. TIMES: the three times of the top row.
# RMSE: the four settings' RMSE (rk4-32, rk4-32-projected, rk4-128, rk4-128-projected). LARGEST: the
# largest error, white in every error map (grey levels). SETTINGS: the noise, frequency, seed and size, for the title.
array settings[4] = ["rk4-32", "rk4-32-projected", "rk4-128", "rk4-128-projected"]
array labels[4] = ["RK4, 32 steps, no projection", "RK4, 32 steps, projected", "RK4, 128 steps, no projection", \
                   "RK4, 128 steps, projected"]
dir = ARG2
tile_w = 480
tile_h = tile_w * int(ARG4) / int(ARG3) + 56
set terminal pngcairo size 4 * tile_w, 2 * tile_h + 70 font 'sans,11'
set output ARG1
set multiplot layout 2, 4 title "Figure 6: a texture warped on the unit sphere along the tangent 3D DFVN field\n".ARG8 font 'sans,14'
unset key; unset tics; unset border; unset colorbox
set size ratio -1
set margins 1, 1, 1, 4
set title "t = 0: the source texture" noenhanced
plot dir.'/source.png' binary filetype=png with rgbimage
do for [i = 1:3] {
  set title sprintf("t = %s (RK4, projected)", word(ARG5, i)) noenhanced
  plot dir.'/time-'.word(ARG5, i).'.png' binary filetype=png with rgbimage
}
do for [i = 1:4] {
  set title sprintf("%s: RMSE %s grey levels\n|error|, log scale from 1e-5 x %s (black) to %s (white)", labels[i], word(ARG6, i), ARG7, ARG7) noenhanced
  plot dir.'/error-'.settings[i].'.png' binary filetype=png with rgbimage
}
unset multiplot
