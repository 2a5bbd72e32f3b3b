#!/usr/bin/env bash
# Bad input through the real command line: exit code 2, exactly one line on stderr that
# names the file and the place, and no output file created or damaged.
set -u
rayrad="$1"
src="$2"
source "$(dirname "$0")/test_lib.sh"

# expect NAME EXPECTED_SUBSTRING -- ARGS...
expect() {
    local name="$1" want="$2"
    shift 3
    local err rc
    err=$("$rayrad" "$@" 2>&1 >/dev/null)
    rc=$?
    local lines
    lines=$(printf '%s\n' "$err" | grep -c .)
    if [ "$rc" -ne 2 ] || [ "$lines" -ne 1 ] || [[ "$err" != *"$want"* ]]; then
        echo "FAIL $name: exit $rc, $lines line(s): $err (wanted: $want)"
        failures=$((failures + 1))
    else
        passed=$((passed + 1))
    fi
    # No partial or temporary output may be left.
    if ls "$work"/out* "$work"/.out* >/dev/null 2>&1; then
        echo "FAIL $name: left output: $(ls -a "$work" | tr '\n' ' ')"
        failures=$((failures + 1))
    fi
}

scene() {  # scene NAME JSON: writes $work/NAME.json
    printf '%s\n' "$2" > "$work/$1.json"
}

good_materials='"materials": {"white": {"type": "diffuse", "reflectance": 0.5}}'
good_box='"objects": [{"type": "box", "min": [0,0,0], "max": [1,1,1], "facing": "inward", "material": "white"}]'
good_light='"lights": [{"type": "point", "position": [0.5,0.5,0.5], "intensity_cd": 10}]'
good_camera='"camera": {"position": [0.5,0.5,0.1], "look_at": [0.5,0.5,1], "resolution": [8,8]}'

scene malformed '{ "materials": { "white": { "reflectance": 0.5, } } }'
expect "malformed JSON" "$work/malformed.json: line 1, column" -- solve "$work/malformed.json"

scene unknown_material "{$good_materials, \"objects\": [{\"type\": \"box\", \"min\": [0,0,0], \"max\": [1,1,1], \"material\": \"whte\"}], $good_light}"
expect "unknown material" "unknown_material.json: /objects/0/material: unknown material \"whte\" (did you mean \"white\"?)" -- solve "$work/unknown_material.json"

scene negative "{$good_materials, $good_box, \"lights\": [{\"type\": \"point\", \"position\": [0.5,0.5,0.5], \"intensity_cd\": -5}]}"
expect "negative intensity" "negative.json: /lights/0/intensity_cd: expected a positive number, got -5" -- solve "$work/negative.json"

scene reflectance "{\"materials\": {\"white\": {\"reflectance\": 1.0}}, $good_box, $good_light}"
expect "reflectance >= 1" "reflectance.json: /materials/white/reflectance: expected values in [0, 1)" -- solve "$work/reflectance.json"

scene mesh "{$good_materials, \"objects\": [{\"type\": \"mesh\", \"file\": \"missing.obj\", \"material\": \"white\"}], $good_light}"
expect "missing mesh" "mesh.json: /objects/0/file: mesh file" -- solve "$work/mesh.json"

mirror_materials='"materials": {"white": {"reflectance": 0.5}, "m": {"type": "mirror", "specular_reflectance": 0.9}}'
scene curved_mirror "{$mirror_materials, \"objects\": [{\"type\": \"sphere\", \"material\": \"m\"}], $good_light}"
expect "curved mirror" "curved_mirror.json: /objects/0/material: a mirror must be a quad, polygon or box" -- solve "$work/curved_mirror.json"
scene mirror_type "{\"materials\": {\"white\": {\"type\": \"mirorr\"}}, $good_box, $good_light}"
expect "material type typo" "mirror_type.json: /materials/white/type: unknown material type \"mirorr\" (did you mean \"mirror\"?)" -- solve "$work/mirror_type.json"
scene mirror_ks "{\"materials\": {\"white\": {\"reflectance\": 0.5}, \"m\": {\"type\": \"mirror\", \"specular_reflectance\": 1.5}}, $good_box, $good_light}"
expect "mirror Ks > 1" "mirror_ks.json: /materials/m/specular_reflectance: expected values in [0, 1]" -- solve "$work/mirror_ks.json"

expect "missing scene" "$work/nothere.json: no such file" -- solve "$work/nothere.json"

scene good "{$good_materials, $good_box, $good_light, $good_camera}"
expect "unwritable output" "$work/no/such/dir/out.png: cannot write: directory" -- render "$work/good.json" -o "$work/no/such/dir/out.png"
expect "unknown image format" "$work/out.bmp: unknown image format" -- render "$work/good.json" -o "$work/out.bmp"
expect "unwritable csv" "$work/nodir/out.csv: cannot write" -- solve "$work/good.json" --sensors "$work/nodir/out.csv"
expect "bad --set" "/radiosity/max_egde: unknown key (did you mean \"max_edge\"?)" -- solve "$work/good.json" --set radiosity.max_egde=1
expect "bad --exposure" "--exposure: expected \"auto\" or a number" -- render "$work/good.json" -o "$work/out.png" --exposure bright
scene nocamera "{$good_materials, $good_box, $good_light}"
expect "render without camera" "nocamera.json: /camera: rendering needs a camera" -- render "$work/nocamera.json" -o "$work/out.png"

# An existing output survives a failed run untouched.
echo keep > "$work/keep.png"
"$rayrad" render "$work/negative.json" -o "$work/keep.png" >/dev/null 2>&1
if [ "$(cat "$work/keep.png")" != keep ]; then echo "FAIL existing output was overwritten"; failures=$((failures + 1)); else passed=$((passed + 1)); fi

finish "bad input"
