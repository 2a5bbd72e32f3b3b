#!/usr/bin/env bash
# Benchmark: rayrad on scenes nobody here made (bench/corpus/*/scene.json, each with its
# source and licence in its README, and the tutorial's room). Per scene: patches, the
# solve's CPU seconds, the sensors' CPU seconds a point, the sensors whose mesh value
# (what an image shows) is more than 5 % from their gather, the energy account, the
# warnings; then bench/surface_agreement at random points on the scene's surfaces and at
# the surfaces its camera sees through random pixels (what its image shows): the mesh
# against the gather, median and 95th percentile of |Δ| / total where the indirect light is
# at least 10 % of the total, and what a point's gather costs.
# Usage: bench/corpus.sh [POINTS (300)] [SCENE.json ...]   (default: every corpus scene;
#        POINTS 0: no surface_agreement. The FZK house's solve takes about 10 CPU-minutes and
#        its points tens of CPU-seconds each at its default mesh)
#        SET="--set KEY=VALUE ..." passes settings to both runs
set -euo pipefail
cd "$(dirname "$0")/.."
rayrad=build/src/rayrad
agreement=build/bench/surface_agreement
[ -x "$rayrad" ] && [ -x "$agreement" ] || scripts/build rayrad surface_agreement
points=${1:-300}
shift || true
scenes=("$@")
[ ${#scenes[@]} -gt 0 ] || scenes=(bench/corpus/*/scene.json scenes/tutorial/room.json)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
read -ra extra <<< "${SET:-}"
for scene in "${scenes[@]}"; do
    echo "== $scene"
    "$rayrad" solve "$scene" "${extra[@]}" --sensors "$tmp/s.csv" > /dev/null 2> "$tmp/err.txt" || {
        echo "solve failed:"; cat "$tmp/err.txt"; continue; }
    patches=$(sed -n 's/^patches: \([0-9]*\),.*/\1/p' "$tmp/err.txt")
    total=$(awk '/^total/ {print $3}' "$tmp/err.txt")
    sensors=$(awk '/^sensors \(/ {print $(NF-1)}' "$tmp/err.txt")
    count=$(($(wc -l < "$tmp/s.csv") - 1))
    echo "patches $patches; solve + sensors ${total} CPU-s, of it the $count sensors ${sensors:-0} CPU-s" \
        "($(awk -v s="${sensors:-0}" -v n="$count" 'BEGIN {printf "%.1f", n ? 1000 * s / n : 0}') ms a sensor)"
    python3 - "$tmp/s.csv" <<'PY'
import csv, sys
rows = [r for r in csv.DictReader(open(sys.argv[1])) if r.get("indirect_vertex_lx")]
off = []
for r in rows:
    g, m = float(r["indirect_lx"]), float(r["indirect_vertex_lx"])
    if g > 0 and abs(m - g) > 0.05 * g:
        off.append(f'{r["sensor"]} {100 * (m - g) / g:+.1f} %')
print(f"sensors on a surface: {len(rows)}, mesh more than 5 % from the gather: {len(off)}"
      + (" (" + ", ".join(off) + ")" if off else ""))
PY
    grep -E '^(energy|closure):' "$tmp/err.txt" || true
    echo "warnings: $(grep -c '^warning' "$tmp/err.txt" || true)"
    grep '^warning' "$tmp/err.txt" | cut -c1-200 || true
    if [ "$points" -gt 0 ]; then
        "$agreement" "$scene" "$points" "${extra[@]}" --both 2>&1 | grep -v -e '^  ' -e '^worst points'
    fi
done
