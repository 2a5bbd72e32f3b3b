#!/usr/bin/env bash
# rayrad annual through the real command line: a year under a courtyard open to the sky,
# its outputs, and bad weather files, schedules and scenes (exit 2, one line, nothing written).
set -u
rayrad="$1"
src="$2"
source "$(dirname "$0")/test_lib.sh"
epw="$src/scenes/weather/USA_IL_Chicago-OHare.Intl.AP.725300_TMY3.epw"

walls="$court_objects"
materials='"materials": {"white": {"reflectance": 0.5}, "sky": {"type": "opening"}}'
plane='"sensors": [{"name": "floor", "position": [1,0.05,1], "normal": [0,1,0]}],
  "work_planes": [{"name": "floor plane", "outline": [[0,0],[2,0],[2,2],[0,2]], "height": 0.5, "border": 0.2, "spacing": 0.4}],
  "radiosity": {"max_edge": 0.5}'
# The sun placed at Munich: the weather file's Chicago is far from it (a warning, not an error).
# A lamp under the opening, for --dimming.
lamp='"lights": [{"type": "point", "position": [0.5,1.8,0.5], "intensity_cd": 50, "group": "left"},
                 {"type": "point", "position": [1.5,1.8,1.5], "intensity_cd": 50, "group": "right"}],
  "camera": {"position": [0.2,0.3,0.2], "look_at": [1.5,1.5,1.8], "resolution": [48,36]}'
scene court "{$materials, $walls, $plane, $lamp, \"daylight\": {\"up\": [0,1,0], \"north\": [0,0,-1],
  \"sky\": {\"type\": \"cie_overcast\", \"diffuse_horizontal_illuminance\": 10000},
  \"sun\": {\"latitude\": 48.14, \"longitude\": 11.58, \"utc_offset\": 1, \"date\": \"2021-06-21\", \"time\": \"12:00\"}}}"

# The year: every output, the grid's figures, the warning about the place.
out=$("$rayrad" annual "$work/court.json" --weather "$epw" --metrics "$work/m.csv" --hourly "$work/h.bin" \
      --plan "$work/plan.png" --report "$work/r.json" --hour 06-21T13 --dimming 500 --dimming-control left=floor \
      --image 06-21T13="$work/june.png" --image 06-21T13="$work/june.exr" -q 2>"$work/err")
check "annual exits 0" [ $? -eq 0 ]
check "warns of the place" grep -q "the weather file is for Chicago Ohare Intl Ap (41.98°, -87.92°) but the scene's sun is placed at (48.14°, 11.58°)" "$work/err"
check "prints the grid" grep -q "^floor plane *16 *100.0%" <<<"$out"
check "prints the hour by part" grep -q "^floor " <<<"$out"
check "prints the dimming" grep -q "^daylight-linked dimming to 500 lx" <<<"$out"
check "dims the light groups" grep -qE "^  left +[0-9.]+ %  \(control: floor, " <<<"$out"
check "a group's control by default" grep -qE "^  right +[0-9.]+ %  \(control: floor plane" <<<"$out"
check "groups in the report" python3 -c "import json,sys; g=json.load(open('$work/r.json'))['dimming_groups']; sys.exit(0 if [x['group'] for x in g]==['left','right'] and g[0]['control']=='floor' else 1)"
check "metrics CSV header" grep -q "^sensor,grid,da_pct,cda_pct,udi_below_pct,udi_useful_pct,udi_above_pct,sun_hours,en17037_target_pct,en17037_minimum_pct,excluded,lamp_energy_pct$" "$work/m.csv"
check "metrics CSV rows" [ "$(wc -l < "$work/m.csv")" -eq 18 ]
check "hourly header" bash -c "head -1 '$work/h.bin' | grep -q 'rayrad hourly illuminance 1 points=17 hours=8760 layout=point-major float32-le total-then-sun'"
header=$(head -1 "$work/h.bin" | wc -c)
check "hourly size" [ "$(stat -c %s "$work/h.bin")" -eq $((header + 2 * 17 * 8760 * 4)) ]
check "plan is a PNG" bash -c "head -c 8 '$work/plan.png' | grep -q PNG"
check "an hour's image" bash -c "head -c 8 '$work/june.png' | grep -q PNG"
check "an hour's image in cd/m2" [ -s "$work/june.exr" ]
check "one rendering for the hour" [ "$(grep '^stages run' "$work/err" | grep -o 'ray trace (hour 06-21T13)' | wc -l)" -eq 1 ]
check "report is JSON" python3 -c "import json,sys; j=json.load(open('$work/r.json')); sys.exit(0 if j['grids'][0]['points']==16 and j['coefficients']['solved_suns']>0 else 1)"

