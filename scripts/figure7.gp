# Figure 7 (Section 5.4): a ring pattern warped inside the disc of radius 1/2, as one titled montage. Top
# row: the source pattern, the warp along the field bounded by Eq. 13 and along the paper's own
# construction; bottom: the 3D half, the central slices of the unit cube through the ball of radius 1/2.
# Compiled into dfvn-sample (dfvn/plot/gnuplot.hpp), which runs it as
#   gnuplot -c figure7.gp OUT.png DIR SIDE SIDE3D SETTINGS LEFT
# DIR: the folder of source.png, warped.png, warped_paper.png and slices_3d.png (its 3 x 3 tiles of SIDE3D
# pixels with 2-pixel gaps). SIDE: the 2D images' side. SETTINGS: the settings for the title. LEFT: the
# traces that left the disc, eq13 and paper ("0 0").
dir = ARG2
side = int(ARG3)
s3 = int(ARG4)
m3 = 3 * s3 + 4
set terminal pngcairo size 1500, 1120 font 'sans,11'
set output ARG1
set multiplot title "Figure 7: a ring pattern warped along 2D DFVN confined to the disc of radius 1/2, and its 3D half\n".ARG5 font 'sans,14'
unset key; unset colorbox
set size ratio -1
set lmargin 1; set rmargin 1; set tmargin 2; set bmargin 1
unset tics; unset border
array files[3] = ["source.png", "warped.png", "warped_paper.png"]
array titles[3] = ["the source pattern (t = 0)", "warped, Eq. 13 bound + reprojection", "warped, the paper's construction (RK4 only)"]
do for [i = 1:3] {
  set origin (i - 1) / 3.0, 0.47
  set size 1 / 3.0, 0.46
  set title titles[i].(i > 1 ? sprintf("\n%s traces left the disc", word(ARG6, i - 1)) : "\n") noenhanced
  plot dir.'/'.files[i] binary filetype=png with rgbimage
}
set origin 0.2, 0.0
set size 0.6, 0.46
set border
set tics scale 0 font 'sans,11'
set xtics ("slice z = 1/2" s3 / 2.0, "slice y = 1/2" m3 / 2.0, "slice x = 1/2" m3 - s3 / 2.0) offset 0, 0.5
set ytics ("source" m3 - s3 / 2.0, "Eq. 13" m3 / 2.0, "paper" s3 / 2.0) rotate by 90 center offset 0.5, 0
set lmargin 4; set bmargin 2
set title "3D: the ball of radius 1/2 (dark shell just inside its sphere), central slices of the unit cube" noenhanced
plot dir.'/slices_3d.png' binary filetype=png with rgbimage
unset multiplot
