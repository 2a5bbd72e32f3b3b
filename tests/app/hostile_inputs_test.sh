#!/usr/bin/env bash
# Hostile inputs through the real command line, the second round: input that once reached
# a signal (deep nesting, points no ray can start from, a closed pipe) and results that
# once left with exit 0 though broken. Each gives one line on stderr naming the file and
# the problem and a non-zero exit — never a signal (exit 128 + N).
set -u
rayrad="$1"
src="$2"
source "$(dirname "$0")/test_lib.sh"
quietly() { "$@" > /dev/null 2>&1; }

materials=$good_materials box=$good_box light=$good_light
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

printf '%s\n' "$deep" > "$work/deep_align.json"
pfm_ok() { printf 'PF\n1 1\n-1.0\n\x00\x00\x80\x3f\x00\x00\x80\x3f\x00\x00\x80\x3f' > "$work/$1.pfm"; }
pfm_ok a1; pfm_ok b1
expect 2 "60 000 nested arrays in an alignment file" "deep_align.json: byte 64: arrays and objects nested more than 64 levels deep" -- compare "$work/a1.pfm" "$work/b1.pfm" --align "$work/deep_align.json"
expect 2 "65 nested objects in --set" "--set render: the value nests arrays and objects more than 64 levels deep" -- solve "$work/good.json" --set "render=$deep65"
scene nul_name "{\"materials\": {\"w\\u0000x\": {\"reflectance\": 0.5}}, $box, $light}"
expect 2 "a NUL in a material's name" "nul_name.json: /materials/w\\u0000x: the material's name holds a NUL character" -- solve "$work/nul_name.json"

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
scene box_far "{$materials, \"objects\": [{\"type\": \"box\", \"min\": [0,0,0], \"max\": [2e9,1,1], \"material\": \"white\"}], $light}"
expect 2 "a box reaching 2e9 m" "box_far.json: /objects/0/max: expected numbers within ±1e9 (m)" -- solve "$work/box_far.json"
scene axis_zero "{$materials, \"objects\": [{\"type\": \"box\", \"min\": [0,0,0], \"max\": [1,1,1], \"facing\": \"inward\", \"material\": \"white\", \"transform\": {\"rotate_axis\": [0,0,0], \"rotate_deg\": 30}}], $light}"
expect 2 "a zero rotation axis" "axis_zero.json: /objects/0/transform/rotate_axis: the rotation axis must not be zero" -- solve "$work/axis_zero.json"
scene grid_flat "{$materials, $box, $light, \"sensor_grids\": [{\"name\": \"g\", \"origin\": [0.1,0.1,0.5], \"u\": [1e-200,0,0], \"v\": [0,1e-200,0], \"counts\": [2,2]}]}"
expect 2 "a grid of 1e-200 m sides" "grid_flat.json: /sensor_grids/0/v: the grid's normal is zero" -- solve "$work/grid_flat.json"
scene path_up "{$materials, $box, $light, \"camera_path\": {\"frames\": 2, \"resolution\": [8, 8], \"keyframes\": [{\"position\": [0.5,0.5,0.9], \"look_at\": [0.5,0.5,0], \"up\": [0,0,0]}, {\"position\": [0.4,0.5,0.8], \"look_at\": [0.5,0.4,0]}]}}"
expect 2 "a keyframe's up zero" "path_up.json: /camera_path/keyframes/0/up: up must not be zero" -- render "$work/path_up.json" --frames all -o "$work/out.png"
scene spot_denormal "{$materials, $box, \"lights\": [{\"type\": \"spot\", \"position\": [0.5,0.5,0.9], \"direction\": [0,0,-1e-320], \"intensity_cd\": 10}]}"
check "a spot aimed along a denormal direction: solved" quietly "$rayrad" solve "$work/spot_denormal.json" -q
# A denormal up or normal is a direction like any other: scaled before it is normalised.
scene up_denormal "{$materials, $box, $light, $(camera '[0.5,0.5,0.1]' '[1e-320,0,0]'), \"sensors\": [{\"name\": \"s\", \"position\": [0.5,0.5,0], \"normal\": [0,0,1e-320]}]}"
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

