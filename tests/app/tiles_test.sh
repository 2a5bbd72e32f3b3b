#!/usr/bin/env bash
# Tiles: a saved solution rendered as 4 tiles by GNU parallel on this machine
# (-S : is the local host, as a list of hosts would be), merged: the EXR is bit-identical
# to rendering the whole image; a missing or repeated tile is refused.
set -u
rayrad="$1"
src="$2"
source "$(dirname "$0")/test_lib.sh"

if ! command -v parallel > /dev/null; then
    echo "FAIL GNU parallel is not installed (scripts/install-deps installs it)"
    exit 1
fi
scene="$src/scenes/cornell/cornell.json"
set_args=(--set camera.resolution=[48,40] --set radiosity.max_edge=0.2)
"$rayrad" solve "$scene" "${set_args[@]}" --save "$work/cornell.rrs" -q > /dev/null 2>&1
check "solve --save" test -s "$work/cornell.rrs"
"$rayrad" render "$scene" "${set_args[@]}" --solution "$work/cornell.rrs" -o "$work/whole.exr" -q > /dev/null 2>&1
check "the whole image" test -s "$work/whole.exr"
parallel --will-cite -S : "$rayrad" render "$scene" "${set_args[@]}" --solution "$work/cornell.rrs" --tile {}/4 \
    -o "$work/tile{}.exr" -q ::: 1 2 3 4 > /dev/null 2> "$work/parallel.err"
check "four tiles through GNU parallel" test $? -eq 0 -a -s "$work/tile4.exr"
"$rayrad" merge -o "$work/merged.exr" -o "$work/merged.png" "$work/tile3.exr" "$work/tile1.exr" "$work/tile4.exr" \
    "$work/tile2.exr" > /dev/null 2>&1
check "merge exit 0" test $? -eq 0
check "merged EXR bit-identical to the whole" cmp -s "$work/whole.exr" "$work/merged.exr"
check "merged PNG" test -s "$work/merged.png"
"$rayrad" merge -o "$work/m2.exr" "$work/tile1.exr" "$work/tile2.exr" "$work/tile3.exr" > /dev/null 2> "$work/missing.err"
check "a missing tile is exit 2" test $? -eq 2
check "names it" grep -q "missing tile(s) 4 of 4" "$work/missing.err"
"$rayrad" merge -o "$work/m2.exr" "$work/tile1.exr" "$work/tile1.exr" "$work/tile3.exr" "$work/tile4.exr" > /dev/null 2> "$work/twice.err"
check "a repeated tile is exit 2" grep -q "tile 1/4 is given twice" "$work/twice.err"
check "nothing written" test ! -e "$work/m2.exr"
finish tiles
