#!/usr/bin/env bash
# Issue 24, sets: `sample -m/--sets M --points` writes M sets into one file (dat with '#' between sets,
# npy (M, points, N), UTK's .bin) and `stats` reads several inputs and standard input, one row a set,
# with --rdf. Runs the real binary ($DFVN_SAMPLE).
set -u
source "$(dirname "${BASH_SOURCE[0]}")/harness.sh"
python=/usr/bin/python3

# The rows of a stats CSV whose set column is a set number (every data row).
set_rows() { awk -F, 'NR > 1 && $2 ~ /^[0-9]+$/' "$1"; }

# The pipe of the issue's target, as written: 8 Sobol sets as dat on standard output, read back from
# standard input. -n puts every method in [0,1]^N (the unit protocol), so stats needs no --domain-side.
"$bin" -n 1024 -d 2 -m 8 --methods sobol --points - --no-stats --format dat 2>"$work/err" |
  "$bin" stats --input - --format dat >"$work/pipe.csv" 2>>"$work/err" && ok || bad "target pipe: $(cat "$work/err")"
[[ $(set_rows "$work/pipe.csv" | wc -l) -eq 8 ]] && ok || bad "target pipe: $(set_rows "$work/pipe.csv" | wc -l) set rows, not 8"
[[ $(set_rows "$work/pipe.csv" | cut -d, -f1,2,4 | tr '\n' ' ') == '"-",0,1024 "-",1,1024 "-",2,1024 "-",3,1024 "-",4,1024 "-",5,1024 "-",6,1024 "-",7,1024 ' ]] &&
  ok || bad "target pipe rows: $(cut -d, -f1,2,4 "$work/pipe.csv" | tr '\n' ' ')"
# The 8 set rows and nothing else (the summary goes to --summary).
[[ $(wc -l <"$work/pipe.csv") -eq 9 ]] && ok || bad "target pipe: $(wc -l <"$work/pipe.csv") lines, not a header and 8 rows"
# With the paper protocol asked for, Sobol's 1024 points lie in [0, 0.1 K]^2 with K = 32: stats is told the side.
"$bin" -n 1024 -d 2 -m 8 --methods sobol --protocol paper --points - --no-stats --format dat 2>/dev/null |
  "$bin" stats --input - --format dat --domain-side 3.2 >"$work/paper.csv" 2>"$work/err" && ok || bad "paper pipe: $(cat "$work/err")"
[[ $(set_rows "$work/paper.csv" | wc -l) -eq 8 ]] && ok || bad "paper pipe: $(set_rows "$work/paper.csv" | wc -l) set rows"
# The dat stream: 8 sets of 1024 lines, 7 separator lines "#".
"$bin" -n 1024 -d 2 -m 8 --methods sobol --points - --no-stats --format dat 2>/dev/null >"$work/eight.dat"
[[ $(grep -c '^#$' "$work/eight.dat") -eq 7 && $(grep -vc '^#' "$work/eight.dat") -eq 8192 ]] && ok || bad "dat separators"
# Set k of -m 8 is the run of seed s + k: set 3 equals --seed 4's single set.
"$bin" -n 1024 -d 2 --seed 4 --methods sobol --points - --no-stats --format dat 2>/dev/null >"$work/seed4.dat"
awk '/^#/ { s++; next } s == 3' "$work/eight.dat" | cmp -s - "$work/seed4.dat" && ok || bad "set 3 is not seed 4's set"

# Standard input needs --format; it is read once.
expect_error "stdin without format" "0.1 0.2\n" "standard input \('-'\) has no extension to tell its format: give --format" \
  stats --input -
expect_error "stdin twice" "0.1 0.2\n" "standard input \('-'\) can be read once" stats --input - - --format dat

# Several inputs, as --input and positional: rows of each, numbered within the input.
"$bin" -n 256 -d 3 -m 3 --methods sobol,pds --domain cube --points "$work/b" --format bin --no-stats 2>/dev/null && ok || bad "sample bin"
"$bin" -n 256 -d 3 -m 3 --methods sobol --domain cube --points "$work/n" --format npy --no-stats 2>/dev/null && ok || bad "sample npy"
"$bin" -n 256 -d 3 -m 3 --methods sobol,pds --domain cube --points "$work/d" --format dat --no-stats 2>/dev/null && ok || bad "sample dat"
"$bin" stats --no-timing "$work/b/sobol.bin" --input "$work/n/sobol.npy" "$work/d/pds.dat" -o "$work/many.csv" 2>"$work/err" &&
  ok || bad "several inputs: $(cat "$work/err")"
[[ $(set_rows "$work/many.csv" | wc -l) -eq 9 ]] && ok || bad "several inputs: $(set_rows "$work/many.csv" | wc -l) set rows"
# The same sets in bin, npy and dat: the same statistics (all but the input column).
diff <(set_rows "$work/many.csv" | grep sobol.bin | cut -d, -f2-) <(set_rows "$work/many.csv" | grep sobol.npy | cut -d, -f2-) >/dev/null &&
  ok || bad "bin and npy statistics differ"
"$bin" stats --no-timing "$work/d/pds.dat" -o "$work/pds_dat.csv" && "$bin" stats --no-timing "$work/b/pds.bin" -o "$work/pds_bin.csv" &&
  diff <(cut -d, -f2- "$work/pds_dat.csv") <(cut -d, -f2- "$work/pds_bin.csv") >/dev/null && ok || bad "bin and dat statistics differ"
