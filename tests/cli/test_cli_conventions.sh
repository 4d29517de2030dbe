#!/usr/bin/env bash
# Issue 12's command-line conventions, machine-readable results and progress, on the real binary:
# usage without arguments, help and version, short options, -n, field's input layouts, points on
# standard output and as dat, --no-stats, --no-timing, --json, --progress.
set -u
source "$(dirname "${BASH_SOURCE[0]}")/harness.sh"
python=/usr/bin/python3

# No arguments: a short usage on stdout and exit 0, at once (not the minute-long main job).
start=$(date +%s)
"$bin" </dev/null >"$work/usage" 2>"$work/err"
rc=$?
[[ $rc -eq 0 && ! -s $work/err && $(($(date +%s) - start)) -lt 5 ]] && ok || bad "no arguments: rc=$rc $(cat "$work/err")"
for word in "The main job" "dfvn-sample --dim 7 --grid 6" "sample" "field" "stats" "reproduce" "--help" "--version"; do
  grep -q -- "$word" "$work/usage" && ok || bad "usage lacks '$word'"
done

# --help names the subcommands, --version and --help-all; --help-all works; each subcommand has -h.
"$bin" --help >"$work/help" 2>&1 && grep -q -- "--version" "$work/help" && grep -q -- "--help-all" "$work/help" &&
  grep -q "stats" "$work/help" && ok || bad "--help: $(cat "$work/help")"
"$bin" --help-all >"$work/help_all" 2>&1 && grep -q -- "--step-scale" "$work/help_all" && grep -q -- "--diagnose" "$work/help_all" &&
  ok || bad "--help-all: $(head -3 "$work/help_all")"
"$bin" sample -h >"$work/out" 2>&1 && grep -q -- "-n, --count" "$work/out" && grep -q -- "-o, --output, --stats" "$work/out" &&
  grep -q -- "-q, --quiet" "$work/out" && grep -q -- "--progress" "$work/out" && grep -q -- "-d, --dim" "$work/out" &&
  grep -q -- "-s, --seed" "$work/out" && ok || bad "sample -h lacks a short option"
"$bin" --version | grep -q "^dfvn-sample [0-9]" && ok || bad "--version"

# Refused combinations.
expect_error "format without points" "" "--format npy applies to --points" -d 2 --grid 4 --format npy
expect_error "rdf and stats on stdout" "" "--rdf - would both write to standard output" -d 2 --grid 4 --rdf -
expect_error "json and stats on stdout" "" "--json - would both write" -d 2 --grid 4 --json -
expect_error "points - with two methods" "" "one point set to standard output" -d 2 --grid 4 --methods jitter,sobol --points - -o "$work/x.csv"
# --points - alone writes the points, and no statistics, to standard output (tests/cli/test_cli_habits.sh).
expect_error "points - and stats on stdout" "" "--points - would both write" -d 2 --grid 4 --methods sobol --points - -o -
expect_error "no-stats without points" "" "give --points" -d 2 --grid 4 --no-stats
expect_error "-n and --grid" "" "excludes" -d 2 --grid 4 -n 100
expect_error "-n too small" "" "count" -d 2 -n 1
[[ ! -e $work/x.csv ]] && ok || bad "a refused run left a file"

# Short options, same run as the long ones.
"$bin" -d 3 --grid 5 -s 7 -q --methods jitter,sobol --no-timing -o "$work/short.csv" 2>"$work/err" &&
  "$bin" --dim 3 --grid 5 --seed 7 --quiet --methods jitter,sobol --no-timing --stats "$work/long.csv" 2>>"$work/err" &&
  cmp -s "$work/short.csv" "$work/long.csv" && ok || bad "short options differ from long ones: $(cat "$work/err")"

# -n: lattice K^N nearest COUNT (the grid column says which), exactly COUNT for the others.
"$bin" -d 3 -n 1200 -q --domain cube --methods jitter,sobol,random,pds --no-timing -o "$work/n.csv" 2>"$work/err" && ok ||
  bad "-n run: $(cat "$work/err")"
awk -F, 'NR > 1 { print $2, $3, $4 }' "$work/n.csv" >"$work/n.txt"
grep -qx "11 jitter 1331" "$work/n.txt" && grep -qx "11 sobol 1200" "$work/n.txt" && grep -qx "11 random 1200" "$work/n.txt" &&
  ok || bad "-n counts: $(cat "$work/n.txt")"
