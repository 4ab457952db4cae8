#!/usr/bin/env bash
# The main job: installs what is missing, builds (Release) and estimates the
# normals of the bundled fandisk point set (examples/data/fandisk_20k.xyz)
# with the command-line tool rrht_normals.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/scripts/install_dependencies.sh"
build="$root/build/release"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DCGAL_RRHT_BUILD_TESTS=OFF > /dev/null
cmake --build "$build" -j"$(nproc)" --target rrht_normals
output="$build/fandisk_20k_normals.xyz"
"$build/examples/rrht_normals" "$root/examples/data/fandisk_20k.xyz" "$output"
echo "Output: $output (one 'x y z nx ny nz' line per point)"
echo "Your own files: $build/examples/rrht_normals INPUT [OUTPUT] [options]  (--help lists them)"
