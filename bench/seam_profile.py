#!/usr/bin/env python3
"""The indirect light across a concave seam: the Cornell box's ceiling and back wall .

Sensors in four rows run away from the seam where the ceiling meets the back wall: two
on the ceiling (x = 0.10 and 0.45 m) and two down the back wall, from 0.3 mm to 280 mm.
Each sensor has the final gather (`indirect_lx`) and the mesh's vertex-interpolated value
at the same point (`indirect_vertex_lx`, what the ray tracer shows); the table prints
both and their difference. A mesh that follows the corner's fall-off reads within a few
per cent at every distance.

Usage: bench/seam_profile.py [--set KEY=VALUE ...]   (extra settings for rayrad solve;
       the scene's own max_edge is 0.05 m)
"""
import csv
import json
import os
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
RAYRAD = os.path.join(ROOT, "build", "src", "rayrad")
SCENE = os.path.join(ROOT, "scenes", "cornell", "cornell.json")
CEILING_Y, BACK_Z = 0.5488, 0.5592      # m, the ceiling's height and the back wall's depth
DISTANCES_MM = [0.3, 1, 2, 4, 8, 15, 25, 40, 60, 100, 150, 200, 280]
ROWS = [("ceiling x=0.10", 0.10, "ceiling"), ("ceiling x=0.45", 0.45, "ceiling"),
        ("back wall x=0.10", 0.10, "wall"), ("back wall x=0.45", 0.45, "wall")]


def sensor(row, x, surface, mm):
    s = mm / 1000
    if surface == "ceiling":
        return {"name": f"{row}|{mm}", "position": [x, CEILING_Y, BACK_Z - s], "normal": [0, -1, 0]}
    return {"name": f"{row}|{mm}", "position": [x, CEILING_Y - s, BACK_Z], "normal": [0, 0, -1]}


def main():
    if not os.access(RAYRAD, os.X_OK):
        sys.exit(f"{RAYRAD} not found: run scripts/build first")
    with open(SCENE) as f:
        scene = json.load(f)
    scene["sensors"] = [sensor(row, x, surface, mm) for row, x, surface in ROWS for mm in DISTANCES_MM]
    scene.pop("sensor_grids", None)
    with tempfile.TemporaryDirectory() as tmp:
        scene_path, table = os.path.join(tmp, "seam.json"), os.path.join(tmp, "seam.csv")
        with open(scene_path, "w") as f:
            json.dump(scene, f)
        start = time.time()
        subprocess.run([RAYRAD, "solve", scene_path, "--sensors", table, "-q"] + sys.argv[1:], check=True,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        wall = time.time() - start
        values = {}
        with open(table) as f:
            for r in csv.DictReader(f):
                values[r["sensor"]] = (float(r["indirect_lx"]), float(r["indirect_vertex_lx"]))
    print("indirect lx, gather / mesh (mesh against gather); solve " + f"{wall:.1f} s wall")
    print("| mm from the seam | " + " | ".join(row for row, _, _ in ROWS) + " |")
    print("|---" * (len(ROWS) + 1) + "|")
    for mm in DISTANCES_MM:
        cells = []
        for row, _, _ in ROWS:
            gather, mesh = values[f"{row}|{mm}"]
            cells.append(f"{gather:.0f} / {mesh:.0f} ({100 * (mesh / gather - 1):+.1f} %)")
        print(f"| {mm:g} | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()
