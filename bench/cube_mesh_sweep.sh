#!/usr/bin/env bash
# Benchmark: the paper's empty cube at 1200 / 4800 / 19200 (optionally 76800) triangles,
# baseline (non-clustered) progressive radiosity. Prints solve time, total time, peak
# memory and the A/B/C errors (gathered and vertex-reconstructed) per mesh.
# Usage: bench/cube_mesh_sweep.sh [max_edge ...]   (default: 1 0.5 0.25)
set -euo pipefail
cd "$(dirname "$0")/.."
rayrad=build/src/rayrad
[ -x "$rayrad" ] || scripts/build
edges=("$@")
[ ${#edges[@]} -gt 0 ] || edges=(1 0.5 0.25)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

printf '%-9s %-7s %9s %9s %9s %9s  %-26s %-26s\n' triangles shots "solve s" "total s" "peak MiB" "B/patch" \
    "gathered err A/B/C %" "vertex err A/B/C %"
for e in "${edges[@]}"; do
    "$rayrad" solve scenes/cube/cube.json --set radiosity.max_edge="$e" --sensors "$tmp/s.csv" -q \
        > /dev/null 2> "$tmp/err.txt"
    patches=$(sed -n 's/^patches: \([0-9]*\),.*/\1/p' "$tmp/err.txt")
    shots=$(sed -n 's/^patches: [0-9]*, shots: \([0-9]*\),.*/\1/p' "$tmp/err.txt")
    solve=$(awk '/^secondary pass/ {print $(NF-1)}' "$tmp/err.txt")
    total=$(awk '/^total/ {print $2}' "$tmp/err.txt")
    peak=$(awk '/^total/ {print $3}' "$tmp/err.txt")
    perpatch=$(awk -v p="$peak" -v n="$patches" 'BEGIN {printf "%.0f", p * 1048576 / n}')
    # CSV columns: 15 = err_indirect_pct, 18 = err_indirect_vertex_pct
    gathered=$(awk -F, 'NR > 1 {printf "%s%+.2f", (NR > 2 ? "/" : ""), $15}' "$tmp/s.csv")
    vertex=$(awk -F, 'NR > 1 {printf "%s%+.2f", (NR > 2 ? "/" : ""), $18}' "$tmp/s.csv")
    printf '%-9s %-7s %9s %9s %9s %9s  %-26s %-26s\n' "$patches" "$shots" "$solve" "$total" "$peak" "$perpatch" \
        "$gathered" "$vertex"
done
echo "(peak MiB is the whole process: the ~125 MiB floor is libraries and the TBB/Embree runtime)"
