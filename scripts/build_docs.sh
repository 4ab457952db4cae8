#!/usr/bin/env bash
# Builds the reference documentation (HTML) with Doxygen: installs Doxygen
# when it is missing (Debian package `doxygen`, with
# scripts/install_dependencies.sh), runs it on doc/Doxyfile from doc/, and
# writes build/doc/html/ (open build/doc/html/index.html; build/ is
# git-ignored). Fails on any warning of Doxygen (doc/Doxyfile sets
# WARN_AS_ERROR = FAIL_ON_WARNINGS, and this script also fails if Doxygen
# writes anything to stderr), and if a name of an internal namespace of RRHT
# reaches the HTML.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
command -v doxygen > /dev/null || bash "$root/scripts/install_dependencies.sh" doxygen

out=$root/build/doc
rm -rf "$out"
mkdir -p "$out"
status=0
(cd "$root/doc" && doxygen Doxyfile) > "$out/doxygen.log" 2> "$out/warnings.log" || status=$?
if [ "$status" -ne 0 ] || [ -s "$out/warnings.log" ]; then
  cat "$out/warnings.log" >&2
  echo "Doxygen failed (exit status $status) or warned: see above, or $out/warnings.log" >&2
  exit 1
fi

# CGAL::RRHT::internal, CGAL::RRHT::internal_np, CGAL::RRHT::parameters::internal
# (and these names unqualified) must not appear; CGAL's own
# CGAL::internal_np::... may, in the signatures of the named-parameter chains.
leaks=$(grep -rnoP '(RRHT|parameters)::internal|(?<!CGAL::)(?<![\w:])internal(_np)?::' "$out/html" || true)
if [ -n "$leaks" ]; then
  echo "$leaks" >&2
  echo "internal names of RRHT in the reference documentation: see above" >&2
  exit 1
fi
# The user manual shows pictures of benchmark/results by their path from
# doc/, which the HTML keeps: the same path from build/doc/html.
for picture in $(grep -oP '\]\(\.\./\Kbenchmark/results/[^)]+' "$root/doc/user_manual.md"); do
  mkdir -p "$out/$(dirname "$picture")"
  cp "$root/$picture" "$out/$picture"
done
echo "documentation built without warnings (doxygen $(doxygen --version)): $out/html/index.html"
