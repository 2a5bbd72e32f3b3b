#!/usr/bin/env bash
# The command line end to end on the bundled cube (coarse mesh): info, solve, render.
set -u
rayrad="$1"
src="$2"
source "$(dirname "$0")/test_lib.sh"

cube="$src/scenes/cube/cube.json"
"$rayrad" info "$cube" > "$work/info.txt"
check "info counts patches" grep -q "patches (premeshed triangles): 4800" "$work/info.txt"
check "info lists stages" grep -q "stages needed: premesh, direct light, secondary pass, sensor gather, ray trace" "$work/info.txt"
# Every kind of material, and every view with its lens: the side-lit office's opening and fisheye.
"$rayrad" info "$src/scenes/daylight-office/daylight-office.json" > "$work/info_day.txt"
check "info of a daylight scene exits 0" [ $? -eq 0 ]
check "info names an opening" grep -q "window: opening, transmittance 0.8" "$work/info_day.txt"
check "info names a fisheye view" grep -q 'view "desk-eye": 480x480, fisheye 180 deg' "$work/info_day.txt"

"$rayrad" solve "$cube" --set radiosity.max_edge=2.5 --sensors "$work/s.csv" -q > "$work/solve.txt" 2> "$work/solve.err"
check "solve exit 0" test $? -eq 0
check "csv header" grep -qx "sensor,x,y,z,nx,ny,nz,direct_lx,indirect_lx,total_lx,ref_direct_lx,ref_indirect_lx,ref_total_lx,err_direct_pct,err_indirect_pct,err_total_pct,indirect_vertex_lx,err_indirect_vertex_pct" "$work/s.csv"
check "csv rows" test "$(wc -l < "$work/s.csv")" -eq 4
check "stage times on stderr" grep -q "secondary pass (shooting)" "$work/solve.err"
check "energy line" grep -q "energy: emitted" "$work/solve.err"

# The image libraries are loaded only by commands that read or write an image: the program
# does not link them, and a solve to a CSV never opens the image module.
check "OpenImageIO not linked" test "$(ldd "$rayrad" | grep -c -e OpenImageIO -e OpenColorIO)" -eq 0
LD_DEBUG=files "$rayrad" solve "$cube" --set radiosity.max_edge=2.5 --sensors "$work/s2.csv" -q > /dev/null 2> "$work/ld.txt"
check "solve loads no image module" test "$(grep -c 'file=.*librayrad_image' "$work/ld.txt")" -eq 0
LD_DEBUG=files "$rayrad" render "$cube" --set radiosity.max_edge=2.5 --set camera.resolution=[8,8] -o "$work/l.png" -q \
    > /dev/null 2> "$work/ld.txt"
check "render loads the image module" grep -q 'file=.*librayrad_image' "$work/ld.txt"

"$rayrad" render "$cube" --set radiosity.max_edge=2.5 --set camera.resolution=[16,16] -o "$work/c.exr" -o "$work/c.png" -o "$work/c.jpg" -q > /dev/null 2>&1
check "render exit 0" test $? -eq 0
check "exr written" test -s "$work/c.exr"
check "png written" test -s "$work/c.png"
check "jpg written" test -s "$work/c.jpg"
check "no temporary files left" test "$(ls -a "$work" | grep -c '\.tmp')" -eq 0

# Tone reproduction and white balance: recorded in the display image's metadata.
"$rayrad" render "$cube" --set radiosity.max_edge=2.5 --set camera.resolution=[16,16] --tonemap ward --white-balance 3000K \
    -o "$work/ward.png" -q > /dev/null 2>&1
check "ward render exit 0" test $? -eq 0
check "png records the tone operator" grep -aq "tone: ward: L_wa" "$work/ward.png"
check "png records the white balance" grep -aq "white balance: 3000 K → D65 (Bradford)" "$work/ward.png"
for op in tumblin-rushmeier reinhard; do
    "$rayrad" render "$cube" --set radiosity.max_edge=2.5 --set camera.resolution=[16,16] --tonemap "$op" --white-balance grey-world \
        -o "$work/$op.png" -q > /dev/null 2>&1
    check "$op render exit 0" test $? -eq 0
done

# rayrad compare: an image against itself passes a tight bound; against another
# rendering it reports and fails a bound it exceeds (exit 1); outputs written.
"$rayrad" render "$cube" --set radiosity.max_edge=2.5 --set camera.resolution=[24,24] -o "$work/c1.exr" -q > /dev/null 2>&1
"$rayrad" render "$cube" --set radiosity.max_edge=2.5 --set camera.resolution=[24,24] --set materials.wall.reflectance=0.6 \
    -o "$work/c2.exr" -q > /dev/null 2>&1