# Broken results: exit 4, nothing written.
# 4×4 PFM images (linear floats): every pixel v (bytes of a little-endian float).
pfm() {  # pfm NAME PIXELS... (each "1", "1.1", "0" or "nan"): 16 pixels, grey
    printf 'PF\n4 4\n-1.0\n' > "$work/$1.pfm"
    local name="$1" v
    shift
    for v in "$@"; do
        case "$v" in
            1) printf '\x00\x00\x80\x3f\x00\x00\x80\x3f\x00\x00\x80\x3f' ;;
            1.1) printf '\xcd\xcc\x8c\x3f\xcd\xcc\x8c\x3f\xcd\xcc\x8c\x3f' ;;
            0) printf '\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00' ;;
            nan) printf '\x00\x00\xc0\x7f\x00\x00\xc0\x7f\x00\x00\xc0\x7f' ;;
        esac >> "$work/$name.pfm"
    done
}
sixteen() { for _ in $(seq 16); do printf '%s ' "$1"; done; }
pfm one $(sixteen 1)
pfm other $(sixteen 1.1)
pfm black $(sixteen 0)
pfm nan $(sixteen nan)
pfm halfnan $(sixteen nan | cut -d' ' -f1-8) $(sixteen 1 | cut -d' ' -f1-8)
printf 'PF\n1 1\n-1.0\n\x00\x00\x80\x7f\x00\x00\x80\x7f\x00\x00\x80\x7f' > "$work/inf.pfm"
linear=(--a-space linear --b-space linear --fail-above mean_abs_rel_pct=50)
check "compare of two images" quietly "$rayrad" compare "$work/one.pfm" "$work/other.pfm" "${linear[@]}"
expect 4 "compare with an all-black reference" "black.pfm: every pixel is black: there is nothing to compare" -- compare "$work/one.pfm" "$work/black.pfm" "${linear[@]}"
expect 4 "compare with an all-NaN image" "nan.pfm: 16 of its 16 pixels are not finite" -- compare "$work/nan.pfm" "$work/one.pfm" "${linear[@]}"
expect 4 "compare with an Inf pixel" "inf.pfm: 1 of its 1 pixels are not finite" -- compare "$work/inf.pfm" "$work/a1.pfm" "${linear[@]}"
expect 4 "compare with a half-NaN image" "halfnan.pfm: 8 of its 16 pixels are not finite" -- compare "$work/one.pfm" "$work/halfnan.pfm" "${linear[@]}"
printf '%s\n' '[{"a":[100,100],"b":[0,0]},{"a":[104,100],"b":[4,0]},{"a":[104,104],"b":[4,4]},{"a":[100,104],"b":[0,4]}]' > "$work/away.json"
expect 4 "an alignment that maps outside the image" "away.json: the alignment maps $work/one.pfm onto 0.0 % of $work/other.pfm, less than the 10 %" -- compare "$work/one.pfm" "$work/other.pfm" "${linear[@]}" --align "$work/away.json"

# A NaN texel: refused where the texture is read (it made a NaN solution that solve
# --save and export wrote).
printf 'PF\n1 1\n-1.0\n\x00\x00\xc0\x7f\x00\x00\x00\x3f\x00\x00\x00\x3f' > "$work/nantexel.pfm"
scene nan_texel "{\"materials\": {\"t\": {\"texture\": \"nantexel.pfm\"}}, \"objects\": [{\"type\": \"box\", \"min\": [0,0,0], \"max\": [1,1,1], \"facing\": \"inward\", \"material\": \"t\"}], $light}"
expect 2 "a NaN texel, solve --save" "nantexel.pfm: 1 texel value(s) are not finite" -- solve "$work/nan_texel.json" --save "$work/out.rrs"
expect 2 "a NaN texel, export" "nantexel.pfm: 1 texel value(s) are not finite" -- export "$work/nan_texel.json" -o "$work/out.glb"

