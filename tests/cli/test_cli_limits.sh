#!/usr/bin/env bash
# Issue 40 items 3-6 against the real binary ($DFVN_SAMPLE), one section per class; every check failed on
# main 9f7cabe: --stream's temporary space and its cleanup on signals; extreme parameters computed or
# refused with their range (nothing written holds NaN or Inf, no move reported that did not happen); the
# documented limits enforced; one-line messages quoting once, numbers with %g, and the exit codes
# (2: the command line, 1: the data or the run).
set -u
source "$(dirname "${BASH_SOURCE[0]}")/harness.sh"

# csv_column FILE COLUMN: the column of the first data row of a CSV.
csv_column() { /usr/bin/python3 -c 'import csv, sys; print(next(csv.DictReader(open(sys.argv[1])))[sys.argv[2]])' "$1" "$2"; }

# ---------------------------------------------------------------------------------------------------
# --stream: the temporary bytes are estimated and refused up front when $TMPDIR cannot hold them.
mkdir -p "$work/tmp"
export TMPDIR=$work/tmp
expect_error "stream 2^40 points" "" '--stream needs about [0-9.]+ TiB of temporary files in \$TMPDIR .*which has [0-9.]+ [KMGTP]?i?B free' \
  --dim 2 -n 1099511627776 --methods jitter --stream --points "$work/never"
[[ ! -e $work/never && -z $(ls "$work/tmp") ]] && ok || bad "stream 2^40 points: wrote $(ls "$work" "$work/tmp")"
# The automatic switch to streaming says both: the memory the sets need and the space streaming needs
# (--max-memory 64: 8 GiB slabs fit it on any host, 2^38 points in memory do not).
expect_error "automatic stream 2^38 points" "" 'the point sets need about .* of memory \(limit 64\.0 GiB\), and --stream needs about .* free' \
  --dim 3 -n 274877906944 --methods random --max-memory 64
TMPDIR=$work/no-such-folder expect_error "TMPDIR missing" "" "\\\$TMPDIR, and '.*no-such-folder' is not a directory" \
  --dim 2 --grid 8 --methods jitter --stream
# A real small $TMPDIR: a 1 MiB tmpfs in a user and mount namespace, where the system allows them.
if unshare --user --map-root-user --mount true 2>/dev/null; then
  mkdir -p "$work/small"
  small_run() {
    unshare --user --map-root-user --mount bash -c 'mount -t tmpfs -o size=1m tmpfs "$1" && shift && TMPDIR=$0 "$@"' \
      "$work/small" "$work/small" "$bin" "$@"
  }
  # 65536 points x (N + 5) x 8 bytes = 3.5 MiB of temporaries: refused, naming the 1 MiB free.
  small_run --dim 2 --grid 256 --methods jitter --stream -q -o "$work/small.csv" >"$work/out" 2>"$work/err"
  [[ $? -eq 1 && $(wc -l <"$work/err") -eq 1 ]] && grep -Eq 'needs about 3.50 MiB .*which has 1.00 MiB free' "$work/err" && ok ||
    bad "stream into a 1 MiB TMPDIR: $(cat "$work/err")"
  [[ ! -e $work/small.csv ]] && ok || bad "stream into a 1 MiB TMPDIR wrote its statistics"
  small_run --dim 2 --grid 64 --methods jitter --stream -q -o "$work/fits.csv" 2>"$work/err" && [[ -s $work/fits.csv ]] && ok ||
    bad "stream of 224 KiB into a 1 MiB TMPDIR: $(cat "$work/err")"
else
  echo "no user namespaces here: the 1 MiB tmpfs case is skipped (the 2^40-point case above stands)"
fi
# More buckets than the process may open files: refused naming the limit, not "cannot create .../bucket9998".
(ulimit -n 64 && "$bin" --dim 2 --grid 64 --methods jitter --stream --slabs 64 -q >"$work/out" 2>"$work/err")
[[ $? -eq 1 ]] && grep -q 'more than this process may open (64, ulimit -n): give fewer --slabs' "$work/err" && ok ||
  bad "stream with more buckets than open files: $(cat "$work/err")"

