#!/usr/bin/env bash
# `cmake --install` into a temporary prefix, then use the installed tree as a user would: the binary,
# the man page and completion, a consumer project built with find_package(dfvn) and with
# pkg-config, whose field values must equal the installed dfvn-sample's to the last bit, and the Python
# package dfvn (imported from the prefix's site folder, and from `pip install .`'s wheel).
# Environment: DFVN_BUILD_DIR, DFVN_SOURCE_DIR, DFVN_LIBDIR (CMAKE_INSTALL_LIBDIR), DFVN_DATA_DIR,
# DFVN_MAN_PAGE (1 when help2man made one), CXX (the compiler), DFVN_PYTHON (the interpreter the module is
# built for; empty when it is not built) and DFVN_PYTHON_INSTALL_DIR (its folder under the prefix).
set -euo pipefail
: "${DFVN_BUILD_DIR:?}" "${DFVN_SOURCE_DIR:?}" "${DFVN_LIBDIR:?}" "${DFVN_DATA_DIR:?}" "${DFVN_MAN_PAGE:?}" "${CXX:?}"
: "${DFVN_PYTHON=}" "${DFVN_PYTHON_INSTALL_DIR=}"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

cmake --install "$DFVN_BUILD_DIR" --prefix "$work/install" >/dev/null
# The tree is relocatable: everything below is used from where it was moved to.
mv "$work/install" "$work/moved"
prefix=$work/moved

for path in bin/dfvn-sample "$DFVN_LIBDIR/libdfvn.so" include/dfvn/field/dfvn_field.hpp \
            include/dfvn/experiment/experiment.hpp "$DFVN_LIBDIR/cmake/dfvn/dfvnConfig.cmake" \
            "$DFVN_LIBDIR/cmake/dfvn/dfvnConfigVersion.cmake" "$DFVN_LIBDIR/cmake/dfvn/dfvnTargets.cmake" \
            "$DFVN_LIBDIR/pkgconfig/dfvn.pc" "$DFVN_DATA_DIR/figure4.gp" \
            share/bash-completion/completions/dfvn-sample; do
  [[ -e $prefix/$path ]] || fail "not installed: $path"
done
# Only the public API is installed: headers of private dependencies (OpenMP, nanoflann), template
# internals, the reproductions, the plots and the command line's text helpers stay private.
for path in include/dfvn/core/parallel.hpp include/dfvn/stats/kd_tree.hpp include/dfvn/integrate/trace_impl.hpp \
            include/dfvn/io/markdown_text.hpp include/dfvn/core/message_text.hpp include/dfvn/plot/gnuplot.hpp \
            include/dfvn/reproduce/reproduce.hpp include/dfvn/reproduce/cnj_study.hpp; do
  [[ ! -e $prefix/$path ]] || fail "installed, but private: $path"
done
# The umbrella <dfvn/dfvn.hpp> includes exactly the installed headers.
installed=$(cd "$prefix/include" && find dfvn -name '*.hpp' ! -path dfvn/dfvn.hpp | sort)
umbrella=$(sed -n 's@^#include "\(dfvn/.*\.hpp\)"$@\1@p' "$prefix/include/dfvn/dfvn.hpp" | sort)
[[ $installed == "$umbrella" ]] ||
  fail "<dfvn/dfvn.hpp> and the installed headers differ: $(diff <(echo "$umbrella") <(echo "$installed") | grep '^[<>]' | tr '\n' ' ')"
# Every include inside the installed headers is rooted at dfvn/ (a bare "core/x.hpp" would resolve
# against the user's own folders).
if grep -rnE '^\s*#\s*include\s+["<](core|experiment|field|integrate|io|noise|quadrature|sampling|stats|warp)/' \
     "$prefix/include/dfvn"; then
  fail "an installed header includes a library header without the dfvn/ root"
fi
echo "ok: the tree"

