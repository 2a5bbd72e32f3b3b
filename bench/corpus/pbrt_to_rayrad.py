#!/usr/bin/env python3
"""Convert a pbrt-v3 scene as Bitterli's Rendering Resources publish them into a rayrad scene.

    bench/corpus/pbrt_to_rayrad.py SCENE.pbrt OUT_DIR [--luminance-scale S] [--guess NAME=R,G,B ...]
                                   [--emissive NAME=CD_M2 ...] [--two-sided [NAME ...]]
                                   [--extra EXTRA.json]

Reads the subset of pbrt-v3 those exports use: the camera (`Transform`, `Camera
"perspective"` with `fov`, `Film` resolution), `MakeNamedMaterial` / `NamedMaterial` /
`Material`, `AttributeBegin/End`, `TransformBegin/End`, `Transform`, `ConcatTransform`,
`Translate`, `Scale`, `LookAt`, `AreaLightSource "diffuse"`, `Include`, and shapes `plymesh` (binary or
ASCII PLY, triangles and quads) and `trianglemesh`. Textures, `LightSource` (point, distant
and environment lights) and everything else are skipped.

Writes OUT_DIR/meshes/NAME.ply (every triangle of one material in world space, positions
only, binary little-endian) and OUT_DIR/scene.json; the keys of EXTRA.json (a description,
sensors, views) are added to it. What it approximates, and why:
- pbrt surfaces reflect on both sides; rayrad's reflect on their front. A shape with vertex
  normals has each triangle wound so its normal agrees with them (the side the modeller
  shaded) and stays one-sided: rayrad's energy account then says how much light lands on
  backs. A shape without normals that is a closed solid (every edge shared by two of its
  triangles) is turned to face outward (positive signed volume); one that is open keeps its
  winding, which then means nothing, and gets the material "NAME two-sided", a copy that
  reflects on both sides (an emitter's copy does not: rayrad's emitters are one-sided).
  Vertex normals are not always the side one sees (an exporter may write a room's walls with
  normals facing out; rayrad then warns of direct light on backs and names the material):
  --two-sided NAME ... makes those materials reflect on both sides, as in pbrt; --two-sided
  alone makes every diffuse material so, at twice the patches.
- matte, substrate, plastic and uber → diffuse with their Kd (clamped to 0.9). A Kd given by
  an image texture → the image's mean (TGA, sRGB decoded; rayrad's patches would average it
  the same way), or where the image is missing the colour from --guess NAME=R,G,B, else
  grey 0.5 (the conversion says which).
- metal → diffuse grey 0.5 (rayrad has no glossy reflection); glass → glass, index 1.5.
- mirror → of the planes of the material's triangles at least half as large as its largest,
  the one whose front faces the camera becomes rayrad mirror quads (Ks 0.9); the rest of it
  (edges, bevels, back) is diffuse grey 0.5.
- AreaLightSource "diffuse" with radiance L → emissive, luminance = S · Y(L) cd/m² (pbrt's
  radiance has no unit; S = --luminance-scale, default 100), colour L. --emissive NAME=L
  makes the material NAME an emitter of L cd/m² (a lamp the exporter left as a material).
"""
import argparse
import json
import math
import os
import re
import struct
import sys
from collections import defaultdict

# ---------------------------------------------------------------------------------------
# pbrt tokens and statements


def tokens(text):
    """Yield pbrt tokens: quoted strings (with quotes), '[', ']', numbers and words."""
    pattern = re.compile(r'"[^"]*"|\[|\]|[^\s\[\]"#]+|#[^\n]*')
    for m in pattern.finditer(text):
        t = m.group(0)
        if not t.startswith("#"):
            yield t


def statements(text):
    """Group tokens into (directive, [arguments]); a bracketed list is one argument (a list)."""
    directive, args, inside = None, [], None
    for t in tokens(text):
        if t == "[":
            inside = []
        elif t == "]":
            args.append(inside)
            inside = None
        elif inside is not None:
            inside.append(t)
        elif t[0].isalpha():
            if directive:
                yield directive, args
            directive, args = t, []
        else:
            args.append(t)
    if directive:
        yield directive, args


def included(path):
    """The statements of a pbrt file with its `Include`s spliced in."""
    for directive, a in statements(open(path).read()):
        if directive == "Include":
            yield from included(os.path.join(os.path.dirname(path), unquote(a[0])))
        else:
            yield directive, a