# SIGINT, SIGTERM and SIGHUP at any moment while --stream creates its 4096 bucket files: the bucket folder
# goes whole (it was left with hundreds of files). set -m: a background job's SIGINT is not ignored.
for signal in INT TERM HUP; do
  for delay in 0.01 0.03 0.06 0.1 0.2; do
    rm -rf "$work/tmp" && mkdir "$work/tmp"
    (
      exec 2>/dev/null  # the job-control notices
      set -m
      "$bin" --dim 2 -n 4194304 --methods jitter --stream --slabs 2048 -q -o "$work/sig.csv" 2>/dev/null &
      pid=$!
      sleep "$delay"
      kill -s "$signal" "$pid" 2>/dev/null
      wait "$pid"
      echo $? >"$work/status"
    )
    status=$(cat "$work/status")
    left=$(find "$work/tmp" -mindepth 1 | head -3)
    if [[ -z $left && ($status -ge 128 || $status -eq 0) ]]; then ok; else bad "SIG$signal after $delay s: status $status, left $left"; fi
  done
done
unset TMPDIR

# ---------------------------------------------------------------------------------------------------
# Extreme parameters: computed correctly or refused with the allowed range.
# An obstacle of radius 1e-310 (and the smallest double): finite at its very centre, in every dimension.
for n in 2 3 5 8; do
  centre=$(printf '0.5,%.0s' $(seq 1 "$n"))
  centre=${centre%,}
  printf '%s\n%s\n' "$centre" "$(printf '0.25,%.0s' $(seq 1 "$n") | sed 's/,$//')" >"$work/centre$n.csv"
  for r in 1e-310 5e-324; do
    "$bin" field --dim "$n" --domain cube --input "$work/centre$n.csv" --obstacle "sphere:$centre,$r" -o "$work/obstacle$n-$r.csv" \
      2>"$work/err" && ok || bad "obstacle $r ${n}D: $(cat "$work/err")"
    expect_finite "obstacle $r ${n}D" "$work/obstacle$n-$r.csv"
  done
done
"$bin" field --dim 3 --domain cube --field curl --bound ramp --input "$work/centre3.csv" --obstacle sphere:0.5,0.5,0.5,1e-310 \
  -o "$work/curl-obstacle.csv" 2>"$work/err" && ok || bad "curl obstacle 1e-310: $(cat "$work/err")"
expect_finite "curl obstacle 1e-310" "$work/curl-obstacle.csv"
# The lift's ramp and slopes: at most 2^50; everything within is finite.
printf '0,0\n0.1,0.1\n0.5,0.5\n' >"$work/lift.csv"
expect_error "lift ramp 1e308" "" '--lift-ramp must be in \[-2\^50, 2\^50\] = \[-1\.1259e\+15, 1\.1259e\+15\], got 1e\+308' \
  field --input "$work/lift.csv" --lift plane:1,0 --lift-ramp 1e308
expect_error "lift ramp 1e20 in sample" "" '--lift-ramp must be in \[-2\^50, 2\^50\]' \
  --dim 2 --grid 8 --methods cnj --domain cube --lift plane:1,0.5 --lift-ramp 1e20
expect_error "lift bump of radius 1e-310" "" "--lift bump:H,R .*steepest slope is beyond the largest double, above 2\^50" \
  field --input "$work/lift.csv" --lift bump:1,1e-310
expect_error "lift plane slope 1e300" "" "--lift plane:SX,SY: the height's steepest slope is 1e\+300, above 2\^50" \
  field --input "$work/lift.csv" --lift plane:1e300,0
/usr/bin/python3 -c 'import numpy; numpy.save("'"$work"'/steep.npy", numpy.array([[0.0, 1e300], [0.0, 0.0]]))'
expect_error "lift npy of steep heights" "" "--lift npy: the height's steepest slope is .*above 2\^50" \
  field --input "$work/lift.csv" --lift "npy:$work/steep.npy"
"$bin" field --input "$work/lift.csv" --lift plane:1e15,0 --lift-ramp -1125899906842624 -o "$work/lift-edge.csv" 2>"$work/err" &&
  ok || bad "lift at its limits: $(cat "$work/err")"
