#!/usr/bin/env bash
# The tests: installs what is missing, then runs four passes, each printing
# its wall time, and a summary of them at the end (CONTRIBUTING.md says why
# the passes are these):
#  1. gcc, Release, against the system's CGAL: every target (the benchmark
#     with a smoke run), the C++ suite and the examples with their outputs
#     checked, through ctest; the README's demo (scripts/demo.sh) on that
#     build; the Python package installed as a user does (pip install
#     --no-build-isolation . in a virtual environment on Debian's Python
#     packages, without network) and its whole pytest suite on it.
#  2. clang with AddressSanitizer and UndefinedBehaviorSanitizer: the C++
#     suite and the examples again, through ctest, and the same normals, bit
#     for bit, as pass 1's (RRHT_SANITIZE=0 skips it).
#  3. Against each CGAL release of ../shared/cgal (5.6.1, 6.0.1, 6.2.1: see
#     its README), unpacked under build/cgal without installing anything:
#     every public header, rrht_normals and the Python module built, the
#     interface's tests (named parameters, ranges, kernels, Point_set_3, the
#     orientation) and the binding's (against rrht_normals, the orientation)
#     run, and the same normals, bit for bit, as pass 1's (skipped, saying
#     so, when ../shared/cgal is absent; RRHT_CGAL_VERSIONS=0 skips it).
#  4. The reference documentation with Doxygen (scripts/build_docs.sh),
#     which fails on any warning.
# Every build fails on a compiler warning. The switches that skip a pass are
# for local use: CI (.ci/run) runs every pass. RRHT_CCACHE=1 compiles through
# ccache (Debian's package), so that a developer's fresh clone reuses the
# objects of an earlier clone's run; CI's runs are cold.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
jobs=$(nproc)
# Debian's Python, the one its python3-* packages are for (not a pyenv's).
python=/usr/bin/python3

# Each pass prints its wall time when it ends; the summary lists them all,
# and which pass failed, if one did.
summary=() pass_name="" pass_start=0
minutes() { printf '%d min %02d s' $(($1 / 60)) $(($1 % 60)); }
end_pass() {
  [ -n "$pass_name" ] || return 0
  local took=$((SECONDS - pass_start))
  echo "== $pass_name: passed in $(minutes $took)"
  summary+=("$(printf '%-14s %s' "$(minutes $took)" "$pass_name")")
  pass_name=""
}
begin_pass() { end_pass; pass_name=$1; pass_start=$SECONDS; echo; echo "== $pass_name"; }
skip_pass() { # pass, why
  end_pass
  echo; echo "== SKIPPED: $1 ($2)"
  summary+=("$(printf '%-14s %s' skipped "$1 ($2)")")
}
print_summary() {
  local status=$?
  if [ -n "$pass_name" ]; then
    if [ "$status" -eq 0 ]; then end_pass; else
      summary+=("$(printf '%-14s %s' "$(minutes $((SECONDS - pass_start)))" "$pass_name: FAILED")")
    fi
  fi
  echo; echo "== Summary (wall time of each pass)"
  printf '  %s\n' "${summary[@]}"
  echo "  $(minutes $SECONDS) in all: $([ "$status" -eq 0 ] && echo passed || echo FAILED)"
}
trap print_summary EXIT

configure() { # build folder, extra cmake arguments...
  local build=$1; shift
  cmake -S "$root" -B "$build" -DCGAL_RRHT_BUILD_TESTS=ON -DCGAL_RRHT_BUILD_EXAMPLES=ON \
        -DCGAL_RRHT_WARNINGS_AS_ERRORS=ON "$@" > /dev/null
}
run_ctest() { # build folder, tests left out (a ctest regex, or "")
  (cd "$1" && ctest --output-on-failure -j"$jobs" ${2:+-E "$2"})
}
# pytest with this Python on the cgal_rrht it imports (named first) and the
# rrht_normals of $CGAL_RRHT_CLI.
run_pytest() { # python, test files or folders...
  local python=$1; shift
  (cd "$root/build" && "$python" -c "import cgal_rrht; print('testing', cgal_rrht.__file__)" &&
     "$python" -m pytest -q -rs -p no:cacheprovider "$@")
}

# The same input and seed give the same normals, written exactly (17
# digits), with the rrht_normals of build $1 as with pass 1's.
normal_runs=(
  ""
  "--setting paper_fast --sampling cubes"
  "--setting paper_fast --sampling unif --aggregation mean"
  "--radius 0.05 -k 0 --seed 7"
  "--setting paper_precise --radius 0.05 -k 30 --aggregation best --slices 12"
  "--setting paper_fast --refit"
  "--refit -k 40")