def unquote(t):
    return t[1:-1] if t.startswith('"') else t


def parameters(args):
    """pbrt parameter list '"type name" [values]' → {name: (type, [values])}."""
    out = {}
    i = 0
    while i + 1 < len(args):
        decl = unquote(args[i]).split()
        value = args[i + 1]
        values = value if isinstance(value, list) else [value]
        if len(decl) == 2:
            out[decl[1]] = (decl[0], [unquote(v) for v in values])
        i += 2
    return out


def numbers(param):
    return [float(v) for v in param[1]]


# ---------------------------------------------------------------------------------------
# 4 × 4 matrices (row-major lists), pbrt's transform statements


def identity():
    return [[1.0 if i == j else 0.0 for j in range(4)] for i in range(4)]


def multiply(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(4)) for j in range(4)] for i in range(4)]


def from_pbrt(values):
    """pbrt writes a matrix column by column."""
    return [[values[j * 4 + i] for j in range(4)] for i in range(4)]


def apply(m, p, w=1.0):
    return tuple(m[i][0] * p[0] + m[i][1] * p[1] + m[i][2] * p[2] + m[i][3] * w for i in range(3))


def inverse(m):
    """Inverse of an affine 4 × 4 matrix (rotation/scale block and translation)."""
    a = [row[:3] for row in m[:3]]
    det = (a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1])
           - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0])
           + a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]))
    inv = [[0.0] * 3 for _ in range(3)]
    for i in range(3):
        for j in range(3):
            r = [x for x in range(3) if x != j]
            c = [x for x in range(3) if x != i]
            minor = a[r[0]][c[0]] * a[r[1]][c[1]] - a[r[0]][c[1]] * a[r[1]][c[0]]
            inv[i][j] = (-1) ** (i + j) * minor / det
    t = [m[0][3], m[1][3], m[2][3]]
    out = identity()
    for i in range(3):
        out[i][:3] = inv[i]
        out[i][3] = -sum(inv[i][k] * t[k] for k in range(3))
    return out


# ---------------------------------------------------------------------------------------
# Meshes


def look_at(ex, ey, ez, lx, ly, lz, ux, uy, uz):
    """pbrt's LookAt: the world-to-camera matrix of a camera at e looking at l with up u
    (camera space left-handed: x right, y up, z ahead)."""
    eye = (ex, ey, ez)
    ahead = sub((lx, ly, lz), eye)
    ahead = tuple(c / math.sqrt(dot(ahead, ahead)) for c in ahead)
    right = cross((ux, uy, uz), ahead)
    right = tuple(c / math.sqrt(dot(right, right)) for c in right)
    up = cross(ahead, right)
    camera_to_world = [[right[i], up[i], ahead[i], eye[i]] for i in range(3)] + [[0, 0, 0, 1]]
    return inverse(camera_to_world)


def read_ply(path):
    """Positions, vertex normals (or None) and faces of a PLY file (ASCII or binary)."""
    data = open(path, "rb").read()
    end = data.index(b"end_header") + len(b"end_header")
    end = data.index(b"\n", end) + 1
    header = data[:end].decode("ascii").splitlines()
    fmt = header[1].split()[1]
    elements = []
    for line in header:
        w = line.split()
        if w[0] == "element":
            elements.append([w[1], int(w[2]), []])
        elif w[0] == "property":
            elements[-1][2].append(w[1:])
    sizes = {"char": "b", "uchar": "B", "uint8": "B", "int8": "b", "short": "h", "ushort": "H",
             "int16": "h", "uint16": "H", "int": "i", "uint": "I", "int32": "i", "uint32": "I",
             "float": "f", "float32": "f", "double": "d", "float64": "d"}
    order = "<" if fmt == "binary_little_endian" else ">"
    positions, normals, faces = [], [], []
    if fmt == "ascii":
        words = iter(data[end:].split())
    offset = end
    for name, count, props in elements:
        for _ in range(count):
            record = {}
            for prop in props:
                if prop[0] == "list":
                    if fmt == "ascii":
                        n = int(next(words))
                        record[prop[-1]] = [int(next(words)) for _ in range(n)]
                    else:
                        n = struct.unpack_from(order + sizes[prop[1]], data, offset)[0]
                        offset += struct.calcsize(sizes[prop[1]])
                        f = order + str(n) + sizes[prop[2]]
                        record[prop[-1]] = list(struct.unpack_from(f, data, offset))
                        offset += struct.calcsize(f)
                else:
                    if fmt == "ascii":
                        record[prop[1]] = float(next(words))
                    else:
                        f = order + sizes[prop[0]]
                        record[prop[1]] = struct.unpack_from(f, data, offset)[0]
                        offset += struct.calcsize(f)
            if name == "vertex":
                positions.append((record["x"], record["y"], record["z"]))
                if "nx" in record:
                    normals.append((record["nx"], record["ny"], record["nz"]))
            elif name == "face":
                faces.append(record.get("vertex_indices", record.get("vertex_index")))
    return positions, (normals if len(normals) == len(positions) else None), faces


