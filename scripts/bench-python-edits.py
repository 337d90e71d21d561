#!/usr/bin/env python3
"""Times what an edit costs a Renderer (docs/benchmarks.md): N renders of one view of a scene
with nothing changed between them, against N renders each after Scene.place moved an object
(each sets the scene up again: on the CPU its BVH or Embree's trees, on the GPU the device
scene). Run by hand, not in CI:

  PYTHONPATH=build/release/python python3 scripts/bench-python-edits.py --backend gpu
"""
import argparse
import time

import numpy as np

import rtvk

ap = argparse.ArgumentParser()
ap.add_argument("--scene", default="cornell-box")
ap.add_argument("--backend", default="cpu")
ap.add_argument("--precision", default="auto")
ap.add_argument("--views", type=int, default=20)
ap.add_argument("--width", type=int, default=160)
ap.add_argument("--spp", type=int, default=4)
a = ap.parse_args()

scene = rtvk.Scene(a.scene)
objects = scene.objects()
moved = next((o for o in objects if o["kind"] in ("box", "instance", "mesh")), objects[-1])
cam = rtvk.Camera.from_scene(scene)
renderer = rtvk.Renderer(scene, a.backend, precision=a.precision)
main = scene.to_dict()["camera"]
height = max(1, round(a.width * cam.height / cam.width))
view = rtvk.Camera.look_at(main["lookfrom"], main["lookat"], a.width, height,
                           vfov=main.get("vfov", 40), vup=main.get("vup", (0, 1, 0)))


def timed(edit):
    start = time.perf_counter()
    for k in range(a.views):
        if edit:
            m = np.eye(4)
            m[0, 3] = 0.01 * (k + 1)  # a hundredth of a unit further each time
            scene.place(moved["id"], m)
        renderer.render(view, spp=a.spp)
    return (time.perf_counter() - start) / a.views


start = time.perf_counter()
renderer.render(view, spp=a.spp)
first = time.perf_counter() - start
still = timed(False)
edited = timed(True)
print("%s (%d objects; moving object %d, a %s), %s, %dx%d at %d spp, %d views each" %
      (a.scene, len(objects), moved["id"], moved["kind"], renderer.description, a.width,
       height, a.spp, a.views))
print("first render (set-up included): %.1f ms" % (1000 * first))
print("unchanged scene: %.1f ms a view; after a place: %.1f ms a view (%.2fx); set-ups %d" %
      (1000 * still, 1000 * edited, edited / still, renderer.set_ups))
