#!/usr/bin/env bash
# Tiles through a Slurm job array, not in the default run: it installs Slurm and
# munge and makes this machine a one-node cluster (scripts/slurm/single-node, needs root).
# Four array tasks render four tiles from a saved solution; the merge is bit-identical to
# rendering the whole; a sweep's jobs run as a job array. Run: ctest -L slurm (from build/).
set -u
rayrad="$1"
src="$2"
source "$(dirname "$0")/test_lib.sh"

"$src/scripts/slurm/single-node" > "$work/setup.log" 2>&1
check "a one-node Slurm cluster is up" test $? -eq 0 || { cat "$work/setup.log"; finish slurm; exit 1; }
scene="$src/scenes/cornell/cornell.json"
set_args=(--set camera.resolution=[48,40] --set radiosity.max_edge=0.2)
"$rayrad" solve "$scene" "${set_args[@]}" --save "$work/cornell.rrs" -q > /dev/null 2>&1
"$rayrad" render "$scene" "${set_args[@]}" --solution "$work/cornell.rrs" -o "$work/whole.exr" -q > /dev/null 2>&1
(cd "$work" && sbatch --array=1-4 --wait "$src/scripts/slurm/render-tiles.sbatch" "$rayrad" "$scene" "$work/cornell.rrs" \
    "$work" "${set_args[@]}" > "$work/sbatch.log" 2>&1)
check "the job array ran" test $? -eq 0 -a -s "$work/tile4.exr"
"$rayrad" merge -o "$work/merged.exr" "$work"/tile*.exr > /dev/null 2>&1
check "merged" test $? -eq 0
check "bit-identical to the whole" cmp -s "$work/whole.exr" "$work/merged.exr"
# A sweep's four jobs as a job array (scripts/slurm/sweep.sbatch runs line K + 1).
"$rayrad" sweep "$scene" --vary radiosity.max_edge=0.25,0.2 --vary render.seed=1,2 \
    --run "solve -q --sensors $work/sweep{job}.csv" --jobs "$work/jobs.txt" > /dev/null 2>&1
(cd "$work" && sbatch --array=0-3 --wait "$src/scripts/slurm/sweep.sbatch" "$work/jobs.txt" > "$work/sweep.log" 2>&1)
check "the sweep's job array ran every job" test $? -eq 0 -a -s "$work/sweep0.csv" -a -s "$work/sweep3.csv"
finish slurm
