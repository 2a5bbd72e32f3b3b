#!/usr/bin/env bash
# docs/tutorial.md end to end: scripts/tutorial runs its every command; the results it
# shows are checked here.
set -u
rayrad="$1"
src="$2"
source "$(dirname "$0")/test_lib.sh"

RAYRAD="$rayrad" "$src/scripts/tutorial" "$work/t" > "$work/log.txt" 2>&1
check "tutorial exit 0" test $? -eq 0
check "step 1 finds the millimetres" grep -qF "bounds: (0, 0, 0) to (556, 548.79" "$work/t/first-look.txt"
check "step 1 finds Kd 1 clamped" grep -q "4 mesh-file materials had a reflectance above 0.95" "$work/t/first-look.txt"
check "step 2 reads the luminaire" grep -q "integrated flux: 4779.19 lm" "$work/t/luminaire.txt"
for f in room.png room.exr work-plane.png room-false-colour.png room.csv; do
    check "wrote $f" test -s "$work/t/$f"
done
check "work plane statistics leave out the points in the furniture" \
    grep -qE "^floor +35 .*\(14 more inside solids, left out\)" "$work/t/solve.txt"
finish tutorial
[ "$failures" -eq 0 ]
