#!/usr/bin/env bash
# Hostile-input tests of the real binary ($DFVN_SAMPLE), one section per class of issue 9: crashes and
# NaN/Inf, output safety (signals, devices, links, FIFOs, two outputs on one path, an output that is an
# input), values that must be refused, and messages (one line, the tool's own, echoes shortened and
# escaped).
set -u
source "$(dirname "${BASH_SOURCE[0]}")/harness.sh"

# expect_no_temporaries NAME DIR: no <file>.tmp.<pid> left in DIR (recursively).
expect_no_temporaries() {
  local left
  left=$(find "$2" -name '*.tmp.*' | head -3)
  [[ -z $left ]] && ok || bad "$1: temporary left behind: $left"
}

# ---------------------------------------------------------------------------------------------------
# Crashes and NaN/Inf: coordinates and frequencies outside the noise domain are refused, naming them.
for n in 2 3 4 5 6 7 8; do
  row=$(printf '1e308%.0s,' $(seq 1 "$n"))
  expect_error "huge coordinates ${n}D" "${row%,}\n" "" field --dim "$n"
  expect_message "huge coordinates ${n}D" "line 1|point 1"
  expect_message "huge coordinates ${n}D" "1e\+308.*outside the noise domain"
done
expect_error "coordinate just outside the domain" "0,1125899906842624\n" "" field --dim 2
expect_message "coordinate just outside the domain" "column 2: 1125899906842624 is outside the noise domain"
expect_error "field frequency 1e308" "0.1,0.2\n" "" field --dim 2 --frequency 1e308
expect_message "field frequency 1e308" "--frequency.*1e308"
expect_error "field subnormal frequency" "0.1,0.2\n" "" field --dim 2 --frequency 1e-320
expect_message "field subnormal frequency" "--frequency.*2\^-50"
expect_error "cnj frequency 1e307" "" "" --dim 3 --grid 4 --methods cnj --cycles-per-spacing 1e307
expect_error "cnj subnormal frequency" "" "" --dim 3 --grid 4 --methods cnj --cycles-per-spacing 1e-320
expect_error "cnj field frequency over the bound" "" "" --dim 3 --grid 4 --methods cnj --cycles-per-spacing 1e15
expect_message "cnj field frequency over the bound" "field frequency"
expect_error "table2 frequency 1e308" "" "" reproduce table2 --frequency 1e308 --out "$work/t2bad"
expect_error "table2 frequency over the image height" "" "" reproduce table2 --frequency 1e15 --width 2 --height 20000 --out "$work/t2bad"
expect_error "step scale 1e300" "" "" --dim 3 --grid 4 --methods cnj --step-scale 1e300
expect_error "rdf-max 1e-300" "" "" --dim 3 --grid 4 --methods jitter --rdf "$work/rdf-bad.csv" --rdf-max 1e-300
expect_message "rdf-max 1e-300" "--rdf-max"
[[ ! -e $work/t2bad && ! -e $work/rdf-bad.csv ]] && ok || bad "an output was written for refused input"
for t in 100000 1000000 2147483647 99999999999999999999 -1 '' 1.5; do
  expect_error "threads '$t'" "" "" --dim 3 --grid 4 --methods jitter --threads "$t"
  expect_message "threads '$t'" "--threads: must be 0 \(all cores\) or 1\.\.[0-9]+ "
done
expect_error "threads in field" "0,0\n" "" field --dim 2 --threads 100000
printf 'x,y\n0.1,0.2\n0.6,0.7\n' >"$work/two.csv"
expect_error "threads in stats" "" "--threads: must be 0 \(all cores\) or 1\.\.[0-9]+ " stats --input "$work/two.csv" --threads 100000
OMP_NUM_THREADS=100000 "$bin" --dim 2 --grid 5 --methods jitter --quiet >"$work/omp.csv" 2>"$work/err" && ok ||
  bad "OMP_NUM_THREADS=100000: $(cat "$work/err")"

