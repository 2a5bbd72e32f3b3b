#!/usr/bin/env python3
"""Writes the bench hall: a 20 x 40 x 4 m open-plan office with 100 ceiling
troffers (0.6 x 0.6 m emissive quads of 2 653 cd/m², 3 000 lm each, 1 cm below the ceiling), 100 desks
(boxes standing on the carpet) and 20 cabinets along the long walls. With the default
max_edge below it premeshes to 104 240 patches.

Usage: bench/hall.py > hall.json
"""
import json
import sys

W, L, H = 20.0, 40.0, 4.0      # hall width (x), length (z), height (y), m
ROWS, COLS = 10, 10            # luminaires and desks: ROWS along z, COLS along x


def quad(material, vertices, facing):
    """A quad whose front (counter-clockwise side) faces `facing`."""
    a, b, c = vertices[0], vertices[1], vertices[2]
    e1 = [b[i] - a[i] for i in range(3)]
    e2 = [c[i] - b[i] for i in range(3)]
    n = [e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]]
    if sum(n[i] * facing[i] for i in range(3)) < 0:
        vertices = vertices[::-1]
    return {"type": "quad", "material": material, "vertices": vertices}


def box(material, lo, hi):
    return {"type": "box", "material": material, "min": lo, "max": hi}


def main():
    objects = [
        # The shell: floor, ceiling and walls, each facing into the hall.
        quad("carpet", [[0, 0, 0], [W, 0, 0], [W, 0, L], [0, 0, L]], [0, 1, 0]),
        quad("ceiling", [[0, H, 0], [W, H, 0], [W, H, L], [0, H, L]], [0, -1, 0]),
        quad("wall", [[0, 0, 0], [0, 0, L], [0, H, L], [0, H, 0]], [1, 0, 0]),
        quad("wall", [[W, 0, 0], [W, 0, L], [W, H, L], [W, H, 0]], [-1, 0, 0]),
        quad("wall", [[0, 0, 0], [W, 0, 0], [W, H, 0], [0, H, 0]], [0, 0, 1]),
        quad("wall", [[0, 0, L], [W, 0, L], [W, H, L], [0, H, L]], [0, 0, -1]),
    ]
    y = H - 0.01
    for r in range(ROWS):
        for c in range(COLS):
            x = (c + 0.5) * W / COLS
            z = (r + 0.5) * L / ROWS
            # Troffer, facing down.
            objects.append(quad("troffer", [[x - 0.3, y, z - 0.3], [x + 0.3, y, z - 0.3],
                                            [x + 0.3, y, z + 0.3], [x - 0.3, y, z + 0.3]], [0, -1, 0]))
            # Desk under it, offset so it is not in the troffer's axis.
            objects.append(box("desk", [x - 0.8, 0.0, z + 0.6], [x + 0.8, 0.75, z + 1.4]))
    for k in range(10):  # cabinets against the long walls, touching wall and floor
        z = 2.0 + k * 4.0
        objects.append(box("cabinet", [0.0, 0.0, z], [0.45, 1.2, z + 1.0]))
        objects.append(box("cabinet", [W - 0.45, 0.0, z], [W, 1.2, z + 1.0]))
    scene = {
        "description": "Bench hall: 20 x 40 x 4 m office, 100 troffers of 3 000 lm, "
                       "100 desks, 20 cabinets. Written by bench/hall.py.",
        "materials": {
            "carpet": {"type": "diffuse", "reflectance": [0.25, 0.22, 0.2]},
            "wall": {"type": "diffuse", "reflectance": 0.6},
            "ceiling": {"type": "diffuse", "reflectance": 0.8},
            "desk": {"type": "diffuse", "reflectance": [0.55, 0.45, 0.35]},
            "cabinet": {"type": "diffuse", "reflectance": 0.5},
            "troffer": {"type": "emissive", "luminance_cd_m2": 2653, "reflectance": 0.7},
        },
        "objects": objects,
        "camera": {"position": [W / 2, 1.6, 0.5], "look_at": [W / 2, 1.2, L], "up": [0, 1, 0],
                   "vfov_deg": 60, "resolution": [1280, 1024]},
        "radiosity": {"max_edge": 0.25},
        "render": {"spp": 4},
    }
    json.dump(scene, sys.stdout, indent=1)
    sys.stdout.write("\n")


if __name__ == "__main__":
    main()
