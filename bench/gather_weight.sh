#!/usr/bin/env bash
# Benchmark: what the sensor gather's re-gathers cost and what they change. Solves SCENE
# once (or takes a saved solution), then runs bench/surface_agreement at the same random
# points with radiosity.gather_min_weight at each of WEIGHTS (and gather_levels 1), and
# prints per setting the median and 90th percentile of a point's gather CPU time and how
# far its gathered values lie from the first setting's, point by point (95th percentile
# and max of |Δ| / the point's total light, over the points whose indirect light is at
# least 10 % of their total).
# Usage: bench/gather_weight.sh SCENE.json [POINTS (100)] [WEIGHTS ("0.01 0.03 0.1 0.2")]
#        SOLUTION=FILE.rrs takes a solution saved by `rayrad solve SCENE --save FILE.rrs`
#        (otherwise one is solved and saved in a temporary directory first); VIEW=1 takes
#        the pixels of the scene's camera view instead of points spread over its surfaces.
set -euo pipefail
cd "$(dirname "$0")/.."
[ $# -ge 1 ] || { sed -n 2,13p "$0"; exit 2; }
scene=$1
points=${2:-100}
read -ra weights <<< "${3:-0.01 0.03 0.1 0.2}"
rayrad=build/src/rayrad
agreement=build/bench/surface_agreement
[ -x "$rayrad" ] && [ -x "$agreement" ] || scripts/build rayrad surface_agreement
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
solution=${SOLUTION:-}
if [ -z "$solution" ]; then
    solution=$tmp/solution.rrs
    echo "solving $scene once ..."
    "$rayrad" solve "$scene" -q --save "$solution" > /dev/null 2> "$tmp/solve.err" || { cat "$tmp/solve.err"; exit 1; }
fi
where=()
[ "${VIEW:-0}" = 1 ] && where=(--view)
run() {  # name, settings...
    local name=$1
    shift
    "$agreement" "$scene" "$points" "$@" "${where[@]}" --solution="$solution" --csv="$tmp/$name.csv" \
        > "$tmp/$name.txt" 2>&1
}
names=()
for w in "${weights[@]}"; do
    run "w$w" "radiosity.gather_min_weight=$w"
    names+=("w$w")
done
run levels1 radiosity.gather_levels=1
names+=(levels1)
python3 - "$tmp" "${names[@]}" <<'PY'
import csv, statistics, sys
tmp, names = sys.argv[1], sys.argv[2:]
rows = {n: list(csv.DictReader(open(f"{tmp}/{n}.csv"))) for n in names}
first = rows[names[0]]
def pct(values, q):
    values = sorted(values)
    return values[min(len(values) - 1, int(q * len(values)))] if values else float("nan")
def label(n):
    return "min_weight " + n[1:] if n.startswith("w") else "gather_levels 1"
print(f"{'setting':>16} {'points':>6} {'median ms':>10} {'p90 ms':>9} {'gathers med':>12}   "
      f"against {label(names[0])}: p95 / max of |Δ| / total")
for n in names:
    r = rows[n]
    cpu = [1000 * float(x["cpu_s"]) for x in r]
    gathers = [int(x["gathers"]) for x in r]
    diffs = []
    for a, b in zip(first, r):
        assert a["x"] == b["x"], "the settings took different points"
        total = float(a["direct_lx"]) + float(a["gather_indirect_lx"])
        if total > 0 and float(a["gather_indirect_lx"]) >= 0.1 * total:
            diffs.append(100 * abs(float(b["gather_indirect_lx"]) - float(a["gather_indirect_lx"])) / total)
    print(f"{label(n):>16} {len(r):>6} {statistics.median(cpu):>10.1f} {pct(cpu, 0.9):>9.1f} "
          f"{statistics.median(gathers):>12.0f}   {pct(diffs, 0.95):.2f} / {max(diffs, default=0):.2f} %")
PY