# Every number written is finite, at the edges of what is accepted.
printf '1e14,-1e14,0\n1e-300,5e-324,-0\n0.5,0.25,0.125\n' >"$work/edge3.csv"
"$bin" field --dim 3 --input "$work/edge3.csv" --output "$work/edge3.out" 2>"$work/err" && ok || bad "field near the bound: $(cat "$work/err")"
"$bin" field --dim 3 --frequency 8.8817841970012523e-16 --input "$work/edge3.csv" --output "$work/edge3-low.out" 2>"$work/err" &&
  ok || bad "field at the lowest frequency: $(cat "$work/err")"
printf '0.5,-0.99,0.999\n' | "$bin" field --dim 3 --frequency 1125899906842624 --output "$work/edge3-high.out" 2>"$work/err" &&
  ok || bad "field at the highest frequency: $(cat "$work/err")"
expect_finite "field outputs" "$work/edge3.out" "$work/edge3-low.out" "$work/edge3-high.out"
for n in 2 5 8; do
  "$bin" --dim "$n" --grid 4 --methods jitter,sobol,random --rdf "$work/rdf-far$n.csv" --rdf-max 1e-6 --rdf-bins 3 \
    --quiet --stats "$work/stats-far$n.csv" 2>"$work/err" && ok || bad "tiny RDF range ${n}D: $(cat "$work/err")"
  # At a frequency this low the field is one vector over the lattice: a small step keeps the points in.
  # The free field (--domain-mode drop): in the conformant field the noise's values grow like
  # 1/frequency, and Eq. 13's (f~ - G d) grad alpha term then throws boundary points out, so nearly every
  # point is retraced 6 times and kept at its site (finite, but minutes in 8D under ASan; see the notes).
  "$bin" --dim "$n" --grid 4 --methods cnj --cycles-per-spacing 1e-13 --step-scale 1e-6 --domain-mode drop --quiet \
    --stats "$work/stats-low$n.csv" 2>"$work/err" && ok || bad "low frequency sample ${n}D: $(cat "$work/err")"
  "$bin" --dim "$n" --grid 4 --methods cnj --cycles-per-spacing 1e14 --domain-mode drop --quiet --stats "$work/stats-high$n.csv" 2>"$work/err" &&
    ok || bad "high frequency sample ${n}D: $(cat "$work/err")"
  expect_finite "sample ${n}D" "$work/rdf-far$n.csv" "$work/stats-far$n.csv" "$work/stats-low$n.csv" "$work/stats-high$n.csv"
done
# With --domain-mode drop a large step scale moves many points out of the unit cube: finite
# statistics of the rest; the largest moves every point out: a clear error. Conformant CNJ (the
# default) keeps every point at any step scale.
"$bin" --dim 5 --grid 4 --methods cnj --step-scale 3 --domain-mode drop --quiet --stats "$work/stats-step.csv" 2>"$work/err" &&
  ok || bad "large step scale 5D: $(cat "$work/err")"
expect_finite "large step scale 5D" "$work/stats-step.csv"
expect_error "every CNJ point dropped" "" "" --dim 2 --grid 4 --methods cnj --step-scale 1048576 --domain-mode drop
expect_message "every CNJ point dropped" "the cnj point set has [01] point"
expect_error "every CNJ point dropped 5D" "" "" --dim 5 --grid 4 --methods cnj --step-scale 1048576 --domain-mode drop
expect_message "every CNJ point dropped 5D" "the cnj point set has [01] point"
for n in 2 5; do
  "$bin" --dim $n --grid 3 --methods cnj --step-scale 1048576 --quiet --stats "$work/stats-huge$n.csv" 2>"$work/err" &&
    awk -F, -v n=$n '$1 == n && $3 == "cnj" && $4 == 3 ^ n && $25 == "0" { found = 1 } END { exit !found }' \
      "$work/stats-huge$n.csv" && ok ||
    bad "conformant CNJ at the largest step scale ${n}D: $(cat "$work/err" "$work/stats-huge$n.csv")"
  expect_finite "conformant largest step ${n}D" "$work/stats-huge$n.csv"
done
"$bin" reproduce table2 --width 8 --height 6 --frequency 1e14 --out "$work/t2high" --quiet >/dev/null 2>"$work/err" &&
  ok || bad "table2 at a high frequency: $(cat "$work/err")"
