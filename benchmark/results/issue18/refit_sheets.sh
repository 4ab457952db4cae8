#!/usr/bin/env bash
# The runs of the fourth session behind refit_sheets.txt (see README.md): two parallel
# sheets for thin parts. From the top folder of the repository, with refit_quadric.cpp
# built as /tmp/refit_quadric.
source "$(dirname "$0")/refit_run.sh"
L="MODE=1 QQ=25 FLOOR=0.01 MAXANG=20 KJ=100" # refit(true) as it landed before; jet with the same K
sharp=("cube 0.2" "fandisk 0.2" "corner 0.2" "cylinder 0.2")
run "before: the landed refit, 0.5% then 1% thick" "$L" "box 0.2" "sheet 0.2"
run "before, 1%" "$L T=1" "box 0.2" "sheet 0.2"
run "two sheets (quadrics, all neighbors) where the refit is not kept, 1% thick" "$L TWOSHEET=1 T=1" "box 0.2"
run "two sheets before the refit wherever they pass the refit's gate, 0.5%" "$L TWOSHEET=1 TWOFIRST=0" "box 0.2" "sphere 0.2" "bunny00 0.2" "${sharp[@]}"
run "the same, 1%" "$L TWOSHEET=1 TWOFIRST=0 T=1" "box 0.2"
G="MINSIDE=0.15 OFFC=0.3 PARA=10"
run "two sheets where the refit is not kept, with the smaller sheet >= 15%, under the point, parallel within 10 degrees" "$L TWOSHEET=1 $G" "box 0.2" "cube 0.2" "fandisk 0.2"
run "the same, planes instead of quadrics, fitted on the band after the first fit" "$L TWOSHEET=1 $G TWOQUAD=0 TWOBAND=1" "box 0.2" "${sharp[@]}"
run "the same, 1%" "$L TWOSHEET=1 $G TWOQUAD=0 TWOBAND=1 T=1" "box 0.2"
run "how far apart the two sheets are, in deviations of their residuals (both passes; RRHT above 10 degrees in brackets)" "$L $G TWOQUAD=0 TWOBAND=1 GAPHIST=1 TWOFIRST=100 OWNSPREAD=1" "box 0.2" "sphere 0.2" "bunny00 0.2" "cube 0.2" "fandisk 0.2"
run "the same, 1%" "$L $G TWOQUAD=0 TWOBAND=1 GAPHIST=1 TWOFIRST=100 OWNSPREAD=1 T=1" "box 0.2"
S="$L $G TWOQUAD=0 TWOBAND=1 OWNSPREAD=1 TWOFIRST=4"
run "two sheets first where they are 4 deviations apart, else the refit" "$S" "box 0.2" "sheet 0.2" "sphere 0.2" "bunny00 0.2" "${sharp[@]}"
run "the same, 1%" "$S T=1" "box 0.2" "sheet 0.2"
run "two planes by total least squares, everywhere, 0.5% and 1%" "$L $G TWOTLS=1 TWOBAND=1 TWOFIRST=0" "box 0.2" "sheet 0.2"
run "two planes by least squares, everywhere, 0.5%" "$L $G TWOQUAD=0 TWOBAND=1 TWOFIRST=0" "box 0.2" "sheet 0.2"
run "and jet's normal where every neighbor lies within 3 deviations of the refit (ALLIN=3)" "$S ALLIN=3" "box 0.2" "sheet 0.2" "${sharp[@]}"
run "the same, 1%" "$S ALLIN=3 T=1" "box 0.2" "sheet 0.2"
run "ALLIN=4" "$S ALLIN=4" "box 0.2" "sheet 0.2" "fandisk 0.2" "corner 0.2"
run "ALLIN=3, where the cylinder loses: the smaller sheet >= 25%" "$S ALLIN=3 MINSIDE=0.25" "cylinder 0.2" "sphere 0"
run "the same, 1%" "$S ALLIN=3 MINSIDE=0.25 T=1" "box 0.2" "sheet 0.2"
run "the same with quadrics for the two sheets" "$S ALLIN=3 MINSIDE=0.25 TWOQUAD=1" "sphere 0" "cube 0.2"
F="$S ALLIN=3 MINSIDE=0.25 RING=1"
run "what landed: planes, the other sheet not a ring around a cap (RING=1); LIB=1 runs the library's refit(true)" "$F LIB=1" "box 0.2" "sheet 0.2" "sphere 0.2" "sphere 0" "bunny00 0.2" "${sharp[@]}" "cube 1"
run "what landed, 1% then 2% thick" "$F LIB=1 T=1" "box 0.2" "sheet 0.2"
run "what landed, 2%" "$F LIB=1 T=2" "box 0.2" "sheet 0.2"
run "what landed, with jet K = 80, on the clean point sets" "$F KJ=80" "kitten 0" "bunny100k 0" "fandisk100k 0"
