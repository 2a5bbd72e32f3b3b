#!/usr/bin/env bash
# Benchmark: the paper's empty cube at 1 200 / 4 800 / 19 200 / 76 800 triangles with the
# default solver (1 % clusters). Prints solve time, total time, peak memory, bytes per
# patch above the libraries' baseline (flat: no links are stored) and the A/B/C indirect
# errors (gathered and vertex-reconstructed) per mesh.
# Usage: bench/cube_mesh_sweep.sh [max_edge ...]   (default: 1 0.5 0.25 0.125)
# Extra solver settings: SET="--set clusters.enabled=false" bench/cube_mesh_sweep.sh 0.5
set -euo pipefail
cd "$(dirname "$0")/.."
rayrad=build/src/rayrad
[ -x "$rayrad" ] || scripts/build
edges=("$@")
[ ${#edges[@]} -gt 0 ] || edges=(1 0.5 0.25 0.125)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

printf '%-9s %-7s %9s %9s %9s %9s  %-26s %-26s\n' triangles shots "solve s" "total s" "peak MiB" "B/patch" \
    "gathered err A/B/C %" "vertex err A/B/C %"
for e in "${edges[@]}"; do
    # shellcheck disable=SC2086
    "$rayrad" solve scenes/cube/cube.json --set radiosity.max_edge="$e" ${SET:-} --sensors "$tmp/s.csv" -q \
        > /dev/null 2> "$tmp/err.txt"
    patches=$(sed -n 's/^patches: \([0-9]*\),.*/\1/p' "$tmp/err.txt")
    shots=$(sed -n 's/^patches: [0-9]*, shots: \([0-9]*\),.*/\1/p' "$tmp/err.txt")
    solve=$(awk '/^secondary pass/ {print $(NF-1)}' "$tmp/err.txt")
    total=$(awk '/^total/ {print $2}' "$tmp/err.txt")
    peak=$(awk '/^total/ {print $3}' "$tmp/err.txt")
    base=$(awk '/^parse \+ build scene/ {print $NF}' "$tmp/err.txt")
    perpatch=$(awk -v p="$peak" -v b="$base" -v n="$patches" 'BEGIN {printf "%.0f", (p - b) * 1048576 / n}')
    # CSV columns: 15 = err_indirect_pct, 18 = err_indirect_vertex_pct
    gathered=$(awk -F, 'NR > 1 {printf "%s%+.2f", (NR > 2 ? "/" : ""), $15}' "$tmp/s.csv")
    vertex=$(awk -F, 'NR > 1 {printf "%s%+.2f", (NR > 2 ? "/" : ""), $18}' "$tmp/s.csv")
    printf '%-9s %-7s %9s %9s %9s %9s  %-26s %-26s\n' "$patches" "$shots" "$solve" "$total" "$peak" "$perpatch" \
        "$gathered" "$vertex"
done
echo "(peak MiB is the whole process, ~125 MiB of it libraries and runtime; B/patch is the peak above the"
echo " peak after parsing, per patch)"