# A light of 1e-300 cd: black as the EXR's floats hold it.
scene faint "{$materials, $box, \"lights\": [{\"type\": \"point\", \"position\": [0.5,0.5,0.5], \"intensity_cd\": 1e-300}], $(camera '[0.5,0.5,0.1]' '[0,1,0]')}"
expect 4 "a light of 1e-300 cd" "every pixel of the image is black as an EXR float holds it" -- render "$work/faint.json" -o "$work/out.exr"

# Tiles of two renderings of one file (a light changed between them) are not one image.
mkdir -p "$work/tiles"
scene tiles/s "{$materials, $box, $light, $(camera '[0.5,0.5,0.1]' '[0,1,0]')}"
quietly "$rayrad" render "$work/tiles/s.json" --tile 1/2 -o "$work/tiles/t1.exr" -q
sed -i 's/"intensity_cd": 10/"intensity_cd": 20/' "$work/tiles/s.json"
quietly "$rayrad" render "$work/tiles/s.json" --tile 2/2 -o "$work/tiles/t2.exr" -q
expect 2 "merge of tiles of two renderings" "t2.exr: is a tile of another rendering than $work/tiles/t1.exr: the scene's geometry, materials, lights, settings or camera differ" -- merge -o "$work/out.exr" "$work/tiles/t1.exr" "$work/tiles/t2.exr"

# What users bring, read as they meant it (or a warning saying how it was read).
mkdir -p "$work/mm"
{
    echo "mtllib room.mtl"
    for v in "0 0 0" "4000 0 0" "4000 0 3000" "0 0 3000" "0 2700 0" "4000 2700 0" "4000 2700 3000" "0 2700 3000"; do echo "v $v"; done
    echo "usemtl white"
    printf 'f 4 3 2 1\nf 6 7 8 5\nf 2 6 5 1\nf 3 7 6 2\nf 4 8 7 3\nf 1 5 8 4\n'
} > "$work/mm/room.obj"
room_lamp='"lights": [{"type": "point", "position": [2, 1.5, 1.35], "intensity_cd": 100}]'
scene mm/metres "{\"objects\": [{\"type\": \"mesh\", \"file\": \"room.obj\"}], $room_lamp}"
"$rayrad" info "$work/mm/metres.json" > "$work/mm/info.txt" 2>&1
check "a model in millimetres: the unit named" grep -q 'the mesh spans 4000 × 2700 × 3000 units, read as metres; if it is modelled in millimetres (4 × 2.7 × 3 m), give the object "units": "mm"' "$work/mm/info.txt"
check "a missing .mtl: a warning" grep -q '/objects/0/file: line 1: material library .*room.mtl: no such file' "$work/mm/info.txt"
printf 'newmtl white\nKd 0.5 0.5 0.5\n' > "$work/mm/room.mtl"
scene mm/mm "{\"materials\": {\"room.obj:white\": {\"reflectance\": 0.2}}, \"objects\": [{\"type\": \"mesh\", \"file\": \"room.obj\", \"units\": \"mm\"}], $room_lamp}"
"$rayrad" info "$work/mm/mm.json" > "$work/mm/info.txt" 2>&1
check "units mm: no size warning" bash -c "! grep -q 'read as metres' '$work/mm/info.txt'"
check "a JSON material named FILE:NAME replaces the file's" grep -q 'room.obj:white: diffuse, reflectance (0.2, 0.2, 0.2)' "$work/mm/info.txt"
scene mm/bad_unit "{\"objects\": [{\"type\": \"mesh\", \"file\": \"room.obj\", \"units\": \"yards\"}], $room_lamp}"
expect 2 "an unknown unit" "bad_unit.json: /objects/0/units: expected \"m\", \"cm\", \"mm\", \"in\" or \"ft\", got \"yards\"" -- solve "$work/mm/bad_unit.json"
# keep_above on a mesh of two materials, one wholly below the plane: the other is kept.
printf 'newmtl a\nKd 0.5 0.5 0.5\nnewmtl b\nKd 0.5 0.5 0.5\n' > "$work/mm/two.mtl"
printf 'mtllib two.mtl\nv 0 0 1\nv 1 0 1\nv 0 1 1\nv 0 0 -1\nv 1 0 -1\nv 0 1 -1\nusemtl a\nf 1 2 3\nusemtl b\nf 4 5 6\n' > "$work/mm/two.obj"
scene mm/keep "{\"materials\": {\"w\": {\"reflectance\": 0.5}}, \"objects\": [{\"type\": \"mesh\", \"file\": \"two.obj\", \"keep_above\": [[0, 0, 1, 0]]}, {\"type\": \"box\", \"min\": [-2,-2,-2], \"max\": [2,2,2], \"facing\": \"inward\", \"material\": \"w\"}], \"lights\": [{\"type\": \"point\", \"position\": [0.3, 0.3, 1.5], \"intensity_cd\": 10}]}"
check "keep_above leaves one material of a mesh empty" quietly "$rayrad" info "$work/mm/keep.json"
# A NUL inside a name or a path would cut it short.
printf '%s\n' "{\"objects\": [{\"type\": \"mesh\", \"file\": \"room.obj\\u0000.ply\"}], $room_lamp}" > "$work/mm/nul.json"
expect 2 "a NUL in a file name" "nul.json: /objects/0/file: the string holds a NUL character" -- solve "$work/mm/nul.json"

