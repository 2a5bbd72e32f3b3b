#!/usr/bin/env python3
"""Vertex reconstruction against the final gather on the Cornell box's floor .

A 64 x 64 sensor grid lies on the floor (y = 0), so each point has both the final gather
(`indirect_lx`) and the vertex-interpolated indirect light the ray tracer shows
(`indirect_vertex_lx`). Over the points on the open floor (not under the two boxes, whose
footprints are read from the scene), it prints the distribution of
(vertex - gather) / total illuminance, the points more than 5 % off, and the worst ones.
A band of error along the boxes' bases is what a 4 spp image would show as the radiosity
mesh's triangles.

Usage: bench/vertex_vs_gather.py [--set KEY=VALUE ...]   (extra settings for rayrad solve)
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
COUNT = 64


def footprints(scene):
    """Closed loops of the floor-level edges of quads standing on the floor, inside the room."""
    edges = []
    for o in scene["objects"]:
        v = o.get("vertices") or []
        low = [tuple(p) for p in v if abs(p[1]) < 1e-9]
        if len(low) == 2 and len(v) == 4 and all(0.01 < p[0] < 0.54 and 0.01 < p[2] < 0.55 for p in low):
            edges.append(low)
    loops = []
    while edges:
        loop = list(edges.pop())
        while True:
            nxt = next((e for e in edges if e[0] == loop[-1] or e[1] == loop[-1]), None)
            if nxt is None:
                break
            edges.remove(nxt)
            loop.append(nxt[1] if nxt[0] == loop[-1] else nxt[0])
        loops.append([(p[0], p[2]) for p in loop[:-1]])
    return loops


def inside(loop, x, z):
    """Point in a convex polygon (either winding), with a hair of margin."""
    sides = []
    for (ax, az), (bx, bz) in zip(loop, loop[1:] + loop[:1]):
        sides.append((bx - ax) * (z - az) - (bz - az) * (x - ax))
    return all(s >= -1e-9 for s in sides) or all(s <= 1e-9 for s in sides)


def main():
    scene = json.load(open(SCENE))
    boxes = footprints(scene)
    scene["sensors"] = []
    scene["sensor_grids"] = [{"name": "floor", "origin": [0.0, 0.0, 0.0], "u": [0.5528, 0, 0],
                              "v": [0, 0, 0.5592], "counts": [COUNT, COUNT], "normal": [0, 1, 0]}]
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "cornell_grid.json")
        json.dump(scene, open(path, "w"))
        csv_path = os.path.join(tmp, "grid.csv")
        start = time.time()
        run = subprocess.run([RAYRAD, "solve", path, "--sensors", csv_path, "-q"] + sys.argv[1:],
                             capture_output=True, text=True)
        if run.returncode != 0:
            sys.exit("rayrad solve failed:\n" + run.stderr)
        for line in run.stderr.splitlines():
            if line.startswith(("vertices from a point gather", "reconstruct vertices", "total")):
                print(line)
        rows = list(csv.DictReader(open(csv_path)))
    errors = []
    for r in rows:
        x, z, total = float(r["x"]), float(r["z"]), float(r["total_lx"])
        if total <= 0 or any(inside(b, x, z) for b in boxes):
            continue
        gather, vertex = float(r["indirect_lx"]), float(r["indirect_vertex_lx"])
        errors.append(((vertex - gather) / total * 100, r["sensor"], gather, vertex, total))
    errors.sort()
    n = len(errors)
    pct = lambda q: errors[min(n - 1, int(q * n))][0]
    off = sum(abs(e[0]) > 5 for e in errors)
    print(f"{n} points on the open floor ({len(rows) - n} under the {len(boxes)} boxes left out); "
          f"(vertex - gather) / total: median {pct(0.5):+.1f} %, 5th percentile {pct(0.05):+.1f} %, "
          f"95th {pct(0.95):+.1f} %; more than 5 % off: {off} ({100 * off / n:.0f} %); "
          f"{time.time() - start:.1f} s wall")
    print("largest:")
    for e in errors[:3] + errors[-3:]:
        print("  %+6.1f %%  %-12s gather %5.0f lx, vertex %5.0f lx, total %5.0f lx" % e)


if __name__ == "__main__":
    main()
