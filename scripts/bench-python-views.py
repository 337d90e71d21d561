#!/usr/bin/env python3
"""Times N views of a scene rendered in one rtvk.Renderer against N `rtvk render` processes
(docs/benchmarks.md): the same cameras (a ring around the scene's own look-at point), sizes,
samples and backend. Run by hand, not in CI:

  PYTHONPATH=build/release/python python3 scripts/bench-python-views.py \\
      --rtvk build/release/rtvk --scene cornell-box --backend cpu --views 100
"""
import argparse
import math
import os
import subprocess
import tempfile
import time

import rtvk

ap = argparse.ArgumentParser()
ap.add_argument("--rtvk", default="rtvk")
ap.add_argument("--scene", default="cornell-box")
ap.add_argument("--backend", default="cpu")
ap.add_argument("--views", type=int, default=100)
ap.add_argument("--width", type=int, default=160)
ap.add_argument("--height", type=int, default=120)
ap.add_argument("--spp", type=int, default=4)
a = ap.parse_args()

scene = rtvk.Scene(a.scene)
main = scene.to_dict()["camera"]
target, eye, vfov = main["lookat"], main["lookfrom"], main.get("vfov", 40)
radius = math.hypot(eye[0] - target[0], eye[2] - target[2])


def pose(k):
    t = 0.6 * (k / max(1, a.views - 1) - 0.5)  # a sweep of +-0.3 rad around the scene's own view
    return ([target[0] + radius * math.sin(t) * (1 if eye[2] < target[2] else -1), eye[1],
             target[2] + radius * math.cos(t) * (-1 if eye[2] < target[2] else 1)], target)


start = time.perf_counter()
renderer = rtvk.Renderer(scene, a.backend)
setup = time.perf_counter() - start
for k in range(a.views):
    lookfrom, lookat = pose(k)
    renderer.render(rtvk.Camera.look_at(lookfrom, lookat, a.width, a.height, vfov=vfov),
                    spp=a.spp)
in_process = time.perf_counter() - start

with tempfile.TemporaryDirectory() as d:
    start = time.perf_counter()
    for k in range(a.views):
        lookfrom, lookat = pose(k)
        subprocess.run([a.rtvk, "render", a.scene, "--backend", a.backend, "--width",
                        str(a.width), "--aspect", "%d:%d" % (a.width, a.height), "--spp",
                        str(a.spp), "--vfov", str(vfov), "--lookfrom", ",".join(map(str, lookfrom)),
                        "--lookat", ",".join(map(str, lookat)), "-q", "-o",
                        os.path.join(d, "v.exr")], check=True)
    processes = time.perf_counter() - start

print("%s, %s, %d views of %dx%d at %d spp (%s)" % (a.scene, a.backend, a.views, a.width,
                                                    a.height, a.spp, renderer.description))
print("one Renderer: %.2f s (set-up %.3f s), %.1f ms a view" %
      (in_process, setup, 1000 * (in_process - setup) / a.views))
print("%d processes: %.2f s, %.1f ms a view" % (a.views, processes, 1000 * processes / a.views))
print("ratio: %.1fx" % (processes / in_process))