def closed(triangles):
    """Whether every edge of the triangles is shared by exactly two of them (a solid)."""
    count = defaultdict(int)
    for t in triangles:
        keys = [tuple(round(x, 7) for x in p) for p in t]
        for i in range(3):
            count[tuple(sorted((keys[i], keys[(i + 1) % 3])))] += 1
    return bool(count) and all(c == 2 for c in count.values())


def signed_volume(triangles):
    return sum(dot(t[0], cross(t[1], t[2])) for t in triangles) / 6.0


def oriented(triangles, has_normals):
    """(triangles, whether they need both sides) for a shape: see the module's docstring."""
    if has_normals:
        return triangles, False
    if closed(triangles):
        if signed_volume(triangles) < 0:
            triangles = [(a, c, b) for a, b, c in triangles]
        return triangles, False
    return triangles, True


def triangles_of(positions, normals, faces, matrix):
    """World-space triangles, each wound so its normal agrees with the vertex normals."""
    world = [apply(matrix, p) for p in positions]
    normal_matrix = [list(r) for r in zip(*[row[:3] for row in inverse(matrix)[:3]])]
    out = []
    for face in faces:
        for k in range(1, len(face) - 1):
            tri = [face[0], face[k], face[k + 1]]
            a, b, c = (world[i] for i in tri)
            n = cross(sub(b, a), sub(c, a))
            if normals:
                shading = [0.0, 0.0, 0.0]
                for i in tri:
                    nn = normals[i]
                    for r in range(3):
                        shading[r] += sum(normal_matrix[r][s] * nn[s] for s in range(3))
                if dot(n, shading) < 0:
                    b, c = c, b
            out.append((a, b, c))
    return out


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def area(t):
    n = cross(sub(t[1], t[0]), sub(t[2], t[0]))
    return 0.5 * math.sqrt(dot(n, n))


def write_ply(path, triangles):
    """Binary little-endian PLY: float positions (shared where equal), int triangles."""
    index, vertices, faces = {}, [], []
    for t in triangles:
        face = []
        for p in t:
            key = tuple(p)
            if key not in index:
                index[key] = len(vertices)
                vertices.append(key)
            face.append(index[key])
        faces.append(face)
    with open(path, "wb") as f:
        f.write(("ply\nformat binary_little_endian 1.0\n"
                 f"element vertex {len(vertices)}\nproperty float x\nproperty float y\n"
                 f"property float z\nelement face {len(faces)}\n"
                 "property list uchar int vertex_indices\nend_header\n").encode())
        for v in vertices:
            f.write(struct.pack("<3f", *v))
        for face in faces:
            f.write(struct.pack("<B3i", 3, *face))


# ---------------------------------------------------------------------------------------
# Materials


def luminance(rgb):
    """Y of linear sRGB (Rec. 709 primaries)."""
    return 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2]


def srgb_to_linear(c):
    c /= 255.0
    return c / 12.92 if c <= 0.04045 else ((c + 0.055) / 1.055) ** 2.4