"$bin" reproduce table2 --width 8 --height 6 --frequency 1e-15 --out "$work/t2low" --quiet >/dev/null 2>"$work/err" &&
  ok || bad "table2 at a low frequency: $(cat "$work/err")"
expect_finite "table2" "$work/t2high/table2.csv" "$work/t2high/table2.md" "$work/t2low/table2.csv" "$work/t2low/table2.md"

# ---------------------------------------------------------------------------------------------------
# Output safety: SIGTERM and SIGINT while a large point file is being written remove the temporary,
# and the process dies of the signal (status 143, 130). The write of 4M 2D points takes about a
# second after the statistics; the test waits for the temporary to appear, then signals.
# Job control keeps SIGINT deliverable to a background job (otherwise bash ignores it there).
set -m
for signal in TERM INT; do
  dir=$work/signal-$signal
  mkdir -p "$dir"
  "$bin" --dim 2 --grid 2000 --methods jitter --threads 2 --quiet --points "$dir/points" --stats "$dir/stats.csv" \
    --rdf "$dir/rdf.csv" 2>"$dir/err" &
  pid=$!
  seen=""
  for ((i = 0; i < 6000; ++i)); do  # up to 120 s (a slow sanitizer build)
    seen=$(find "$dir" -name '*.tmp.*' -size +1k 2>/dev/null | head -1)
    [[ -n $seen ]] && break
    kill -0 "$pid" 2>/dev/null || break
    sleep 0.02
  done
  if [[ -z $seen ]]; then
    wait "$pid"
    bad "SIG$signal: the write finished before its temporary was seen; make the output larger"
    continue
  fi
  kill "-$signal" "$pid"
  wait "$pid"
  rc=$?
  expected=$((128 + $(kill -l "$signal")))
  [[ $rc -eq $expected ]] && ok || bad "SIG$signal: exit status $rc, expected $expected"
  expect_no_temporaries "SIG$signal" "$dir"
  [[ ! -e $dir/points/jitter.csv && ! -e $dir/stats.csv && ! -e $dir/rdf.csv ]] && ok || bad "SIG$signal: a partial output exists"
done
set +m

# Outputs that are not regular files are written through and keep their type.
mkdir -p "$work/targets"
cd "$work/targets" || exit 1
if [[ $(id -u) -eq 0 ]] && mknod null-device c 1 3 2>/dev/null; then
  "$bin" --dim 3 --grid 4 --methods jitter --quiet --stats null-device --rdf null-device 2>"$work/err" && ok ||
    bad "character device as --stats: $(cat "$work/err")"
  [[ -c null-device ]] && ok || bad "the character device was replaced: $(ls -l null-device)"
  printf '0,0\n' | "$bin" field --dim 2 --output null-device 2>"$work/err" && [[ -c null-device ]] && ok ||
    bad "character device as field --output"
else
  echo "SKIP: character device test (needs root and mknod)"
fi
echo "old" >target.csv
ln -s target.csv link.csv
ln -s link.csv link2.csv
"$bin" --dim 3 --grid 4 --methods jitter --quiet --stats link2.csv 2>"$work/err" && ok || bad "symlink as --stats: $(cat "$work/err")"
[[ -L link.csv && -L link2.csv && -f target.csv ]] && ok || bad "symlinks were replaced: $(ls -l)"
head -1 target.csv | grep -q "^dim,grid,method" && ok || bad "the symlink's target was not written"
chmod 640 target.csv
printf '0.1,0.2\n' | "$bin" field --dim 2 --output link.csv 2>"$work/err" && ok || bad "symlink as field --output: $(cat "$work/err")"
[[ -L link.csv ]] && head -1 target.csv | grep -q "^x0,x1,c0" && ok || bad "field through a symlink"
[[ $(stat -c %a target.csv) == 640 ]] && ok || bad "the replaced file lost its permissions: $(stat -c %a target.csv)"
ln -s missing-target.csv dangling.csv
"$bin" --dim 3 --grid 4 --methods jitter --quiet --stats dangling.csv 2>"$work/err" && [[ -L dangling.csv && -f missing-target.csv ]] &&
  ok || bad "dangling symlink as --stats: $(cat "$work/err"); $(ls -l)"