# The installed binary runs from the moved tree, finding its library without LD_LIBRARY_PATH.
version=$(env -u LD_LIBRARY_PATH "$prefix/bin/dfvn-sample" --version </dev/null)
[[ $version == "dfvn-sample "[0-9]* ]] || fail "--version printed '$version'"
echo "ok: $version"
# dfvn-sample-mpi, installed when built (-DDFVN_MPI=ON), finds libdfvn the same way.
if [[ -e $prefix/bin/dfvn-sample-mpi ]]; then
  version=$(env -u LD_LIBRARY_PATH "$prefix/bin/dfvn-sample-mpi" --version </dev/null)
  [[ $version == "dfvn-sample-mpi "[0-9]* ]] || fail "dfvn-sample-mpi --version printed '$version'"
  [[ $DFVN_MAN_PAGE != 1 || -e $prefix/share/man/man1/dfvn-sample-mpi.1 ]] || fail "no man page of dfvn-sample-mpi"
  [[ -e $prefix/share/bash-completion/completions/dfvn-sample-mpi ]] || fail "no completion of dfvn-sample-mpi"
  echo "ok: $version"
fi

if [[ $DFVN_MAN_PAGE == 1 ]]; then
  man_page=$prefix/share/man/man1/dfvn-sample.1
  [[ -e $man_page ]] || fail "help2man is there but the man page is not installed"
  grep -q '^\.TH DFVN-SAMPLE "1"' "$man_page" || fail "the man page has no .TH DFVN-SAMPLE header"
  grep -q 'dim' "$man_page" || fail "the man page does not show the options of --help"
  # Made from --help-all: a section per subcommand, reproduce's included, with their options.
  for section in sample field stats reproduce "reproduce table1" "reproduce table2" "reproduce cnj-study" \
    "reproduce integration"; do
    grep -q "^\.SS \"dfvn-sample $section:\"" "$man_page" || fail "the man page has no section for $section"
  done
  for option in 'cycles\\-per\\-spacing' 'second\\-width' 'max\\-points' 'diagnose\\-points' 'spectrum\\-frequency'; do
    grep -q -- "$option" "$man_page" || fail "the man page does not show --${option//\\\\/}"
  done
  for section in "EXIT STATUS" ENVIRONMENT FILES; do  # from cmake/dfvn-sample.h2m
    grep -Eq "^\.SH \"?$section\"?$" "$man_page" || fail "the man page has no $section section"
  done
  grep -q 'TMPDIR' "$man_page" && grep -q 'OMP_NUM_THREADS' "$man_page" && grep -q 'sidecar' "$man_page" ||
    fail "the man page does not name TMPDIR, OMP_NUM_THREADS and the sidecar"
  grep -q 'command line could not be parsed' "$man_page" || fail "the man page's EXIT STATUS does not say what 2 means"
  echo "ok: the man page"
fi

# Every public header compiles on its own include path (no private dependency, no missing include).
pc_path=$prefix/$DFVN_LIBDIR/pkgconfig
read -r -a cflags <<<"$(PKG_CONFIG_PATH=$pc_path pkg-config --cflags dfvn)"
read -r -a libs <<<"$(PKG_CONFIG_PATH=$pc_path pkg-config --libs dfvn)"
[[ " ${cflags[*]} " == *" -I$pc_path/"* ]] || fail "pkg-config --cflags gives '${cflags[*]}', not this prefix"
[[ " ${cflags[*]} " != *"/include/dfvn "* ]] || fail "pkg-config --cflags adds include/dfvn: '${cflags[*]}'"
(cd "$prefix/include" && find dfvn -name '*.hpp' | sort | sed 's/.*/#include <&>/') >"$work/all_headers.cpp"
"$CXX" -std=c++20 -fsyntax-only "${cflags[@]}" "$work/all_headers.cpp" || fail "the installed headers do not compile"
echo "ok: $(wc -l <"$work/all_headers.cpp") headers compile"

# The field at one point, from the installed command line: its c0..c2 columns.
point=(0.25 -1.5 3.125)
expected=$(printf '%s,%s,%s\n' "${point[@]}" |
  "$prefix/bin/dfvn-sample" field --dim 3 --seed 7 --frequency 0.5 --noise turning-bands | tail -n 1 | cut -d, -f4-6)
[[ -n $expected ]] || fail "dfvn-sample field printed nothing"