# A file and standard input together.
"$bin" stats --no-timing --format bin "$work/b/sobol.bin" - <"$work/b/pds.bin" >"$work/mixed.csv" 2>"$work/err" &&
  [[ $(set_rows "$work/mixed.csv" | cut -d, -f1 | sort | uniq -c | awk '{print $1}' | tr '\n' ' ') == "3 3 " ]] &&
  ok || bad "file and stdin: $(cat "$work/err")"

# UTK's .bin, bit for bit: an independent reader of UTK's layout (uint32 count, then float64 points, per
# set) finds the npy's sets in it, and writing them again gives the same bytes.
$python - "$work/b/sobol.bin" "$work/n/sobol.npy" "$work/again.bin" <<'PY' && ok || bad ".bin layout"
import struct, sys
import numpy as np
data = open(sys.argv[1], "rb").read()
sets, at = [], 0
while at < len(data):
    (count,) = struct.unpack_from("<I", data, at)
    at += 4
    sets.append(np.frombuffer(data, dtype="<f8", count=count * 3, offset=at).reshape(count, 3))
    at += count * 24
npy = np.load(sys.argv[2])
assert npy.shape == (3, 256, 3), npy.shape
assert len(sets) == 3 and all(np.array_equal(a, b) for a, b in zip(sets, npy))
with open(sys.argv[3], "wb") as out:
    for s in sets:
        out.write(struct.pack("<I", len(s)) + s.astype("<f8").tobytes())
PY
cmp "$work/b/sobol.bin" "$work/again.bin" && ok || bad ".bin rewritten differs"
# Truncated and empty .bin: one line, no output file.
head -c 1000 "$work/b/sobol.bin" >"$work/cut.bin"
expect_error "truncated bin" "" "cut.bin, bin: .*truncated" stats --input "$work/cut.bin" -o "$work/cut.csv"
[[ ! -e $work/cut.csv ]] && ok || bad "partial output after a truncated .bin"
printf '\x01\x00\x00\x00\x00\x00\x00\x00\x00\x00\xe0\x3f\x00\x00\x00\x00\x00\x00\xe0\x3f\x00\x00\x00\x00' >"$work/empty_set.bin"
expect_error "empty set in bin" "" "set 1 \(at byte 20\) holds no points" stats --input "$work/empty_set.bin" --dim 2
expect_error "dim of bin" "" "bin: as 3D points, set 0's record at byte 0 runs past the end" stats --input "$work/empty_set.bin" --dim 3
expect_error "dim of dat" "0.1 0.2\n" "standard input, 2D points, not the 3D of --dim" stats --input - --format dat --dim 3
# A good input then a bad one: no output at all.
expect_error "good then bad" "" "cut.bin" stats "$work/b/sobol.bin" "$work/cut.bin" -o "$work/gb.csv"
[[ ! -e $work/gb.csv ]] && ok || bad "partial output after a bad second input"

expect_error "json of two inputs" "" "--json describes one input; 2 are given" stats "$work/b/sobol.bin" "$work/b/pds.bin" --json "$work/j.json"

# --rdf: one curve a set (input,set,dim,r,g), --rdf-bins rows each.
"$bin" stats --no-timing "$work/b/sobol.bin" --rdf "$work/rdf.csv" --rdf-bins 20 -o /dev/null 2>"$work/err" && ok || bad "rdf: $(cat "$work/err")"
[[ $(head -1 "$work/rdf.csv") == "input,set,dim,r,g" && $(tail -n +2 "$work/rdf.csv" | wc -l) -eq 60 ]] && ok || bad "rdf rows"
[[ $(tail -n +2 "$work/rdf.csv" | cut -d, -f2 | uniq | tr '\n' ' ') == "0 1 2 " ]] && ok || bad "rdf sets"
# Poisson disk's g(r) is 0 below its radius (0.1 here, the unit protocol's 1 / K at K = 6.35 -> radius 1/6).
"$bin" stats --no-timing "$work/d/pds.dat" --rdf "$work/rdf_pds.csv" --rdf-bins 25 --rdf-max 0.5 -o /dev/null &&
  awk -F, 'NR > 1 && $4 < 0.09 && $5 != 0.0 { bad = 1 } END { exit bad }' "$work/rdf_pds.csv" && ok || bad "pds rdf below its radius"
expect_error "rdf 1D" "0.1\n0.5\n0.9\n" "--rdf needs 2D..8D points" stats --input - --format dat --rdf "$work/r1.csv"
[[ ! -e $work/r1.csv ]] && ok || bad "partial rdf"

# sample: csv holds one set; npy refuses pds's sets of varying size before any work; --rdf one realization.
expect_error "sets in csv" "" "--format dat, npy or bin \(csv holds one set\)" -n 64 -d 2 -m 2 --points "$work/x"
expect_error "npy pds" "" "pds's sets differ in size" -n 64 -d 2 -m 2 --methods pds --points "$work/x" --format npy
expect_error "points - many methods" "" "--points - writes one point set" -n 64 -d 2 -m 2 --methods sobol,pds --points - --format dat
[[ $("$bin" sample --help 2>&1 | grep -c -- '-m, --sets') -ge 1 ]] && ok || bad "--help lacks -m,--sets"

finish "cli_sets"
