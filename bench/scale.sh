#!/usr/bin/env bash
# Scale benchmark. For the paper's empty cube at each max_edge (default 1 0.5
# 0.25 0.125 0.0625: 1 200 … 307 200 triangles; add 0.03125 for 1.2 M) it prints the
# shots, the CPU seconds (user + sys, all threads) of each stage, wall time, peak memory,
# bytes per patch above the peak after parsing, the growth exponent of the total CPU time
# against the previous row (log(t2/t1)/log(N2/N1)) and the gathered indirect error at the
# three sensors A/B/C (against Table 1; the Monte Carlo reference is 0.07–0.09 % above it).
# Usage: bench/scale.sh [max_edge ...]
#        bench/scale.sh --living-room [max_seconds]   (the living room, mirrors on, defaults: solve and
#                                                      a 1280 x 720, 4 spp render, as target
#                                                      counts them; stage table; the solve stops at
#                                                      max_seconds, default 1800)
#        bench/scale.sh --hall                        (bench/hall.py: 100 troffers, 104 k patches;
#                                                      solve + 1280 x 1024 render at 4 spp, stage table)
# Extra settings: SET="--set clusters.enabled=false" bench/scale.sh 0.5
set -euo pipefail
cd "$(dirname "$0")/.."
rayrad=build/src/rayrad
[ -x "$rayrad" ] || scripts/build
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

if [ "${1:-}" = "--living-room" ]; then
    scene=scenes/living-room/living-room.json
    [ -f "$scene" ] || { echo "bench/scale.sh: $scene not found" >&2; exit 2; }
    # shellcheck disable=SC2086
    "$rayrad" render "$scene" --set radiosity.max_seconds="${2:-1800}" --set 'camera.resolution=[1280,720]' \
        --spp 4 ${SET:-} -o "$tmp/living-room.exr" -q > /dev/null 2> "$tmp/err.txt" || true
    grep -v '^warning' "$tmp/err.txt"
    exit 0
fi

if [ "${1:-}" = "--hall" ]; then
    bench/hall.py > "$tmp/hall.json"
    # shellcheck disable=SC2086
    "$rayrad" render "$tmp/hall.json" ${SET:-} -o "$tmp/hall.png" -q > /dev/null 2> "$tmp/err.txt"
    grep -v '^warning' "$tmp/err.txt"
    exit 0
fi

edges=("$@")
[ ${#edges[@]} -gt 0 ] || edges=(1 0.5 0.25 0.125 0.0625)
# The stage table's CPU column of the stage whose name starts with $1 (0 when not run).
cpu_of() { awk -v s="$1" 'index($0, s) == 1 && /[0-9]/ {v = $(NF-1)} END {print v + 0}' "$tmp/err.txt"; }

printf '%-8s %-6s %8s %8s %8s %8s %8s %8s %9s %8s %8s %7s %5s  %s\n' patches shots premesh direct clusters \
    shooting vertices sensors "CPU s" "wall s" "peak MiB" B/patch "N^x" "gathered err A/B/C %"
prevN=0 prevT=0
for e in "${edges[@]}"; do
    # shellcheck disable=SC2086
    "$rayrad" solve scenes/cube/cube.json --set radiosity.max_edge="$e" ${SET:-} --sensors "$tmp/s.csv" -q \
        > /dev/null 2> "$tmp/err.txt"
    patches=$(sed -n 's/^patches: \([0-9]*\),.*/\1/p' "$tmp/err.txt")
    shots=$(sed -n 's/^patches: .* shots: \([0-9]*\),.*/\1/p' "$tmp/err.txt")
    total=$(awk '/^total/ {print $3}' "$tmp/err.txt")
    wall=$(awk '/^total/ {print $2}' "$tmp/err.txt")
    peak=$(awk '/^total/ {print $4}' "$tmp/err.txt")
    base=$(awk '/^parse \+ build scene/ {print $NF}' "$tmp/err.txt")
    perpatch=$(awk -v p="$peak" -v b="$base" -v n="$patches" 'BEGIN {printf "%.0f", (p - b) * 1048576 / n}')
    growth=$(awk -v n="$patches" -v t="$total" -v pn="$prevN" -v pt="$prevT" \
        'BEGIN {if (pn > 0 && pt > 0) printf "%.2f", log(t / pt) / log(n / pn); else printf "-"}')
    # CSV column 15 = err_indirect_pct
    gathered=$(awk -F, 'NR > 1 {printf "%s%+.2f", (NR > 2 ? "/" : ""), $15}' "$tmp/s.csv")
    printf '%-8s %-6s %8.2f %8.2f %8.2f %8.2f %8.2f %8.2f %9.2f %8.2f %8.1f %7s %5s  %s\n' "$patches" "$shots" \
        "$(cpu_of premesh)" "$(cpu_of 'direct light')" "$(cpu_of clusters)" "$(cpu_of 'secondary pass')" \
        "$(cpu_of 'reconstruct vertices')" "$(cpu_of sensors)" "$total" "$wall" "$peak" "$perpatch" "$growth" \
        "$gathered"
    prevN=$patches prevT=$total
done
echo "(CPU s: user + sys of all threads per stage; peak MiB is the whole process, ~11 MiB of it the program and its libraries;"
echo " B/patch is the peak above the peak after parsing, per patch; N^x: growth of the total CPU s from the row above)"