mkfifo fifo
cat fifo >from-fifo &
reader=$!
"$bin" --dim 3 --grid 4 --methods jitter --quiet --stats fifo 2>"$work/err" && ok || bad "FIFO as --stats: $(cat "$work/err")"
wait "$reader"
[[ -p fifo ]] && ok || bad "the FIFO was replaced"
[[ $(wc -l <from-fifo) -eq 2 ]] && ok || bad "the FIFO's reader got $(wc -l <from-fifo) lines"
"$bin" --dim 3 --grid 4 --methods jitter --quiet --stats /dev/stdout >stdout.csv 2>"$work/err" && ok || bad "/dev/stdout: $(cat "$work/err")"
[[ $(wc -l <stdout.csv) -eq 2 ]] && ok || bad "/dev/stdout into a file: $(wc -l <stdout.csv) lines"
lines=$("$bin" --dim 3 --grid 4 --methods jitter --quiet --stats /dev/fd/1 2>"$work/err" | wc -l)
[[ $lines -eq 2 ]] && ok || bad "/dev/fd/1 into a pipe: $lines lines, $(cat "$work/err")"
expect_error "directory as --stats" "" "" --dim 3 --grid 4 --methods jitter --stats "$work/targets"
expect_message "directory as --stats" "directory"
expect_no_temporaries "after the output tests" "$work/targets"

# Two outputs of one run on one path are refused, whatever the spelling.
expect_error "same --rdf and --stats" "" "" --dim 3 --grid 4 --methods jitter --rdf x.csv --stats x.csv
expect_message "same --rdf and --stats" "--output and --rdf"
expect_error "same path spelled twice" "" "" --dim 3 --grid 4 --methods jitter --rdf ./x.csv --stats "$work/targets/x.csv"
expect_error "--stats through a link to --rdf" "" "" --dim 3 --grid 4 --methods jitter --rdf target.csv --stats link2.csv
ln target.csv hard.csv
expect_error "--stats a hard link of --rdf" "" "" --dim 3 --grid 4 --methods jitter --rdf target.csv --stats hard.csv
expect_error "--stats inside --points" "" "" --dim 3 --grid 4 --methods jitter,cnj --points pts --stats pts/cnj.csv
expect_message "--stats inside --points" "--points \(cnj.csv\)"
[[ ! -e x.csv && ! -e pts ]] && ok || bad "refused outputs were created"
cd "$work" || exit 1

# An output that is an input (the same file by any path) is refused before anything is written, and the
# input stays as it was: stats, field and sample, every output option, every spelling of the same file.
mkdir -p "$work/inputs/t" && cd "$work/inputs" || exit 1
"$bin" --dim 2 --grid 8 --methods sobol --points made --format csv --no-stats --quiet 2>"$work/err" || bad "points: $(cat "$work/err")"
"$bin" --dim 2 --grid 8 --methods sobol --points made --format npy --no-stats --quiet 2>"$work/err" || bad "points: $(cat "$work/err")"
cp made/sobol.csv IN.csv && cp made/sobol.csv P_radial.csv && cp made/sobol.npy H.npy
ln -s IN.csv link.csv && ln IN.csv hard.csv
before=$(cat IN.csv P_radial.csv H.npy | cksum)
expect_error "stats -o the input" "" "--output 'IN.csv' and the input 'IN.csv' are the same file" stats IN.csv -o IN.csv
expect_error "stats --json the input" "" "--json 'IN.csv' and the input 'IN.csv'" stats IN.csv --json IN.csv
expect_error "stats --rdf the input" "" "--rdf 'IN.csv' and the input 'IN.csv'" stats IN.csv --rdf IN.csv
expect_error "stats --spectrum over the input" "" "--spectrum \(IN.csv\) and the input 'IN.csv'" stats IN.csv --spectrum IN
expect_error "stats --spectrum's radial file over the input" "" "--spectrum \(P_radial.csv\) and the input" \
  stats P_radial.csv --spectrum P
