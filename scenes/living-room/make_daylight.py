#!/usr/bin/env python3
"""Writes living-room-daylight.json: living-room.json with its two lamps off and the sky
and the sun coming in through its four windows.

The windows are holes in the walls (the model's wall meshes, found by rasterising them)
at the back of deep bays whose frames reach 0.51 m beyond the wall x = 0 and 0.59 m beyond
the wall z = 0. Each opening is a quad just beyond the outermost frame, spanning its bay;
the frames and mullions in it shade the sky and the sun as they do in the model. Axes: y up; north is +x, so the arched windows in the wall x = 0 face south
and the two in the wall z = 0 face east. The sky: the CIE clear sky with the sun of
Munich (48.14 N, 11.58 E) on 21 March at 15:00 (UTC+1); rayrad's --set changes it (see
README.md)."""
import json

scene = json.load(open("living-room.json"))
# The lamps off: their surfaces become dark diffuse ones.
for name in ("emitter1", "emitter2"):
    scene["materials"][name] = {"type": "diffuse", "reflectance": 0.05}

scene["materials"]["window"] = {"type": "opening"}
X_OUT, Z_OUT = -0.514, 0.594  # just beyond the frames of the bays (their meshes reach -0.513 and 0.593)
Y0 = 0.0
openings = [
    # Wall x = 0 (arched windows), facing +x into the room: corners CCW seen from +x. Each
    # spans its bay's frame (meshes 038 and 055) across and up to its top.
    [[X_OUT, Y0, -1.943], [X_OUT, Y0, -3.101], [X_OUT, 2.555, -3.101], [X_OUT, 2.555, -1.943]],
    [[X_OUT, Y0, 0.002], [X_OUT, Y0, -1.156], [X_OUT, 2.555, -1.156], [X_OUT, 2.555, 0.002]],
    # Wall z = 0 (rectangular windows, frames 029 and 039), facing -z into the room: CCW seen from -z.
    [[1.341, Y0, Z_OUT], [0.183, Y0, Z_OUT], [0.183, 2.562, Z_OUT], [1.341, 2.562, Z_OUT]],
    [[3.574, Y0, Z_OUT], [2.426, Y0, Z_OUT], [2.426, 2.562, Z_OUT], [3.574, 2.562, Z_OUT]],
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