# A consumer project configured against the installed package: find_package(dfvn) -> dfvn::dfvn.
cmake -S "$DFVN_SOURCE_DIR/tests/install/consumer" -B "$work/consumer" -DCMAKE_PREFIX_PATH="$prefix" \
      -DCMAKE_CXX_COMPILER="$CXX" -DCMAKE_BUILD_TYPE=Release >"$work/configure.log" 2>&1 ||
  { cat "$work/configure.log" >&2; fail "the consumer project does not configure"; }
cmake --build "$work/consumer" >"$work/build.log" 2>&1 || { cat "$work/build.log" >&2; fail "the consumer does not build"; }
got=$("$work/consumer/consumer" "${point[@]}")
[[ $got == "$expected" ]] || fail "find_package consumer: c = $got, dfvn-sample field: $expected"
echo "ok: find_package(dfvn) consumer: c = $got"

# The same consumer compiled by hand with pkg-config, its own folders first on the include path, as
# README shows it; the rpath comes from `pkg-config --libs`, so it runs without LD_LIBRARY_PATH.
"$CXX" -std=c++20 -I"$DFVN_SOURCE_DIR/tests/install/consumer" "${cflags[@]}" \
       "$DFVN_SOURCE_DIR/tests/install/consumer/main.cpp" "${libs[@]}" -o "$work/consumer_pc" ||
  fail "the pkg-config build fails"
got=$(env -u LD_LIBRARY_PATH "$work/consumer_pc" "${point[@]}")
[[ $got == "$expected" ]] || fail "pkg-config consumer: c = $got, dfvn-sample field: $expected"
echo "ok: pkg-config consumer: c = $got"

# The Python package, from the moved prefix's site folder: the interpreter finds it with that folder on
# PYTHONPATH, and the module finds the installed libdfvn through its relative rpath (no LD_LIBRARY_PATH).
# Run from an empty folder, so that nothing of the source or build tree is imported instead.
if [[ -n $DFVN_PYTHON ]]; then
  site=$prefix/$DFVN_PYTHON_INSTALL_DIR
  [[ -e $site/dfvn/__init__.py && -e $site/dfvn/qmc.py ]] || fail "the Python package is not in $site/dfvn"
  mkdir "$work/elsewhere"
  probe='import dfvn, sys; assert dfvn.__file__.startswith(sys.argv[1]), dfvn.__file__; print(dfvn.Sobol(3, seed=5).random(4).tobytes().hex())'
  from_prefix=$(cd "$work/elsewhere" && env -u LD_LIBRARY_PATH PYTHONPATH="$site" "$DFVN_PYTHON" -c "$probe" "$site") ||
    fail "import dfvn from $site fails"
  # With prefix /usr/local the same folder is on the interpreter's own path: no setting needed there.
  "$DFVN_PYTHON" -c 'import sys; p = "/usr/local/" + sys.argv[1]; assert p in sys.path, p + " not in " + str(sys.path)' \
    "$DFVN_PYTHON_INSTALL_DIR" || fail "cmake --install --prefix /usr/local would put dfvn off the interpreter's path"
  echo "ok: import dfvn from <prefix>/$DFVN_PYTHON_INSTALL_DIR"
  # pip install . --no-build-isolation, offline, from this build tree (DFVN_CMAKE_BUILD_DIR: no second build):
  # the wheel holds the package and libdfvn; the same points as the cmake-installed package.
  if "$DFVN_PYTHON" -m pip --version >/dev/null 2>&1; then
    DFVN_CMAKE_BUILD_DIR=$DFVN_BUILD_DIR PIP_NO_INPUT=1 "$DFVN_PYTHON" -m pip install "$DFVN_SOURCE_DIR" --no-build-isolation \
      --no-deps --no-index --target "$work/pip" >"$work/pip.log" 2>&1 || { cat "$work/pip.log" >&2; fail "pip install . fails"; }
    from_wheel=$(cd "$work/elsewhere" && env -u LD_LIBRARY_PATH PYTHONPATH="$work/pip" "$DFVN_PYTHON" -c "$probe" "$work/pip") ||
      fail "import dfvn from pip's install fails"
    [[ $from_wheel == "$from_prefix" ]] || fail "pip's dfvn and cmake's dfvn give other points"
    echo "ok: pip install . --no-build-isolation"
  else
    echo "skipped: pip install . ($DFVN_PYTHON has no pip: apt-get install python3-pip)"
  fi
fi
