#!/usr/bin/env bash
# The tests: installs what is missing, then
#  1. builds in Release against the system's CGAL (with a smoke run of the
#     benchmark and the Python module) and runs the C++ suite with ctest;
#  1b. runs the README's demo (scripts/demo.sh) on that build, and installs
#     the Python package as a user does (pip install
#     --no-build-isolation . in a virtual environment on Debian's Python
#     packages, without network) and runs the Python tests on it;
#  2. builds again with AddressSanitizer and UndefinedBehaviorSanitizer and
#     runs it once more (RRHT_SANITIZE=0 skips this pass);
#  3. builds in Release and runs the suite, the Python tests included,
#     against each CGAL release of ../shared/cgal (5.6.1, 6.0.1, 6.2.1: see
#     its README), unpacked under build/cgal without installing anything,
#     and checks that the normals are the same, bit for bit, as with the
#     system's CGAL (skipped, with a message, when ../shared/cgal is absent;
#     RRHT_CGAL_VERSIONS=0 skips it);
#  4. builds in Release with clang and runs the suite, the Python tests
#     included (RRHT_CLANG=0 skips it);
#  5. builds the reference documentation with Doxygen (scripts/build_docs.sh),
#     which fails on any warning.
# Every build fails on a compiler warning.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
extra_packages=(--python doxygen)
[ "${RRHT_CLANG:-1}" != "0" ] && extra_packages+=(clang)
bash "$root/scripts/install_dependencies.sh" "${extra_packages[@]}"
jobs=$(nproc)
# Debian's Python, the one its python3-* packages are for (not a pyenv's).
python=/usr/bin/python3
[ -x "$python" ] || python=$(command -v python3)

run_suite() { # build folder, tests left out (a ctest regex, or ""), extra cmake arguments...
  local build=$1 excluded=$2; shift 2
  cmake -S "$root" -B "$build" -DCGAL_RRHT_BUILD_TESTS=ON -DCGAL_RRHT_BUILD_EXAMPLES=ON \
        -DCGAL_RRHT_WARNINGS_AS_ERRORS=ON "$@" > /dev/null
  cmake --build "$build" -j"$jobs"
  (cd "$build" && ctest --output-on-failure -j"$jobs" ${excluded:+-E "$excluded"})
}

# The same input and seed give the same normals, written exactly (17
# digits), with the rrht_normals of build $1 as with that of build $2.
same_normals() { # build, reference build
  local data=$root/examples/data runs=(
    ""
    "--setting paper_fast --sampling cubes"
    "--setting paper_fast --sampling unif --aggregation mean"
    "--radius 0.05 -k 0 --seed 7"
    "--setting paper_precise --radius 0.05 -k 30 --aggregation best --slices 12"
    "--setting paper_fast --refit"
    "--refit -k 40")
  local i=0
  for run in "${runs[@]}"; do
    for build in "$1" "$2"; do
      # shellcheck disable=SC2086
      "$build/examples/rrht_normals" "$data/fandisk_20k.xyz" "$build/same_normals_$i.xyz" $run --precision 17 -q > /dev/null
    done
    if ! cmp "$1/same_normals_$i.xyz" "$2/same_normals_$i.xyz"; then
      echo "different normals from $1 and $2 with: rrht_normals fandisk_20k.xyz $run" >&2
      return 1
    fi
    i=$((i + 1))
  done
  echo "same normals, bit for bit, as $2 (${#runs[@]} settings of rrht_normals on fandisk_20k.xyz)"
}

echo "== Release build and tests (system CGAL), the Python module's included"
# The Python tests run on the package that pip installs from this tree, below.
run_suite "$root/build/release" "^python_tests$" -DCMAKE_BUILD_TYPE=Release -DCGAL_RRHT_BUILD_BENCHMARKS=ON \
          -DCGAL_RRHT_BUILD_PYTHON=ON -DPython_EXECUTABLE="$python"

echo "== The README's first command: the demo (on the build above)"
bash "$root/scripts/demo.sh"

echo "== The Python package installed by pip in a virtual environment, and its tests"
venv=$root/build/venv
rm -rf "$venv"
"$python" -m venv --system-site-packages "$venv"
"$venv/bin/pip" install --no-build-isolation --no-index --quiet "$root"
(cd "$root/build" && "$venv/bin/python" -c "import cgal_rrht; print('testing', cgal_rrht.__file__)" &&
   CGAL_RRHT_CLI="$root/build/release/examples/rrht_normals" \
   "$venv/bin/python" -m pytest -q -rs -p no:cacheprovider "$root/python/tests")

if [ "${RRHT_SANITIZE:-1}" != "0" ]; then
  echo "== AddressSanitizer + UndefinedBehaviorSanitizer build and tests"
  ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
    # find_package_consumer builds a project of its own, without the sanitizers.
    run_suite "$root/build/sanitize" "^find_package_consumer$" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCGAL_RRHT_SANITIZE=ON
fi

if [ "${RRHT_CGAL_VERSIONS:-1}" != "0" ]; then
  shared_cgal=$root/../shared/cgal
  if [ ! -d "$shared_cgal" ]; then
    echo "== SKIPPED: the builds against CGAL 5.6.1, 6.0.1 and 6.2.1 ($shared_cgal not found)"
  else
    unpacked=$root/build/cgal
    mkdir -p "$unpacked"
    for version in 5.6.1 6.0.1 6.2.1; do
      if [ "$version" = 5.6.1 ]; then
        [ -d "$unpacked/CGAL-5.6.1" ] || tar -xJf "$shared_cgal/CGAL-5.6.1-headers.tar.xz" -C "$unpacked"
        cgal_dir=$unpacked/CGAL-5.6.1
      else
        [ -d "$unpacked/$version" ] || dpkg -x "$shared_cgal/libcgal-dev_${version}-1_amd64.deb" "$unpacked/$version"
        cgal_dir=$unpacked/$version/usr/lib/x86_64-linux-gnu/cmake/CGAL
      fi
      echo "== Release build and tests against CGAL $version"
      run_suite "$root/build/cgal-$version" "" -DCMAKE_BUILD_TYPE=Release -DCGAL_DIR="$cgal_dir" \
                -DCGAL_RRHT_BUILD_PYTHON=ON -DPython_EXECUTABLE="$python"
      same_normals "$root/build/cgal-$version" "$root/build/release"
    done
  fi
fi

echo "== Reference documentation (Doxygen, fails on any warning)"
bash "$root/scripts/build_docs.sh"

if [ "${RRHT_CLANG:-1}" != "0" ]; then
  echo "== Release build and tests with clang"
  run_suite "$root/build/clang" "" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=clang++ \
            -DCGAL_RRHT_BUILD_PYTHON=ON -DPython_EXECUTABLE="$python"
  same_normals "$root/build/clang" "$root/build/release"
fi
