#!/usr/bin/env bash
# Command-line tests of the figures (src/plot/gnuplot.hpp) and of what `reproduce` prints: figures are
# drawn without a shell into folders of any name, a figure gnuplot cannot draw fails the command, a
# missing gnuplot only says how to get it, the terminal gets plain text, table1 has mean +- sd cells.
set -u
source "$(dirname "${BASH_SOURCE[0]}")/harness.sh"

is_png() { [[ -s $1 && $(head -c 8 "$1" | od -An -tx1 | tr -d ' \n') == 89504e470d0a1a0a ]]; }

command -v gnuplot >/dev/null || { echo "test_cli_figures: gnuplot is not installed (scripts/setup installs it)" >&2; exit 1; }

# A folder named it's: a single quote broke the shell commands that used to draw the figures.
odd="$work/it's here"
"$bin" reproduce table2 --width 32 --height 18 --second-width 16 --out "$odd/t2" --quiet >"$work/t2.txt" 2>"$work/err" \
  && ok || bad "table2 into $odd: $(cat "$work/err")"
is_png "$odd/t2/figure5.png" && ok || bad "table2 wrote no figure5.png into $odd"
! grep -q "not drawn" "$work/err" && ok || bad "table2: $(cat "$work/err")"
# The terminal gets plain text, the file keeps the Markdown.
! grep -q -e "<br>" -e "| ---" -e "\*\*[A-Z]" "$work/t2.txt" && ok || bad "table2 printed Markdown: $(grep -m1 -e '<br>' -e '| ---' -e '\*\*[A-Z]' "$work/t2.txt")"
grep -q "^| steps | reprojection |" "$odd/t2/table2.md" && ok || bad "table2.md lost its Markdown table"
grep -q "hardware threads" "$odd/t2/table2.md" && ok || bad "table2.md does not name the machine"

# Table 1 in 3D with two realizations: mean +- sd cells, the summary file, Figure 4, a reading about 3D only.
"$bin" reproduce table1 --dims 3 --realizations 2 --out "$odd/t1" --quiet >"$work/t1.txt" 2>"$work/err" \
  && ok || bad "table1 into $odd: $(cat "$work/err")"
is_png "$odd/t1/figure4.png" && ok || bad "table1 wrote no figure4.png into $odd"
grep -q "<br>" "$odd/t1/table1.md" && ! grep -q "<br>" "$work/t1.txt" && ok || bad "table1: <br> belongs in the file only"
grep -q "ours 0\.[0-9]* ± 0\.[0-9]* (0\.[0-9]* ± 0\.[0-9]*)" "$work/t1.txt" && ok || bad "table1 cells are not mean ± sd: $(cat "$work/t1.txt")"
grep -q "^\"Jittering\",3,10,jitter,nn_min,2," "$odd/t1/table1_summary.csv" \
  && ok || bad "table1_summary.csv has no jitter summary: $(cat "$odd/t1/table1_summary.csv")"
[[ $(grep -c '^"CNJ (simplex)",3,' "$odd/t1/table1.csv") -eq 2 ]] && ok || bad "table1.csv: 2 simplex rows, data only"
! grep -q -e "[4-7]D" "$odd/t1/table1.md" && ok || bad "table1 --dims 3 talks about other dimensions: $(grep -o -m3 '.\{30\}[4-7]D.\{30\}' "$odd/t1/table1.md")"
grep -q "Time\*\* on .*hardware threads" "$odd/t1/table1.md" && ok || bad "table1.md does not name the machine"
"$bin" reproduce table1 --realizations 0 --out "$work/bad" >/dev/null 2>"$work/err"; [[ $? -ne 0 ]] && grep -q "realizations" "$work/err" \
  && ok || bad "--realizations 0 accepted: $(cat "$work/err")"

# The spectrum and the integration figures, into the same folder.
printf 'x,y\n0.1,0.2\n0.5,0.7\n0.9,0.4\n0.3,0.8\n' >"$odd/p.csv"
"$bin" stats --input "$odd/p.csv" --spectrum "$odd/spec" --spectrum-frequency 4 --quiet >/dev/null 2>"$work/err" \
  && is_png "$odd/spec.png" && ok || bad "spectrum figure into $odd: $(cat "$work/err")"
"$bin" reproduce integration --dims 3 --realizations 2 --max-points 512 --methods jitter,random --out "$odd/int" --quiet \
  >/dev/null 2>"$work/err" && is_png "$odd/int/integration_3d.png" && ok || bad "integration figure into $odd: $(cat "$work/err")"

# A gnuplot that fails: the command fails with gnuplot's reason, and leaves no figure.
mkdir -p "$work/broken" "$work/silent" "$work/nognuplot"
printf '#!/bin/sh\necho "gnuplot here: broken on purpose" >&2\nexit 3\n' >"$work/broken/gnuplot"
printf '#!/bin/sh\nexit 0\n' >"$work/silent/gnuplot"
chmod +x "$work/broken/gnuplot" "$work/silent/gnuplot"
PATH="$work/broken:$PATH" "$bin" reproduce table2 --width 32 --height 18 --second-width 0 --out "$work/b2" --quiet >/dev/null 2>"$work/err"
rc=$?
[[ $rc -ne 0 ]] && grep -q "figure5.png.*not drawn: gnuplot (figure5.gp) failed with exit status 3: gnuplot here: broken on purpose" "$work/err" \
  && ok || bad "a failing gnuplot: rc=$rc, stderr: $(cat "$work/err")"
[[ ! -e $work/b2/figure5.png ]] && ok || bad "a failing gnuplot left figure5.png"
[[ -z $(find "$work/b2" -name '*.tmp*') ]] && ok || bad "a failing gnuplot left temporaries: $(ls "$work/b2")"
PATH="$work/silent:$PATH" "$bin" stats --input "$odd/p.csv" --spectrum "$work/s2" --spectrum-frequency 4 --quiet >/dev/null 2>"$work/err"
rc=$?
[[ $rc -ne 0 ]] && grep -q "s2.png.*not drawn: gnuplot (spectrum.gp) wrote no image" "$work/err" && [[ ! -e $work/s2.png ]] \
  && ok || bad "a gnuplot that draws nothing: rc=$rc, stderr: $(cat "$work/err")"

# No gnuplot at all: the tables are written, the command succeeds and says how to get the figure.
PATH="$work/nognuplot" "$bin" reproduce table2 --width 32 --height 18 --second-width 0 --out "$work/n2" --quiet >/dev/null 2>"$work/err"
rc=$?
[[ $rc -eq 0 && -s $work/n2/table2.md && ! -e $work/n2/figure5.png ]] && grep -q "figure5.png.*gnuplot is not installed.*apt-get install gnuplot-nox" "$work/err" \
  && ok || bad "no gnuplot: rc=$rc, stderr: $(cat "$work/err")"

finish "cli_figures"
