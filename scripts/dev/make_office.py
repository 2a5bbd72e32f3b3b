#!/usr/bin/env python3
"""Writes scenes/office/office.json: a 6 x 8 x 2.8 m office lit by eight recessed LED
luminaires (the CIE 190:2010 example luminaire, tests/data/luminaires/
eulumdatugr_sample_11.ldt, scaled to 3 600 lm each), with four desks, a cabinet, a work
plane at 0.75 m (0.5 m border, EN 12464-1 spacing), four seated observers (UGR, EN 12464-1's
limit for offices) and a camera.

Usage: scripts/dev/make_office.py > scenes/office/office.json
"""
import json
import sys

W, L, H = 6.0, 8.0, 2.8  # x, z, y (up), m


def box(material, lo, hi, facing="outward"):
    return {"type": "box", "material": material, "min": lo, "max": hi, "facing": facing}


def main():
    objects = [box("wall", [0, 0, 0], [W, H, L], "inward")]
    # Four desks (0.75 m high, 1.6 x 0.8 m), two by the window wall, two by the inner wall.
    for x in (1.0, 3.6):
        for z in (1.6, 5.0):
            objects.append(box("desk", [x, 0, z], [x + 1.6, 0.75, z + 0.8]))
    objects.append(box("cabinet", [5.55, 0, 3.0], [6.0, 1.9, 4.6]))  # against the wall
    lights = []
    for x in (1.5, 4.5):
        for z in (1.0, 3.0, 5.0, 7.0):
            lights.append({"type": "luminaire", "file": "../../tests/data/luminaires/eulumdatugr_sample_11.ldt",
                           "position": [x, H - 0.01, z], "aim": [x, 0, z], "c0_toward": [0, 0, 1],
                           "flux_lm": 3600, "maintenance_factor": 0.8, "cct_k": 4000})
    scene = {
        "description": "Office, 6 x 8 x 2.8 m, eight recessed LED luminaires (CIE 190 example distribution, "
                       "3 600 lm, maintenance factor 0.8, 4 000 K), four desks, a cabinet; work plane at 0.75 m; four seated observers. "
                       "Written by scripts/dev/make_office.py.",
        "materials": {
            "wall": {"reflectance": 0.7},
            "desk": {"reflectance": [0.45, 0.35, 0.25]},
            "cabinet": {"reflectance": 0.5},
        },
        "objects": objects,
        "lights": lights,
        "work_planes": [{"name": "office", "outline": [[0, 0], [W, 0], [W, L], [0, L]], "height": 0.75, "border": 0.5}],
        "surface_grids": [{"name": "desk", "material": "desk", "facing": [0, 1, 0]}],
        # Seated at each desk (eye 1.2 m), looking along the room over the desk.
        "observers": [{"name": name, "position": [x, 1.2, z], "direction": [0, 0, dz], "task": "office"}
                      for name, x, z, dz in (("desk-1", 1.8, 1.1, 1), ("desk-2", 4.4, 1.1, 1),
                                             ("desk-3", 1.8, 6.3, -1), ("desk-4", 4.4, 6.3, -1))],
        "camera": {"position": [0.4, 1.6, 0.4], "look_at": [4.0, 0.9, 6.5], "up": [0, 1, 0], "vfov_deg": 65,
                   "resolution": [640, 480]},
        "radiosity": {"max_edge": 0.25},
        "render": {"spp": 4},
    }
    json.dump(scene, sys.stdout, indent=1)
    sys.stdout.write("\n")


if __name__ == "__main__":
    main()
