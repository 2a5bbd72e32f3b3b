#!/usr/bin/env bash
# Walkthroughs, export and sweeps: a camera path's frames (each the same image a
# camera at that place gives), rendered from a saved solution, also through GNU parallel;
# the lit mesh exported as .glb, checked by the Khronos glTF validator and shown by the
# three.js viewer in headless Chromium; a parameter sweep's jobs run by GNU parallel.
set -u
rayrad="$1"
src="$2"
source "$(dirname "$0")/test_lib.sh"
viewer="$src/scripts/viewer"

room='"materials": {"w": {"reflectance": 0.6}, "red": {"reflectance": [0.6, 0.1, 0.1]}},
  "objects": [{"type": "box", "min": [0, 0, 0], "max": [4, 2.8, 3], "facing": "inward", "material": "w"},
              {"type": "box", "min": [2.5, 0, 0.5], "max": [3.5, 0.75, 1.5], "material": "red"}],
  "lights": [{"type": "point", "position": [1.5, 2.5, 1.5], "intensity_cd": 200}],
  "sensors": [{"name": "floor", "position": [1, 0, 1], "normal": [0, 1, 0]}],
  "radiosity": {"max_edge": 0.4}, "render": {"spp": 2}'
path='"camera_path": {"frames": 6, "resolution": [48, 32], "vfov_deg": 60, "keyframes": [
    {"position": [0.4, 1.5, 2.6], "look_at": [3, 0.6, 1]},
    {"position": [2, 1.6, 2.6], "look_at": [3, 0.4, 0.5]},
    {"position": [3.6, 1.5, 2.6], "look_at": [2, 0.6, 0.2]}]}'
scene walk "{ $room, $path }"
scene first "{ $room, \"camera\": {\"position\": [0.4, 1.5, 2.6], \"look_at\": [3, 0.6, 1], \"vfov_deg\": 60, \"resolution\": [48, 32]} }"
scene nopath "{ $room, \"camera\": {\"position\": [0.4, 1.5, 2.6], \"look_at\": [3, 0.6, 1]} }"

# Frames: all six, numbered; frame 0 is the image a camera at keyframe 0 gives.
"$rayrad" render "$work/walk.json" --frames all -o "$work/f.exr" -o "$work/f.png" -q > /dev/null 2> "$work/frames.err"
check "frames: exit 0" test $? -eq 0
check "frames: six EXR and six PNG" test "$(ls "$work"/f.000?.exr "$work"/f.000?.png | wc -l)" -eq 12
"$rayrad" render "$work/first.json" -o "$work/first.exr" -q > /dev/null 2>&1
"$rayrad" compare "$work/f.0000.exr" "$work/first.exr" --calibrate none --fail-above mean_abs_rel_pct=1e-6 > /dev/null 2>&1
check "frames: frame 0 is the keyframe's view" test $? -eq 0
"$rayrad" compare "$work/f.0005.exr" "$work/first.exr" --calibrate none --fail-above mean_abs_rel_pct=1 > /dev/null 2>&1
check "frames: frame 5 is another view" test $? -eq 1

# From a saved solution, a range at a time through GNU parallel (as for a farm).
"$rayrad" solve "$work/walk.json" --save "$work/walk.rrs" -q > /dev/null 2>&1
parallel --will-cite -S : "$rayrad" render "$work/walk.json" --solution "$work/walk.rrs" --frames {} -o "$work/p.exr" -q \
    ::: 0:2 3:5 > /dev/null 2> "$work/parallel.err"
check "frames: two ranges through GNU parallel" test $? -eq 0 -a "$(ls "$work"/p.000?.exr | wc -l)" -eq 6
"$rayrad" compare "$work/p.0004.exr" "$work/f.0004.exr" --calibrate none --fail-above mean_abs_rel_pct=1e-6 > /dev/null 2>&1
check "frames: from the saved solution, the same frame" test $? -eq 0
rm -f "$work"/p.* "$work"/f.*
expect 2 "frames: beyond the path" "frame 6 is beyond the path's 6 frames" -- render "$work/walk.json" --frames 6 -o "$work/out.png"
expect 2 "frames: backwards" "the last frame comes before the first" -- render "$work/walk.json" --frames 4:2 -o "$work/out.png"
expect 2 "frames: malformed" "expected all, K or A:B" -- render "$work/walk.json" --frames x -o "$work/out.png"
expect 2 "frames: no path" "the scene has no \"camera_path\"" -- render "$work/nopath.json" --frames all -o "$work/out.png"
expect 2 "frames: not with --camera" "not with --camera" -- render "$work/walk.json" --frames all --camera camera -o "$work/out.png"
expect 2 "frames: not with --sensors" "not with --sensors" -- render "$work/walk.json" --frames all --sensors "$work/out.csv" -o "$work/out.png"

# Export: the lit mesh as .glb.
"$rayrad" export "$work/walk.json" --solution "$work/walk.rrs" -o "$work/room.glb" -q > /dev/null 2> "$work/export.err"
check "export: exit 0" test $? -eq 0 -a -s "$work/room.glb"
expect 2 "export: only .glb" "give a .glb file" -- export "$work/walk.json" -o "$work/out.gltf"
if [ -d "$viewer/node_modules/gltf-validator" ] && command -v node > /dev/null; then
    node "$viewer/validate.mjs" "$work/room.glb" > "$work/validator.txt" 2>&1
    check "export: the glTF validator finds no error or warning" test $? -eq 0
    check "export: says 0 errors" grep -q ": 0 errors, 0 warnings" "$work/validator.txt"