# Wrong energy, said: a floor modelled twice, a reflectance of (almost) 1.
scene twice "{$materials, \"objects\": [{\"type\": \"box\", \"min\": [0,0,0], \"max\": [4,3,2.7], \"facing\": \"inward\", \"material\": \"white\"}, {\"type\": \"quad\", \"vertices\": [[0,0,0],[4,0,0],[4,3,0],[0,3,0]], \"material\": \"white\"}], \"lights\": [{\"type\": \"point\", \"position\": [2,1.5,2.5], \"intensity_cd\": 100}]}"
"$rayrad" info "$work/twice.json" > "$work/twice.txt" 2>&1
check "a floor modelled twice: the coincident surfaces named" grep -q '/objects/0 (material "white") and /objects/1 (material "white"): 12 m² of them lie in one plane, facing the same way' "$work/twice.txt"
"$rayrad" info "$work/good.json" > "$work/once.txt" 2>&1
check "one box: no coincident surfaces" bash -c "! grep -q 'lie in one plane' '$work/once.txt'"
scene almost_one "{\"materials\": {\"white\": {\"reflectance\": 0.9999999999999999}}, $box, $light}"
expect 2 "reflectance 1 − 1e-16" "almost_one.json: /materials/white/reflectance: expected values in [0, 0.999], got 0.9999999999999999" -- solve "$work/almost_one.json"

# Codes and messages.
expect 2 "a resolution over the pixel cap" "/camera/resolution: 16384 × 16384 is 268435456 pixels, more than the 100 000 000 an image may have" -- render "$work/good.json" --set 'camera.resolution=[16384,16384]' -o "$work/out.png"
expect 2 "more tiles than rows" "--tile: 100 bands of an image 8 pixels high: at most 8" -- render "$work/good.json" --tile 3/100 -o "$work/out.exr"
truncate -s 10G "$work/huge.rrs" 2> /dev/null || dd if=/dev/zero of="$work/huge.rrs" bs=1M count=64 2> /dev/null
expect 2 "a 10 GB file as --solution: refused by its first bytes" "huge.rrs: not a rayrad solution file" -- render "$work/good.json" --solution "$work/huge.rrs" -o "$work/out.png"
rm -f "$work/huge.rrs"
expect 2 "a sweep key with a tab" "--vary: a control character (code 9)" -- sweep "$work/good.json" --vary "$(printf 'render.seed\t=1,2')" --jobs "$work/out.txt"
expect 2 "a sweep value with a line break" "--vary: a control character (code 10) in the values of \"render.seed\"" -- sweep "$work/good.json" --vary "render.seed=1,$(printf '2\n3')" --jobs "$work/out.txt"
mkdir -p "$work/sweep"
quietly "$rayrad" sweep "$work/good.json" --vary 'camera.resolution=[8,8],[16,16]' --jobs "$work/sweep/jobs.txt"
check "sweep values with commas are quoted in the CSV" grep -qx '1,"\[16,16\]"' "$work/sweep/jobs.csv"

