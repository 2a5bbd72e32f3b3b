#!/usr/bin/env bash
# Benchmark: how far the radiosity mesh's indirect light is from a final
# gather at every hit, in an image. One solve, saved; then two renders from it with the
# same seed (so the direct light is the same, sample for sample): the indirect light
# interpolated from the mesh's vertex values (the default), and gathered at each hit
# (render.indirect "gather", as at a sensor: no mesh can show). `rayrad compare` prints
# their difference (mesh against gather) and writes a difference map, and, with
# ImageMagick's montage, a contact sheet of the three. Prints each render's CPU seconds
# (user + sys) and wall seconds.
# Usage: bench/mesh_vs_gather_image.sh [SCENE [WIDTHxHEIGHT [MAX_EDGE [OUTDIR]]]]
#        (default: the Cornell box, 64x64, 0.1 m, a temporary directory;
#        SET="--set KEY=VALUE ..." passes more settings to the solve and the renders)
set -euo pipefail
cd "$(dirname "$0")/.."
rayrad=build/src/rayrad
[ -x "$rayrad" ] || scripts/build
scene=${1:-scenes/cornell/cornell.json}
size=${2:-64x64}
edge=${3:-0.1}
w=${size%x*} h=${size#*x}
if [ -n "${4:-}" ]; then out=$4; mkdir -p "$out"; else out=$(mktemp -d); trap 'rm -rf "$out"' EXIT; fi
total() { awk '/^total/ {printf "%s CPU-s, %s s wall", $3, $2}' "$1"; }
read -ra extra <<< "${SET:-}"
set_edge=(--set "radiosity.max_edge=$edge" --set "camera.resolution=[$w,$h]" --set render.spp=1 "${extra[@]}")
"$rayrad" solve "$scene" "${set_edge[@]}" --save "$out/solution.rrs" -q > /dev/null 2> "$out/solve.err"
echo "solve: $(total "$out/solve.err")"
"$rayrad" render "$scene" "${set_edge[@]}" --solution "$out/solution.rrs" -o "$out/mesh.exr" -o "$out/mesh.png" -q \
    > /dev/null 2> "$out/mesh.err"
echo "render, indirect from the mesh: $(total "$out/mesh.err")"
"$rayrad" render "$scene" "${set_edge[@]}" --set render.indirect=gather --solution "$out/solution.rrs" \
    -o "$out/gather.exr" -o "$out/gather.png" -q > /dev/null 2> "$out/gather.err"
echo "render, indirect gathered at each hit: $(total "$out/gather.err")"
"$rayrad" compare "$out/mesh.exr" "$out/gather.exr" --calibrate none --diff-map "$out/mesh_vs_gather.png" 2>&1 |
    grep -v "^compare:"
# A contact sheet, mesh | gather | difference (with ImageMagick, when installed).
if command -v montage > /dev/null && montage -version > /dev/null 2>&1; then
    montage -label "mesh (the image)" "$out/mesh.png" -label "gather at each hit" "$out/gather.png" \
        -label "|mesh − gather| / gather" "$out/mesh_vs_gather.png" -tile 3x1 -geometry +4+4 "$out/contact_sheet.png"
fi
[ -n "${4:-}" ] && echo "images and difference map in $out"
exit 0