echo '[{"name": "centre", "x": 8, "y": 8, "width": 8, "height": 8}]' > "$work/regions.json"
"$rayrad" compare "$work/c1.exr" "$work/c1.exr" --fail-above mean_abs_rel_pct=1e-9 --fail-above ssim_loss=1e-9 > "$work/same.txt" 2>&1
check "compare: an image against itself passes" test $? -eq 0
"$rayrad" compare "$work/c1.exr" "$work/c2.exr" --regions "$work/regions.json" --diff-map "$work/diff.png" \
    --side-by-side "$work/sbs.png" --report "$work/cmp.json" --csv "$work/cmp.csv" --fail-above p95_abs_rel_pct=0.5 \
    > "$work/cmp.txt" 2> "$work/cmp.err"
check "compare: a bound exceeded is exit 1" test $? -eq 1
check "compare: says which bound" grep -q "p95_abs_rel_pct = .* exceeds 0.5" "$work/cmp.err"
check "compare: region row" grep -q "^centre" "$work/cmp.txt"
check "compare: csv rows" test "$(wc -l < "$work/cmp.csv")" -eq 3
check "compare: json exceeded" grep -q '"exceeded": true' "$work/cmp.json"
check "compare: pictures" test -s "$work/diff.png" -a -s "$work/sbs.png"
echo '[{"a": [2, 2], "b": [2, 2]}, {"a": [22, 2], "b": [22, 2]}, {"a": [22, 22], "b": [22, 22]}, {"a": [2, 22], "b": [2, 22]}]' \
    > "$work/align.json"
"$rayrad" compare "$work/c1.exr" "$work/c1.exr" --align "$work/align.json" --fail-above mean_abs_rel_pct=1e-6 > "$work/align.txt" 2>&1
check "compare --align: the identity passes" test $? -eq 0
check "compare --align: says so" grep -q "aligned by a homography through 4 point pairs" "$work/align.txt"
echo '[{"a": [2, 2], "b": [2, 2]}, {"a": [22, 2], "b": [22, 2]}, {"a": [22, 22], "b": [22, 22]}]' > "$work/three.json"
"$rayrad" compare "$work/c1.exr" "$work/c1.exr" --align "$work/three.json" > /dev/null 2> "$work/three.err"
check "compare --align with 3 points: exit 2" test $? -eq 2
check "compare --align with 3 points: named" grep -q "three.json: .*at least 4 point pairs" "$work/three.err"
"$rayrad" compare "$work/c1.exr" "$work/c2.exr" --fail-above bogus=1 > /dev/null 2> "$work/bogus.err"
check "compare: unknown metric is exit 2" test $? -eq 2

# The golden Cornell box (tests/data/cornell_64.exr, as golden_image_test renders it) through
# rayrad compare, as an image-diff test would use it.
"$rayrad" render "$src/scenes/cornell/cornell.json" --set camera.resolution=[64,64] --spp 4 --set radiosity.max_edge=0.1 \
    --set render.area_light_samples=16 \
    -o "$work/cornell64.exr" -q > /dev/null 2>&1
"$rayrad" compare "$work/cornell64.exr" "$src/tests/data/cornell_64.exr" --calibrate none \
    --fail-above median_abs_rel_pct=0.5 --fail-above ssim_loss=0.005 > "$work/golden.txt" 2>&1
check "compare: the golden Cornell box within bounds" test $? -eq 0

# Named views: one solve, a ray trace per view, an image each.
cat > "$work/views.json" <<'JSON'
{"materials": {"w": {"reflectance": 0.5}},
 "objects": [{"type": "box", "min": [0, 0, 0], "max": [3, 2.5, 3], "facing": "inward", "material": "w"},
             {"type": "box", "min": [1, 0, 1], "max": [2, 0.8, 2], "material": "w"}],
 "lights": [{"type": "point", "position": [1.5, 2.2, 1.5], "intensity_cd": 100}],
 "sensors": [{"name": "desk", "position": [1.5, 0.8, 1.5], "normal": [0, 1, 0]}],
 "cameras": [{"name": "front", "position": [1.5, 1.5, 2.9], "look_at": [1.5, 1, 0], "resolution": [16, 16]},
             {"name": "side", "position": [2.9, 1.5, 1.5], "look_at": [0, 1, 1.5], "resolution": [20, 15]}],
 "radiosity": {"max_edge": 1}}
JSON
"$rayrad" render "$work/views.json" --camera all -o "$work/v.png" -o "$work/v.exr" > /dev/null 2> "$work/views.err"
check "views: exit 0" test $? -eq 0
check "views: one image per view" test -s "$work/v.front.png" -a -s "$work/v.side.exr" -a ! -e "$work/v.png"
check "views: one solve" test "$(grep -c '^secondary pass' "$work/views.err")" -eq 1
check "views: a ray trace per view" grep -q "^ray trace (side)" "$work/views.err"
check "views: sensors only when asked" grep -q "sensors (not asked for" "$work/views.err"
"$rayrad" render "$work/views.json" --camera top -o "$work/v.png" > /dev/null 2> "$work/top.err"
check "views: an unknown view is exit 2" test $? -eq 2
check "views: names the views" grep -q 'no view "top" (it has "front", "side", or all)' "$work/top.err"