# All outputs or none: a rename that fails, or SIGTERM while the temporaries are written
# or the outputs renamed, leaves every old output byte-identical and no temporary.
mkdir -p "$work/commit"
scene commit/s "{$materials, $box, $light, $(camera '[0.5,0.5,0.1]' '[0,1,0]'), \"sensors\": [{\"name\": \"s\", \"position\": [0.5,0.5,0], \"normal\": [0,0,1]}]}"

# Daylight that cannot be: each refused at its place, before anything is computed.
daylit() {  # daylit NAME MATERIALS DAYLIGHT: the courtyard under that daylight
    scene "$1" "{$2, $court_objects, \"daylight\": {$3}}"
}
court_materials='"materials": {"white": {"reflectance": 0.5}, "sky": {"type": "opening"}}'
overcast='"sky": {"type": "cie_overcast", "diffuse_horizontal_illuminance": 10000}'
sun_at() { printf '"sun": {"latitude": %s, "longitude": 0, "utc_offset": %s, "date": "%s", "time": "%s"}' "$@"; }
daylit lat91 "$court_materials" "$overcast, $(sun_at 91 0 2026-03-21 12:00)"
expect 2 "latitude 91°" "lat91.json: /daylight/sun/latitude: a latitude lies within [−90°, 90°], got 91" -- solve "$work/lat91.json"
daylit feb30 "$court_materials" "$overcast, $(sun_at 50 0 2026-02-30 12:00)"
expect 2 "30 February" "feb30.json: /daylight/sun/date: 2026-02-30 is not a date of the calendar" -- solve "$work/feb30.json"
daylit hour25 "$court_materials" "$overcast, $(sun_at 50 0 2026-02-03 25:00)"
expect 2 "25 o'clock, at the time's place" "hour25.json: /daylight/sun/time: 25:00 is not a time of the day" -- solve "$work/hour25.json"
daylit offset20 "$court_materials" "$overcast, $(sun_at 50 20 2026-02-03 12:00)"
expect 2 "a time zone 20 h from UTC" "offset20.json: /daylight/sun/utc_offset: a time zone's offset from UTC lies within ±14 h, got 20" -- solve "$work/offset20.json"
daylit alt100 "$court_materials" "$overcast, \"sun\": {\"altitude\": 100, \"azimuth\": 180}"
expect 2 "the sun 100° high" "alt100.json: /daylight/sun/altitude: the sun's altitude must be within [−90°, 90°], got 100" -- solve "$work/alt100.json"
daylit two_scales "$court_materials" '"sky": {"type": "uniform", "zenith_luminance": 1000, "diffuse_horizontal_illuminance": 10000}'
expect 2 "a sky with two scales" "two_scales.json: /daylight/sky/zenith_luminance: a sky needs exactly one scale" -- solve "$work/two_scales.json"
daylit clear_no_sun "$court_materials" '"sky": {"type": "cie_clear", "diffuse_horizontal_illuminance": 10000}'
expect 2 "a clear sky without the sun" "clear_no_sun.json: /daylight/sun: CIE sky type 12 is brighter toward the sun" -- solve "$work/clear_no_sun.json"
daylit cie16 "$court_materials" '"sky": {"type": "cie_standard", "cie_type": 16, "zenith_luminance": 1000}'
expect 2 "CIE sky type 16" "cie16.json: /daylight/sky/cie_type: expected a whole number from 1 to 15, got 16" -- solve "$work/cie16.json"
perez() { printf '"sky": {"type": "perez", "direct_normal_irradiance": %s, "diffuse_horizontal_irradiance": %s%s}, "sun": {"altitude": 30, "azimuth": 180}' "$@"; }
daylit perez_negative "$court_materials" "$(perez -5 100 '')"
expect 2 "a Perez sky's negative direct irradiance" "perez_negative.json: /daylight/sky/direct_normal_irradiance: expected a number >= 0, got -5" -- solve "$work/perez_negative.json"
daylit perez_bright "$court_materials" "$(perez 5000 100 '')"
expect 2 "a Perez sky brighter than the sun" "perez_bright.json: /daylight/sky/direct_normal_irradiance: 5000 W/m² is more than the sun and sky give on the ground" -- solve "$work/perez_bright.json"
daylit perez_dark "$court_materials" "$(perez 0 0 '')"
expect 2 "a Perez sky without diffuse light" "perez_dark.json: /daylight/sky/diffuse_horizontal_irradiance: expected a positive number, got 0" -- solve "$work/perez_dark.json"
daylit dew500 "$court_materials" "$(perez 500 100 ', "dew_point": 500')"
expect 2 "a dew point of 500 °C" "dew500.json: /daylight/sky/dew_point: expected a dew point in [−60, 40] °C, got 500" -- solve "$work/dew500.json"
daylit up_is_north "$court_materials" "$overcast, \"up\": [0,1,0], \"north\": [0,1,0]"
expect 2 "north straight up" "up_is_north.json: /daylight/north: \"up\" and \"north\" must be non-zero and not parallel" -- solve "$work/up_is_north.json"
daylit ground2 "$court_materials" "$overcast, \"ground_reflectance\": 2"
expect 2 "ground reflectance 2" "ground2.json: /daylight/ground_reflectance: expected a reflectance in [0, 1), got 2" -- solve "$work/ground2.json"
daylit median0 "$court_materials" "$overcast, \"median_external_illuminance\": 0"
expect 2 "a median external illuminance of 0" "median0.json: /daylight/median_external_illuminance: expected a positive number, got 0" -- solve "$work/median0.json"
daylit tau0 '"materials": {"white": {"reflectance": 0.5}, "sky": {"type": "opening", "transmittance": 0}}' "$overcast"
expect 2 "a glazing that lets nothing through" "tau0.json: /materials/sky/transmittance: a glazing's normal transmittance lies in (0, 1] (1: no glazing), got 0" -- solve "$work/tau0.json"