expect_error "stats -o a link to the input" "" "--output 'link.csv' and the input 'IN.csv'" stats IN.csv -o link.csv
expect_error "stats the link, -o its target" "" "--output 'IN.csv' and the input 'link.csv'" stats link.csv -o IN.csv
expect_error "stats -o t/../IN.csv" "" "same file" stats IN.csv -o t/../IN.csv
expect_error "stats -o ./IN.csv" "" "same file" stats --input IN.csv -o ./IN.csv
expect_error "stats -o a hard link of the input" "" "--output 'hard.csv' and the input 'IN.csv'" stats IN.csv -o hard.csv
expect_error "stats -o the second input" "" "and the input 'IN.csv'" stats made/sobol.csv IN.csv -o "$work/inputs/IN.csv"
"$bin" stats --format csv -o IN.csv - <IN.csv >"$work/out" 2>"$work/err"
[[ $? -ne 0 ]] && grep -q "and standard input are the same file" "$work/err" && ok || bad "stats - <IN -o IN: $(cat "$work/err")"
"$bin" stats IN.csv >>IN.csv 2>"$work/err"
[[ $? -ne 0 ]] && grep -q "standard output and the input 'IN.csv'" "$work/err" && ok || bad "stats IN >>IN: $(cat "$work/err")"
expect_error "field --input F -o F" "" "--output 'IN.csv' and --input 'IN.csv'" field --dim 2 --input IN.csv -o IN.csv
"$bin" field --dim 2 -o IN.csv <IN.csv >"$work/out" 2>"$work/err"
[[ $? -ne 0 ]] && grep -q "and standard input are the same file" "$work/err" && ok || bad "field <IN -o IN: $(cat "$work/err")"
expect_error "field --lift npy:H -o H" "0.5,0.5\n" "--output 'H.npy' and --lift npy:'H.npy'" field --dim 2 --lift npy:H.npy -o H.npy
cp H.npy cnj.npy && before_cnj=$(cksum <cnj.npy)
expect_error "sample --lift npy:F --points over F" "" "--points \(cnj.npy\) and --lift npy:'cnj.npy'" \
  --dim 2 --grid 4 --domain cube --methods cnj --lift npy:cnj.npy --points . --format npy --quiet
[[ $(cat IN.csv P_radial.csv H.npy | cksum) == "$before" && $(cksum <cnj.npy) == "$before_cnj" ]] && ok ||
  bad "an input was changed by a refused run"
[[ -z $(find . -name '*.tmp.*' -o -name 'IN.json' -o -name 'IN.png' -o -name 'P.*' | head -1) ]] && ok ||
  bad "a refused run wrote: $(find . -newer made | head -3)"
cd "$work" || exit 1

# ---------------------------------------------------------------------------------------------------
# Values that must be refused, not wrapped or guessed.
for seed in -1 18446744073709551616 '' 0x10 1e3; do
  expect_error "seed '$seed'" "" "" --dim 3 --grid 4 --methods jitter --seed "$seed"
  expect_message "seed '$seed'" "--seed: must be an integer in 0\.\.18446744073709551615"
done
expect_error "seed in field" "0,0\n" "" field --dim 2 --seed -1
expect_error "seed in table1" "" "" reproduce table1 --seed -1 --out "$work/r1bad"
"$bin" --dim 3 --grid 4 --methods jitter --seed 18446744073709551615 --quiet >/dev/null && ok || bad "seed 2^64 - 1 refused"
expect_error "rdf-queries -1" "" "" --dim 3 --grid 4 --methods jitter --rdf "$work/q.csv" --rdf-queries -1
expect_error "CSV +-1" "+-1,2\n" "" field --dim 2
expect_message "CSV +-1" "line 1, column 1: '\+-1' is not a number"
expect_error "CSV --1" "1,--1\n" "" field --dim 2
printf '+1,2\n' | "$bin" field --dim 2 >"$work/plus.csv" && [[ $(wc -l <"$work/plus.csv") -eq 2 ]] && ok || bad "+1 not read"
printf '"0.1","0.2","0.3"\n"0.4", "0.5" ,0.6\n' | "$bin" field --dim 3 >"$work/quoted.csv" 2>"$work/err" && ok ||
  bad "quoted numbers: $(cat "$work/err")"
[[ $(wc -l <"$work/quoted.csv") -eq 3 ]] && sed -n 2p "$work/quoted.csv" | grep -q "^0.10000000000000001,0.20000000000000001," && ok ||
  bad "quoted numbers were not read as the first data line: $(head -2 "$work/quoted.csv")"
