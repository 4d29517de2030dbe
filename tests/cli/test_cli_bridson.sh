#!/usr/bin/env bash
# Bridson et al. 2007's toolbox on field and sample (issue 44 item 1): --octaves, --octave-gain, --amplitude,
# --viscous, --body and --vortex.
# - checked from outside by central differences of `field` output (tests/cli/bridson_check.py): with octaves,
#   bodies, vortices, amplitude and viscous walls the median |div c| is below 1e-5 of RMS |c| (curl noise in
#   3D, DFVN in 2D and 4D); on a moving body's surface |(c - V - W x (x - x0)) . n| < 1e-8; c = 0 on viscous
#   walls and obstacles; c . n = 0 on inviscid ones;
# - --octaves 1 is the field without it, byte for byte; --octaves 2, a gain, an amplitude change it;
# - sample takes them (CNJ along the octaved field);
# - bad values: one line, non-zero exit, nothing written.
set -u
source "$(dirname "${BASH_SOURCE[0]}")/harness.sh"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
cp "$here/../../data/points_3d_example.csv" "$work/points_3d.csv"
cd "$work" || exit 1
check() { /usr/bin/python3 "$here/bridson_check.py" "$bin" "$@"; }

solids=(--field curl --domain cube --bound ramp --boundary-width 0.05 --octaves 3
  --body sphere:0.5,0.5,0.55,0.08,0.3,0,0.5,0,0,2 --vortex ring:0.5,0.5,0.2,0,0,1,0.15,3,0.05
  --vortex particle:0.2,0.2,0.8,0,1,0,0.1 --obstacle sphere:0.25,0.75,0.5,0.06)
curl=("${solids[@]}" --amplitude obstacles:0.45 --amplitude height:-0.5,1.5)
for viscous in "" --viscous; do
  out=$(check divergence 3 "${curl[@]}" $viscous) && ok || bad "curl divergence $viscous: $out"
  out=$(check body 0.5,0.5,0.55 0.08 0.3,0,0.5 0,0,2 "${curl[@]}" $viscous) && ok || bad "moving body $viscous: $out"
  out=$(check obstacle 0.25,0.75,0.5 0.06 "${curl[@]}" $viscous) && ok || bad "static obstacle $viscous: $out"
done
out=$(check wall 3 "${solids[@]}") && ok || bad "curl walls (slip): $out"
out=$(check wall 3 "${solids[@]}" --viscous) && ok || bad "curl viscous walls: $out"
for n in 2 4; do
  dfvn=(--domain cube --octaves 3 --octave-gain 0.6 --amplitude height:-0.5,1.2 --obstacle "sphere:$(printf '0.5,%.0s' $(seq "$n"))0.12")
  out=$(check divergence "$n" "${dfvn[@]}" --viscous) && ok || bad "dfvn ${n}D divergence: $out"
  out=$(check wall "$n" "${dfvn[@]}" --viscous) && ok || bad "dfvn ${n}D viscous walls: $out"
done

"$bin" field --input points_3d.csv -o plain.csv && "$bin" field --input points_3d.csv --octaves 1 -o one.csv && cmp -s plain.csv one.csv &&
  ok || bad "--octaves 1 is not the field without octaves"
"$bin" field --input points_3d.csv --octaves 2 -o two.csv && ! cmp -s plain.csv two.csv && ok || bad "--octaves 2 changed nothing"
"$bin" field --input points_3d.csv --octaves 2 --octave-gain 0.5 -o gain.csv && ! cmp -s two.csv gain.csv && ok ||
  bad "--octave-gain changed nothing"
"$bin" field --input points_3d.csv --amplitude constant:2 -o twice.csv && ! cmp -s plain.csv twice.csv && ok || bad "--amplitude changed nothing"
"$bin" --dim 3 --grid 5 --methods cnj --domain cube --bound ramp --octaves 2 --amplitude height:0,1 --viscous --no-stats --points - -q \
  >cnj.csv && [[ $(wc -l <cnj.csv) -gt 100 ]] && ok || bad "sample with the toolbox"
"$bin" --dim 3 --grid 5 --methods cnj --domain cube --no-stats --points - -q >cnj0.csv && ! cmp -s cnj.csv cnj0.csv && ok ||
  bad "sample: the toolbox changed nothing"

check_bad() {
  local name=$1 pattern=$2
  shift 2
  expect_error "$name" "" "$pattern" "$@" -o bad.csv
  [[ -e bad.csv ]] && bad "$name wrote bad.csv" || ok
  rm -f bad.csv
}
f3=(field --input points_3d.csv)
check_bad "--octaves 0" "octaves" "${f3[@]}" --octaves 0
check_bad "--octaves 11" "octaves" "${f3[@]}" --octaves 11
check_bad "--octave-gain 0" "octave-gain" "${f3[@]}" --octave-gain 0
check_bad "--octave-gain nan" "octave-gain" "${f3[@]}" --octave-gain nan
check_bad "amplitude shape" "amplitude 'wake:1'" "${f3[@]}" --amplitude wake:1
check_bad "amplitude Z0 = Z1" "must differ" "${f3[@]}" --amplitude height:1,1
check_bad "amplitude without obstacles" "needs an --obstacle or a --body" "${f3[@]}" --domain cube --amplitude obstacles:0.2
check_bad "viscous in free space" "viscous" "${f3[@]}" --viscous
check_bad "body for dfvn" "curl in 3D" "${f3[@]}" --domain cube --body sphere:0.5,0.5,0.5,0.1,1,0,0,0,0,0
check_bad "body in free space" "needs --domain cube or ball" "${f3[@]}" --field curl --body sphere:0.5,0.5,0.5,0.1,1,0,0,0,0,0
check_bad "body too near the wall" "blend region" "${f3[@]}" --field curl --domain cube --bound ramp --body sphere:0.5,0.5,0.2,0.1,1,0,0,0,0,0
check_bad "body arity" "10 numbers" "${f3[@]}" --field curl --domain cube --bound ramp --body sphere:0.5,0.5,0.5,0.1
check_bad "vortex kind" "particle:CX" "${f3[@]}" --field curl --vortex line:0,0,0
check_bad "vortex core beyond the ring" "below the ring radius" "${f3[@]}" --field curl --vortex ring:0,0,0,0,0,1,0.1,1,0.2
check_bad "vortex not a number" "not a number" "${f3[@]}" --field curl --vortex particle:0,0,x,0,0,1,0.1
check_bad "torus amplitude" "torus takes --octaves only" "${f3[@]}" --domain torus --amplitude constant:2
check_bad "sample: vortex for dfvn" "curl in 3D" --dim 3 --grid 3 --methods cnj --domain cube --vortex particle:0.5,0.5,0.5,0,0,1,0.1
finish cli_bridson