# Mesh files that lie: far vertices, faces that name vertices the file does not have.
mesh_scene() {  # mesh_scene NAME FILE
    scene "$1" "{$materials, \"objects\": [{\"type\": \"box\", \"min\": [0,0,0], \"max\": [1,1,1], \"facing\": \"inward\", \"material\": \"white\"}, {\"type\": \"mesh\", \"file\": \"$2\", \"material\": \"white\"}], $light}"
}
printf 'v 1e30 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\n' > "$work/far.obj"
mesh_scene far_vertex far.obj
expect 2 "an OBJ vertex 1e30 m away" "far_vertex.json: /objects/1: the surface reaches (1e+30, 0, 0) m, beyond ±1e9 m" -- solve "$work/far_vertex.json"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n' > "$work/index7.obj"
mesh_scene obj_index index7.obj
expect 2 "an OBJ face naming vertex 7 of 3" "obj_index.json: /objects/1/file: cannot read mesh" -- solve "$work/obj_index.json"
printf 'ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 5\n' > "$work/index5.ply"
mesh_scene ply_index index5.ply
expect 2 "a PLY whose only face names vertex 5 of 3" "ply_index.json: /objects/1/file: mesh '$work/index5.ply' has no triangles: its 1 face(s) are points or lines, or name vertices the file does not have" -- solve "$work/ply_index.json"
printf '{"asset": {"version": "2.0"}, "nodes": [{"children": [0]}], "scenes": [{"nodes": [0]}]}' > "$work/cycle.gltf"
mesh_scene gltf_cycle cycle.gltf
expect 2 "a glTF node that is its own child" "gltf_cycle.json: /objects/1/file: mesh '$work/cycle.gltf': the node hierarchy is deeper than 256 levels (a cycle?)" -- solve "$work/gltf_cycle.json"
printf '{"asset": {"version": "2.0"}, "buffers": [{"uri": "gone.bin", "byteLength": 36}], "bufferViews": [{"buffer": 0, "byteLength": 36}], "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0,0,0], "max": [1,1,0]}], "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}], "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}]}' > "$work/nobin.gltf"
mesh_scene gltf_no_bin nobin.gltf
expect 2 "a glTF whose buffer file is missing" "gltf_no_bin.json: /objects/1/file: mesh '$work/nobin.gltf': not a valid glTF 2.0 file" -- solve "$work/gltf_no_bin.json"

