#!/usr/bin/env python3
"""Writes scenes/sphere/sph2.json and sph4.json: the paper's sphere with mirrors
(../shared/method.md, "Sphere with mirrors"). Total references are the paper's Table 4
figures; the direct part is computed here exactly (point light and its mirror images:
E = sum of w I cos / d^2), and the indirect reference is total - direct."""
import json, math, os

RHO, I = 0.7, 100.0
LIGHT = (0.2, 0.4, 0.6)
S2, S3 = 1 / math.sqrt(2), 1 / math.sqrt(3)
POINTS = {"A": (0.0, 0.0, 1.0), "B": (0.0, S2, S2), "C": (S3, S3, S3)}

def direct(p, images):
    """Illuminance at p on the unit sphere (normal -p) from weighted image points."""
    e = 0.0
    for w, s in images:
        d = [s[i] - p[i] for i in range(3)]
        r2 = sum(c * c for c in d)
        cos = -sum(d[i] * p[i] for i in range(3)) / math.sqrt(r2)
        e += w * I * cos / r2
    return e

def scene(name, description, keep, mirrors, images, totals):
    sensors = []
    for key, total in totals.items():
        p = POINTS[key]
        d = direct(p, images)
        sensors.append({"name": key, "position": list(p), "normal": [-c for c in p],
                        "reference": {"direct_lx": round(d, 3), "indirect_lx": round(total - d, 3),
                                      "total_lx": total}})
    return {
        "description": description,
        "provenance": "Myszkowski & Kunii, Table 4; references in ../shared/method.md; "
                      "written by scripts/dev/make_sphere_scenes.py",
        "materials": {
            "wall": {"type": "diffuse", "reflectance": RHO},
            **{m["material"]: {"type": "mirror", "specular_reflectance": m["ks"]} for m in mirrors},
        },
        "objects": [{"type": "sphere", "material": "wall", "center": [0, 0, 0], "radius": 1,
                     "subdivisions": 8, "facing": "inward", "keep_above": keep}]
                   + [{"type": "quad", "material": m["material"], "vertices": m["vertices"]} for m in mirrors],
        "lights": [{"type": "point", "position": list(LIGHT), "intensity_cd": I}],
        "camera": {"position": [0, -0.2, 0.05], "look_at": [0, 0.6, 0.6], "up": [0, 0, 1],
                   "vfov_deg": 100, "resolution": [256, 256]},
        "sensors": sensors,
        "radiosity": {"stop_unshot": 1e-4, "max_edge": 10},
    }

x, y, z = LIGHT
R = 1.2  # mirrors reach past the sphere's rim
sph2 = scene(
    "SPH2",
    "Half a unit sphere (z > 0, diffuse rho = 0.7, 768-triangle sphere cut in half) closed by a "
    "Ks = 1 mirror in the xy plane; isotropic 100 cd at (0.2, 0.4, 0.6). Unfolded, a full sphere "
    "with the light and its image.",
    [[0, 0, 1, 0]],
    [{"material": "mirror", "ks": 1.0, "vertices": [[-R, -R, 0], [R, -R, 0], [R, R, 0], [-R, R, 0]]}],
    [(1.0, LIGHT), (1.0, (x, y, -z))],
    {"A": 686.746, "B": 1038.472, "C": 939.904})
sph4 = scene(
    "SPH4",
    "A quarter of a unit sphere (z > 0, y > 0, rho = 0.7) closed by two mirrors: the xy plane at "
    "Ks = 0.8 and the xz plane at Ks = 1.0 (the orientation that reproduces Table 4, see "
    "method.md); isotropic 100 cd at (0.2, 0.4, 0.6).",
    [[0, 0, 1, 0], [0, 1, 0, 0]],
    [{"material": "mirror_xy", "ks": 0.8, "vertices": [[-R, 0, 0], [R, 0, 0], [R, R, 0], [-R, R, 0]]},
     {"material": "mirror_xz", "ks": 1.0, "vertices": [[-R, 0, 0], [-R, 0, R], [R, 0, R], [R, 0, 0]]}],
    [(1.0, LIGHT), (0.8, (x, y, -z)), (1.0, (x, -y, z)), (0.8, (x, -y, -z))],
    {"B": 1299.769, "C": 1210.660})

out = os.path.join(os.path.dirname(__file__), "..", "..", "scenes", "sphere")
for name, s in (("sph2.json", sph2), ("sph4.json", sph4)):
    with open(os.path.join(out, name), "w") as f:
        json.dump(s, f, indent=2)
        f.write("\n")
    print("wrote", name, [(p["name"], p["reference"]) for p in s["sensors"]])