def tga_mean(path):
    """Mean linear RGB of a true-colour TGA (uncompressed or RLE, 24 or 32 bits), or None."""
    try:
        data = open(path, "rb").read()
    except OSError:
        return None
    id_length, kind, depth = data[0], data[2], data[16]
    if kind not in (2, 10) or depth not in (24, 32):
        return None
    width, height = struct.unpack_from("<HH", data, 12)
    size = depth // 8
    p = 18 + id_length
    pixels, count = [], width * height
    while len(pixels) < count:
        if kind == 2:
            pixels.append(data[p:p + size])
            p += size
            continue
        header = data[p]
        p += 1
        n = (header & 0x7F) + 1
        if header & 0x80:
            pixels.extend([data[p:p + size]] * n)
            p += size
        else:
            pixels.extend(data[p + i * size:p + (i + 1) * size] for i in range(n))
            p += n * size
    table = [srgb_to_linear(float(i)) for i in range(256)]
    sums = [0.0, 0.0, 0.0]
    for px in pixels[:count]:
        sums[0] += table[px[2]]  # TGA stores blue, green, red
        sums[1] += table[px[1]]
        sums[2] += table[px[0]]
    return [s / count for s in sums]


def rayrad_material(name, kind, params, guesses, textures, notes):
    """The rayrad material for a pbrt material (see the module's docstring)."""
    if kind in ("matte", "substrate", "plastic", "uber", "translucent", "disney"):
        if "Kd" in params and params["Kd"][0] in ("rgb", "color"):
            kd = [min(0.9, max(0.0, v)) for v in numbers(params["Kd"])]
            return {"type": "diffuse", "reflectance": kd}
        image = textures.get(params["Kd"][1][0]) if "Kd" in params else None
        mean = tga_mean(image) if image else None
        if mean:
            kd = [round(min(0.9, v), 4) for v in mean]
            notes.append(f"{name}: textured {kind}, reflectance the mean of "
                         f"{os.path.basename(image)}: {kd}")
            return {"type": "diffuse", "reflectance": kd}
        if name in guesses:
            notes.append(f"{name}: textured {kind}, reflectance guessed {guesses[name]}")
            return {"type": "diffuse", "reflectance": guesses[name]}
        if "Kd" in params:
            notes.append(f"{name}: textured {kind} without a guess, grey 0.5")
            return {"type": "diffuse", "reflectance": 0.5}
        notes.append(f"{name}: {kind} without Kd, pbrt's default 0.5")
        return {"type": "diffuse", "reflectance": 0.5}
    if kind == "glass":
        return {"type": "glass", "ior": 1.5}
    if kind == "mirror":
        return {"type": "mirror", "specular_reflectance": 0.9}
    notes.append(f"{name}: {kind} read as diffuse grey 0.5")
    return {"type": "diffuse", "reflectance": 0.5}


def mirror_quads(triangles, eye):
    """The mirror plane of a mirror mesh (of the planes at least half as large as the
    largest, the one facing the eye) as quads (pairs of triangles sharing an edge), and the
    triangles left over."""
    planes = defaultdict(list)
    for t in triangles:
        n = cross(sub(t[1], t[0]), sub(t[2], t[0]))
        length = math.sqrt(dot(n, n))
        if length == 0:
            continue
        n = tuple(round(x / length, 3) for x in n)
        planes[(n, round(dot(n, t[0]), 3))].append(t)
    largest = max(sum(area(t) for t in ts) for ts in planes.values())
    large = [(key, ts) for key, ts in planes.items() if sum(area(t) for t in ts) >= 0.5 * largest]
    facing = [ts for (n, d), ts in large if dot(n, eye) > d] or [large[0][1]]
    best = max(facing, key=lambda ts: sum(area(t) for t in ts))
    rest = [t for ts in planes.values() if ts is not best for t in ts]
    quads, left = [], list(best)
    while left:
        a = left.pop()
        partner = None
        for i, b in enumerate(left):
            shared = [p for p in a if any(max(abs(p[k] - q[k]) for k in range(3)) < 1e-6 for q in b)]
            if len(shared) == 2:
                partner = left.pop(i)
                break
        if partner is None:
            quads.append([list(p) for p in a])
            continue
        # a = (p0, p1, p2) wound by its normal; insert b's other vertex after the shared edge
        other = [p for p in partner
                 if not any(max(abs(p[k] - q[k]) for k in range(3)) < 1e-6 for q in a)][0]
        for i in range(3):
            p, q = a[i], a[(i + 1) % 3]
            if p in shared and q in shared:
                quads.append([list(x) for x in (a[i], other, a[(i + 1) % 3], a[(i + 2) % 3])])
                break
    return quads, rest