write_normals() { # build folder: writes its same_normals/<i>.xyz
  local i=0
  rm -rf "$1/same_normals" && mkdir -p "$1/same_normals"
  for run in "${normal_runs[@]}"; do
    # shellcheck disable=SC2086
    "$1/examples/rrht_normals" "$root/examples/data/fandisk_20k.xyz" "$1/same_normals/$i.xyz" $run \
      --precision 17 -q > /dev/null
    i=$((i + 1))
  done
}
reference=$root/build/release
same_normals() { # build folder
  write_normals "$1"
  local i=0
  for run in "${normal_runs[@]}"; do
    if ! cmp "$1/same_normals/$i.xyz" "$reference/same_normals/$i.xyz"; then
      echo "different normals from $1 and $reference with: rrht_normals fandisk_20k.xyz $run" >&2
      return 1
    fi
    i=$((i + 1))
  done
  echo "same normals, bit for bit, as $reference (${#normal_runs[@]} settings of rrht_normals on fandisk_20k.xyz)"
}

begin_pass "Set-up: the Debian packages that are missing"
extra_packages=(--python doxygen)
[ "${RRHT_SANITIZE:-1}" != "0" ] && extra_packages+=(clang)
bash "$root/scripts/install_dependencies.sh" "${extra_packages[@]}"
[ -x "$python" ] || python=$(command -v python3)
if [ "${RRHT_CCACHE:-0}" = "1" ]; then
  command -v ccache > /dev/null || bash "$root/scripts/install_dependencies.sh" ccache
  # Paths relative to the clone, so that another clone's objects match.
  export CMAKE_CXX_COMPILER_LAUNCHER=ccache CCACHE_BASEDIR=$root CCACHE_NOHASHDIR=1
fi

begin_pass "1. gcc, Release, system CGAL: C++ suite and examples, the README's demo, the pip-installed package's pytest suite"
configure "$reference" -DCMAKE_BUILD_TYPE=Release -DCGAL_RRHT_BUILD_BENCHMARKS=ON
cmake --build "$reference" -j"$jobs"
run_ctest "$reference" ""
write_normals "$reference"
echo "-- The README's first command: the demo (on the build above)"
bash "$root/scripts/demo.sh"
echo "-- The Python package installed by pip in a virtual environment, and its tests"
venv=$root/build/venv
rm -rf "$venv"
"$python" -m venv --system-site-packages "$venv"
"$venv/bin/pip" install --no-build-isolation --no-index --quiet "$root"
CGAL_RRHT_CLI="$reference/examples/rrht_normals" run_pytest "$venv/bin/python" "$root/python/tests"

if [ "${RRHT_SANITIZE:-1}" != "0" ]; then
  begin_pass "2. clang with AddressSanitizer and UndefinedBehaviorSanitizer: C++ suite and examples, the same normals"
  # Line tables are what the sanitizers' reports need; full debug information
  # of CGAL's templates makes each object three times as large.
  configure "$root/build/sanitize" -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
            "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2 -gline-tables-only -DNDEBUG" -DCGAL_RRHT_SANITIZE=ON
  cmake --build "$root/build/sanitize" -j"$jobs"
  # find_package_consumer builds a project of its own, without the sanitizers.
  ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 run_ctest "$root/build/sanitize" "^find_package_consumer$"
  same_normals "$root/build/sanitize"
else
  skip_pass "2. clang with the sanitizers" "RRHT_SANITIZE=0"
fi

shared_cgal=$root/../shared/cgal
if [ "${RRHT_CGAL_VERSIONS:-1}" = "0" ]; then
  skip_pass "3. CGAL 5.6.1, 6.0.1 and 6.2.1" "RRHT_CGAL_VERSIONS=0"
elif [ ! -d "$shared_cgal" ]; then
  skip_pass "3. CGAL 5.6.1, 6.0.1 and 6.2.1" "$shared_cgal not found"
else
  unpacked=$root/build/cgal
  mkdir -p "$unpacked"
  for version in 5.6.1 6.0.1 6.2.1; do
    begin_pass "3. CGAL $version: public headers, interface tests, Python binding, the same normals"
    if [ "$version" = 5.6.1 ]; then
      [ -d "$unpacked/CGAL-5.6.1" ] || tar -xJf "$shared_cgal/CGAL-5.6.1-headers.tar.xz" -C "$unpacked"
      cgal_dir=$unpacked/CGAL-5.6.1
    else
      [ -d "$unpacked/$version" ] || dpkg -x "$shared_cgal/libcgal-dev_${version}-1_amd64.deb" "$unpacked/$version"
      cgal_dir=$unpacked/$version/usr/lib/x86_64-linux-gnu/cmake/CGAL
    fi
    build=$root/build/cgal-$version
    configure "$build" -DCMAKE_BUILD_TYPE=Release -DCGAL_DIR="$cgal_dir" \
              -DCGAL_RRHT_BUILD_PYTHON=ON -DPython_EXECUTABLE="$python"
    # rrht_interface_tests compiles every public header on its own.
    cmake --build "$build" -j"$jobs" --target rrht_interface_tests rrht_normals cgal_rrht_core
    "$build/test/rrht_interface_tests" --warn NoTests
    PYTHONPATH="$build/python" CGAL_RRHT_CLI="$build/examples/rrht_normals" \
      run_pytest "$python" "$root/python/tests/test_cli_identity.py" "$root/python/tests/test_orient.py"
    same_normals "$build"
  done
fi

begin_pass "4. Reference documentation (Doxygen, fails on any warning)"
bash "$root/scripts/build_docs.sh"
