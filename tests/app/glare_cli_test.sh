#!/usr/bin/env bash
# Glare through the real command line: UGR at observers, a UGR table, DGP of a fisheye,
# and bad observers, luminaire files and images (exit 2, one line, nothing written).
set -u
rayrad="$1"
src="$2"
source "$(dirname "$0")/test_lib.sh"
ldt="$src/tests/data/luminaires/eulumdatugr_sample_11.ldt"

materials='"materials": {"white": {"reflectance": 0.5}}'
room='{"type": "box", "min": [0,0,0], "max": [4,3,6], "facing": "inward", "material": "white"}'
luminaires="\"lights\": [
  {\"type\": \"luminaire\", \"file\": \"$ldt\", \"position\": [2,2.99,2], \"aim\": [2,0,2], \"c0_toward\": [0,0,1]},
  {\"type\": \"luminaire\", \"file\": \"$ldt\", \"position\": [2,2.99,4], \"aim\": [2,0,4], \"c0_toward\": [0,0,1]}]"
observer='{"name": "desk", "position": [2,1.2,0.5], "direction": [0,0,1], "task": "office"}'
scene room "{$materials, \"objects\": [$room], $luminaires, \"observers\": [$observer],
  \"camera\": {\"position\": [2,1.5,0.3], \"look_at\": [2,1.5,6], \"resolution\": [64,48]}, \"radiosity\": {\"max_edge\": 0.5}}"

# UGR at the observer: the table, the CSV beside the sensors', the JSON report.
out=$("$rayrad" solve "$work/room.json" --sensors "$work/s.csv" --report "$work/r.json" -q 2>"$work/err")
check "solve exits 0" [ $? -eq 0 ]
check "prints the observer" grep -qE "^desk +[0-9]+\.[0-9] +19 +pass +2 " <<<"$out"
check "lists its sources" grep -q "^    /lights/1 " <<<"$out"
check "glare CSV" grep -qE "^desk,2,1.2,0.5,0,0,1,[0-9.]+,19,office,pass," "$work/s.glare.csv"
check "report has the observer" python3 -c "import json,sys; o=json.load(open('$work/r.json'))['observers'][0]; sys.exit(0 if o['name']=='desk' and o['ugr']>5 and len(o['sources'])==2 else 1)"

# Each observer's fisheye with its sources marked (the luminaires ringed), and DGP with it.
mkdir -p "$work/pictures"
out=$("$rayrad" solve "$work/room.json" --glare-pictures "$work/pictures" -q 2>/dev/null)
check "glare pictures: solve exits 0" [ $? -eq 0 ]
check "glare pictures: the observer's picture" bash -c "head -c 8 '$work/pictures/desk.png' | grep -q PNG"
check "glare pictures: DGP with them" grep -qE "^desk +[0-9]+\.[0-9] .* 0\.[0-9]{3}  (imperceptible|perceptible|disturbing|intolerable)" <<<"$out"

# The UGR table of a luminaire file, and its CSV.
out=$("$rayrad" info "$ldt" --ugr-table --ugr-csv "$work/t.csv" 2>/dev/null)
check "info exits 0" [ $? -eq 0 ]
check "table heading" grep -q "^UGR table (CIE 190 tabular method)" <<<"$out"
check "table rows" [ "$(grep -cE '^ +[0-9]+H +[0-9]+H ' <<<"$out")" -eq 19 ]
check "table CSV" [ "$(wc -l < "$work/t.csv")" -eq 20 ]

# DGP of a fisheye rendering, and its marked picture.
scene fish "{$materials, \"objects\": [$room], $luminaires, \"camera\": {\"position\": [2,1.2,0.5],
  \"look_at\": [2,1.8,6], \"projection\": \"fisheye\", \"resolution\": [200,200]}, \"radiosity\": {\"max_edge\": 0.5}}"
"$rayrad" render "$work/fish.json" -o "$work/fish.exr" -q 2>/dev/null
check "fisheye rendered" [ -s "$work/fish.exr" ]
out=$("$rayrad" glare "$work/fish.exr" --marked "$work/marked.png" --report "$work/g.json" 2>/dev/null)
check "glare exits 0" [ $? -eq 0 ]
check "prints DGP and its class" grep -qE "^DGP 0\.[0-9]+ \((imperceptible|perceptible|disturbing|intolerable)\); UGR " <<<"$out"
check "marked picture is a PNG" bash -c "head -c 8 '$work/marked.png' | grep -q PNG"
check "glare report" python3 -c "import json,sys; j=json.load(open('$work/g.json')); sys.exit(0 if j['ev_lx']>0 and 'dgp_class' in j else 1)"

# Under a daylight each observer also gets DGP, from a fisheye rendered at its eye: a
# courtyard open to an overcast sky, the observer looking up at it.
scene court "{\"materials\": {\"white\": {\"reflectance\": 0.5}, \"sky\": {\"type\": \"opening\"}}, $court_objects,
  \"daylight\": {\"sky\": {\"type\": \"cie_overcast\", \"diffuse_horizontal_illuminance\": 20000}},
  \"observers\": [{\"name\": \"up\", \"position\": [1,1,0.3], \"direction\": [0,1,1]}], \"radiosity\": {\"max_edge\": 0.5}}"
out=$("$rayrad" solve "$work/court.json" --sensors "$work/c.csv" -q 2>/dev/null)
check "daylight solve exits 0" [ $? -eq 0 ]
check "prints DGP per observer" grep -qE "^up +- .* 0\.[0-9]{3}  (imperceptible|perceptible|disturbing|intolerable)" <<<"$out"
check "DGP in the CSV" grep -qE "^up,.*,0\.[0-9]{4},(imperceptible|perceptible|disturbing|intolerable)$" "$work/c.glare.csv"

# rayrad validate glare: every check within its bound.
out=$("$rayrad" validate glare 2>/dev/null)
check "validate glare exits 0" [ $? -eq 0 ]
check "validate glare prints its 12 checks" [ "$(grep -c ' s |$' <<<"$out")" -eq 12 ]

# Bad input: one line naming the place, exit 2 (3 for an output), nothing written.
scene inside "{$materials, \"objects\": [$room, {\"type\": \"box\", \"min\": [1,0,3], \"max\": [3,2,5],
  \"facing\": \"outward\", \"material\": \"white\"}], $luminaires,
  \"observers\": [{\"name\": \"buried\", \"position\": [2,1,4], \"direction\": [0,0,1]}]}"
expect 2 "observer inside a solid" "inside.json: /observers/0: observer \"buried\" at (2, 1, 4) is inside a solid" -- solve "$work/inside.json" --sensors "$work/out.csv" -q
scene zero "{$materials, \"objects\": [$room], $luminaires, \"observers\": [{\"position\": [2,1,1], \"direction\": [0,0,0]}]}"
expect 2 "view direction of zero length" "zero.json: /observers/0/direction: the view direction has zero length" -- solve "$work/zero.json" --sensors "$work/out.csv"
scene task "{$materials, \"objects\": [$room], $luminaires, \"observers\": [{\"position\": [2,1,1], \"direction\": [0,0,1], \"task\": \"juggling\"}]}"
expect 2 "unknown task" "task.json: /observers/0/task: unknown task \"juggling\"" -- solve "$work/task.json" --sensors "$work/out.csv"
scene point "{$materials, \"objects\": [$room], \"lights\": [{\"type\": \"point\", \"position\": [2,2.5,3], \"intensity_cd\": 100}],
  \"observers\": [$observer]}"
expect 2 "a point light in view" "point.json: /observers/0: observer \"desk\" sees the light /lights/0 (a point light), which has no luminous area" -- solve "$work/point.json" --sensors "$work/out.csv" -q
printf 'IESNA:LM-63-2002\n[TEST] none\nTILT=NONE\n1 1000 1 3 1 1 2 0 0 0\n1 1 10\n0 90 180\n0\n300 100 0\n' > "$work/flat.ies"
expect 2 "luminaire file without a luminous area" "flat.ies: the file gives no luminous area" -- info "$work/flat.ies" --ugr-csv "$work/out.csv"
scene flat "{$materials, \"objects\": [$room], \"lights\": [{\"type\": \"luminaire\", \"file\": \"$work/flat.ies\",
  \"position\": [2,2.99,3], \"aim\": [2,0,3]}], \"observers\": [$observer]}"
expect 2 "an observer sees a luminaire without a luminous area" "whose file $work/flat.ies gives no luminous area" -- solve "$work/flat.json" --sensors "$work/out.csv" -q
expect 2 "glare pictures without observers" "--glare-pictures: the scene has no observers" -- solve "$work/fish.json" --glare-pictures "$work"
expect 2 "UGR table of a scene" "--ugr-table: a UGR table is made for a photometric file" -- info "$work/room.json" --ugr-table
"$rayrad" render "$work/room.json" -o "$work/view.exr" -q 2>/dev/null
expect 2 "glare of an image that is no fisheye" "view.exr: pixel (0, 0): not black outside the image's inscribed circle" -- glare "$work/view.exr" --report "$work/out.json"
expect 3 "marked picture as EXR" "the marked fisheye is a display image" -- glare "$work/fish.exr" --marked "$work/out.exr"

finish "glare cli"