expect_finite "lift at its limits" "$work/lift-edge.csv"
# A CNJ trace whose steps leave the noise domain (speed 1e29) stops at its edge: its point did not move,
# and the counters say so (they said 0 kept, 0 retraced, 0 dropped for points that never moved).
"$bin" --dim 2 --grid 8 --methods cnj --domain cube --lift plane:1e14,0.5 --lift-ramp 1e15 -q -o "$work/edge.csv" 2>"$work/err" &&
  ok || bad "CNJ at the noise domain's edge: $(cat "$work/err")"
if [[ -s $work/edge.csv ]]; then
  [[ $(csv_column "$work/edge.csv" frac_unmoved) == 1.0 && $(csv_column "$work/edge.csv" kept_at_site) == 64 ]] && ok ||
    bad "CNJ at the noise domain's edge: frac_unmoved $(csv_column "$work/edge.csv" frac_unmoved), kept_at_site $(csv_column "$work/edge.csv" kept_at_site)"
fi
expect_error "CNJ at the noise domain's edge, drop mode" "" "the cnj point set has 0 point\(s\) \(64 dropped\)" \
  --dim 2 --grid 8 --methods cnj --domain-mode drop --lift plane:1e14,0.5 --lift-ramp 1e15
# animate --phase 1e17: the frames' phases advance (1e17 + 0.05 was 1e17) and the particles move.
"$bin" animate --grid 4 --frames 4 --phase 1e17 -q --out "$work/phase" >"$work/phase.txt" 2>"$work/err" && ok ||
  bad "animate --phase 1e17: $(cat "$work/err")"
/usr/bin/python3 - "$work/phase/frames.csv" <<'EOF' && ok || bad "animate --phase 1e17: the phase does not advance"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
phases = [float(r["phase"]) for r in rows]
moves = [float(r["rms_move"]) for r in rows[1:]]
steps = [b - a for a, b in zip(phases, phases[1:])]
sys.exit(0 if all(abs(s - 0.05) < 1e-12 for s in steps) and all(m > 0 for m in moves) else 1)
EOF
grep -q "phase 1e+17 (.* modulo 2 pi) + k \* 0.05 rad" "$work/phase.txt" && ok || bad "animate --phase 1e17 summary: $(head -1 "$work/phase.txt")"
expect_error "animate phase step 1e-310" "" 'phase step must be in \[2\^-30, 2 pi\] = \[9\.31323e-10, 6\.28319\] radians per frame, got 1e-310' \
  animate --grid 4 --frames 2 --phase-step 1e-310 --out "$work/never"
# stats --periodic in a box of side 1e300 around points of [0, 1]: the two scales went back and forth for
# ever (a stack overflow, SIGSEGV); one scale now: refused where the distances cannot be resolved, exact
# where they can.
expect_error "periodic statistics in a box of side 1e300" "" "closer than 2\^-510" stats --input "$work/lift.csv" --periodic --domain-side 1e300
"$bin" stats --input "$work/lift.csv" --periodic --domain-side 1e100 -q -o "$work/side.csv" 2>"$work/err" && ok ||
  bad "periodic statistics in a box of side 1e100: $(cat "$work/err")"
expect_finite "periodic statistics in a box of side 1e100" "$work/side.csv"
# Directions of extreme length: the field of U is the field of U / |U| (byte for byte when U is a power of
# two times the unit direction's U: 2^-1000, 2^1000, 2^-1060 (subnormal), the smallest double; within
# 1e-12 for 1e-300 and 1e300, whose scaling rounds).
printf '0.1,0.2\n0.6,0.7\n' >"$work/two.csv"
"$bin" field --input "$work/two.csv" --stretch 1,1:2 -o "$work/stretch-1.csv" 2>"$work/err" || bad "stretch 1,1: $(cat "$work/err")"
"$bin" field --input "$work/two.csv" --stretch 1,0:2 -o "$work/stretch-x.csv" 2>"$work/err" || bad "stretch 1,0: $(cat "$work/err")"
for u in 9.332636185032189e-302,9.332636185032189e-302 1.0715086071862673e+301,1.0715086071862673e+301 8.095e-320,8.095e-320; do
  "$bin" field --input "$work/two.csv" --stretch "$u:2" -o "$work/stretch.csv" 2>"$work/err" && cmp -s "$work/stretch.csv" "$work/stretch-1.csv" &&
    ok || bad "--stretch $u:2 is not --stretch 1,1:2: $(cat "$work/err")"