grep -q "warning: sobol: 1200 points is not a power of 2" "$work/err" && ok || bad "no Sobol warning: $(cat "$work/err")"
grep -q "warning: -n 1200: the lattice methods use K = 11, 11^3 = 1331" "$work/err" && ok || bad "no lattice note: $(cat "$work/err")"
"$bin" -d 2 -n 5000 -q --domain cube --methods pds --pds-radius 0.05 --no-timing -o "$work/sat.csv" 2>"$work/err" &&
  grep -q "warning: pds saturated at [0-9]* of 5000 points" "$work/err" && ok || bad "no PDS saturation report: $(cat "$work/err")"

# Numbers and settings in their own columns, in the user's units; notes keep the remaining words.
"$bin" -d 3 --grid 6 -q --methods cnj,pds --cycles-per-spacing 0.5 --no-timing -o "$work/cols.csv" 2>"$work/err" && ok || bad "cols run"
$python - "$work/cols.csv" <<'PY' && ok || bad "stats columns"
import csv, sys
rows = {r["method"]: r for r in csv.DictReader(open(sys.argv[1]))}
cnj, pds = rows["cnj"], rows["pds"]
assert cnj["cycles_per_spacing"] == "0.5", cnj["cycles_per_spacing"]
# On the torus: the cell-centred lattice (spacing 1/6), and the frequency its periodic field realises.
assert abs(float(cnj["field_frequency"]) / (0.5 * 6) - 1) < 0.1, cnj["field_frequency"]
assert (cnj["noise"], cnj["mode"], cnj["notes"]) == ("turning-bands", "conformant", ""), cnj["notes"]
assert pds["noise"] == "" and pds["mode"] == ""
assert cnj["domain"] == "torus" and pds["domain"] == "torus", (cnj["domain"], pds["domain"])
assert cnj["dropped"].isdigit() and cnj["skipped_updates"].isdigit() and float(cnj["trace_time"]) > 0
assert pds["cycles_per_spacing"] == "" and pds["dropped"] == "" and pds["saturated"] == "0" and 0.1 < float(pds["radius"]) < 0.2
assert pds["rms_displacement"] == "" and cnj["rms_displacement"] != ""
for r in rows.values():
    assert "=" not in r["notes"], r["notes"]
    assert r["seconds_generate"] == "" and r["seconds_stats"] == ""
    assert "." in r["domain_side"], r["domain_side"]
PY

# --no-timing: two runs with the same seed give identical files (stats, RDF, JSON), and the thread count
# changes nothing.
for t in 1 2; do
  "$bin" -d 3 --grid 6 -q -s 3 --threads $t --methods cnj,jitter,pds,sobol --rdf "$work/rdf$t.csv" --rdf-bins 8 \
    --json "$work/run$t.json" --no-timing -o "$work/st$t.csv" 2>"$work/err" || bad "no-timing run $t: $(cat "$work/err")"
done
cmp -s "$work/st1.csv" "$work/st2.csv" && cmp -s "$work/rdf1.csv" "$work/rdf2.csv" && cmp -s "$work/run1.json" "$work/run2.json" &&
  ok || bad "--no-timing files differ: $(diff "$work/st1.csv" "$work/st2.csv" | head -3)"
"$bin" -d 3 --grid 6 -q -s 3 --methods jitter -o "$work/timed.csv" && awk -F, 'NR == 2 { exit ($15 == "") }' "$work/timed.csv" &&
  ok || bad "without --no-timing the seconds are there"

# --json: parameters, every method's statistics, derived values; equal to the CSV.
$python - "$work/run1.json" "$work/st1.csv" <<'PY' && ok || bad "json content"
import csv, json, sys
run = json.load(open(sys.argv[1]))
rows = {r["method"]: r for r in csv.DictReader(open(sys.argv[2]))}
p = run["parameters"]
assert p["dim"] == 3 and p["grid"] == 6 and p["seed"] == 3 and p["methods"] == ["cnj", "jitter", "pds", "sobol"], p
assert p["cnj"]["noise"] == "turning-bands" and p["cnj"]["cycles_per_spacing"] == 0.2 and p["count"] is None
results = {r["method"]: r for r in run["results"]}
assert set(results) == set(rows)
for m, r in results.items():
    assert r["points"] == int(rows[m]["points"])
    assert abs(r["nearest_neighbour"]["median"] - float(rows[m]["nn_median"])) <= 1e-8 * r["nearest_neighbour"]["median"]
    assert "seconds" not in r