else
    echo "FAIL the viewer's node modules are missing (scripts/install-test-deps installs them)"
    failures=$((failures + 1))
fi
if [ -d "$viewer/node_modules/puppeteer-core" ] && [ -x "${CHROMIUM:-/usr/bin/chromium}" ]; then
    # The scene has no "camera": the viewer frames the model itself.
    node "$viewer/screenshot.mjs" "$work/room.glb" "$work/room.png" 320 200 > "$work/browser.txt" 2>&1
    check "viewer: headless Chromium shows the lit room (centre pixels not background)" test $? -eq 0 -a -s "$work/room.png"
    [ -s "$work/room.png" ] || cat "$work/browser.txt"
else
    echo "FAIL chromium or puppeteer-core is missing (scripts/install-test-deps installs them)"
    failures=$((failures + 1))
fi

# A saved solution with light groups follows a group's dimming: rendered from it, the room
# with the second light at half strength agrees with solving it so (the clustered solver is
# linear in the emission to within its tolerance); a moved light is refused.
groups='"materials": {"w": {"reflectance": 0.6}},
  "objects": [{"type": "box", "min": [0, 0, 0], "max": [4, 2.8, 3], "facing": "inward", "material": "w"},
              {"type": "box", "min": [2.5, 0, 0.5], "max": [3.5, 0.75, 1.5], "material": "w"}],
  "lights": [{"type": "point", "position": [1, 2.5, 1.5], "intensity_cd": 200, "group": "left"},
             {"type": "point", "position": [3, 2.5, 1.5], "intensity_cd": 200, "group": "right"}],
  "camera": {"position": [0.4, 1.5, 2.6], "look_at": [3, 0.6, 1], "resolution": [48, 32]},
  "radiosity": {"max_edge": 0.4}, "render": {"spp": 2}'
scene groups "{ $groups }"
"$rayrad" solve "$work/groups.json" --save "$work/groups.rrs" -q > /dev/null 2>&1
check "groups: solve --save" test -s "$work/groups.rrs"
"$rayrad" render "$work/groups.json" --set lights.1.intensity_cd=100 --solution "$work/groups.rrs" -o "$work/dimmed.exr" -q \
    > /dev/null 2> "$work/dimmed.err"
check "groups: a dimmed group rendered from the saved solution" test $? -eq 0 -a -s "$work/dimmed.exr"
"$rayrad" render "$work/groups.json" --set lights.1.intensity_cd=100 -o "$work/resolved.exr" -q > /dev/null 2>&1
"$rayrad" compare "$work/dimmed.exr" "$work/resolved.exr" --calibrate none --fail-above mean_abs_rel_pct=0.3 > "$work/dim.txt" 2>&1
check "groups: the same image as solving it dimmed (mean |rel. error| below 0.3 %)" test $? -eq 0
"$rayrad" render "$work/groups.json" --solution "$work/groups.rrs" -o "$work/undimmed.exr" -q > /dev/null 2>&1
"$rayrad" compare "$work/undimmed.exr" "$work/dimmed.exr" --calibrate none --fail-above mean_abs_rel_pct=5 > /dev/null 2>&1
check "groups: dimming changed the image" test $? -eq 1
expect 2 "groups: a moved light is refused" "the lights differ" -- render "$work/groups.json" --set lights.1.position=[3,2.4,1.5] \
    --solution "$work/groups.rrs" -o "$work/out.exr"

# Sweep: two values of a light's intensity and two meshes, four jobs run by GNU parallel;
# the light is linear in the intensity, so 400 cd gives twice the illuminance of 200.
"$rayrad" sweep "$work/walk.json" --vary lights.0.intensity_cd=200,400 --vary radiosity.max_edge=0.5,0.4 \
    --run "solve -q --sensors $work/sweep{job}.csv" --jobs "$work/jobs.txt" > /dev/null 2> "$work/sweep.err"
check "sweep: exit 0" test $? -eq 0
check "sweep: four jobs" test "$(wc -l < "$work/jobs.txt")" -eq 4
check "sweep: the values table" grep -qx "2,400,0.5" "$work/jobs.csv"
parallel --will-cite < "$work/jobs.txt" > /dev/null 2>&1
check "sweep: the jobs ran" test -s "$work/sweep0.csv" -a -s "$work/sweep3.csv"
e0=$(awk -F, '$1 == "floor" { print $10 }' "$work/sweep0.csv")
e2=$(awk -F, '$1 == "floor" { print $10 }' "$work/sweep2.csv")
check "sweep: twice the light, twice the illuminance ($e0, $e2 lx)" awk -v a="$e0" -v b="$e2" 'BEGIN { exit !(a > 0 && (b / a - 2)^2 < 1e-10) }'
expect 2 "sweep: a value the scene refuses is named with its job" "job 1 (-5,0.4)" -- sweep "$work/walk.json" \
    --vary lights.0.intensity_cd=200,-5 --vary radiosity.max_edge=0.4 --jobs "$work/out.txt"
finish walkthrough
