#!/usr/bin/env bash
# Issue 26 item 1, `--field curl` (Bridson's curl noise) on the command line: what it refuses (one line,
# non-zero exit, no output), that --field dfvn is today's field byte for byte, and that the curl field's
# diagnosis and CNJ run.
set -u
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
source "$here/harness.sh"
cd "$work" || exit 1
cp "$here/../../data/points_3d_example.csv" p3.csv
printf '0.1,0.2\n0.5,0.7\n0.9,0.4\n' >p2.csv
printf '0.1,0.2,0.3,0.4\n' >p4.csv

# --field dfvn is the default field: the same bytes (the default's own bytes are held by cli_reference).
"$bin" field --input p3.csv -o default.csv && "$bin" field --input p3.csv --field dfvn -o dfvn.csv &&
  cmp -s default.csv dfvn.csv && ok || bad "field --field dfvn differs from field"
"$bin" --dim 2 --grid 6 --methods cnj --no-timing -q -o s_default.csv &&
  "$bin" --dim 2 --grid 6 --methods cnj --no-timing -q --field dfvn -o s_dfvn.csv &&
  cmp -s s_default.csv s_dfvn.csv && ok || bad "sample --field dfvn differs from sample"

# Curl noise differs from dfvn in 3D, equals it in 2D (the 2D cross product is (d psi/dy, -d psi/dx)).
"$bin" field --input p3.csv --field curl -o curl3.csv && ! cmp -s curl3.csv dfvn.csv && ok ||
  bad "field --field curl in 3D is not a field of its own"
"$bin" field --input p2.csv --field curl -o curl2.csv && "$bin" field --input p2.csv -o dfvn2.csv &&
  cmp -s curl2.csv dfvn2.csv && ok || bad "2D curl noise is not the 2D dfvn field"
expect_finite curl curl3.csv curl2.csv

# The diagnosis: RMS |c| within 3% of 1, divergence median <= 1e-8 (10^4 points here; 10^5 in test_curl_field).
for noise in turning-bands simplex quintic-gradient; do
  for dim in 2 3; do
    "$bin" field --diagnose --field curl --dim "$dim" --noise "$noise" --diagnose-points 10000 -q -o d.csv ||
      bad "diagnose curl $noise ${dim}D failed"
    awk -F, 'NR == 2 { exit !($7 > 0.97 && $7 < 1.03 && $11 <= 1e-8 && $12 <= 1e-6) }' d.csv && ok ||
      bad "diagnose curl $noise ${dim}D: $(tail -1 d.csv)"
  done
done
"$bin" field --diagnose --field curl --dim 3 --domain torus --frequency 1.2 --diagnose-points 10000 -q -o t.csv &&
  awk -F, 'NR == 2 { exit !($7 > 0.97 && $7 < 1.03 && $19 == "torus") }' t.csv && ok || bad "curl on the torus: $(tail -1 t.csv)"

# CNJ along curl noise: no reprojection by default, on the torus and in drop mode.
"$bin" --dim 3 --grid 6 --methods cnj --field curl --no-timing -q -o c.csv && grep -q "curl noise field, no reprojection" c.csv &&
  ok || bad "sample --field curl on the torus"
"$bin" --dim 2 --grid 6 --methods cnj --field curl --domain cube --domain-mode drop --no-timing -q -o c.csv && ok ||
  bad "sample --field curl in drop mode"
"$bin" --dim 3 --grid 6 --methods cnj --field curl --reproject none --no-timing -q -o c2.csv &&
  "$bin" --dim 3 --grid 6 --methods cnj --field curl --no-timing -q -o c1.csv && cmp -s c1.csv c2.csv && ok ||
  bad "sample --field curl's default is not --reproject none"

# Refused, one line each.
expect_error field_4d "" "2D and 3D" field --input p4.csv --field curl -o never.csv
expect_error diagnose_4d "" "2D and 3D" field --diagnose --dim 4 --field curl
expect_error field_cube "" "bound ramp" field --input p3.csv --field curl --domain cube
expect_error field_ball "" "bound ramp" field --diagnose --field curl --domain ball
expect_error sample_4d "" "2D and 3D" --dim 4 --grid 4 --field curl -q
expect_error sample_newton "" "no reprojection" --dim 3 --grid 4 --field curl --reproject newton -q
expect_error sample_gauss_newton "" "no reprojection" --dim 2 --grid 4 --field curl --reproject gauss-newton -q
expect_error sample_cube "" "no boundary" --dim 3 --grid 4 --field curl --domain cube -q
expect_error sample_sphere "" "surface" --dim 3 --grid 4 --field curl --on sphere -q
expect_error unknown_field "" "field" field --input p3.csv --field bitangent

# Bridson's boundaries and obstacles (issue 26 item 2): accepted with --bound ramp; bad obstacles refused.
printf '0.5,0.5,0.5\n0.2,0.3,0.4\n' >pc.csv
"$bin" field --input pc.csv --field curl --domain cube --bound ramp --obstacle sphere:0.5,0.5,0.5,0.1 -o ob.csv && ok ||
  bad "field --field curl --domain cube --bound ramp --obstacle"
"$bin" field --input pc.csv --domain ball --obstacle sphere:0.5,0.5,0.5,0.1 --obstacle sphere:0.5,0.5,0.25,0.05 \
  --boundary-width 0.02 -o ob2.csv && ok || bad "field --domain ball with two obstacles"
expect_finite obstacles ob.csv ob2.csv
expect_error obstacle_outside "" "inside the cube" field --input pc.csv --domain cube --obstacle sphere:1.5,0.5,0.5,0.1 -o never.csv
expect_error obstacle_radius "" "radius must be positive" field --input pc.csv --domain cube --obstacle sphere:0.5,0.5,0.5,-0.1 -o never.csv
expect_error obstacle_zero "" "radius must be positive" field --input pc.csv --domain cube --obstacle sphere:0.5,0.5,0.5,0 -o never.csv
expect_error obstacle_nan "" "finite" field --input pc.csv --domain cube --obstacle sphere:nan,0.5,0.5,0.1 -o never.csv
expect_error obstacle_arity "" "centre coordinates" field --input pc.csv --domain cube --obstacle sphere:0.5,0.5,0.1 -o never.csv
expect_error obstacle_shape "" "sphere:CX" field --input pc.csv --domain cube --obstacle box:0.5,0.5,0.5,0.1 -o never.csv
expect_error obstacle_free "" "cube or ball" field --input pc.csv --obstacle sphere:0.5,0.5,0.5,0.1 -o never.csv
expect_error obstacle_overlap "" "closer than" field --input pc.csv --domain cube --obstacle sphere:0.4,0.5,0.5,0.1 \
  --obstacle sphere:0.6,0.5,0.5,0.1 -o never.csv
[[ ! -e never.csv ]] && ok || bad "a refused field wrote never.csv"

finish cli_curl