done
for u in 1e-300,1e-300 1e300,1e300 1e-310,1e-310; do
  "$bin" field --input "$work/two.csv" --stretch "$u:2" -o "$work/stretch.csv" 2>"$work/err" &&
    /usr/bin/python3 -c 'import numpy as n, sys; a, b = (n.loadtxt(f, delimiter=",", skiprows=1) for f in sys.argv[1:]); sys.exit(not n.allclose(a, b, rtol=1e-12, atol=1e-12))' \
      "$work/stretch.csv" "$work/stretch-1.csv" && ok || bad "--stretch $u:2 is not within 1e-12 of --stretch 1,1:2: $(cat "$work/err")"
done
"$bin" field --input "$work/two.csv" --stretch 5e-324,0:2 -o "$work/stretch.csv" 2>"$work/err" && cmp -s "$work/stretch.csv" "$work/stretch-x.csv" &&
  ok || bad "--stretch 5e-324,0:2 is not --stretch 1,0:2: $(cat "$work/err")"
"$bin" field --input "$work/two.csv" --noise steerable --steer-dir 1,0 -o "$work/steer-x.csv" 2>"$work/err" || bad "steer 1,0: $(cat "$work/err")"
for u in 9.332636185032189e-302,0 1.0715086071862673e+301,0 5e-324,0; do
  "$bin" field --input "$work/two.csv" --noise steerable --steer-dir "$u" -o "$work/steer.csv" 2>"$work/err" &&
    cmp -s "$work/steer.csv" "$work/steer-x.csv" && ok || bad "--steer-dir $u is not --steer-dir 1,0: $(cat "$work/err")"
done
expect_error "stretch of zero length" "" "--stretch: the direction must not be zero" field --input "$work/two.csv" --stretch 0,-0:2

# ---------------------------------------------------------------------------------------------------
# Documented limits: --boundary-spacings at most a quarter of the side; a ball without a site is an error.
expect_error "sample boundary spacings over a quarter" "" \
  "--boundary-spacings 3: 3 spacings of 0.25 is 0.75 of the side, more than a quarter: at most 1 spacings with --grid 4" \
  --dim 3 --grid 4 --methods cnj --domain cube --boundary-spacings 3
# The paper's lattice (spacing 0.3) only lives in --protocol paper, which drops: no boundary band there.
expect_error "boundary spacings with the paper's protocol" "" \
  "--boundary-spacings applies to conformant CNJ in --domain cube or ball; --protocol paper drops the points that leave" \
  --dim 3 --grid 4 --protocol paper --methods cnj --boundary-spacings 1
expect_error "animate boundary spacings over a quarter" "" "boundary width 3 lattice spacings is 0.75 of the side, more than a quarter: at most 1 spacings" \
  animate --grid 4 --frames 2 --boundary-spacings 3 --out "$work/never"
"$bin" --dim 3 --grid 4 --methods cnj --domain cube --boundary-spacings 1 -q >"$work/quarter.csv" 2>"$work/err" && ok ||
  bad "a quarter of the side exactly: $(cat "$work/err")"
for n in 4 5 8; do
  expect_error "sample ball without a site ${n}D" "" "the ball inscribed in the cube holds no site of the 2\^$n lattice of --grid 2; the smallest --grid with a site inside is 3" \
    --dim "$n" --grid 2 --domain ball --methods cnj --no-stats --points -
  # animate keeps the sites on the sphere too: in 4D the 2^4 sites (1/4 or 3/4) lie on it
  [[ $n == 4 ]] && continue
  expect_error "animate ball without a site ${n}D" "" "holds no site of the cubic start lattice of grid 2 in ${n}D; the smallest grid with a site inside is 3" \
    animate --dim "$n" --grid 2 --domain ball --frames 2 --out "$work/never"