# Luminaire files that lie.
lum_scene() {  # lum_scene NAME FILE
    scene "$1" "{$materials, \"objects\": [{\"type\": \"box\", \"min\": [0,0,0], \"max\": [4,4,3], \"facing\": \"inward\", \"material\": \"white\"}], \"lights\": [{\"type\": \"luminaire\", \"file\": \"$2\", \"position\": [2,2,2.5]}]}"
}
ies() {  # ies FILE VERTICAL_COUNT HORIZONTAL_COUNT VERTICAL HORIZONTAL CANDELA
    printf 'IESNA:LM-63-2002\nTILT=NONE\n1 1000 1 %s %s 1 2 0 0 0\n1 1 10\n%s\n%s\n%s\n' "$2" "$3" "$4" "$5" "$6" > "$work/$1"
}
ies two_planes.ies 3 1 "0 45 90" "0 90" "100 50 20 100 50 20"; lum_scene ies_extra two_planes.ies
expect 2 "an IES listing two horizontal angles after counting one" "two_planes.ies: line 7: 4 number(s) after the 3 × 1 candela values" -- solve "$work/ies_extra.json"
ies short.ies 3 2 "0 45 90" "0" "100 50 20"; lum_scene ies_short short.ies
expect 2 "an IES ending early" "short.ies: line 7: the file ends before candela value 3 of 6" -- solve "$work/ies_short.json"
ies v200.ies 3 1 "0 45 200" "0" "100 50 20"; lum_scene ies_v200 v200.ies
expect 2 "an IES vertical angle of 200°" "v200.ies: line 5: vertical angle 200 is outside 0 to 180 degrees" -- solve "$work/ies_v200.json"
ies dark.ies 3 1 "0 45 90" "0" "0 0 0"; lum_scene ies_dark dark.ies
expect 2 "an IES table of zeros" "'$work/dark.ies' emits no light (its candela table is zero)" -- solve "$work/ies_dark.json"
ldt="$src/tests/data/luminaires/photometricviewer_multiple_lamp_sets.ldt"
head -30 "$ldt" > "$work/cut.ldt"; lum_scene ldt_cut cut.ldt
expect 2 "an EULUMDAT file cut inside its lamp sets" "cut.ldt: line 30: the file ends before line 32 (the wattage of set 1 (W))" -- solve "$work/ldt_cut.json"
sed '26s/.*/0/' "$ldt" > "$work/no_sets.ldt"; lum_scene ldt_no_sets no_sets.ldt
expect 2 "an EULUMDAT file of no lamp sets" "no_sets.ldt: line 26: expected the number of lamp sets (a whole number from 1 to 20), got 0" -- solve "$work/ldt_no_sets.json"
sed '29s/.*/-500/' "$ldt" > "$work/negative_flux.ldt"; lum_scene ldt_negative negative_flux.ldt
expect 2 "an EULUMDAT lamp flux of -500 lm" "negative_flux.ldt: line 29: the lamp flux of set 1 must be positive, got -500" -- solve "$work/ldt_negative.json"
: > "$work/empty.ldt"; lum_scene ldt_empty empty.ldt
expect 2 "an empty EULUMDAT file" "empty.ldt: the file is empty" -- solve "$work/ldt_empty.json"

