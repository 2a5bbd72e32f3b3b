#!/usr/bin/env bash
# Benchmark: a year of daylight (rayrad annual) in the side-lit office turned to face south,
# under Chicago's typical year (scenes/weather, TMY3).
#  1. The year on a work plane of about 1 000 points (spacing 0.12 m): channels and suns
#     solved, the coefficients' CPU seconds (user + sys) and peak memory, the year's CPU
#     seconds, and the metrics.
#  2. One hour from the coefficients against a solve of that hour's Perez sky, at the
#     office's three sensors, for each sky subdivision in PATCHES (default "145 577"; 2305
#     takes about 16 times as long as 145): the discretisation error with its cost.
# Usage: bench/annual_daylight.sh [year|hours|all (default)]
set -euo pipefail
cd "$(dirname "$0")/.."
rayrad=build/src/rayrad
[ -x "$rayrad" ] || scripts/build rayrad
which=${1:-all}
office=scenes/daylight-office/daylight-office.json
epw=scenes/weather/USA_IL_Chicago-OHare.Intl.AP.725300_TMY3.epw
south=(--set 'daylight.north=[0,0,1]')
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

if [ "$which" = year ] || [ "$which" = all ]; then
    echo "== the year: side-lit office facing south, Chicago TMY3, 145 sky patches + suns =="
    /usr/bin/time -f "%U %S %e %M" -o "$tmp/time" "$rayrad" annual "$office" "${south[@]}" \
        --set 'work_planes.0.spacing=0.12' --weather "$epw" --report "$tmp/r.json" -q > "$tmp/out" 2> "$tmp/err" || {
        cat "$tmp/err"; exit 1; }
    cat "$tmp/out"
    read -r user sys wall rss < "$tmp/time"
    python3 - "$tmp/r.json" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
c, y = r["coefficients"], r["year"]
print(f"sensors {len(r['sensors'])}; channels {c['channels']} ({c['solved_channels']} solved), suns {c['solved_suns']}")
print(f"coefficients {c['cpu_s']:.1f} CPU-s ({c['wall_s']:.1f} s wall); the year {y['cpu_s']:.1f} CPU-s "
      f"({y['wall_s']:.1f} s wall); peak memory {r['peak_memory_bytes'] / 2**20:.0f} MiB")
PY
    printf 'whole run: CPU %.1f s (user %.1f + sys %.1f), wall %.1f s, peak %d MiB\n' \
        "$(echo "$user + $sys" | bc)" "$user" "$sys" "$wall" "$((rss / 1024))"
fi

if [ "$which" = hours ] || [ "$which" = all ]; then
    # Hours of the weather file: MM-DDTHH (the hour ending then, standard time UTC−6).
    hours=(03-15T12 06-21T13 03-31T12)
    for patches in ${PATCHES:-145 577}; do
        echo "== one hour from the coefficients ($patches sky patches) against a solve of its sky =="
        args=()
        for h in "${hours[@]}"; do args+=(--hour "$h"); done
        /usr/bin/time -f "%U %S" -o "$tmp/time" "$rayrad" annual "$office" "${south[@]}" --set 'work_planes=[]' \
            --weather "$epw" --sky-patches "$patches" "${args[@]}" -q > "$tmp/hours" 2> "$tmp/err" || {
            cat "$tmp/err"; exit 1; }
        read -r user sys < "$tmp/time"
        printf 'coefficients for the three sensors: %.1f CPU-s\n' "$(echo "$user + $sys" | bc)"
        printf '%-9s %-7s %12s %12s %8s\n' hour sensor "coeffs lx" "solve lx" error
        for h in "${hours[@]}"; do
            month=$((10#${h:0:2})) day=$((10#${h:3:2})) hour=$((10#${h:6:2}))
            read -r dew dni dhi < <(awk -F, -v m="$month" -v d="$day" -v h="$hour" \
                'NR > 8 && $2 == m && $3 == d && $4 == h { print $8, $15, $16 }' "$epw")
            sky="{\"type\":\"perez\",\"direct_normal_irradiance\":$dni,\"diffuse_horizontal_irradiance\":$dhi,\"dew_point\":$dew}"
            sun=$(printf '{"latitude":41.98,"longitude":-87.92,"utc_offset":-6,"elevation":201,"date":"2021-%02d-%02d","time":"%02d:30"}' \
                "$month" "$day" "$((hour - 1))")
            "$rayrad" solve "$office" "${south[@]}" --set 'work_planes=[]' --set "daylight.sky=$sky" \
                --set "daylight.sun=$sun" --sensors "$tmp/solve.csv" -q > /dev/null 2>&1
            # The block of this hour in the annual output: "hour N (MM-DD, …" then a header and a line per sensor.
            awk -v tag="$(printf '(%02d-%02d, %.1f h' "$month" "$day" "$(echo "$hour - 0.5" | bc)")" \
                'index($0, tag) { on = 1; getline; next } on && NF == 6 { print $1, $6; next } { on = 0 }' "$tmp/hours" > "$tmp/coeffs"
            while read -r name got; do
                want=$(awk -F, -v n="$name" '$1 == n { print $10 }' "$tmp/solve.csv")
                printf '%-9s %-7s %12.1f %12.1f %+7.2f%%\n' "$h" "$name" "$got" "$want" \
                    "$(echo "100 * ($got - $want) / $want" | bc -l)"
            done < "$tmp/coeffs"
        done
    done
fi
