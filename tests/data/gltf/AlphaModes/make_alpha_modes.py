#!/usr/bin/env python3
"""Writes AlphaModes.gltf and alpha_ramp.png beside this script: a small stand-in for Khronos'
AlphaBlendModeTest (2.9 MB, not shipped) that tests/scene/test_gltf_samples.cpp checks.

Five quads, one above the other in the plane z = 0, each 2 wide and 0.4 tall, facing +z, every one
textured with alpha_ramp.png: 8 texels in a row, white, whose alpha bytes are ALPHA below (a pair
either side of each cutoff 0.25, 0.5 and 0.75, and 0 and 255 at the ends). From the top:
OPAQUE, BLEND, MASK with no alphaCutoff (glTF's default, 0.5), MASK 0.25 and MASK 0.75. Behind
them, at z = -0.5, a blue quad (baseColorFactor 0, 0, 1) that shows where a quad lets rays pass.
Only the standard library: run it again after changing it and commit both outputs."""
import base64
import json
import pathlib
import struct
import zlib

ALPHA = [0, 63, 64, 127, 128, 191, 192, 255]  # the texels' alpha bytes, left to right
MODES = [("OPAQUE", None), ("BLEND", None), ("MASK", None), ("MASK", 0.25), ("MASK", 0.75)]
WIDTH, HEIGHT, GAP = 2.0, 0.4, 0.1  # each quad's size and the space between two, scene units


def png(width, height, rgba_rows):
    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body))
    raw = b"".join(b"\0" + bytes(row) for row in rgba_rows)
    return (b"\x89PNG\r\n\x1a\n" +
            chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def quad(x0, y0, x1, y1, z):
    """Positions and uvs of a quad facing +z (counter-clockwise seen from +z): u left to right,
    v top to bottom as glTF's are."""
    positions = [(x0, y0, z), (x1, y0, z), (x1, y1, z), (x0, y1, z)]
    uvs = [(0, 1), (1, 1), (1, 0), (0, 0)]
    return positions, uvs


def main():
    here = pathlib.Path(__file__).resolve().parent
    (here / "alpha_ramp.png").write_bytes(
        png(len(ALPHA), 1, [[c for a in ALPHA for c in (255, 255, 255, a)]]))

    quads = []
    top = 2.5 * HEIGHT + 2 * GAP
    for k in range(len(MODES)):
        y1 = top - k * (HEIGHT + GAP)
        quads.append(quad(-WIDTH / 2, y1 - HEIGHT, WIDTH / 2, y1, 0.0))
    background = quad(-1.2, -top - 0.1, 1.2, top + 0.1, -0.5)

    blob, views, accessors, meshes = b"", [], [], []

    def add(data, fmt, count, kind, target, minmax=None):
        nonlocal blob
        while len(blob) % 4:
            blob += b"\0"
        views.append({"buffer": 0, "byteOffset": len(blob), "byteLength": len(data),
                      "target": target})
        blob += data
        acc = {"bufferView": len(views) - 1, "componentType": fmt, "count": count, "type": kind}
        if minmax:
            acc["min"], acc["max"] = minmax
        accessors.append(acc)
        return len(accessors) - 1

    indices = add(struct.pack("<6H", 0, 1, 2, 0, 2, 3), 5123, 6, "SCALAR", 34963)
    for k, (positions, uvs) in enumerate(quads + [background]):
        flat = [c for p in positions for c in p]
        lo = [min(p[i] for p in positions) for i in range(3)]
        hi = [max(p[i] for p in positions) for i in range(3)]
        pos = add(struct.pack("<12f", *flat), 5126, 4, "VEC3", 34962, (lo, hi))
        uv = add(struct.pack("<8f", *[c for t in uvs for c in t]), 5126, 4, "VEC2", 34962)
        meshes.append({"primitives": [{"attributes": {"POSITION": pos, "TEXCOORD_0": uv},
                                       "indices": indices, "material": k}]})

    materials = []
    for mode, cutoff in MODES:
        m = {"name": mode + ("" if cutoff is None else " %g" % cutoff),
             "pbrMetallicRoughness": {"baseColorTexture": {"index": 0}, "metallicFactor": 0},
             "alphaMode": mode}
        if cutoff is not None:
            m["alphaCutoff"] = cutoff
        materials.append(m)
    materials.append({"name": "background",
                      "pbrMetallicRoughness": {"baseColorFactor": [0, 0, 1, 1],
                                               "metallicFactor": 0}})

    gltf = {
        "asset": {"version": "2.0", "generator": "rtvk tests/data/gltf/AlphaModes/make_alpha_modes.py"},
        "scene": 0,
        "scenes": [{"nodes": list(range(len(meshes)))}],
        "nodes": [{"mesh": k, "name": materials[k]["name"]} for k in range(len(meshes))],
        "meshes": meshes,
        "materials": materials,
        "textures": [{"source": 0, "sampler": 0}],
        "samplers": [{"magFilter": 9728, "minFilter": 9728, "wrapS": 33071, "wrapT": 33071}],
        "images": [{"uri": "alpha_ramp.png"}],
        "buffers": [{"byteLength": len(blob),
                     "uri": "data:application/octet-stream;base64," +
                            base64.b64encode(blob).decode()}],
        "bufferViews": views,
        "accessors": accessors,
    }
    (here / "AlphaModes.gltf").write_text(json.dumps(gltf, indent=1) + "\n")


if __name__ == "__main__":
    main()
