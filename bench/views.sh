#!/usr/bin/env bash
# Benchmark: three views of the office rendered one run each (three solves), in
# one run with three --camera (one solve, three ray traces), and as solve --save followed by
# three runs of render --solution (one solve, three ray traces in separate processes). Prints each run's CPU seconds
# (user + sys, all threads, from the stage table) and wall seconds, and the stages of the
# single run.
# Usage: bench/views.sh [WIDTHxHEIGHT]   (default 640x480)
set -euo pipefail
cd "$(dirname "$0")/.."
rayrad=build/src/rayrad
[ -x "$rayrad" ] || scripts/build
size=${1:-640x480}
w=${size%x*} h=${size#*x}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cameras="[{\"name\": \"door\", \"position\": [0.4, 1.6, 0.4], \"look_at\": [4.0, 0.9, 6.5], \"resolution\": [$w, $h], \"vfov_deg\": 65},
 {\"name\": \"window\", \"position\": [5.6, 1.6, 7.6], \"look_at\": [2.0, 0.9, 1.0], \"resolution\": [$w, $h], \"vfov_deg\": 65},
 {\"name\": \"desk\", \"position\": [3.0, 1.2, 4.0], \"look_at\": [3.0, 0.75, 2.0], \"resolution\": [$w, $h], \"vfov_deg\": 60}]"
total() { awk '/^total/ {printf "%s CPU-s, %s s wall", $3, $2}' "$1"; }
sum=0
for view in door window desk; do
    "$rayrad" render scenes/office/office.json --set "cameras=$cameras" --camera "$view" -o "$tmp/$view.png" -q \
        > /dev/null 2> "$tmp/$view.err"
    echo "one run for $view: $(total "$tmp/$view.err")"
    sum=$(awk -v s="$sum" '/^total/ {print s + $3}' "$tmp/$view.err")
done
echo "three runs: $sum CPU-s"
"$rayrad" render scenes/office/office.json --set "cameras=$cameras" --camera door --camera window --camera desk \
    -o "$tmp/all.png" -q > /dev/null 2> "$tmp/all.err"
echo "one run, three --camera: $(total "$tmp/all.err")"
grep -E '^(direct light|secondary pass|reconstruct|ray trace|tone map)' "$tmp/all.err"
# Solve once and save; then each view in a run of its own from the saved solution.
"$rayrad" solve scenes/office/office.json --save "$tmp/office.rrs" -q > /dev/null 2> "$tmp/save.err"
echo "solve --save: $(total "$tmp/save.err")"
sum=$(awk '/^total/ {print $3}' "$tmp/save.err")
for view in door window desk; do
    "$rayrad" render scenes/office/office.json --set "cameras=$cameras" --camera "$view" --solution "$tmp/office.rrs" \
        -o "$tmp/$view.sol.png" -q > /dev/null 2> "$tmp/$view.sol.err"
    echo "render --solution, $view: $(total "$tmp/$view.sol.err")"
    sum=$(awk -v s="$sum" '/^total/ {print s + $3}' "$tmp/$view.sol.err")
done
echo "one solve + three renders from it: $sum CPU-s"
