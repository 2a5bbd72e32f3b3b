#!/usr/bin/env bash
# Benchmark: the closed diffuse sphere at ρ → 1. Radius 1, seen from inside,
# 100 cd off centre at (0.2, 0.4, 0.6); every point has E_ind = ρ/(1−ρ) Φ/A, A the
# polyhedron's area (method.md). Prints shots, solve + gather time, the gathered E_ind at
# three points with its error, the residual it stopped at, and the energy account, with
# overshooting on (the default) and off.
# Usage: bench/stiff_sphere.sh [subdivisions]   (default 30: 10 800 patches)
# Plain shooting at ρ = 0.99 is run to a 1 % residual only (it takes minutes).
set -euo pipefail
cd "$(dirname "$0")/.."
rayrad=build/src/rayrad
[ -x "$rayrad" ] || scripts/build
subdivisions=${1:-30}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

printf '%-6s %-10s %-9s %8s %9s  %-32s %-9s %-10s %s\n' rho overshoot stop shots "time s" "E_ind A / B / C lx" \
    "worst %" "residual" "not accounted"
run() {  # run RHO OVERSHOOT STOP
    cat > "$tmp/sphere.json" <<JSON
{"materials": {"m": {"reflectance": $1}},
 "objects": [{"type": "sphere", "material": "m", "radius": 1, "subdivisions": $subdivisions, "facing": "inward"}],
 "lights": [{"type": "point", "position": [0.2, 0.4, 0.6], "intensity_cd": 100}],
 "sensors": [{"name": "A", "position": [0, 0, 1], "normal": [0, 0, -1]},
             {"name": "B", "position": [0, -1, 0], "normal": [0, 1, 0]},
             {"name": "C", "position": [0.57735027, 0.57735027, 0.57735027], "normal": [-0.57735027, -0.57735027, -0.57735027]}],
 "radiosity": {"max_edge": 10, "overshoot": $2, "stop_unshot": $3}}
JSON
    area=$("$rayrad" info "$tmp/sphere.json" | sed -n 's/.*area: \([0-9.]*\) m².*/\1/p')
    local start end
    start=$(date +%s.%N)
    "$rayrad" solve "$tmp/sphere.json" --sensors "$tmp/s.csv" -q > /dev/null 2> "$tmp/err.txt"
    end=$(date +%s.%N)
    shots=$(sed -n 's/^patches: [0-9]*, channels: [0-9] ([^)]*), shots: \([0-9]*\),.*/\1/p;s/^patches: [0-9]*, channels: [0-9], shots: \([0-9]*\),.*/\1/p' "$tmp/err.txt")
    residual=$(sed -n 's/.*unshot: \([-0-9.e]*%\).*/\1/p' "$tmp/err.txt")
    account=$(sed -n 's/.*not accounted \([-+0-9.]*%\).*/\1/p' "$tmp/err.txt")
    # CSV column 9 = indirect_lx.
    awk -F, -v rho="$1" -v area="$area" -v os="$2" -v stop="$3" -v shots="$shots" -v t="$(echo "$end - $start" | bc)" \
        -v residual="$residual" -v account="$account" '
        NR > 1 { e[NR - 1] = $9 }
        END {
            expected = rho / (1 - rho) * 4 * 3.14159265358979 * 100 / area
            worst = 0
            for (k = 1; k <= 3; ++k) { err = 100 * (e[k] - expected) / expected; if (err * err > worst * worst) worst = err }
            printf "%-6s %-10s %-9s %8d %9.1f  %-32s %+8.2f  %-10s %s\n", rho, os, stop, shots, t,
                sprintf("%.1f / %.1f / %.1f", e[1], e[2], e[3]), worst, residual, account
        }' "$tmp/s.csv"
}
run 0.9 true 0.001
run 0.9 false 0.001
run 0.99 true 0.001
run 0.99 false 0.01
run 0.999 true 0.001
