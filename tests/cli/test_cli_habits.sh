#!/usr/bin/env bash
# The habits a user brings from other tools (UTK, SciPy, git): a mistyped option or subcommand gets one
# suggestion; --points FILE.ext with one method writes that file in the extension's format; -i is
# stats' --input; --points - alone writes points, not statistics, to standard output; the help's labels
# are short and its lines within 100 columns; the lists of the usage come from the subcommands
# themselves. Runs the real binary ($DFVN_SAMPLE).
set -u
source "$(dirname "${BASH_SOURCE[0]}")/harness.sh"
cd "$work" || exit 1

# Suggestions: one name (or the few tied), never the whole list.
expect_error "--method" "" "unknown option '--method'; did you mean --methods\?" --method sobol
expect_error "--dimm" "" "unknown option '--dimm'; did you mean --dim\?" --dimm 3
expect_error "--grdi" "" "unknown option '--grdi'; did you mean --grid\?" --grdi 4
expect_error "stat" "" "unknown subcommand 'stat'; did you mean stats\?" stat FILE
expect_error "tabel1" "" "unknown reproduce subcommand 'tabel1'; did you mean table1\? " reproduce tabel1
expect_message "tabel1 alone" "did you mean table1\?"
grep -q "table2" "$work/err" && bad "reproduce tabel1 suggests more than table1: $(cat "$work/err")" || ok
expect_error "an option of a subcommand" "" "unknown option '--widht' for figure6; did you mean --width\?" \
  reproduce figure6 --widht 3
expect_error "stats --outptu" "" "unknown option '--outptu' for stats; did you mean --output\?" stats --outptu=x
# Far from every name: no suggestion, the arguments as given.
expect_error "no suggestion" "" "unexpected arguments: '--bogus1' 'third'" --dim 3 --bogus1 third
grep -q "did you mean" "$work/err" && bad "a far name got a suggestion: $(cat "$work/err")" || ok

# --points FILE.ext with one method: that file and its sidecar, in the extension's format.
"$bin" -n 64 -d 2 --methods sobol --points pts.dat -q -o stats.csv && [[ -f pts.dat && -f pts.dat.json ]] &&
  [[ $(grep -vc '^#' pts.dat) -eq 64 ]] && ok || bad "--points pts.dat --methods sobol writes pts.dat: $(ls)"
"$bin" -n 64 -d 3 --methods random --points pts.npy -q -o /dev/null &&
  /usr/bin/python3 -c "import numpy; assert numpy.load('pts.npy').shape == (64, 3)" && ok ||
  bad "--points pts.npy writes an npy file"
"$bin" -n 64 -d 2 --methods jitter --points pts.txt -q -o /dev/null && [[ -f pts.txt ]] &&
  [[ $(wc -l <pts.txt) -eq 64 ]] && ok || bad "--points pts.txt writes dat text"
expect_error "several methods, one file" "" "names one file, but --methods names 2 methods" \
  -n 64 -d 2 --methods sobol,random --points two.dat
expect_error "format against extension" "" "--format npy contradicts the extension" \
  -n 64 -d 2 --methods sobol --points one.dat --format npy
[[ ! -e two.dat && ! -e one.dat ]] && ok || bad "a refused --points made a file or folder"
# Several methods and a name without a point extension: a folder, one file each.
"$bin" -n 64 -d 2 --methods sobol,random --points folder --format bin -q -o /dev/null &&
  [[ -f folder/sobol.bin && -f folder/random.bin && -f folder/sobol.bin.json ]] && ok || bad "--points folder"

# -i is stats' --input; the sidecar puts the file back in its domain.
"$bin" stats -i pts.dat --no-timing -q -o via_i.csv && "$bin" stats --input pts.dat --no-timing -q -o via_input.csv &&
  cmp -s via_i.csv via_input.csv && [[ $(wc -l <via_i.csv) -eq 2 ]] && ok || bad "stats -i pts.dat"
grep -q ",torus," via_i.csv && ok || bad "stats -i pts.dat measures in the sidecar's torus: $(cat via_i.csv)"

# --points - alone: the points on standard output, no statistics there (nor anywhere).
"$bin" -n 16 -d 2 --methods random --points - --format dat >points.txt 2>err.txt && [[ $(wc -l <points.txt) -eq 16 ]] &&
  ! grep -q nn_min points.txt && ok || bad "--points - writes only points: $(head -3 points.txt) $(cat err.txt)"
# ... and with -o FILE the statistics go there.
"$bin" -n 16 -d 2 --methods random --points - --format dat -q -o s.csv >points2.txt && cmp -s points.txt points2.txt &&
  grep -q "^dim,grid,method," s.csv && ok || bad "--points - -o s.csv"

# The help: short labels, lines within 100 columns (--help-all, the widest), no CLI11 type words.
"$bin" --help-all >help_all.txt
awk 'length($0) > 100 { n++ } END { exit n > 0 }' help_all.txt && ok ||
  bad "--help-all has lines over 100 columns: $(awk 'length($0) > 100' help_all.txt | head -3)"
grep -q -- "-d, --dim N (2\.\.8, default 7)" help_all.txt && ok || bad "sample's --dim label"
grep -Eq "INT:|UINT:|FLOAT:|TEXT:|REQUIRED" help_all.txt && bad "CLI11 type labels: $(grep -E 'INT:|TEXT:' help_all.txt | head -2)" || ok
[[ $("$bin" stats --help | grep -c -- "--input") -ge 1 && $("$bin" stats --help | grep -c "^Positionals") -eq 0 ]] && ok ||
  bad "stats --help lists its files twice"

# The usage's lists come from the subcommands: every reproduction, every subcommand.
"$bin" >usage.txt
for name in $("$bin" reproduce --help | sed -n '/^Subcommands:$/,/^$/s/^  \([a-z][a-z0-9-]*\) .*/\1/p'); do
  grep -q "$name" usage.txt && ok || bad "the usage does not list reproduce $name"
done
for name in sample field stats reproduce animate; do grep -q "^  $name " usage.txt && ok || bad "usage lacks $name"; done
grep -q "about a minute" usage.txt && bad "the usage still guesses the main job's time" || ok

# table2's --width alone keeps the 16:9 aspect of its default 384 x 216 (it gave a portrait image).
png_size() { /usr/bin/python3 -c "import struct, sys; print(*struct.unpack('>II', open(sys.argv[1], 'rb').read(24)[16:24]))" "$1"; }
"$bin" reproduce table2 --width 64 --second-width 0 --out t2 -q >/dev/null 2>&1 && [[ $(png_size t2/source.png) == "64 36" ]] && ok ||
  bad "table2 --width 64: $(png_size t2/source.png 2>&1)"
"$bin" reproduce table2 --width 32 --height 32 --second-width 0 --out t2b -q >/dev/null 2>&1 &&
  [[ $(png_size t2b/source.png) == "32 32" ]] && ok || bad "table2 --width 32 --height 32"

finish "cli_habits"
