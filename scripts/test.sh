#!/usr/bin/env bash
# The tests: installs what is missing, builds in Release (with a smoke run of
# the benchmark) and runs the whole suite with ctest, then builds again with AddressSanitizer and
# UndefinedBehaviorSanitizer and runs it once more (RRHT_SANITIZE=0 skips
# that second pass).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/scripts/install_dependencies.sh"
jobs=$(nproc)

run_suite() { # build folder, extra cmake arguments...
  local build=$1; shift
  cmake -S "$root" -B "$build" -DCGAL_RRHT_BUILD_TESTS=ON -DCGAL_RRHT_BUILD_EXAMPLES=ON "$@" > /dev/null
  cmake --build "$build" -j"$jobs"
  (cd "$build" && ctest --output-on-failure -j1)
}

echo "== Release build and tests"
run_suite "$root/build/release" -DCMAKE_BUILD_TYPE=Release -DCGAL_RRHT_BUILD_BENCHMARKS=ON
if [ "${RRHT_SANITIZE:-1}" != "0" ]; then
  echo "== AddressSanitizer + UndefinedBehaviorSanitizer build and tests"
  ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
    run_suite "$root/build/sanitize" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCGAL_RRHT_SANITIZE=ON
fi