assert results["cnj"]["displacement"]["lattice_order"] > 0 and results["sobol"]["displacement"] is None
assert results["cnj"]["generation"]["dropped"] == int(rows["cnj"]["dropped"])
assert results["pds"]["generation"]["saturated"] in (True, False)
assert "summary" not in run
PY
# The JSON names the step count CNJ traced with: 0 resolves by domain (2 on the torus and in drop mode's free
# field, 1 in the bounded cube), and the sphere traces as conformant.
json_steps() { "$bin" -q --methods cnj --json - -o /dev/null "$@" | $python -c 'import json, sys; print(json.load(sys.stdin)["parameters"]["cnj"]["steps"])'; }
[ "$(json_steps -d 3 --grid 4)" = 2 ] && [ "$(json_steps -d 3 --grid 4 --domain cube)" = 1 ] &&
  [ "$(json_steps -d 3 --grid 4 --domain cube --domain-mode drop)" = 2 ] &&
  [ "$(json_steps -d 3 --grid 4 --domain cube --domain-mode drop --steps 3)" = 3 ] &&
  [ "$(json_steps -d 3 --grid 4 --on sphere)" = 1 ] && [ "$(json_steps -d 3 --grid 4 --protocol paper)" = 1 ] &&
  ok || bad "json steps: the resolved step count"
"$bin" -d 2 --grid 5 -q --methods jitter --realizations 3 --json "$work/real.json" -o /dev/null &&
  $python -c 'import json, sys; s = json.load(open(sys.argv[1]))["summary"]["jitter"]; assert s["nearest_neighbour.median"]["sd"] > 0, s' "$work/real.json" &&
  ok || bad "json summary over realizations"

# stats --json: every set's statistics, a summary over the sets of a dat file; -o and --no-timing.
printf '0.1 0.2\n0.3 0.4\n0.8 0.1\n#\n0.5 0.5\n0.2 0.9\n0.7 0.3\n' >"$work/two.dat"
"$bin" stats --input "$work/two.dat" --discrepancy --no-timing --json "$work/two.json" -o "$work/two.csv" 2>"$work/err" &&
  $python - "$work/two.json" "$work/two.csv" <<'PY' && ok || bad "stats --json: $(cat "$work/err")"
import csv, json, sys
run = json.load(open(sys.argv[1]))
rows = list(csv.DictReader(open(sys.argv[2])))
assert run["parameters"]["format"] == "dat" and run["parameters"]["discrepancy"] is True
assert [s["set"] for s in run["sets"]] == [0, 1] and all(s["dim"] == 2 and s["points"] == 3 for s in run["sets"])
for s, r in zip(run["sets"], rows):
    assert abs(s["discrepancy"]["cd"] - float(r["cd"])) <= 1e-8 * s["discrepancy"]["cd"]  # the CSV: 9 digits
    assert abs(s["nearest_neighbour"]["q01"] - float(r["nn_q01"])) <= 1e-8 and "seconds" not in s
assert r["seconds_stats"] == "" and run["summary"]["nearest_neighbour.min"]["sd"] >= 0
PY
expect_error "stats json and csv on stdout" "" "standard output" stats --input "$work/two.dat" --json -

# Points: to standard output with one method, and the dat format (what numpy.loadtxt, UTK and pspec read).
"$bin" -d 3 --grid 4 -q --methods sobol --no-stats --points - >"$work/p.csv" 2>"$work/err" &&
  head -1 "$work/p.csv" | grep -qx "x0,x1,x2" && [[ $(wc -l <"$work/p.csv") -eq 65 ]] && ok || bad "--points - : $(cat "$work/err")"
"$bin" -d 3 --grid 4 -q --methods sobol --no-stats --points - --format dat >"$work/p.dat" 2>"$work/err" &&
  [[ $(wc -l <"$work/p.dat") -eq 64 ]] && ok || bad "--points - --format dat: $(cat "$work/err")"