printf '"x0","x1"\n1,2\n' | "$bin" field --dim 2 >"$work/qh.csv" && [[ $(wc -l <"$work/qh.csv") -eq 2 ]] && ok || bad "quoted header"
expect_error "header after data" "1,2\nx0,x1\n" "" field --dim 2
expect_message "header after data" "line 2, column 1: 'x0' is not a number"
expect_error "half-numeric header" "x0,1\n2,3\n" "" field --dim 2
expect_error "unterminated quote" '"1,2\n' "" field --dim 2
expect_message "unterminated quote" "line 1, column 1: unterminated quote"

# ---------------------------------------------------------------------------------------------------
# Messages: one clear line, the tool's own.
expect_error "threads -1 range" "" "" --threads -1
expect_message "threads -1 range" "1\.\.[0-9]+ \(4 x the [0-9]+ cores, at most 1024\), got '-1'"
# (pds: a method that cannot stream; jitter past the limit now streams by itself, tests/cli/test_cli_stream.sh)
expect_error "memory units" "" "" --dim 3 --grid 40 --methods pds --max-memory 0.001
expect_message "memory units" "about [0-9.]+ MiB of memory \(limit 1\.02 MiB\)"
if [[ ${DFVN_SANITIZED:-0} == 1 ]]; then
  echo "SKIP: allocation failure (AddressSanitizer aborts on an impossible allocation instead of throwing)"
else
  expect_error "allocation failure" "" "" --dim 8 --grid 100 --methods jitter --max-memory 1e300
  expect_message "allocation failure" "out of memory for the jitter point set: 10000000000000000 points in 8D need about [0-9.]+ EiB"
fi
expect_error "dims overflow" "" "" reproduce table1 --dims 99999999999 --out "$work/r1bad"
expect_message "dims overflow" "--dims: '99999999999' is not a dimension in 3\.\.7"
expect_error "unknown reproduce subcommand" "" "" reproduce table3
expect_message "unknown reproduce subcommand" "unknown reproduce subcommand 'table3'; did you mean table1 or table2\\?"
expect_error "missing reproduce subcommand" "" "" reproduce
expect_message "missing reproduce subcommand" "table1 or table2"
expect_error "unknown options in order" "" "" --dim 3 --bogus1 --bogus2 third
expect_message "unknown options in order" "'--bogus1' '--bogus2' 'third'"
python3 -c "print('1,' + 'a' * 1000000)" >"$work/megabyte.csv"
expect_error "1 MB field" "" "" field --dim 2 --input "$work/megabyte.csv"
expect_message "1 MB field" "'a{40}\.\.\.' \(1000000 bytes\)"
expect_error "escape bytes" "1,\033[31mred\n" "" field --dim 2
expect_message "escape bytes" "'\\\\x1B\[31mred'"
expect_error "NUL byte" "1,2\0z\n" "" field --dim 2
expect_message "NUL byte" "'2\\\\0z'"
expect_error "byte order mark" "1,2\n\xef\xbb\xbf3,4\n" "" field --dim 2
expect_message "byte order mark" "'\\\\xEF\\\\xBB\\\\xBF3'"
printf '\xef\xbb\xbfx0,x1\n1,2\n' | "$bin" field --dim 2 >"$work/bom.csv" && [[ $(wc -l <"$work/bom.csv") -eq 2 ]] && ok ||
  bad "byte order mark at the start of the file"
expect_error "escape bytes in an option" "" "" --dim 3 --protocol "$(printf 'x\033[2Jy')"
expect_message "escape bytes in an option" "'x\\\\x1B\[2Jy'"
expect_error "long option value" "" "" --dim 3 --methods "$(printf 'b%.0s' $(seq 1 5000))"
expect_message "long option value" "'b{40}\.\.\.' \(5000 bytes\)"
"$bin" --help-all >"$work/help-all" 2>&1 && grep -q -- "--frequency" "$work/help-all" && grep -q "table2" "$work/help-all" &&
  grep -q -- "--rdf-max" "$work/help-all" && ok || bad "--help-all: $(head -3 "$work/help-all")"

finish "cli hardening"
