#!/usr/bin/env bash
# --phase (issue 25 item 1, rotating gradients) on field and sample:
# - --phase 0 gives the output recorded before phases existed, byte for byte (cmp against
#   tests/cli/reference/, the files of test_cli_reference.sh's runs with the same arguments);
# - a phase other than 0 changes the output, alpha + 2 pi gives it back to ~1e-12 and alpha + pi flips
#   every noise value (field's f columns);
# - a non-finite or non-numeric phase: one line, non-zero exit, no output file.
set -u
source "$(dirname "${BASH_SOURCE[0]}")/harness.sh"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
cp "$here/../../data/points_3d_example.csv" "$work/points_3d.csv"
cd "$work" || exit 1

# field: free (turning bands), simplex from standard input, the cube, the torus, the diagnosis.
"$bin" field --input points_3d.csv -o field.csv --phase 0 && same_as_recorded "field --phase 0" field.csv field.csv
"$bin" field --frequency 2 --noise simplex --phase 0 <points_3d.csv >stdin.csv && same_as_recorded "simplex --phase 0" stdin.csv field_stdin.stdout
"$bin" field --input points_3d.csv --domain cube --bound eq13 --boundary-width 0.2 --phase -0.0 >cube.csv &&
  same_as_recorded "cube --phase -0.0" cube.csv field_cube.stdout
"$bin" field --input points_3d.csv --domain torus --frequency 3 --phase 0 >torus.csv && same_as_recorded "torus --phase 0" torus.csv field_torus.stdout
"$bin" field --diagnose --diagnose-points 2000 --dim 4 --phase 0 >diagnose.csv && same_as_recorded "diagnose --phase 0" diagnose.csv field_diagnose.stdout
# sample: the 2D main job (statistics and JSON), the ball with simplex, CNJ's points on standard output.
"$bin" --dim 2 --grid 8 --realizations 3 --no-timing -q -o main_2d.csv --json main_2d.json --phase 0 &&
  same_as_recorded "sample --phase 0" main_2d.csv main_2d.csv && same_as_recorded "sample --phase 0 json" main_2d.json main_2d.json
"$bin" --dim 3 --grid 6 --domain ball --bound ramp --methods cnj --noise simplex --no-timing -q --phase 0 >ball.csv &&
  same_as_recorded "sample ball --phase 0" ball.csv main_ball.stdout
"$bin" --dim 2 --grid 5 --methods cnj --no-stats --points - -q --phase 0 >points.csv && same_as_recorded "sample points --phase 0" points.csv main_stdout.stdout

# The sphere's CNJ takes the phase too.
"$bin" sample --dim 3 --grid 6 --on sphere --no-timing -q --phase 0 >sphere.csv && same_as_recorded "sphere --phase 0" sphere.csv main_sphere.stdout
"$bin" sample --dim 3 --grid 6 --on sphere --no-timing -q --phase 1 >sphere_1.csv
mkdir -p moved && cp sphere_1.csv moved/main_sphere.stdout
if cmp -s <(normalise_times moved/main_sphere.stdout) "$recorded/main_sphere.stdout"; then bad "sample --on sphere --phase 1 changed nothing"; else ok; fi

# A phase moves the points and the field; 2 pi later they are back, pi later the f_i change sign.
"$bin" --dim 2 --grid 5 --methods cnj --no-stats --points - -q --phase 1 >points_1.csv
if cmp -s points_1.csv points.csv; then bad "sample --phase 1 did not move the points"; else ok; fi
for domain in free torus cube; do
  for noise in turning-bands simplex quintic-gradient; do
    [[ $domain == torus && $noise != turning-bands ]] && continue
    for a in 1 7.283185307179586 4.141592653589793; do  # 1, 1 + 2 pi, 1 + pi
      "$bin" field --input points_3d.csv --domain $domain --noise $noise --phase $a -o "f_${domain}_${noise}_$a.csv" || bad "field --phase $a"
    done
    /usr/bin/python3 - "f_${domain}_${noise}_1.csv" "f_${domain}_${noise}_7.283185307179586.csv" \
      "f_${domain}_${noise}_4.141592653589793.csv" field.csv "$domain" <<'PY' && ok || bad "field $domain $noise: period or sign"
import sys
import numpy as np
a, turned, flipped, zero = (np.loadtxt(p, delimiter=",", skiprows=1) for p in sys.argv[1:5])
f = slice(6, 8)  # f1, f2 of 3D points: x0..x2, c0..c2, f1, f2
assert np.max(np.abs(a - turned)) < 1e-12, np.max(np.abs(a - turned))
if sys.argv[5] != "cube":  # the cube's f_1 is the boundary function, which no phase flips
    assert np.max(np.abs(a[:, f] + flipped[:, f])) < 1e-12, np.max(np.abs(a[:, f] + flipped[:, f]))
assert np.max(np.abs(a[:, 3:] - zero[:, 3:])) > 1e-3  # the phase did something
PY
  done
done

# Bad input: one line, non-zero exit, no output file.
for bad_phase in nan inf -inf 1e999 abc ""; do
  expect_error "phase '$bad_phase'" "" "--phase.*must be a finite number of radians" field --input points_3d.csv --phase "$bad_phase" -o bad.csv
  [[ -e bad.csv ]] && bad "field --phase '$bad_phase' wrote bad.csv" || ok
  expect_error "sample phase '$bad_phase'" "" "--phase.*must be a finite number of radians" --dim 2 --grid 4 -q -o bad.csv --phase "$bad_phase"
  [[ -e bad.csv ]] && bad "sample --phase '$bad_phase' wrote bad.csv" || ok
done
finish cli_phase
