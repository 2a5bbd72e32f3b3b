#!/usr/bin/env python3
"""Writes living-room-daylight.json: living-room.json with its two lamps off and the sky
and the sun coming in through its four windows.

The windows are holes in the walls (the model's wall meshes, found by rasterising them)
at the back of deep bays whose frames reach 0.51 m beyond the wall x = 0 and 0.59 m beyond
the wall z = 0. Each opening is a quad just beyond the outermost frame, covering its bay;
where it is larger than the hole, the wall and the frames shade the rest of it, as they
do the sky. Axes: y up; north is +x, so the arched windows in the wall x = 0 face south
and the two in the wall z = 0 face east. The sky: the CIE clear sky with the sun of
Munich (48.14 N, 11.58 E) on 21 March at 15:00 (UTC+1); rayrad's --set changes it (see
README.md)."""
import json

scene = json.load(open("living-room.json"))
# The lamps off: their surfaces become dark diffuse ones.
for name in ("emitter1", "emitter2"):
    scene["materials"][name] = {"type": "diffuse", "reflectance": 0.05}

scene["materials"]["window"] = {"type": "opening"}
X_OUT, Z_OUT = -0.53, 0.61  # just beyond the frames of the bays
Y0, Y1 = 0.0, 2.6
openings = [
    # Wall x = 0 (arched windows), facing +x into the room: corners CCW seen from +x.
    [[X_OUT, Y0, -1.92], [X_OUT, Y0, -3.12], [X_OUT, Y1, -3.12], [X_OUT, Y1, -1.92]],
    [[X_OUT, Y0, 0.02], [X_OUT, Y0, -1.18], [X_OUT, Y1, -1.18], [X_OUT, Y1, 0.02]],
    # Wall z = 0 (rectangular windows), facing -z into the room: CCW seen from -z.
    [[1.36, Y0, Z_OUT], [0.16, Y0, Z_OUT], [0.16, Y1, Z_OUT], [1.36, Y1, Z_OUT]],
    [[3.60, Y0, Z_OUT], [2.40, Y0, Z_OUT], [2.40, Y1, Z_OUT], [3.60, Y1, Z_OUT]],
]
for v in openings:
    scene["objects"].append({"type": "quad", "material": "window", "vertices": v})

scene["daylight"] = {
    "up": [0, 1, 0],
    "north": [1, 0, 0],
    "sky": {"type": "cie_clear", "diffuse_horizontal_illuminance": 12000},
    "sun": {"latitude": 48.14, "longitude": 11.58, "utc_offset": 1, "date": "2026-03-21", "time": "15:00",
            "direct_normal_illuminance": 60000},
    "ground_reflectance": 0.2,
}
scene["description"] = ("Bitterli's living room (Wig42, CC BY 3.0) lit by daylight through its four windows: "
                        "the CIE clear sky with the sun of Munich on 21 March at 15:00; the lamps off.")
scene["provenance"] = scene.get("provenance", "") + "; daylight and openings by make_daylight.py"
with open("living-room-daylight.json", "w") as f:
    json.dump(scene, f, indent=1)
    f.write("\n")