# Bad input: one line naming the file or the option, exit 2, nothing written.
head -5000 "$epw" > "$work/short.epw"
expect 2 "truncated weather file" "short.epw: 4992 hours: a weather file holds a whole year" -- annual "$work/court.json" --weather "$work/short.epw" --metrics "$work/out.csv"
sed '2000s/^\([^,]*,[^,]*,[^,]*,\)[^,]*/\1x/' "$epw" > "$work/broken.epw"
expect 2 "corrupted weather file" "broken.epw: line 2000: field 4 (hour): expected a number, got \"x\"" -- annual "$work/court.json" --weather "$work/broken.epw" --metrics "$work/out.csv"
printf 'hello\n' > "$work/hello.epw"
expect 2 "not a weather file" "hello.epw: line 1: not an EnergyPlus weather file" -- annual "$work/court.json" --weather "$work/hello.epw" --metrics "$work/out.csv"
expect 2 "missing weather file" "nothere.epw: no such file" -- annual "$work/court.json" --weather "$work/nothere.epw" --metrics "$work/out.csv"
expect 2 "schedule with no hour" "--occupancy: the schedule 9.6–9.9 h takes no hour of the year" -- annual "$work/court.json" --weather "$epw" --occupancy 9.6-9.9 --metrics "$work/out.csv"
expect 2 "schedule backwards" "--occupancy: expected START-END" -- annual "$work/court.json" --weather "$epw" --occupancy 18-8 --metrics "$work/out.csv"
expect 2 "unknown summer time" "--daylight-saving: expected none, us or eu" -- annual "$work/court.json" --weather "$epw" --daylight-saving mars --metrics "$work/out.csv"
expect 2 "sky patch count" "--sky-patches: expected 145, 577 or 2305 sky patches, got 200" -- annual "$work/court.json" --weather "$epw" --sky-patches 200 --metrics "$work/out.csv"
scene overcast "{$materials, $walls, $plane, $lamp,
  \"daylight\": {\"sky\": {\"type\": \"cie_overcast\", \"diffuse_horizontal_illuminance\": 10000}}}"
expect 2 "dimming control without a target" "--dimming-control: needs --dimming LX" -- annual "$work/overcast.json" --weather "$epw" --dimming-control left=floor --metrics "$work/out.csv" -q
expect 2 "dimming control of an unknown group" "--dimming-control: the scene has no light group \"middle\"" -- annual "$work/overcast.json" --weather "$epw" --dimming 500 --dimming-control middle=floor --metrics "$work/out.csv" -q
expect 2 "image without a file" "--image: expected MM-DDTHH=FILE, got \"06-21T13\"" -- annual "$work/overcast.json" --weather "$epw" --image 06-21T13
expect 2 "image of a night hour" "--image: the weather file's hour 01-01T02 has no daylight" -- annual "$work/overcast.json" --weather "$epw" --image 01-01T02="$work/out.png" -q
expect 2 "image of an hour that does not exist" "--image: expected MM-DDTHH, an hour of the weather file's year" -- annual "$work/overcast.json" --weather "$epw" --image 02-30T12="$work/out.png" -q
scene nosky "{$materials, $walls, $plane, \"lights\": [{\"type\": \"point\", \"position\": [1,1,1], \"intensity_cd\": 10}]}"
expect 2 "scene without daylight" "nosky.json: an annual study needs the scene's \"daylight\"" -- annual "$work/nosky.json" --weather "$epw" --metrics "$work/out.csv"
scene nolamp "{$materials, $walls, $plane, \"daylight\": {\"up\": [0,1,0], \"north\": [0,0,-1],
  \"sky\": {\"type\": \"cie_overcast\", \"diffuse_horizontal_illuminance\": 10000}}}"
expect 2 "dimming without lamps" "nolamp.json: --dimming: the scene has no lamps to dim" -- annual "$work/nolamp.json" --weather "$epw" --dimming 500 --metrics "$work/out.csv" -q
expect 3 "plan as HDR" "a false-colour plan is a display image" -- annual "$work/court.json" --weather "$epw" --plan "$work/out.exr"

finish "annual"
