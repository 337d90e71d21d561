#!/usr/bin/python3
"""Writes rtvk's own showcase model: a small glTF 2.0 binary (.glb) of three objects with
metallic-roughness materials, for the built-in scene `showcase` (docs/scenes.md).

    python3 scripts/make-showcase-model.py [OUT.glb]

The default output is docs/scenes/showcase.glb (committed, about 60 KB), which the build embeds
in the rtvk binary (host/formats/CMakeLists.txt), so the scene needs no file at run time. The
model is the project's own (no license but the project's). Units are meters, y up, and every
object rests on the plane y = 0 (the scene's ground, which is not in the file):

- Sphere: radius SPHERE_RADIUS centered at SPHERE_CENTER, red plastic under a clear coat
  (KHR_materials_clearcoat). tests/cpu/test_showcase.cpp finds its shadow on the ground.
- Ring: an upright torus (major radius 0.36, minor 0.12) turned 35 degrees about y, gold
  (metallic 1, roughness 0.35).
- Block: a 0.6 m cube turned 25 degrees about y, blue rough plastic (roughness 0.6), flat faces.

Python 3 only.
"""
import json
import math
import os
import struct
import sys

SPHERE_CENTER = (-1.05, 0.45, 0.2)
SPHERE_RADIUS = 0.45
RING_CENTER = (0.1, 0.48, -0.45)
BLOCK_CENTER = (1.15, 0.3, 0.25)


def uv_sphere(radius, rings=24, segments=48):
    """Positions, normals and triangle indices of a sphere about the origin."""
    pos, nrm = [], []
    for i in range(rings + 1):
        t = math.pi * i / rings
        for j in range(segments + 1):
            p = 2.0 * math.pi * j / segments
            n = (math.sin(t) * math.cos(p), math.cos(t), -math.sin(t) * math.sin(p))
            nrm.append(n)
            pos.append(tuple(round(radius * c, 12) for c in n))
    idx = grid_indices(rings, segments)
    # The poles' rows are one point each: drop the triangles with two corners there.
    keep = [k for k in range(0, len(idx), 3)
            if len({pos[idx[k]], pos[idx[k + 1]], pos[idx[k + 2]]}) == 3]
    return pos, nrm, [idx[k + c] for k in keep for c in range(3)]


def torus(major, minor, rings=48, sides=20):
    """An upright torus about the origin: its circle in the xy plane, its axis along z."""
    pos, nrm = [], []
    for i in range(rings + 1):
        u = 2.0 * math.pi * i / rings
        ring = (math.cos(u), math.sin(u), 0.0)
        for j in range(sides + 1):
            v = 2.0 * math.pi * j / sides
            n = (math.cos(v) * ring[0], math.cos(v) * ring[1], math.sin(v))
            nrm.append(n)
            pos.append(tuple(major * r + minor * c for r, c in zip(ring, n)))
    return pos, nrm, grid_indices(rings, sides)


def grid_indices(rows, cols):
    """Two counter-clockwise triangles per cell of a (rows + 1) x (cols + 1) vertex grid."""
    out = []
    for i in range(rows):
        for j in range(cols):
            a, b = i * (cols + 1) + j, (i + 1) * (cols + 1) + j
            out += [a, b, a + 1, a + 1, b, b + 1]
    return out


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def cube(size):
    """A cube about the origin, four vertices a face so that its faces are flat."""
    pos, nrm, idx = [], [], []
    for axis in range(3):
        for sign in (1.0, -1.0):
            n = tuple(sign if k == axis else 0.0 for k in range(3))
            u = tuple(1.0 if k == (axis + 1) % 3 else 0.0 for k in range(3))
            v = cross(n, u)
            base = len(pos)
            for du, dv in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
                pos.append(tuple(0.5 * size * (n[k] + du * u[k] + dv * v[k]) for k in range(3)))
                nrm.append(n)
            idx += [base, base + 1, base + 2, base, base + 2, base + 3]
    return pos, nrm, idx


def placed(points, degrees, offset=(0.0, 0.0, 0.0)):
    """`points` turned by `degrees` about y (right-handed), then moved by `offset`."""
    c, s = math.cos(math.radians(degrees)), math.sin(math.radians(degrees))
    return [(c * x + s * z + offset[0], y + offset[1], -s * x + c * z + offset[2])
            for x, y, z in points]


