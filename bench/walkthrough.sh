#!/usr/bin/env bash
# Benchmark and picture: a walkthrough of the living room (scenes/
# living-room, all defaults: premeshing, mirrors on) solved once (solve --save), its 50
# frames (bench/living_room_path.json, 480 × 270, 4 spp) rendered from the saved solution
# by GNU parallel in five ranges of ten, a contact sheet (oiiotool), and the lit mesh
# exported as .glb, validated and shown in headless Chromium when the viewer's packages
# are installed (scripts/install-test-deps). Prints CPU seconds (user + sys) and wall
# seconds of each step.
# Usage: bench/walkthrough.sh [OUTDIR] [SOLUTION.rrs]   (default out/walkthrough; a solution
#        saved before for the same scene and settings skips the solve)
set -euo pipefail
cd "$(dirname "$0")/.."
rayrad=$PWD/build/src/rayrad
[ -x "$rayrad" ] || scripts/build
scene=${SCENE:-scenes/living-room/living-room.json}
out=${1:-out/walkthrough}
mkdir -p "$out"
path=$(tr -d '\n' < bench/living_room_path.json)
timed() {  # timed LABEL LOG COMMAND...: runs it (output to LOG), prints CPU and wall seconds
    local label=$1 log=$2
    shift 2
    /usr/bin/time -f "%U %S %e" -o "$out/.time" "$@" > "$log" 2>&1
    awk -v l="$label" '{ printf "%-44s %8.1f CPU-s %7.1f s wall\n", l, $1 + $2, $3 }' "$out/.time"
}
solution=${2:-$out/living-room.rrs}
if [ -z "${2:-}" ]; then
    timed "solve --save (all defaults)" "$out/solve.log" "$rayrad" solve "$scene" --save "$solution" -q
fi
timed "50 frames, 5 x 10 through GNU parallel" "$out/frames.log" parallel --will-cite --quote --jobs 2 \
    "$rayrad" render "$scene" --solution "$solution" --set "camera_path=$path" --frames {} -o "$out/frame.png" -q \
    ::: 0:9 10:19 20:29 30:39 40:49
echo "frames: $(ls "$out"/frame.0*.png | wc -l) PNG files in $out"
if command -v oiiotool > /dev/null; then
    oiiotool "$out"/frame.00[0-4]?.png --mosaic 10x5 --resize 2400x0 -o "$out/contact-sheet.jpg"
    echo "contact sheet: $out/contact-sheet.jpg"
fi
timed "export --solution (.glb)" "$out/export.log" "$rayrad" export "$scene" --solution "$solution" \
    -o "$out/living-room.glb" -q
ls -l "$out/living-room.glb" | awk '{ printf "glb: %.1f MB\n", $5 / 1e6 }'
if [ -d scripts/viewer/node_modules/gltf-validator ]; then
    node scripts/viewer/validate.mjs "$out/living-room.glb"
    timed "viewer screenshot (headless Chromium)" "$out/viewer.log" node scripts/viewer/screenshot.mjs \
        "$out/living-room.glb" "$out/viewer.png" 960 540
    cat "$out/viewer.log"
fi
