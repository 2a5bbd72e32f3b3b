#!/usr/bin/env bash
# Hostile inputs through the real command line, the second round: input that once reached
# a signal (deep nesting, points no ray can start from, a closed pipe) and results that
# once left with exit 0 though broken. Each gives one line on stderr naming the file and
# the problem and a non-zero exit — never a signal (exit 128 + N).
set -u
rayrad="$1"
src="$2"
source "$(dirname "$0")/test_lib.sh"

materials='"materials": {"white": {"type": "diffuse", "reflectance": 0.5}}'
box='"objects": [{"type": "box", "min": [0,0,0], "max": [1,1,1], "facing": "inward", "material": "white"}]'
light='"lights": [{"type": "point", "position": [0.5,0.5,0.5], "intensity_cd": 10}]'
camera() { printf '"camera": {"position": %s, "look_at": [0.5,0.5,1], "up": %s, "resolution": [8,8]}' "$1" "$2"; }

# Nesting: refused before parsing, at the place it goes too deep.
deep=$(printf '[%.0s' $(seq 60000))$(printf ']%.0s' $(seq 60000))
printf '{"materials": %s}\n' "$deep" > "$work/deep.json"
expect 2 "60 000 nested arrays" "deep.json: line 1, column 78: arrays and objects nested more than 64 levels deep" -- solve "$work/deep.json"
scene good "{$materials, $box, $light, $(camera '[0.5,0.5,0.1]' '[0,1,0]')}"
expect 2 "60 000 nested arrays in --set" "--set radiosity.max_edge: the value nests arrays and objects more than 64 levels deep" -- solve "$work/good.json" --set "radiosity.max_edge=$deep"
deep65=$(printf '{"a": %.0s' $(seq 65))1$(printf '}%.0s' $(seq 65))
scene deep_objects "{$materials, $box, $light, \"x\": $deep65}"
expect 2 "65 nested objects" "deep_objects.json: line 1, column" -- solve "$work/deep_objects.json"
small=$(printf '[%.0s' $(seq 60))$(printf ']%.0s' $(seq 60))
scene nested_60 "{\"materials\": {\"white\": {\"reflectance\": $small}}, $box, $light}"
expect 2 "60 nested arrays as a value: described, not printed whole" "nested_60.json: /materials/white/reflectance: expected a number or [r, g, b], got an array of 1 values" -- solve "$work/nested_60.json"

# Points and directions no ray can start from.
scene up_zero "{$materials, $box, $light, $(camera '[0.5,0.5,0.1]' '[0,0,0]')}"
expect 2 "camera up zero" "up_zero.json: /camera/up: up must not be zero" -- render "$work/up_zero.json" -o "$work/out.png"
scene view_up_zero "{$materials, $box, $light, $(camera '[0.5,0.5,0.1]' '[0,1,0]'), \"cameras\": [{\"name\": \"v\", \"position\": [0.5,0.5,0.1], \"look_at\": [0.5,0.5,1], \"up\": [0,0,0]}]}"
expect 2 "a view's up zero" "view_up_zero.json: /cameras/0/up: up must not be zero" -- solve "$work/view_up_zero.json"
scene camera_far "{$materials, $box, $light, $(camera '[0.5,0.5,1e20]' '[0,1,0]')}"
expect 2 "camera at 1e20 m" "camera_far.json: /camera/position: expected numbers within ±1e9 (m)" -- render "$work/camera_far.json" -o "$work/out.png"
scene light_far "{$materials, $box, \"lights\": [{\"type\": \"point\", \"position\": [0.5,0.5,1e300], \"intensity_cd\": 10}]}"
expect 2 "light at 1e300 m" "light_far.json: /lights/0/position: expected numbers within ±1e9 (m)" -- solve "$work/light_far.json"
scene sensor_far "{$materials, $box, $light, \"sensors\": [{\"name\": \"s\", \"position\": [0.5,0.5,1e300], \"normal\": [0,0,1]}]}"
expect 2 "sensor at 1e300 m" "sensor_far.json: /sensors/0/position: expected numbers within ±1e9 (m)" -- solve "$work/sensor_far.json"
scene grid_far "{$materials, $box, $light, \"sensor_grids\": [{\"name\": \"g\", \"origin\": [0.1,0.1,1e300], \"u\": [0.5,0,0], \"v\": [0,0.5,0], \"counts\": [2,2]}]}"
expect 2 "grid at 1e300 m" "grid_far.json: /sensor_grids/0/origin: expected numbers within ±1e9 (m)" -- solve "$work/grid_far.json"
scene scaled_far "{$materials, \"objects\": [{\"type\": \"box\", \"min\": [0,0,0], \"max\": [1,1,1], \"facing\": \"inward\", \"material\": \"white\"}, {\"type\": \"box\", \"min\": [0.2,0.2,0.2], \"max\": [0.3,0.3,0.3], \"material\": \"white\", \"transform\": {\"scale\": 1e30}}], $light}"
expect 2 "an object scaled to 1e29 m" "scaled_far.json: /objects/1: the surface reaches (2e+29, 2e+29, 2e+29) m, beyond ±1e9 m" -- solve "$work/scaled_far.json"
# A denormal up or normal is a direction like any other: scaled before it is normalised.
scene up_denormal "{$materials, $box, $light, $(camera '[0.5,0.5,0.1]' '[1e-320,0,0]'), \"sensors\": [{\"name\": \"s\", \"position\": [0.5,0.5,0], \"normal\": [0,0,1e-320]}]}"
quietly() { "$@" > /dev/null 2>&1; }
check "denormal up and normal: rendered" quietly "$rayrad" render "$work/up_denormal.json" -o "$work/denormal.png" -q --sensors "$work/denormal.csv"
rm -f "$work/denormal.png" "$work/denormal.csv"

# A closed pipe: the write fails and is reported (exit 3), or the output fitted in the
# pipe before it closed (exit 0); never SIGPIPE.
scene sensors "{$materials, $box, $light, \"sensor_grids\": [{\"name\": \"g\", \"origin\": [0.1,0.1,0.5], \"u\": [0.8,0,0], \"v\": [0,0.8,0], \"counts\": [40,40]}]}"
"$rayrad" info "$work/sensors.json" 2> "$work/pipe.txt" | true
rc=${PIPESTATUS[0]}
if [ "$rc" -eq 0 ] || { [ "$rc" -eq 3 ] && grep -q "standard output: cannot write" "$work/pipe.txt"; }; then
    passed=$((passed + 1))
else
    echo "FAIL info into a closed pipe: exit $rc: $(cat "$work/pipe.txt")"; failures=$((failures + 1))
fi
"$rayrad" solve "$work/sensors.json" -q --set radiosity.max_edge=0.5 2> "$work/pipe.txt" | head -c 1 > /dev/null
rc=${PIPESTATUS[0]}
if [ "$rc" -eq 0 ] || [ "$rc" -eq 3 ]; then passed=$((passed + 1)); else echo "FAIL solve into a closed pipe: exit $rc"; failures=$((failures + 1)); fi

finish "hostile inputs"
