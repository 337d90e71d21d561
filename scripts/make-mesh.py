#!/usr/bin/env python3
"""Writes a generated triangle mesh as Wavefront OBJ, for rtvk's pictures and benchmarks.

  make-mesh.py knot TRIANGLES OUT.obj   a (2, 3) torus knot tube with smooth vertex normals, about
                                        TRIANGLES triangles (closed, every vertex shared)

  make-mesh.py knots N MESH.obj DIR   two scene files in DIR placing MESH.obj (a path relative to
                                        DIR) N times on a grid: knots-instanced.json (one group,
                                        N instances) and knots-copied.json (N meshes, each placed)

  make-mesh.py lamps N OUT.obj         N small triangles scattered in a slab 10 wide, 10 deep and
                                        1 high about (0, 3.5, 0), each turned its own way: the
                                        emissive cloud of docs/scenes/many-lamps-slab.json

The mesh depends only on its arguments, so a benchmark run anywhere reads the same triangles.
"""
import json
import math
import os
import random
import sys


def knot(triangles, out):
    # A tube of `around` sides swept along `along` steps of the curve: 2 * along * around faces.
    around = max(8, int(round(math.sqrt(triangles / 2 / 8))))
    along = max(24, int(round(triangles / 2 / around)))

    def curve(t):
        r = 2 + math.cos(3 * t)
        return (r * math.cos(2 * t), r * math.sin(2 * t), -math.sin(3 * t))

    def sub(a, b):
        return (a[0] - b[0], a[1] - b[1], a[2] - b[2])

    def cross(a, b):
        return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])

    def unit(a):
        n = math.sqrt(a[0] ** 2 + a[1] ** 2 + a[2] ** 2)
        return (a[0] / n, a[1] / n, a[2] / n)

    radius = 0.45
    with open(out, "w") as f:
        f.write("# (2, 3) torus knot: rtvk scripts/make-mesh.py knot %d\n" % triangles)
        normals = []
        for i in range(along):
            t = 2 * math.pi * i / along
            p, q = curve(t), curve(t + 1e-4)
            tangent = unit(sub(q, p))
            side = unit(cross(tangent, (0.0, 0.0, 1.0)))
            up = cross(side, tangent)
            for j in range(around):
                a = 2 * math.pi * j / around
                n = tuple(math.cos(a) * side[k] + math.sin(a) * up[k] for k in range(3))
                f.write("v %.6f %.6f %.6f\n" % tuple(p[k] + radius * n[k] for k in range(3)))
                normals.append(n)
        for n in normals:
            f.write("vn %.6f %.6f %.6f\n" % n)
        for i in range(along):
            for j in range(around):
                a = i * around + j + 1
                b = ((i + 1) % along) * around + j + 1
                c = ((i + 1) % along) * around + (j + 1) % around + 1
                d = i * around + (j + 1) % around + 1
                f.write("f %d//%d %d//%d %d//%d\n" % (a, a, b, b, c, c))
                f.write("f %d//%d %d//%d %d//%d\n" % (a, a, c, c, d, d))


def knots(n, mesh, folder):
    # The same placements written twice: as instances of one group, and as n placed meshes.
    columns = max(1, int(math.ceil(math.sqrt(2 * n))))
    placements = []
    for k in range(n):
        i, j = k % columns, k // columns
        placements.append({"scale": 0.4, "rotate": {"axis": [0, 1, 0], "degrees": (37 * i + 11 * j) % 360},
                           "translate": [1.6 * i - 0.8 * (columns - 1), 0.9, -1.6 * j]})
    base = {"camera": {"lookfrom": [0, 6, 10], "lookat": [0, 0.5, -3], "vfov": 50},
            "render": {"width": 320, "aspect": "16:9", "spp": 4, "max_depth": 20},
            "materials": {"gold": {"type": "metal", "albedo": [0.9, 0.7, 0.3], "fuzz": 0.1},
                          "ground": {"type": "lambertian", "albedo": [0.5, 0.5, 0.5]}},
            "quads": [{"Q": [-50, 0, -50], "u": [0, 0, 100], "v": [100, 0, 0], "material": "ground"}]}
    instanced = dict(base, groups={"knot": {"meshes": [{"file": mesh, "material": "gold"}]}},
                     instances=[{"group": "knot", "transform": t} for t in placements])
    copied = dict(base, meshes=[{"file": mesh, "material": "gold", "transform": t} for t in placements])
    for name, scene in (("knots-instanced.json", instanced), ("knots-copied.json", copied)):
        with open(os.path.join(folder, name), "w") as out:
            json.dump(scene, out, indent=1)


def lamps(n, out):
    # Each a triangle of edges up to 0.12 about a point of the slab; Python's Mersenne Twister from
    # a fixed seed, so the same N gives the same triangles everywhere.
    rng = random.Random(46)
    with open(out, "w") as f:
        f.write("# %d small triangles: scripts/make-mesh.py lamps %d\n" % (n, n))
        for _ in range(n):
            c = (rng.uniform(-5, 5), rng.uniform(3, 4), rng.uniform(-5, 5))
            for _ in range(3):
                f.write("v %.6f %.6f %.6f\n" % tuple(c[k] + rng.uniform(-0.06, 0.06) for k in range(3)))
        for k in range(n):
            f.write("f %d %d %d\n" % (3 * k + 1, 3 * k + 2, 3 * k + 3))


if __name__ == "__main__":
    if len(sys.argv) == 4 and sys.argv[1] == "knot":
        knot(int(sys.argv[2]), sys.argv[3])
    elif len(sys.argv) == 4 and sys.argv[1] == "lamps":
        lamps(int(sys.argv[2]), sys.argv[3])
    elif len(sys.argv) == 5 and sys.argv[1] == "knots":
        knots(int(sys.argv[2]), sys.argv[3], sys.argv[4])
    else:
        sys.exit(__doc__)