# ---------------------------------------------------------------------------------------


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("scene")
    ap.add_argument("out")
    ap.add_argument("--luminance-scale", type=float, default=100.0)
    ap.add_argument("--guess", action="append", default=[], metavar="NAME=R,G,B")
    ap.add_argument("--emissive", action="append", default=[], metavar="NAME=CD_M2")
    ap.add_argument("--two-sided", nargs="*", metavar="NAME")
    ap.add_argument("--extra", metavar="EXTRA.json")
    args = ap.parse_args()
    guesses = {}
    for g in args.guess:
        name, rgb = g.split("=")
        guesses[name] = [float(x) for x in rgb.split(",")]
    emissive = {name: float(value) for name, value in (e.split("=") for e in args.emissive)}
    base = os.path.dirname(os.path.abspath(args.scene))

    named = {}
    state = {"ctm": identity(), "material": None, "emit": None}
    stack = []
    camera_matrix, fov, resolution = identity(), 90.0, [640, 480]
    in_world = False
    groups = defaultdict(list)      # material key → triangles
    materials = {}                  # material key → rayrad material
    notes = []
    textures = {}                   # pbrt texture name → image path
    anonymous = 0
    unnamed = set()                 # anonymous materials no mesh has named yet
    alias = {}                      # anonymous material → the name of its first mesh
    for directive, a in included(args.scene):
        if directive == "WorldBegin":
            in_world, camera_matrix = True, state["ctm"]
            state["ctm"] = identity()
        elif directive in ("AttributeBegin", "TransformBegin"):
            stack.append(dict(state))
        elif directive in ("AttributeEnd", "TransformEnd"):
            state = stack.pop()
        elif directive == "Transform":
            state["ctm"] = from_pbrt([float(x) for x in a[0]])
        elif directive == "ConcatTransform":
            state["ctm"] = multiply(state["ctm"], from_pbrt([float(x) for x in a[0]]))
        elif directive == "Translate":
            m = identity()
            for i in range(3):
                m[i][3] = float(a[i])
            state["ctm"] = multiply(state["ctm"], m)
        elif directive == "Scale":
            m = identity()
            for i in range(3):
                m[i][i] = float(a[i])
            state["ctm"] = multiply(state["ctm"], m)
        elif directive == "LookAt":
            state["ctm"] = multiply(state["ctm"], look_at(*[float(x) for x in a[:9]]))
        elif directive == "Camera":
            p = parameters(a[1:])
            if "fov" in p:
                fov = numbers(p["fov"])[0]
        elif directive == "Film":
            p = parameters(a[1:])
            resolution = [int(numbers(p.get("xresolution", ("", [640])))[0]),
                          int(numbers(p.get("yresolution", ("", [480])))[0])]
        elif directive == "MakeNamedMaterial":
            name = unquote(a[0])
            p = parameters(a[1:])
            named[name] = rayrad_material(name, p["type"][1][0], p, guesses, textures, notes)
        elif directive == "Texture":
            p = parameters(a[3:])
            if "filename" in p:
                textures[unquote(a[0])] = os.path.join(base, p["filename"][1][0])
        elif directive == "NamedMaterial":
            state["material"] = unquote(a[0])
        elif directive == "Material":
            anonymous += 1
            name = f"material{anonymous}"
            named[name] = rayrad_material(name, unquote(a[0]), parameters(a[1:]), guesses,
                                          textures, notes)
            state["material"] = name
            unnamed.add(name)
        elif directive == "AreaLightSource":
            p = parameters(a[1:])
            state["emit"] = numbers(p["L"])
        elif directive == "Shape" and in_world:
            kind = unquote(a[0])
            p = parameters(a[1:])
            if kind == "plymesh":
                positions, normals, faces = read_ply(os.path.join(base, p["filename"][1][0]))
            elif kind == "trianglemesh":
                flat = numbers(p["P"])
                positions = [tuple(flat[i:i + 3]) for i in range(0, len(flat), 3)]
                idx = [int(x) for x in p["indices"][1]]
                faces = [idx[i:i + 3] for i in range(0, len(idx), 3)]
                normals = None
                if "N" in p:
                    fn = numbers(p["N"])
                    normals = [tuple(fn[i:i + 3]) for i in range(0, len(fn), 3)]
            else:
                notes.append(f"shape {kind} skipped")
                continue
            if kind == "plymesh" and state["material"] in unnamed:
                # An anonymous material takes the name of the first mesh that uses it (an
                # alias: a later shape may still hold the anonymous name, after AttributeEnd).
                stem = os.path.splitext(os.path.basename(p["filename"][1][0]))[0]
                stem = re.sub(r"_mat\d+$", "", stem)
                if stem not in named:
                    named[stem] = named[state["material"]]
                    alias[state["material"]] = stem
                unnamed.discard(state["material"])
            tris, both_sides = oriented(triangles_of(positions, normals, faces, state["ctm"]),
                                        normals is not None)
            if state["emit"]:
                rgb = state["emit"]
                key = f"emitter{len([k for k in materials if k.startswith('emitter')]) + 1}"
                y = luminance(rgb)
                materials[key] = {"type": "emissive",
                                  "luminance_cd_m2": round(args.luminance_scale * y, 3),
                                  "color": [round(c / y, 4) for c in rgb]}
            else:
                key = alias.get(state["material"], state["material"]) or "default"
                materials.setdefault(key, named.get(key, {"type": "diffuse", "reflectance": 0.5}))
                if key in emissive:
                    materials[key] = {"type": "emissive", "luminance_cd_m2": emissive[key]}
                if both_sides and materials[key]["type"] == "diffuse":
                    key += " two-sided"
                    materials[key] = dict(materials[key[:-len(" two-sided")]], two_sided=True)
            groups[key].extend(tris)

    to_world = inverse(camera_matrix)
    eye = apply(to_world, (0, 0, 0))
    ahead = apply(to_world, (0, 0, 1))
    up = apply(to_world, (0, 1, 0), 0.0)
    # pbrt's camera space is left-handed (x right, y up, z ahead): the image's right is +x
    # there, which rayrad (right = ahead × up) reproduces only when the camera-to-world
    # matrix mirrors. Otherwise the view is left-right mirrored: say so.
    det = sum(camera_matrix[0][i] * cross(camera_matrix[1][:3], camera_matrix[2][:3])[i]
              for i in range(3))
    if det > 0:
        notes.append("camera: pbrt's left-handed view; rayrad's picture is its mirror image")
    aspect = resolution[0] / resolution[1]
    vfov = fov if aspect >= 1 else math.degrees(2 * math.atan(math.tan(math.radians(fov) / 2) / aspect))
    os.makedirs(os.path.join(args.out, "meshes"), exist_ok=True)
    objects, out_materials = [], {}
    for key, tris in sorted(groups.items()):
        m = dict(materials[key])
        if m["type"] == "mirror":
            quads, rest = mirror_quads(tris, eye)
            out_materials[key] = m
            for q in quads:
                objects.append({"type": "quad" if len(q) == 4 else "polygon", "material": key,
                                "vertices": [[round(x, 6) for x in p] for p in q]})
            if rest:
                out_materials[key + "_frame"] = {"type": "diffuse", "reflectance": 0.5}
                write_ply(os.path.join(args.out, "meshes", key + "_frame.ply"), rest)
                objects.append({"type": "mesh", "file": f"meshes/{key}_frame.ply",
                                "material": key + "_frame"})
            notes.append(f"{key}: {len(quads)} mirror quad(s) on the plane facing the camera, "
                         f"{len(rest)} triangles of frame and back diffuse grey 0.5")
            continue
        both = args.two_sided is not None and (not args.two_sided or key in args.two_sided)
        if both and m["type"] == "diffuse":
            m["two_sided"] = True
        out_materials[key] = m
        file = "meshes/" + key.replace(" ", "-") + ".ply"
        write_ply(os.path.join(args.out, file), tris)
        objects.append({"type": "mesh", "file": file, "material": key})

    scene = {
        "description": f"converted from {os.path.basename(args.scene)} by bench/corpus/pbrt_to_rayrad.py",
        "materials": out_materials,
        "objects": objects,
        "lights": [],
        "camera": {"position": [round(x, 5) for x in eye],
                   "look_at": [round(x, 5) for x in ahead],
                   "up": [round(x, 5) for x in up], "vfov_deg": round(vfov, 3),
                   "resolution": resolution},
    }
    if args.extra:
        scene.update(json.load(open(args.extra)))
    json.dump(scene, open(os.path.join(args.out, "scene.json"), "w"), indent=1)
    for n in notes:
        print(n)
    print(f"{sum(len(t) for t in groups.values())} triangles in {len(groups)} materials")


if __name__ == "__main__":
    sys.exit(main())
