#!/usr/bin/env bash
# The runs of refit_quadric.cpp behind refit_quadric.txt (see README.md), from
# the top folder of the repository, with the program built as /tmp/refit_quadric.
source "$(dirname "$0")/refit_run.sh"
smooth_sharp_thin=("sphere 0.2" "bunny00 0.2" "cube 0.2" "fandisk 0.2" "corner 0.2" "box 0.2")
run "the point's own noise, a plane" "QUAD=0" "${smooth_sharp_thin[@]}"
run "the point's own noise, a quadric" "QUAD=1" "${smooth_sharp_thin[@]}"
run "the point's own noise, a wider band" "KAPPA=3" "${smooth_sharp_thin[@]}"
run "an oracle: the true noise" "SIG=0.002" "${smooth_sharp_thin[@]}"
run "the median of the neighbors' noise" "MODE=1 QQ=50" "${smooth_sharp_thin[@]}"
run "their first quartile" "MODE=1 QQ=25" "${smooth_sharp_thin[@]}"
run "landed (refit(true))" "MODE=1 QQ=25 FLOOR=0.01 MAXANG=20" "${smooth_sharp_thin[@]}" "cylinder 0.2" "sheet 0.2" "sphere 0"
run "landed, jet with K = 100" "MODE=1 QQ=25 FLOOR=0.01 MAXANG=20 KJ=100" "sphere 0.2" "bunny00 0.2" "box 0.2" "sheet 0.2"
run "landed, a second frame" "MODE=1 QQ=25 FLOOR=0.01 MAXANG=20 FRAMES=2" "${smooth_sharp_thin[@]}"
run "landed, 2 more outliers allowed" "MODE=1 QQ=25 FLOOR=0.01 MAXANG=20 SLACK=2" "${smooth_sharp_thin[@]}"
run "landed, K = 30 (jet K = 30)" "MODE=1 QQ=25 FLOOR=0.01 MAXANG=20 K=30 KJ=30" "cube 0.2" "box 0.2"
run "landed, the tails of the clean point sets (histograms of RRHT, refit, jet)" "MODE=1 QQ=25 FLOOR=0.01 MAXANG=20 HIST=1" "kitten 0" "bunny100k 0" "fandisk100k 0"
run "the point's own noise, a quadric: the cube's points made worse" "QUAD=1 DIAG=1" "cube 0.2"
run "the landed refit only where the RRHT confidence is at least 0.08" "MODE=1 QQ=25 FLOOR=0.01 MAXANG=20 CONF=0.08" "sphere 0.2" "bunny00 0.2" "cube 0.2" "fandisk 0.2" "box 0.2"
