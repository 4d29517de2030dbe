#!/usr/bin/env bash
# Issue 26 item 4, `dfvn-sample reproduce constructions` on a small run: its files, the CSV's rows,
# columns and types, the divergence targets on every row, the verdict line on the issue's claim against
# the CSV's own numbers, and bad input (one line, non-zero exit, no folder).
set -u
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
source "$here/harness.sh"
cd "$work" || exit 1
is_png() { [[ -s $1 && $(head -c 8 "$1" | od -An -tx1 | tr -d ' \n') == 89504e470d0a1a0a ]]; }

"$bin" reproduce constructions --divergence-points 3000 --speed-points 300 --trace-starts 6 --escape-starts 40 \
  --out c >c.txt 2>c.err --quiet && ok || bad "constructions: $(cat c.err)"
for f in constructions.csv constructions.md curl_obstacle.csv; do [[ -s c/$f ]] && ok || bad "constructions wrote no $f"; done
if command -v gnuplot >/dev/null; then is_png c/curl_obstacle.png && ok || bad "no curl_obstacle.png"; fi
[[ ! -s c.err ]] && ok || bad "--quiet printed: $(cat c.err)"
! grep -q "| ---" c.txt && grep -q "Verdict" c.txt && ok || bad "constructions printed Markdown or no verdict"
python3 "$here/check_csv_types.py" c/constructions.csv c/curl_obstacle.csv >/dev/null && ok || bad "constructions CSV types"

# Rows, columns, types, the divergence targets, and the claim recomputed from the CSV.
python3 - c/constructions.csv c/constructions.md <<'PY' && ok || bad "constructions.csv / .md: see above"
import csv, re, sys
rows = list(csv.DictReader(open(sys.argv[1])))
md = open(sys.argv[2]).read()
problems = []
columns = ("dim,construction,field,noise,frequency,seed,divergence_points,divergence_median,divergence_p95,"
           "divergence_max,still_points,speed_points,ns_per_evaluation,speed_rms,speed_q01,speed_q10,speed_q50,"
           "speed_q90,speed_q99,fraction_below_1pct,integrator,steps,reprojection,trace_starts,trace_time,"
           "endpoint_rmse,evaluations_per_trace,escape_starts,escape_cube_fraction,escape_obstacle_fraction").split(",")
if list(rows[0].keys()) != columns:
    problems.append(f"columns {list(rows[0].keys())}")
bases = ["simplex", "turning-bands", "quintic-gradient", "simplex-separate"]
# 2 dimensions x 4 bases x (curl: 4 variants, no reprojection; cross product: 8 variants)
if len(rows) != 2 * 4 * (4 + 8):
    problems.append(f"{len(rows)} rows, expected 96")
real = re.compile(r"-?([0-9]+\.[0-9]*|[0-9]+(\.[0-9]*)?[eE][-+]?[0-9]+)")
for r in rows:
    name = f"{r['dim']}D {r['construction']} {r['noise']} {r['integrator']} {r['steps']} {r['reprojection']}"
    if r["noise"] not in bases or r["dim"] not in ("2", "3"):
        problems.append(f"{name}: dimension or basis")
    expected = "curl" if r["field"] == "curl" else ("bitangent" if r["dim"] == "3" and "simplex" in r["noise"] else "dfvn")
    if r["construction"] != expected:
        problems.append(f"{name}: construction should be {expected}")
    if r["field"] == "curl" and r["reprojection"] != "none":
        problems.append(f"{name}: curl noise has no reprojection")
    for c in ("frequency", "divergence_median", "divergence_p95", "speed_rms", "endpoint_rmse", "trace_time"):
        if not real.fullmatch(r[c]):
            problems.append(f"{name}: {c} = {r[c]!r} is not a real with a point or exponent")
    escapes = r["escape_cube_fraction"], r["escape_obstacle_fraction"]
    if (r["steps"] == "64") != all(real.fullmatch(e) for e in escapes) or (r["steps"] == "512" and any(escapes)):
        problems.append(f"{name}: escapes {escapes} (measured at 64 steps only)")
    if not (float(r["divergence_median"]) <= 1e-8 and float(r["divergence_p95"]) <= 1e-6):
        problems.append(f"{name}: divergence {r['divergence_median']} / {r['divergence_p95']} misses the targets")
    if not 0.9 < float(r["speed_rms"]) < 1.1:
        problems.append(f"{name}: RMS |c| {r['speed_rms']}")
    if not float(r["endpoint_rmse"]) >= 0.0:
        problems.append(f"{name}: RMSE {r['endpoint_rmse']}")
# The claim: reprojected cross product below curl at equal basis, integrator and steps.
rmse = {(r["dim"], r["field"], r["noise"], r["integrator"], r["steps"], r["reprojection"]): float(r["endpoint_rmse"])
        for r in rows}
cells = [(k, v < rmse[(k[0], "curl", k[2], k[3], k[4], "none")]) for k, v in rmse.items()
         if k[1] == "dfvn" and k[5] == "gauss-newton"]
held = sum(h for _, h in cells)
verdict = f"**Verdict: {'holds' if held == len(cells) else 'does not hold'}** (it holds in {held} of {len(cells)} cells)."
if len(cells) != 32 or verdict not in md:
    problems.append(f"expected the line {verdict!r} in constructions.md: {re.findall(r'.*Verdict.*', md)}")
if "none exists" not in md:
    problems.append("constructions.md does not say that curl noise has no reprojection")
for p in problems:
    print("FAIL:", p, file=sys.stderr)
sys.exit(1 if problems else 0)
PY

# Results depend on the seed only, never on the thread count (ns_per_evaluation, column 13, is a time).
"$bin" reproduce constructions --divergence-points 3000 --speed-points 300 --trace-starts 6 --escape-starts 40 \
  --threads 1 --out c1 -q >/dev/null 2>&1 &&
  cmp -s <(cut -d, -f13 --complement c/constructions.csv) <(cut -d, -f13 --complement c1/constructions.csv) &&
  cmp -s c/curl_obstacle.csv c1/curl_obstacle.csv && ok || bad "constructions differ between 1 thread and all cores"

# Bad input: one line, non-zero exit, no folder.
expect_error "constructions no starts" "" "trace-starts" reproduce constructions --trace-starts 0 --out bad1
[[ ! -e bad1 ]] && ok || bad "a refused constructions run made its folder"
expect_error "constructions NaN frequency" "" "frequency" reproduce constructions --frequency nan --out bad2
[[ ! -e bad2 ]] && ok || bad "a refused constructions run made its folder"
expect_error "constructions negative time" "" "trace-time" reproduce constructions --trace-time -1 --out bad3
[[ ! -e bad3 ]] && ok || bad "a refused constructions run made its folder"
expect_error "constructions few points" "" "divergence-points" reproduce constructions --divergence-points 5 --out bad4
[[ ! -e bad4 ]] && ok || bad "a refused constructions run made its folder"
# An existing file where the folder should go: refused before any work.
touch taken
expect_error "constructions out is a file" "" "" reproduce constructions --out taken
finish cli_constructions
