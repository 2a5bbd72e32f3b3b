#!/usr/bin/env python3
"""Writes daylight-office.json: a side-lit office 4 m wide, 6 m deep, 3 m high (y up,
north = -z: the window faces north... see "daylight" below), one 2 x 1.4 m window in a
0.2 m thick wall, a work plane at 0.8 m, under the CIE overcast sky."""
import json

W, D, H = 4.0, 6.0, 3.0         # room: x in [0, W], y in [0, H] (up), z in [0, D]
T = 0.2                         # window wall thickness: its outer face at z = -T
X0, X1, Y0, Y1 = 1.0, 3.0, 0.9, 2.3  # the window's hole


def quad(material, normal, *vertices):
    """A quad whose front faces `normal` (its corners reordered if they wind the other way)."""
    a, b, c = vertices[0], vertices[1], vertices[2]
    e1 = [b[i] - a[i] for i in range(3)]
    e2 = [c[i] - a[i] for i in range(3)]
    n = [e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]]
    if sum(n[i] * normal[i] for i in range(3)) < 0:
        vertices = vertices[::-1]
    return {"type": "quad", "material": material, "vertices": [list(v) for v in vertices]}


objects = [
    quad("floor", (0, 1, 0), (0, 0, 0), (0, 0, D), (W, 0, D), (W, 0, 0)),          # normal +y
    quad("ceiling", (0, -1, 0), (0, H, 0), (W, H, 0), (W, H, D), (0, H, D)),        # normal -y
    quad("wall", (1, 0, 0), (0, 0, 0), (0, H, 0), (0, H, D), (0, 0, D)),           # x = 0, normal +x
    quad("wall", (-1, 0, 0), (W, 0, 0), (W, 0, D), (W, H, D), (W, H, 0)),           # x = W, normal -x
    quad("wall", (0, 0, -1), (0, 0, D), (0, H, D), (W, H, D), (W, 0, D)),           # back wall, normal -z
    # The window wall (z = 0, normal +z) around the hole.
    quad("wall", (0, 0, 1), (0, 0, 0), (W, 0, 0), (W, Y0, 0), (0, Y0, 0)),
    quad("wall", (0, 0, 1), (0, Y1, 0), (W, Y1, 0), (W, H, 0), (0, H, 0)),
    quad("wall", (0, 0, 1), (0, Y0, 0), (X0, Y0, 0), (X0, Y1, 0), (0, Y1, 0)),
    quad("wall", (0, 0, 1), (X1, Y0, 0), (W, Y0, 0), (W, Y1, 0), (X1, Y1, 0)),
    # The window wall's outer face (z = -T, normal -z) around the hole: the wall is solid.
    quad("wall", (0, 0, -1), (0, 0, -T), (W, 0, -T), (W, Y0, -T), (0, Y0, -T)),
    quad("wall", (0, 0, -1), (0, Y1, -T), (W, Y1, -T), (W, H, -T), (0, H, -T)),
    quad("wall", (0, 0, -1), (0, Y0, -T), (X0, Y0, -T), (X0, Y1, -T), (0, Y1, -T)),
    quad("wall", (0, 0, -1), (X1, Y0, -T), (W, Y0, -T), (W, Y1, -T), (X1, Y1, -T)),
    # The reveals, inside the wall's thickness.
    quad("reveal", (0, 1, 0), (X0, Y0, -T), (X1, Y0, -T), (X1, Y0, 0), (X0, Y0, 0)),   # sill, normal +y
    quad("reveal", (0, -1, 0), (X0, Y1, -T), (X0, Y1, 0), (X1, Y1, 0), (X1, Y1, -T)),   # head, normal -y
    quad("reveal", (1, 0, 0), (X0, Y0, -T), (X0, Y0, 0), (X0, Y1, 0), (X0, Y1, -T)),   # left jamb, normal +x
    quad("reveal", (-1, 0, 0), (X1, Y0, -T), (X1, Y1, -T), (X1, Y1, 0), (X1, Y0, 0)),   # right jamb, normal -x
    # The opening at the wall's outer face, its front toward the room.
    quad("window", (0, 0, 1), (X0, Y0, -T), (X1, Y0, -T), (X1, Y1, -T), (X0, Y1, -T)),
]

scene = {
    "description": "A side-lit office, 4 x 6 x 3 m, one 2 x 1.4 m window (sill 0.9 m) in a 0.2 m wall, "
                   "glazed (normal transmittance 0.8), under the CIE overcast sky of 10 000 lx; "
                   "daylight factors on a work plane at 0.8 m.",
    "provenance": "rayrad, scenes/daylight-office/make_scene.py",
    "materials": {
        "floor": {"type": "diffuse", "reflectance": 0.2},
        "wall": {"type": "diffuse", "reflectance": 0.5},
        "reveal": {"type": "diffuse", "reflectance": 0.5},
        "ceiling": {"type": "diffuse", "reflectance": 0.7},
        "window": {"type": "opening", "transmittance": 0.8},
    },
    "objects": objects,
    "daylight": {
        "up": [0, 1, 0],
        "north": [0, 0, -1],
        "sky": {"type": "cie_overcast", "diffuse_horizontal_illuminance": 10000},
        "ground_reflectance": 0.2,
    },
    "sensors": [
        {"name": "front", "position": [2.0, 0.8, 1.0], "normal": [0, 1, 0]},
        {"name": "middle", "position": [2.0, 0.8, 3.0], "normal": [0, 1, 0]},
        {"name": "back", "position": [2.0, 0.8, 5.0], "normal": [0, 1, 0]},
    ],
    "work_planes": [{"name": "desk height", "outline": [[0, 0], [W, 0], [W, D], [0, D]], "height": 0.8,
                     "border": 0.5}],
    "camera": {"position": [3.6, 1.5, 5.7], "look_at": [1.8, 1.2, 0.0], "up": [0, 1, 0], "vfov_deg": 70,
               "resolution": [480, 360]},
    # A seated eye at the middle of the room, looking at the window: the view for DGP.
    "cameras": [{"name": "desk-eye", "position": [3.0, 1.2, 2.6], "look_at": [1.5, 1.2, 0.0], "up": [0, 1, 0],
                 "projection": "fisheye", "resolution": [480, 480]}],
}

with open("daylight-office.json", "w") as f:
    json.dump(scene, f, indent=1)
    f.write("\n")