# The year's options, refused before the year is computed.
scene year "{$court_materials, $court_objects, \"sensors\": [{\"name\": \"floor\", \"position\": [1,0.05,1], \"normal\": [0,1,0]}], \"daylight\": {$overcast}}"
epw="$src/scenes/weather/USA_IL_Chicago-OHare.Intl.AP.725300_TMY3.epw"
expect 2 "100 sky patches" "--sky-patches: expected 145, 577 or 2305 sky patches, got 100" -- annual "$work/year.json" --weather "$epw" --sky-patches 100
expect 2 "occupancy from 18 to 8" "--occupancy: expected START-END in hours of the clock" -- annual "$work/year.json" --weather "$epw" --occupancy 18-8
expect 2 "the hour of 40 December" "--hour: expected MM-DDTHH, an hour of the weather file's year" -- annual "$work/year.json" --weather "$epw" --hour 12-40T25
expect 2 "summer time on Mars" "--daylight-saving: expected none, us or eu, got \"mars\"" -- annual "$work/year.json" --weather "$epw" --daylight-saving mars

old_outputs() { echo old-image > "$work/commit/a.png"; echo old-table > "$work/commit/a.csv"; echo old-report > "$work/commit/r.json"; }
outputs_are_old() {
    [ "$(cat "$work/commit/a.png" "$work/commit/a.csv" "$work/commit/r.json")" = "$(printf 'old-image\nold-table\nold-report')" ] &&
        ! ls -a "$work/commit" | grep -q '^\.rayrad-'
}
commit_run() { "$rayrad" render "$work/commit/s.json" -o "$work/commit/a.png" --sensors "$work/commit/a.csv" --report "$work/commit/r.json" -q > /dev/null 2> "$work/commit/err.txt"; }
for fault in rename:1 rename:2 rename:3 signal:write:1 signal:write:3 signal:rename:1 signal:rename:2 signal:rename:3; do
    old_outputs
    RAYRAD_TEST_COMMIT_FAULT=$fault commit_run
    rc=$?
    case $fault in rename:*) want=3 ;; *) want=143 ;; esac  # 128 + SIGTERM
    if [ "$rc" -eq "$want" ] && outputs_are_old; then
        passed=$((passed + 1))
    else
        echo "FAIL commit fault $fault: exit $rc (wanted $want): $(ls -a "$work/commit" | tr '\n' ' ') $(head -c 300 "$work/commit/err.txt")"
        failures=$((failures + 1))
    fi
done
# A real SIGTERM at a moment the test does not choose: either the run had finished (exit 0,
# every output new) or every output is old; never a mix, never a temporary.
old_outputs
commit_run &
pid=$!
sleep 0.2
kill -TERM "$pid" 2> /dev/null
wait "$pid"
rc=$?
if { [ "$rc" -eq 143 ] && outputs_are_old; } ||
   { [ "$rc" -eq 0 ] && ! grep -q old "$work/commit/a.png" "$work/commit/a.csv" "$work/commit/r.json" && ! ls -a "$work/commit" | grep -q '^\.rayrad-'; }; then
    passed=$((passed + 1))
else
    echo "FAIL SIGTERM during a run: exit $rc: $(ls -a "$work/commit" | tr '\n' ' ')"; failures=$((failures + 1))
fi
# Temporaries a dead process left are removed by the next run writing beside them; a
# live process's are not.
old_outputs
sleep 30 & live=$!
dead=999999
while kill -0 "$dead" 2> /dev/null; do dead=$((dead - 1)); done
touch "$work/commit/.rayrad-$dead-0.tmp" "$work/commit/.rayrad-$dead-1.old" "$work/commit/.rayrad-$live-0.tmp"
commit_run
if [ ! -e "$work/commit/.rayrad-$dead-0.tmp" ] && [ ! -e "$work/commit/.rayrad-$dead-1.old" ] && [ -e "$work/commit/.rayrad-$live-0.tmp" ]; then
    passed=$((passed + 1))
else
    echo "FAIL stale temporaries: $(ls -a "$work/commit" | tr '\n' ' ')"; failures=$((failures + 1))
fi
kill "$live" 2> /dev/null; wait "$live" 2> /dev/null
rm -f "$work/commit/.rayrad-$live-0.tmp"

finish "hostile inputs"
