#!/usr/bin/env bash
# The runs of the third session behind refit_variants.txt (see README.md), from
# the top folder of the repository, with refit_quadric.cpp built as /tmp/refit_quadric.
set -u
q=/tmp/refit_quadric
run() { # label, environment, clouds...
  local label=$1 environment=$2; shift 2
  echo "== $label: $environment"
  for cloud in "$@"; do env $environment $q $cloud; done
}
L="MODE=1 QQ=25 FLOOR=0.01 MAXANG=20" # refit(true) as it landed
seven=("sphere 0.2" "bunny00 0.2" "cube 0.2" "fandisk 0.2" "corner 0.2" "box 0.2" "sheet 0.2")
run "landed: which points are refitted, which keep RRHT's normal" "$L SPLIT=1" "sphere 0.2" "bunny00 0.2" "corner 0.2"
run "landed, the quartile raised by 15% (it is 0.87 of the true noise on the sphere)" "$L QC=1.15" "${seven[@]}"
run "one noise for the cloud: the median of all points' own" "FLOOR=0.01 MAXANG=20 MODE=2" "${seven[@]}"
run "the smaller of the cloud's and the median of the neighbors'" "FLOOR=0.01 MAXANG=20 MODE=3 QQ=50" "${seven[@]}" "cylinder 0.2"
run "landed, with weights exp(-d^2 / 2 0.6^2)" "$L W=0.6" "sphere 0.2" "bunny00 0.2" "box 0.2"
run "the box against jet with the same K: quadric on all neighbors, frames iterated" "$L KAPPA=100 OUT=1 MAXANG=90 FRAMES=3 KJ=100" "box 0.2"
run "the same in the frame of their PCA (jet fitting)" "$L KAPPA=100 OUT=1 MAXANG=90 PCAFRAME=1 KJ=100" "box 0.2"
run "landed: where the box's normals above 10 degrees are" "$L RIM=1 KJ=100" "box 0.2"
run "landed, each fit in the frame of its band's PCA" "$L PCAIN=1 KJ=100" "${seven[@]}"
run "MODE 3, each fit in its band's PCA frame, jet's normal where every neighbor is within 4 deviations" "FLOOR=0.01 MAXANG=20 MODE=3 QQ=50 PCAIN=1 ALLIN=4 KJ=100" "${seven[@]}"
run "the same, a band of 3 deviations" "FLOOR=0.01 MAXANG=20 MODE=3 QQ=50 PCAIN=1 ALLIN=4 KAPPA=3 KJ=100" "box 0.2" "sheet 0.2" "fandisk 0.2" "corner 0.2"
run "landed, 1% thick" "$L T=1 KJ=100" "box 0.2" "sheet 0.2"
run "MODE 3 with PCA frames and jet's normal, 1% thick" "FLOOR=0.01 MAXANG=20 MODE=3 QQ=50 PCAIN=1 ALLIN=4 T=1 KJ=100" "box 0.2" "sheet 0.2"
run "landed, the clean point sets where their given normals agree and elsewhere" "$L CONSIST=1" "kitten 0" "bunny100k 0" "fandisk100k 0"
run "the paper's fast setting (300 planes, 2 rotations) with the landed refit" "$L PLANES=300 ROT=2" "${seven[@]}" "cylinder 0.2"
run "landed, and jet's normal where every neighbor lies within 3 deviations (0.5%, then 1% thick)" "$L ALLIN=3 KJ=100" "box 0.2" "sheet 0.2"
run "the same, 1% thick" "$L ALLIN=3 KJ=100 T=1" "box 0.2" "sheet 0.2"
run "the same, only where the residuals' kurtosis is at least 2.1 (two sides 5 deviations apart: 1.51)" "$L ALLIN=3 KURT=2.1 KJ=100" "box 0.2" "sheet 0.2"
run "the same, 1% thick" "$L ALLIN=3 KURT=2.1 KJ=100 T=1" "box 0.2" "sheet 0.2"
run "landed, RRHT's normal kept where the kurtosis is below 2" "$L KURTALL=2 KJ=100" "box 0.2" "sheet 0.2" "cube 0.2" "fandisk 0.2"
run "the same, 1% thick" "$L KURTALL=2 KJ=100 T=1" "box 0.2" "sheet 0.2"
run "the median of the neighbors' kurtosis instead of the point's own: RRHT's normal kept below 2" "$L KAVG=1 KURTALL=2 KJ=100" "box 0.2" "sheet 0.2"
run "the same, 1% thick" "$L KAVG=1 KURTALL=2 KJ=100 T=1" "box 0.2" "sheet 0.2"
run "the same, below 2.2" "$L KAVG=1 KURTALL=2.2 KJ=100" "box 0.2" "sheet 0.2"
run "the same, 1% thick" "$L KAVG=1 KURTALL=2.2 KJ=100 T=1" "box 0.2" "sheet 0.2"
run "the same, below 2, and jet's normal where every neighbor is within 3 deviations and the kurtosis at least 2" "$L KAVG=1 ALLIN=3 KURT=2 KURTALL=2 KJ=100" "box 0.2" "sheet 0.2"
run "the same, 1% thick" "$L KAVG=1 ALLIN=3 KURT=2 KURTALL=2 KJ=100 T=1" "box 0.2" "sheet 0.2"