# A saved solution: solve once, render without solving, the same image; a
# solution for other materials or a damaged file is refused.
"$rayrad" solve "$work/views.json" --save "$work/views.rrs" -q > /dev/null 2>&1
check "save: exit 0" test $? -eq 0 -a -s "$work/views.rrs"
"$rayrad" render "$work/views.json" -o "$work/direct.exr" -q > /dev/null 2>&1
"$rayrad" render "$work/views.json" --solution "$work/views.rrs" -o "$work/fromsol.exr" > /dev/null 2> "$work/fromsol.err"
check "solution: exit 0" test $? -eq 0
check "solution: no solve" grep -q "skipped:.*direct light and secondary pass (solution read from" "$work/fromsol.err"
"$rayrad" compare "$work/fromsol.exr" "$work/direct.exr" --calibrate none --fail-above mean_abs_rel_pct=0 > /dev/null 2>&1
check "solution: the same image as solving" test $? -eq 0
"$rayrad" render "$work/views.json" --solution "$work/views.rrs" --set materials.w.reflectance=0.6 -o "$work/x.png" -q \
    > /dev/null 2> "$work/mismatch.err"
check "solution: other materials refused (exit 2)" test $? -eq 2
check "solution: says what differs" grep -q "views.rrs: this solution was computed for another scene: the materials differ" "$work/mismatch.err"
head -c 300 "$work/views.rrs" > "$work/short.rrs"
"$rayrad" render "$work/views.json" --solution "$work/short.rrs" -o "$work/x.png" -q > /dev/null 2> "$work/short.err"
check "solution: a truncated file refused" grep -q "short.rrs: its checksum does not match" "$work/short.err"
check "solution: nothing written" test ! -e "$work/x.png"

# Nothing reflects: no secondary pass, sensors still answer (indirect 0).
"$rayrad" solve "$cube" --set materials.wall.reflectance=0 --set radiosity.max_edge=2.5 --sensors "$work/black.csv" -q \
    > /dev/null 2> "$work/black.err"
check "black walls: exit 0" test $? -eq 0
check "black walls: secondary pass skipped" grep -q "stages skipped:.*secondary pass (no surface reflects light)" "$work/black.err"
check "black walls: indirect 0 at A" grep -q '^A,5,5,10,0,0,-1,2000,0,2000,' "$work/black.csv"

"$rayrad" --help > "$work/help.txt"
check "help lists commands" grep -q "render" "$work/help.txt"

# A luminaire file: info prints what it integrates to.
"$rayrad" info "$src/tests/data/luminaires/radiance_examp1.ies" > "$work/ies.txt"
check "info on an IES file: integrated flux" grep -q "integrated flux: 5296.65 lm" "$work/ies.txt"
check "info on an IES file: output ratio" grep -q "light output ratio: 0.9132" "$work/ies.txt"
"$rayrad" info "$src/tests/data/luminaires/eulumdatugr_sample_11.ldt" > "$work/ldt.txt"
check "info on an LDT file: stated and integrated ratio" grep -q "light output ratio: 0.6497 (integrated / lamp flux); stated 0.6497" "$work/ldt.txt"

# Light groups: each group's part per sensor in the groups CSV and the JSON report.
cat > "$work/groups.json" <<'JSON'
{"materials": {"w": {"reflectance": 0.5}},
 "objects": [{"type": "box", "min": [0, 0, 0], "max": [3, 2.5, 3], "facing": "inward", "material": "w"}],
 "lights": [{"type": "point", "position": [1, 2.2, 1], "intensity_cd": 100, "group": "left"},
            {"type": "point", "position": [2, 2.2, 2], "intensity_cd": 50, "group": "right"}],
 "sensors": [{"name": "desk", "position": [1.5, 0.8, 1.5], "normal": [0, 1, 0]}],
 "radiosity": {"max_edge": 1}}
JSON
"$rayrad" solve "$work/groups.json" --sensors "$work/g.csv" --report "$work/g.report.json" -q > "$work/groups.txt" 2> "$work/groups.err"
check "light groups: exit 0" test $? -eq 0
check "light groups: table" grep -q "light groups (total lx" "$work/groups.txt"
check "light groups: csv rows" test "$(grep -c '^desk,' "$work/g.groups.csv")" -eq 2
check "light groups: report names them" grep -q '"left"' "$work/g.report.json"
check "light groups: report parts" grep -q '"largest_sum_difference_pct"' "$work/g.report.json"
check "light groups: report has both parts" test "$(grep -c '"total_lx"' "$work/g.report.json")" -eq 2

finish cli
