#!/usr/bin/env bash
# The seeds' noise options (issue 44 items 3-4): --rotation two-vector|fast|well-behaved (seed 001) for 3D simplex
# noise on field and sample, and --steer-quality Q and --steer-image FILE (seed 002) for --noise steerable.
# - --rotation two-vector is the field without the option, byte for byte; fast and well-behaved differ from it and
#   from each other; a phase of pi flips every f_i for each;
# - --steer-quality 0 is the default, byte for byte, 2 changes the field; --steer-image reads a .npy (rows, columns, 2)
#   direction array and a PNG flow map; a uniform image along x is the constant direction (1, 0) to 1e-10;
# - bad values: one line, non-zero exit, nothing written.
set -u
source "$(dirname "${BASH_SOURCE[0]}")/harness.sh"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
cp "$here/../../data/points_3d_example.csv" "$work/points_3d.csv"
cd "$work" || exit 1
cut -d, -f1,2 points_3d.csv >points_2d.csv

s3=(field --input points_3d.csv --noise simplex)
"$bin" "${s3[@]}" --phase 0.7 -o plain.csv && "$bin" "${s3[@]}" --phase 0.7 --rotation two-vector -o two.csv && cmp -s plain.csv two.csv &&
  ok || bad "--rotation two-vector is not the default"
for r in fast well-behaved; do
  "$bin" "${s3[@]}" --phase 0.7 --rotation "$r" -o "$r.csv" && ! cmp -s plain.csv "$r.csv" && ok || bad "--rotation $r changed nothing"
  "$bin" "${s3[@]}" --rotation "$r" -o "${r}0.csv" && "$bin" "${s3[@]}" --rotation "$r" --phase 3.141592653589793 -o "${r}pi.csv" &&
    /usr/bin/python3 - "${r}0.csv" "${r}pi.csv" <<'PY' && ok || bad "--rotation $r: a phase of pi does not flip the f_i"
import sys, numpy as np
a, b = (np.loadtxt(f, delimiter=",", skiprows=1) for f in sys.argv[1:])
assert np.max(np.abs(a[:, 6:] + b[:, 6:])) < 1e-12 * max(1, np.max(np.abs(a[:, 6:])))
PY
done
! cmp -s fast.csv well-behaved.csv && ok || bad "fast and well-behaved are the same"
"$bin" --dim 3 --grid 4 --methods cnj --domain cube --noise simplex --rotation fast --phase 1 --no-stats --points - -q >cnj.csv &&
  [[ $(wc -l <cnj.csv) -gt 60 ]] && ok || bad "sample --rotation fast"

# ---- --steer-quality and --steer-image ----
st=(field --input points_2d.csv --noise steerable)
"$bin" "${st[@]}" --steer-dir 1,0 -o q.csv && "$bin" "${st[@]}" --steer-dir 1,0 --steer-quality 0 -o q0.csv && cmp -s q.csv q0.csv &&
  ok || bad "--steer-quality 0 is not the default"
"$bin" "${st[@]}" --steer-dir 1,0 --steer-quality 2 -o q2.csv && ! cmp -s q.csv q2.csv && ok || bad "--steer-quality 2 changed nothing"
"$bin" field --input points_3d.csv --noise steerable --steer-dir 1,0,0 --steer-quality 1 -o q3.csv && ok || bad "3D --steer-quality 1"
# Images: a uniform field along x as .npy (rows, columns, 2) and as a PNG flow map (R = 255, G = 128: (1, 0.004)); a
# uniform .npy image along x gives the constant direction's field to rounding.
/usr/bin/python3 - <<'PY' || bad "could not write the images"
import struct, zlib
import numpy as np
u = np.zeros((6, 9, 2)); u[..., 0] = 1.0
np.save("along_x.npy", u)
split = u.copy(); split[:, 5:, :] = [0.0, 1.0]
np.save("split.npy", split)
np.save("flat.npy", np.zeros((6, 9)))
def png(path, rgb):
    h, w, c = rgb.shape
    raw = b"".join(b"\x00" + rgb[i].astype(np.uint8).tobytes() for i in range(h))
    chunk = lambda t, d: struct.pack(">I", len(d)) + t + d + struct.pack(">I", zlib.crc32(t + d) & 0xffffffff)
    kind = {3: 2, 1: 0}[c]
    open(path, "wb").write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, kind, 0, 0, 0)) +
                          chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))
rgb = np.zeros((8, 8, 3)); rgb[..., 0] = 255; rgb[..., 1] = 128
png("along_x.png", rgb)
png("grey.png", np.full((8, 8, 1), 200))
PY
"$bin" "${st[@]}" --steer-image along_x.npy -o image.csv && /usr/bin/python3 - image.csv q.csv <<'PY' && ok || bad "a uniform image is not its direction"
import sys, numpy as np
a, b = (np.loadtxt(f, delimiter=",", skiprows=1) for f in sys.argv[1:])
assert np.max(np.abs(a - b)) < 1e-10 * max(1, np.max(np.abs(b))), np.max(np.abs(a - b))
PY
"$bin" "${st[@]}" --steer-image along_x.png -o png.csv && ok || bad "--steer-image PNG"
"$bin" "${st[@]}" --steer-image split.npy --steer-quality 1 -o split.csv && ! cmp -s image.csv split.csv && ok || bad "--steer-image split"
"$bin" --dim 2 --grid 5 --methods cnj --domain cube --noise steerable --steer-image split.npy --no-stats --points - -q >si.csv &&
  [[ $(wc -l <si.csv) -gt 20 ]] && ok || bad "sample --steer-image"

check_bad() {
  local name=$1 pattern=$2
  shift 2
  expect_error "$name" "" "$pattern" "$@" -o bad.csv
  [[ -e bad.csv ]] && bad "$name wrote bad.csv" || ok
  rm -f bad.csv
}
check_bad "unknown rotation" "rotation" "${s3[@]}" --rotation slow
check_bad "rotation of turning bands" "simplex in 3D" field --input points_3d.csv --rotation fast
check_bad "rotation in 2D" "3D only" field --input points_2d.csv --noise simplex --rotation well-behaved
check_bad "rotation with --time" "without --stretch, --time" "${s3[@]}" --rotation fast --time 1
check_bad "--steer-quality 3 in 2D" "steer-quality" "${st[@]}" --steer-dir 1,0 --steer-quality 3
check_bad "--steer-quality -1" "steer-quality" "${st[@]}" --steer-dir 1,0 --steer-quality -1
check_bad "--steer-image in 3D" "steers 2D noise" field --input points_3d.csv --noise steerable --steer-image along_x.npy
check_bad "--steer-image beside --steer-dir" "not both" "${st[@]}" --steer-dir 1,0 --steer-image along_x.npy
check_bad "--steer-image grey PNG" "grey PNG" "${st[@]}" --steer-image grey.png
check_bad "--steer-image 2D array" "shape \(rows, columns, 2\)|dimension|coordinates" "${st[@]}" --steer-image flat.npy
check_bad "--steer-image missing" "steer-image" "${st[@]}" --steer-image missing.npy
check_bad "--steer-image other file" "png flow map" "${st[@]}" --steer-image points_2d.csv
check_bad "--steer-quality without steerable" "steer --noise steerable" field --input points_2d.csv --steer-quality 1
finish cli_seeds_noise
