#!/usr/bin/env python3
"""Writes docs/scenes/many-lamps.json: a room lit only by 10,000 small emissive triangles, the
many-lights scene of issue 46's noise-against-time measurements (docs/benchmarks.md, "Noise
against time under next-event estimation").

  make-many-lamps.py [OUT.json] [--count 10000] [--seed 46]

A floor, a back wall and five diffuse objects (spheres and a box) under a canopy of `--count`
triangles 3 to 6 cm across, scattered in a slab above them, each turned at random (a lamp emits
from both faces). Their powers span two orders of magnitude: most are dim (radiance 4 to 16), one
in fifty is bright (radiance 400), in five colors, so that a light sampler that draws lamps by
power (an alias table, a light tree) finds the few that matter, and one that draws them
uniformly does not. No sky: every bit of light comes from the triangles. The same seed writes
the same file (Python's random, Mersenne Twister, is specified across versions).
"""
import argparse
import math
import os
import random
import sys

PALETTE = {  # name: radiance (linear RGB)
    "warm": (1.0, 0.75, 0.45), "white": (1.0, 1.0, 1.0), "cool": (0.6, 0.75, 1.0),
    "amber": (1.0, 0.55, 0.15), "rose": (1.0, 0.5, 0.6)}
STRENGTHS = {"dim": 4.0, "mid": 16.0, "bright": 400.0}


def triangle(rng, center, size):
    """An equilateral triangle of side `size` around `center`, facing a random direction."""
    z = rng.uniform(-1, 1)
    phi = rng.uniform(0, 2 * math.pi)
    n = (math.sqrt(1 - z * z) * math.cos(phi), z, math.sqrt(1 - z * z) * math.sin(phi))
    a = (1.0, 0.0, 0.0) if abs(n[0]) < 0.9 else (0.0, 1.0, 0.0)
    # u, v: an orthonormal pair in the triangle's plane.
    u = (a[1] * n[2] - a[2] * n[1], a[2] * n[0] - a[0] * n[2], a[0] * n[1] - a[1] * n[0])
    ul = math.sqrt(sum(c * c for c in u))
    u = tuple(c / ul for c in u)
    v = (n[1] * u[2] - n[2] * u[1], n[2] * u[0] - n[0] * u[2], n[0] * u[1] - n[1] * u[0])
    r = size / math.sqrt(3)  # the circumradius
    out = []
    for k in range(3):
        t = 2 * math.pi * k / 3
        out.append([round(center[i] + r * (math.cos(t) * u[i] + math.sin(t) * v[i]), 3)
                    for i in range(3)])
    return out


def scene(count, seed):
    rng = random.Random(seed)
    materials = {
        "floor": '{"type":"lambertian","albedo":[0.6,0.6,0.6]}',
        "wall": '{"type":"lambertian","albedo":[0.5,0.5,0.55]}',
        "red": '{"type":"lambertian","albedo":[0.7,0.15,0.1]}',
        "white": '{"type":"lambertian","albedo":[0.8,0.8,0.8]}',
        "teal": '{"type":"lambertian","albedo":[0.1,0.55,0.5]}'}
    for color, rgb in PALETTE.items():
        for strength, s in STRENGTHS.items():
            materials["%s-%s" % (color, strength)] = (
                '{"type":"diffuse_light","emit":[%g,%g,%g]}' % tuple(round(c * s, 4) for c in rgb))
    tris = []
    for _ in range(count):
        center = (rng.uniform(-4, 4), rng.uniform(2.4, 3.4), rng.uniform(-3.5, 1.5))
        u = rng.random()
        strength = "bright" if u < 0.02 else ("mid" if u < 0.3 else "dim")
        color = rng.choice(sorted(PALETTE))
        tris.append('{"vertices":%s,"material":"%s-%s"}' % (
            str(triangle(rng, center, rng.uniform(0.03, 0.06))).replace(" ", ""), color, strength))
    lines = ['{',
             '  "camera": {"lookfrom": [0, 1.6, 6.5], "lookat": [0, 0.9, 0], "vfov": 40},',
             '  "render": {"width": 300, "aspect": 1.5, "spp": 16, "max_depth": 8},',
             '  "background": [0, 0, 0],',
             '  "materials": {',
             ",\n".join('    "%s": %s' % kv for kv in materials.items()),
             '  },',
             '  "quads": [',
             '    {"Q": [-6, 0, -5], "u": [0, 0, 12], "v": [12, 0, 0], "material": "floor"},',
             '    {"Q": [-6, 0, -4], "u": [12, 0, 0], "v": [0, 5, 0], "material": "wall"}',
             '  ],',
             '  "boxes": [{"a": [0.6, 0, -1.6], "b": [1.6, 1.4, -0.6], "material": "white"}],',
             '  "spheres": [',
             '    {"center": [-1.5, 0.7, -0.5], "radius": 0.7, "material": "red"},',
             '    {"center": [0, 0.5, 0.4], "radius": 0.5, "material": "white"},',
             '    {"center": [2.3, 0.45, 0.6], "radius": 0.45, "material": "teal"},',
             '    {"center": [-0.4, 0.3, -1.8], "radius": 0.3, "material": "white"}',
             '  ],',
             '  "triangles": [',
             ",\n".join("    " + t for t in tris),
             '  ]',
             '}']
    return "\n".join(lines) + "\n"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    here = os.path.dirname(os.path.abspath(__file__))
    ap.add_argument("out", nargs="?", default=os.path.join(here, "..", "docs", "scenes",
                                                           "many-lamps.json"))
    ap.add_argument("--count", type=int, default=10000)
    ap.add_argument("--seed", type=int, default=46)
    args = ap.parse_args()
    if args.count < 1:
        sys.exit("make-many-lamps.py: --count %d: must be at least 1" % args.count)
    with open(args.out, "w") as f:
        f.write(scene(args.count, args.seed))


if __name__ == "__main__":
    sys.exit(main())