def unit(points):
    return [tuple(c / math.sqrt(x * x + y * y + z * z) for c in (x, y, z)) for x, y, z in points]


def build():
    sphere = uv_sphere(SPHERE_RADIUS)
    ring = torus(0.36, 0.12)
    block = cube(0.6)
    parts = [
        ("Sphere", placed(sphere[0], 0, SPHERE_CENTER), sphere[1], sphere[2], 0),
        ("Ring", placed(ring[0], 35, RING_CENTER), placed(ring[1], 35), ring[2], 1),
        ("Block", placed(block[0], 25, BLOCK_CENTER), placed(block[1], 25), block[2], 2),
    ]
    materials = [
        {"name": "red clearcoat", "pbrMetallicRoughness": {
            "baseColorFactor": [0.7, 0.06, 0.04, 1.0], "metallicFactor": 0.0,
            "roughnessFactor": 0.45},
         "extensions": {"KHR_materials_clearcoat": {"clearcoatFactor": 1.0,
                                                    "clearcoatRoughnessFactor": 0.2}}},
        {"name": "gold", "pbrMetallicRoughness": {
            "baseColorFactor": [1.0, 0.766, 0.336, 1.0], "metallicFactor": 1.0,
            "roughnessFactor": 0.35}},
        {"name": "blue plastic", "pbrMetallicRoughness": {
            "baseColorFactor": [0.1, 0.25, 0.6, 1.0], "metallicFactor": 0.0,
            "roughnessFactor": 0.6}},
    ]
    blob = bytearray()
    views, accessors, meshes, nodes = [], [], [], []

    def add(values, fmt, count, target, component, kind, bounds=None):
        views.append({"buffer": 0, "byteOffset": len(blob),
                      "byteLength": struct.calcsize("<" + fmt * len(values)), "target": target})
        blob.extend(struct.pack("<" + fmt * len(values), *values))
        blob.extend(b"\0" * (-len(blob) % 4))
        acc = {"bufferView": len(views) - 1, "componentType": component, "count": count,
               "type": kind}
        if bounds:
            acc["min"] = [min(p[k] for p in bounds) for k in range(3)]
            acc["max"] = [max(p[k] for p in bounds) for k in range(3)]
        accessors.append(acc)
        return len(accessors) - 1

    for name, pos, nrm, idx, mat in parts:
        pos = [tuple(struct.unpack("<3f", struct.pack("<3f", *p))) for p in pos]
        flat = lambda vs: [c for v in vs for c in v]
        p = add(flat(pos), "f", len(pos), 34962, 5126, "VEC3", bounds=pos)
        n = add(flat(unit(nrm)), "f", len(nrm), 34962, 5126, "VEC3")
        i = add(idx, "H", len(idx), 34963, 5123, "SCALAR")
        meshes.append({"name": name, "primitives": [
            {"attributes": {"POSITION": p, "NORMAL": n}, "indices": i, "material": mat}]})
        nodes.append({"name": name, "mesh": len(meshes) - 1})
    gltf = {
        "asset": {"version": "2.0", "generator": "rtvk scripts/make-showcase-model.py"},
        "extensionsUsed": ["KHR_materials_clearcoat"],
        "scene": 0, "scenes": [{"nodes": list(range(len(nodes)))}],
        "nodes": nodes, "meshes": meshes, "materials": materials,
        "accessors": accessors, "bufferViews": views,
        "buffers": [{"byteLength": len(blob)}],
    }
    return gltf, bytes(blob)


def write_glb(path, gltf, blob):
    text = json.dumps(gltf, separators=(",", ":")).encode("utf-8")
    text += b" " * (-len(text) % 4)
    total = 12 + 8 + len(text) + 8 + len(blob)
    with open(path, "wb") as f:
        f.write(struct.pack("<4sII", b"glTF", 2, total))
        f.write(struct.pack("<I4s", len(text), b"JSON") + text)
        f.write(struct.pack("<I4s", len(blob), b"BIN\0") + blob)


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "..", "docs", "scenes",
                                                             "showcase.glb")
    gltf, blob = build()
    write_glb(out, gltf, blob)
    print("wrote %s: %d bytes, %d triangles" % (
        out, os.path.getsize(out), sum(a["count"] for a in gltf["accessors"][2::3]) // 3))


if __name__ == "__main__":
    main()
