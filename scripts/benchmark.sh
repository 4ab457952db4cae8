#!/usr/bin/env bash
# The comparison benchmark (benchmark/README.md): installs what is missing,
# builds it optimized, runs it and writes CSV, Markdown tables, plots and
# renderings to benchmark/results/MODE.
#
#   bash scripts/benchmark.sh [quick|full] [more rrht_benchmark options]
#   bash scripts/benchmark.sh poisson [more poisson_benchmark options]
#
# RRHT_BENCHMARK_RESULTS=NAME writes to benchmark/results/NAME instead.
# poisson: the Poisson surfaces against the true meshes (poisson_benchmark,
# about 30 minutes) and their pictures, into benchmark/results/poisson.
#
# quick takes minutes, full hours. PCL and Open3D are compared too when
# Debian's libpcl-dev and libopen3d-dev are installed (RRHT_BENCHMARK_PCL=1
# and RRHT_BENCHMARK_OPEN3D=1 install them).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
mode=${1:-quick}
shift || true
case "$mode" in quick|full|poisson) ;; *) echo "usage: $0 [quick|full|poisson] [options of the benchmark]" >&2; exit 1 ;; esac
program=rrht_benchmark
[ "$mode" = poisson ] && program=poisson_benchmark

extra=(python3-matplotlib) # report.py's plots, poisson_pictures.py's pictures
[ "${RRHT_BENCHMARK_PCL:-0}" = 1 ] && extra+=(libpcl-dev)
[ "${RRHT_BENCHMARK_OPEN3D:-0}" = 1 ] && extra+=(libopen3d-dev)
bash "$root/scripts/install_dependencies.sh" "${extra[@]}"

# The commit the results are of: taken before the build, so that an edit
# made while the benchmark builds or runs does not mark it dirty.
commit=$(git -C "$root" describe --always --dirty 2>/dev/null || echo unknown)
build="$root/build/benchmark"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DCGAL_RRHT_BUILD_BENCHMARKS=ON \
      -DCGAL_RRHT_BUILD_TESTS=OFF -DCGAL_RRHT_BUILD_EXAMPLES=OFF > /dev/null
cmake --build "$build" -j"$(nproc)" --target "$program"

results=${RRHT_BENCHMARK_RESULTS:-$mode}
out="$root/benchmark/results/$results"
scratch="$build/errors-${results//\//-}"
rm -rf "$out" "$scratch"
mkdir -p "$out" "$scratch"
{
  peers="${RRHT_BENCHMARK_PCL:+RRHT_BENCHMARK_PCL=$RRHT_BENCHMARK_PCL }${RRHT_BENCHMARK_OPEN3D:+RRHT_BENCHMARK_OPEN3D=$RRHT_BENCHMARK_OPEN3D }"
  echo "Command: \`$peers${RRHT_BENCHMARK_RESULTS:+RRHT_BENCHMARK_RESULTS=$results }bash scripts/benchmark.sh $mode${*:+ $*}\` at commit $commit, $(date -u '+%Y-%m-%d %H:%M UTC')."
  echo "Machine: $(lscpu | sed -n 's/^Model name: *//p' | head -1), $(nproc) cores, $(free -g | awk '/^Mem:/ {print $2}') GiB;" \
       "$(g++ --version | head -1); CGAL $(dpkg-query -W -f='${Version}' libcgal-dev);" \
       "PCL: $(dpkg-query -W -f='${Version}' libpcl-dev 2>/dev/null || echo 'not installed');" \
       "Open3D: $(dpkg-query -W -f='${Version}' libopen3d-dev 2>/dev/null || echo 'not installed')."
} > "$out/machine.txt"
if [ "$mode" = poisson ]; then
  "$build/benchmark/poisson_benchmark" --out "$out" --scratch "$scratch" --data "$root/../shared/data" "$@" |
    tee "$build/benchmark-${results//\//-}.log"
  /usr/bin/python3 "$root/benchmark/poisson_pictures.py" "$out" "$scratch"
  /usr/bin/python3 "$root/benchmark/report_poisson.py" "$out"
  { echo "# Benchmark results"; echo; cat "$out/machine.txt"; echo; echo "- [Poisson surfaces against the true meshes](poisson.md)"; } > "$out/README.md"
else
  "$build/benchmark/rrht_benchmark" --mode "$mode" --out "$out" --scratch "$scratch" \
      --data "$root/../shared/data" "$@" | tee "$build/benchmark-${results//\//-}.log"
  /usr/bin/python3 "$root/benchmark/report.py" "$out" --scratch "$scratch"
fi
echo "Results: $out/README.md"
