#!/usr/bin/env bash
# Determinism: the same scene, seed and options give bit-identical EXR,
# PNG and CSV files, whatever the thread count; another seed gives another image.
set -u
rayrad="$1"
src="$2"
source "$(dirname "$0")/test_lib.sh"

# The Cornell box: coloured (three channels), clusters, corrections, conservation, overshooting;
# a 12 x 10 floor grid, so the sensors run in several runs with memos of their own, in parallel.
cornell=("$src/scenes/cornell/cornell.json" --set radiosity.max_edge=0.1 --set camera.resolution=[48,48]
         --set "sensor_grids.0.counts=[12,10]" -q)
for run in 1 2; do
    for threads in 1 2; do
        "$rayrad" render "${cornell[@]}" --threads $threads -o "$work/c$run$threads.exr" -o "$work/c$run$threads.png" \
            --sensors "$work/c$run$threads.csv" > /dev/null 2>&1
        check "cornell render $run, $threads threads: exit 0" test $? -eq 0
    done
done
for ext in exr png csv; do
    check "cornell $ext: two runs identical" cmp -s "$work/c11.$ext" "$work/c21.$ext"
    check "cornell $ext: 1 and 2 threads identical" cmp -s "$work/c11.$ext" "$work/c12.$ext"
done
"$rayrad" render "${cornell[@]}" --seed 2 -o "$work/seed2.exr" > /dev/null 2>&1
check "cornell: seed 2 gives another image" test "$(cmp -s "$work/c11.exr" "$work/seed2.exr"; echo $?)" -eq 1

# The mirror room: virtual lights and shooters.
mirrors=("$src/scenes/mirror_room/mirror_room.json" --set radiosity.max_edge=0.4 -q)
for threads in 1 2; do
    "$rayrad" solve "${mirrors[@]}" --threads $threads --sensors "$work/m$threads.csv" > /dev/null 2>&1
    check "mirror room solve, $threads threads: exit 0" test $? -eq 0
done
check "mirror room csv: 1 and 2 threads identical" cmp -s "$work/m1.csv" "$work/m2.csv"

finish determinism