$python -c '
import sys, numpy as np
a = np.loadtxt(sys.argv[1], delimiter=",", skiprows=1); b = np.loadtxt(sys.argv[2])
assert a.shape == (64, 3) and np.array_equal(a, b)' "$work/p.csv" "$work/p.dat" && ok || bad "dat and csv differ"
"$bin" stats --input "$work/p.dat" -q --no-timing -o "$work/pdat.stats" 2>"$work/err" && ok || bad "stats reads our dat: $(cat "$work/err")"
"$bin" -d 3 --grid 4 -q --methods sobol --no-timing --points "$work/pd" --format dat -o "$work/pd.csv" && [[ -s $work/pd/sobol.dat ]] &&
  ok || bad "--points DIR --format dat"

# field: whitespace input (numpy.savetxt) and the dimension from the column count.
$python -c 'import numpy as np; np.savetxt("'"$work"'/sv.txt", np.array([[0.1, 0.2, 0.3], [0.4, 0.5, 0.6]]), header="x y z")'
"$bin" field --input "$work/sv.txt" -s 5 -o "$work/fw.csv" 2>"$work/err" && ok || bad "field whitespace: $(cat "$work/err")"
printf '0.1,0.2,0.3\n0.4,0.5,0.6\n' | "$bin" field --dim 3 -s 5 >"$work/fc.csv" 2>"$work/err" && cmp -s "$work/fw.csv" "$work/fc.csv" &&
  ok || bad "field whitespace and comma input differ"
printf '0.1 0.2\n0.3\n' | "$bin" field >"$work/out" 2>"$work/err"
[[ $? -ne 0 ]] && grep -q "line 2: expected 2 whitespace-separated columns (as in the first line), found 1" "$work/err" &&
  ok || bad "field inferred-dimension error: $(cat "$work/err")"
printf '1 2 3 4 5 6 7 8 9\n' | "$bin" field >"$work/out" 2>"$work/err"
[[ $? -ne 0 ]] && grep -q "9 columns; the field is defined in 2..8 dimensions" "$work/err" && ok || bad "field 9 columns: $(cat "$work/err")"

# Progress: --progress always leaves a plain line per stage in a log (stderr is no terminal here), with
# the stage counter, elapsed time; auto and -q leave the log empty for a short run; output is the same.
"$bin" -d 3 --grid 6 -s 2 --methods cnj,pds --rdf "$work/prdf.csv" --no-timing --progress always -o "$work/pa.csv" 2>"$work/plog" &&
  ok || bad "progress always run"
for stage in "\[1/6\] cnj " "\[2/6\] cnj statistics" "\[3/6\] cnj rdf" "\[4/6\] pds " "\[5/6\] pds statistics" "\[6/6\] pds rdf"; do
  grep -q "^dfvn-sample: $stage.*elapsed" "$work/plog" && ok || bad "progress log lacks $stage: $(cat "$work/plog")"
done
grep -q "^dfvn-sample: done: 6 stages in " "$work/plog" && ok || bad "progress log has no closing line: $(tail -1 "$work/plog")"
grep -q $'\r' "$work/plog" && bad "carriage return in a log" || ok
"$bin" -d 3 --grid 6 -s 2 --methods cnj,pds --rdf "$work/prdf2.csv" --no-timing -o "$work/pn.csv" 2>"$work/plog2" &&
  [[ -z $(grep -v "^dfvn-sample: verdict by " "$work/plog2") ]] && cmp -s "$work/pa.csv" "$work/pn.csv" && ok ||
  bad "progress changed the output or auto wrote a log: $(head -2 "$work/plog2")"
"$bin" -d 3 --grid 6 --methods jitter --progress always -q -o /dev/null 2>"$work/plog3" && [[ ! -s $work/plog3 ]] && ok || bad "-q"
"$bin" stats --input "$work/p.dat" --discrepancy --progress always -o /dev/null 2>"$work/plog4" &&
  grep -q "\[5/5\] L2-star" "$work/plog4" && ok || bad "stats progress: $(cat "$work/plog4")"
expect_error "progress mode" "" "progress" -d 2 --grid 4 --progress sometimes

finish "cli_conventions"
