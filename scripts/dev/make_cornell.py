#!/usr/bin/env python3
"""Writes scenes/cornell/cornell.json from the measured Cornell box data
(../shared/data/cornell-box.md): millimetres -> metres, block sides oriented outward."""
import json, sys

MM = 0.001
def m(p): return [round(c * MM, 7) for c in p]

def cross(a, b): return [a[1]*b[2]-a[2]*b[1], a[2]*b[0]-a[0]*b[2], a[0]*b[1]-a[1]*b[0]]
def sub(a, b): return [x - y for x, y in zip(a, b)]
def dot(a, b): return sum(x * y for x, y in zip(a, b))

def block(top):
    """Top quad (CCW from above) + four vertical sides to y = 0, normals outward."""
    centre = [sum(p[i] for p in top) / 4 for i in range(3)]
    quads = [top]
    for i in range(4):
        a, b = top[i], top[(i + 1) % 4]
        side = [[a[0], 0, a[2]], [b[0], 0, b[2]], [b[0], a[1], b[2]], [a[0], a[1], a[2]]]
        n = cross(sub(side[1], side[0]), sub(side[3], side[0]))
        if dot(n, sub(side[0], centre)) < 0:
            side.reverse()
        quads.append(side)
    return quads

walls = {
    "floor": ("white", [[552.8, 0, 0], [0, 0, 0], [0, 0, 559.2], [549.6, 0, 559.2]]),
    "ceiling": ("white", [[556.0, 548.8, 0], [556.0, 548.8, 559.2], [0, 548.8, 559.2], [0, 548.8, 0]]),
    "back wall": ("white", [[549.6, 0, 559.2], [0, 0, 559.2], [0, 548.8, 559.2], [556.0, 548.8, 559.2]]),
    "right wall": ("green", [[0, 0, 559.2], [0, 0, 0], [0, 548.8, 0], [0, 548.8, 559.2]]),
    "left wall": ("red", [[552.8, 0, 0], [549.6, 0, 559.2], [556.0, 548.8, 559.2], [556.0, 548.8, 0]]),
}
# The light sits 1 mm below the ceiling so the two surfaces do not coincide.
light = [[343.0, 547.8, 227.0], [343.0, 547.8, 332.0], [213.0, 547.8, 332.0], [213.0, 547.8, 227.0]]

objects = [{"type": "quad", "material": mat, "vertices": [m(p) for p in v]} for mat, v in walls.values()]
objects.append({"type": "quad", "material": "light", "vertices": [m(p) for p in light]})
for top in ([[130, 165, 65], [82, 165, 225], [240, 165, 272], [290, 165, 114]],
            [[423, 330, 247], [265, 330, 296], [314, 330, 456], [472, 330, 406]]):
    for q in block(top):
        objects.append({"type": "quad", "material": "white", "vertices": [m(p) for p in q]})

scene = {
    "description": "The measured Cornell box (Program of Computer Graphics, Cornell University). "
                   "Light lowered 1 mm below the ceiling; emitter luminance 15 000 cd/m^2 (our choice, "
                   "the absolute output was never published), about 643 lm.",
    "provenance": "Cornell Box data, Program of Computer Graphics, Cornell University; see scenes/cornell/README.md.",
    "materials": {
        "white": {"type": "diffuse", "reflectance": [0.738, 0.736, 0.739]},
        "green": {"type": "diffuse", "reflectance": [0.068, 0.399, 0.087]},
        "red": {"type": "diffuse", "reflectance": [0.494, 0.049, 0.051]},
        "light": {"type": "emissive", "reflectance": 0.78, "luminance_cd_m2": 15000,
                  "color": [1.675, 0.878, 0.224]},
    },
    "objects": objects,
    "camera": {"position": m([278, 273, -800]), "look_at": m([278, 273, 0]), "up": [0, 1, 0],
               "vfov_deg": 39.31, "resolution": [256, 256]},
    "sensors": [
        {"name": "floor_back_right", "position": m([150, 0, 450]), "normal": [0, 1, 0]},
        {"name": "floor_front_left", "position": m([450, 0, 120]), "normal": [0, 1, 0]},
        {"name": "floor_back_left", "position": m([500, 0, 520]), "normal": [0, 1, 0]},
        {"name": "floor_front_right", "position": m([60, 0, 40]), "normal": [0, 1, 0]},
    ],
    "sensor_grids": [
        {"name": "floor", "origin": m([20, 0.5, 20]), "u": m([512, 0, 0]), "v": m([0, 0, 519]),
         "counts": [4, 4], "normal": [0, 1, 0]},
    ],
    "radiosity": {"max_edge": 0.05, "stop_unshot": 0.001},
    "render": {"spp": 16, "seed": 1},
}
json.dump(scene, sys.stdout, indent=1)
print()
