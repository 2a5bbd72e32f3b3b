#!/usr/bin/env bash
# Benchmark: daylight against lamps. For the side-lit office (overcast, and turned south
# under the CIE clear sky with the sun) and the living room (lit through its four windows,
# and by its two lamps): patches, the energy account and the CPU seconds (user + sys) of
# the solve, and with RENDER=1 of a render at WIDTHxHEIGHT (default 640x360), 4 spp.
# The acceptance figure is the ratio of the living room's daylight run to its lamp run,
# measured here one after the other on the same machine.
# Usage: bench/daylight.sh [office|living-room|all (default)]
set -euo pipefail
cd "$(dirname "$0")/.."
rayrad=build/src/rayrad
[ -x "$rayrad" ] || scripts/build rayrad
which=${1:-all}
size=${SIZE:-640x360}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
sunny=(--set 'daylight.north=[0,0,1]'
       --set 'daylight.sky={"type":"cie_clear","diffuse_horizontal_illuminance":15000}'
       --set 'daylight.sun={"latitude":52.5,"longitude":13.4,"utc_offset":1,"date":"2026-03-21","time":"13:00","direct_normal_illuminance":70000}')

# run NAME SCENE [ARGS...]: one solve (or render), its figures on one line.
run() {
    local name=$1 scene=$2
    shift 2
    local command=(solve "$scene" "$@")
    if [ "${RENDER:-0}" = 1 ]; then
        command=(render "$scene" "$@" -o "$tmp/$name.png" --spp 4
                 --set "camera.resolution=[${size%x*},${size#*x}]")
    fi
    /usr/bin/time -f "%U %S %e" -o "$tmp/time" "$rayrad" "${command[@]}" -q > /dev/null 2> "$tmp/err" || {
        echo "$name: failed"; cat "$tmp/err"; return; }
    read -r user sys wall < "$tmp/time"
    local patches account
    patches=$(sed -n 's/^patches: \([0-9]*\),.*/\1/p' "$tmp/err")
    account=$(sed -n 's/.*not accounted \([^ ]*\) .*/\1/p' "$tmp/err")
    printf '%-28s patches %7s  not accounted %10s  CPU %7.1f s (user %.1f + sys %.1f), wall %.1f s\n' \
        "$name" "$patches" "$account" "$(echo "$user + $sys" | bc)" "$user" "$sys" "$wall"
    echo "$user + $sys" | bc > "$tmp/$name.cpu"
}

if [ "$which" = office ] || [ "$which" = all ]; then
    run "office, overcast" scenes/daylight-office/daylight-office.json
    run "office, clear sky and sun" scenes/daylight-office/daylight-office.json "${sunny[@]}"
fi
if [ "$which" = living-room ] || [ "$which" = all ]; then
    run "living room, daylight" scenes/living-room/living-room-daylight.json
    run "living room, lamps" scenes/living-room/living-room.json
    echo "living room: daylight / lamps CPU = $(echo "scale=2; $(cat "$tmp/living room, daylight.cpu") / $(cat "$tmp/living room, lamps.cpu")" | bc)"
fi