done
[[ ! -e $work/never ]] && ok || bad "a refused run made its output folder"
"$bin" --dim 3 --grid 2 --domain ball --methods cnj -q --no-stats --points - >"$work/ball3.csv" 2>"$work/err" &&
  [[ $(wc -l <"$work/ball3.csv") -eq 9 ]] && ok || bad "3D ball of grid 2: $(cat "$work/err")"
# --on sphere takes any basis: the torus's rule (a periodic basis) is not the sphere's.
"$bin" --dim 3 --grid 6 --on sphere --noise simplex -q -o "$work/sphere.csv" 2>"$work/err" && ok || bad "--on sphere --noise simplex: $(cat "$work/err")"
expect_finite "--on sphere --noise simplex" "$work/sphere.csv"

# ---------------------------------------------------------------------------------------------------
# Messages: the offending text quoted once (a quote inside it escaped), numbers with %g.
expect_error "stretch without a factor" "" "--stretch takes U:S \(a direction and a factor, e.g. 1,0:2\), got '1,0'$" field --input "$work/two.csv" --stretch 1,0
expect_error "lift of an unknown shape" "" "--lift takes plane:SX,SY, bump:H,R\[,CX,CY\[,SX,SY\]\] or npy:FILE, got 'sphere:1,2'$" field --input "$work/two.csv" --lift sphere:1,2
expect_error "lift parameter not a number" "" "--lift plane: 'x' is not a finite real number" field --input "$work/two.csv" --lift plane:1,x
expect_error "steer-dir with a quote" "" "--steer-dir: '\\\\'1' is not a number" field --input "$work/two.csv" --noise steerable --steer-dir "'1,0"
for args in "--stretch 1,0" "--lift sphere:1,2" "--lift plane:1,x"; do
  "$bin" field --input "$work/two.csv" $args 2>"$work/err"
  ! grep -q "''" "$work/err" && ok || bad "$args quoted twice: $(cat "$work/err")"
done
expect_error "boundary width 0" "" "--boundary-width: must be a number in \(0, 1/4\], got '0'" field --input "$work/two.csv" --domain cube --boundary-width 0
expect_error "periods 0" "" "--periods: must be a number in \[0\.001, 1e\+09\], got '0'" field --diagnose --periods 0
expect_error "bump radius -1e-300" "" "--lift bump: the radius R must be positive, got -1e-300" field --input "$work/two.csv" --lift bump:1,-1e-300
expect_error "obstacle radius -1e-300" "" "the radius must be positive, got -1e-300" field --input "$work/two.csv" --domain cube --obstacle sphere:0.5,0.5,-1e-300

# Exit codes: 2 for the command line (an unknown option, a malformed or out-of-range value), 1 for the data
# and the run (a missing, unreadable or bad input file, a value the run refuses, a failed run).
exit_code() { "$bin" "$@" </dev/null >/dev/null 2>"$work/err"; echo $?; }
[[ $(exit_code field --input "$work/missing.csv") == 1 ]] && grep -q "cannot read the file: No such file or directory" "$work/err" && ok ||
  bad "field, missing input: exit $(exit_code field --input "$work/missing.csv"): $(cat "$work/err")"
[[ $(exit_code stats --input "$work/missing.csv") == 1 ]] && ok || bad "stats, missing input: $(cat "$work/err")"
[[ $(exit_code field --input "$work") == 1 ]] && grep -q "cannot read the file: it is a directory" "$work/err" && ok ||
  bad "field, a directory as input: $(cat "$work/err")"
[[ $(exit_code stats --input "$work" --format csv) == 1 ]] && ok || bad "stats, a directory as input: $(cat "$work/err")"
[[ $(exit_code field --input "$work/two.csv" --lift "npy:$work/missing.npy") == 1 ]] && ok || bad "missing lift file: $(cat "$work/err")"
[[ $(exit_code --no-such-option) == 2 ]] && ok || bad "unknown option: $(cat "$work/err")"
[[ $(exit_code --dim 9) == 2 ]] && ok || bad "--dim 9: $(cat "$work/err")"
[[ $(exit_code field --input "$work/two.csv" --frequency abc) == 2 ]] && ok || bad "--frequency abc: $(cat "$work/err")"

finish cli_limits
