#!/usr/bin/env python3
"""The noise-measurement scripts' own checks (issue 46; docs/benchmarks.md, "Noise against time
under next-event estimation" and "rtvk against Blender's Cycles"), without Blender or a device:

1. scripts/exr_pixels.py, the pure-Python OpenEXR reader compare-cycles.py measures both
   renderers with, reads rtvk's ZIP-compressed renders to the mean squared error `rtvk compare`
   prints (to its 7 digits), for two renders of different estimators;
2. scripts/plot-sampling-noise.py draws curves for several modes of a scene file: every mode has
   points (renders of 16x16 pixels, until one takes 0.05 s: at least two), each mode but
   --against has its equal-time ratios, the SVG is written;
3. docs/scenes/many-lamps.json is what scripts/make-many-lamps.py writes (10,000 triangles).

  check_noise_scripts.py RTVK SOURCE_DIR WORK_DIR
"""
import json
import os
import re
import subprocess
import sys


def run(cmd, ok=(0,)):
    done = subprocess.run(cmd, capture_output=True, text=True)
    if done.returncode not in ok:
        sys.exit("failed (exit %d): %s\n%s%s" % (done.returncode, " ".join(cmd), done.stdout,
                                                 done.stderr))
    return done.stdout


def check_exr_reader(rtvk, src, work):
    sys.path.insert(0, os.path.join(src, "scripts"))
    import exr_pixels
    a, b = os.path.join(work, "a.exr"), os.path.join(work, "b.exr")
    run([rtvk, "render", "cornell-box", "--width", "24", "--spp", "4", "--sampling", "lights",
         "--seed", "1", "-q", "-o", a])
    run([rtvk, "render", "cornell-box", "--width", "24", "--spp", "4", "--sampling", "nee",
         "--seed", "2", "-q", "-o", b])
    # rtvk compare exits 1 for images that differ, as these do.
    printed = run([rtvk, "compare", a, b], ok=(0, 1))
    expected = float(re.search(r"^mse\s+(\S+)", printed, re.M).group(1))
    wa, ha, pa = exr_pixels.read_rgb(a)
    wb, hb, pb = exr_pixels.read_rgb(b)
    got = exr_pixels.mse(pa, pb)
    print("exr_pixels: %dx%d, mse %.6e; rtvk compare: %.6e" % (wa, ha, got, expected))
    if (wa, ha) != (24, 24) or (wb, hb) != (24, 24):
        sys.exit("exr_pixels read %dx%d and %dx%d, not 24x24" % (wa, ha, wb, hb))
    if not expected > 0 or abs(got - expected) > 1e-6 * expected:
        sys.exit("exr_pixels' mse %.7e is not rtvk compare's %.7e" % (got, expected))


def check_plot(rtvk, src, work):
    scene = os.path.join(work, "lamp.json")
    with open(scene, "w") as f:
        json.dump({"camera": {"lookfrom": [0, 1, 4], "lookat": [0, 0.5, 0], "vfov": 40},
                   "render": {"width": 16, "aspect": 1, "spp": 4, "max_depth": 4},
                   "background": [0, 0, 0],
                   "materials": {"floor": {"type": "lambertian", "albedo": [0.5, 0.5, 0.5]},
                                 "lamp": {"type": "diffuse_light", "emit": [8, 8, 8]}},
                   "quads": [{"Q": [-2, 0, -2], "u": [0, 0, 4], "v": [4, 0, 0],
                              "material": "floor"}],
                   "spheres": [{"center": [0, 1.5, 0], "radius": 0.3, "material": "lamp"}]}, f)
    ref = os.path.join(work, "ref.exr")
    run([rtvk, "render", scene, "--spp", "64", "--sampling", "nee", "-q", "-o", ref])
    out = os.path.join(work, "plot")
    run([sys.executable, os.path.join(src, "scripts", "plot-sampling-noise.py"), rtvk, ref, out,
         "--scene-file", scene, "--modes", "plain,lights,nee", "--backends", "cpu",
         "--width", "16", "--seconds", "0.05", "--spp-factor", "4", "--crop", "4,4,8,8"])
    with open(os.path.join(out, "sampling-noise-lamp.json")) as f:
        d = json.load(f)
    for mode in ("plain", "lights", "nee"):
        if not d["curves"].get("cpu/" + mode):
            sys.exit("plot-sampling-noise.py drew no points for %s" % mode)
    if d["against"] != "lights" or sorted(d["ratios"]) != ["cpu/nee", "cpu/plain"]:
        sys.exit("plot-sampling-noise.py's ratios are not each mode's against lights: %s, %s" %
                 (d["against"], sorted(d["ratios"])))
    for name, rows in d["ratios"].items():
        if not rows or not all(0 < r["over_lights"] < 1e6 for r in rows):
            sys.exit("plot-sampling-noise.py's equal-time ratios for %s: %s" % (name, rows))
    if not os.path.getsize(os.path.join(out, "sampling-noise-lamp.svg")):
        sys.exit("plot-sampling-noise.py wrote an empty plot")
    print("plot-sampling-noise.py: curves for %s, ratios for %s" % (sorted(d["curves"]),
                                                                   sorted(d["ratios"])))


def check_many_lamps(src, work):
    out = os.path.join(work, "many-lamps.json")
    run([sys.executable, os.path.join(src, "scripts", "make-many-lamps.py"), out])
    with open(out, "rb") as f, open(os.path.join(src, "docs", "scenes", "many-lamps.json"),
                                    "rb") as g:
        made, shipped = f.read(), g.read()
    if made != shipped:
        sys.exit("docs/scenes/many-lamps.json is not what scripts/make-many-lamps.py writes")
    triangles = len(json.loads(made)["triangles"])
    if triangles != 10000:
        sys.exit("many-lamps.json has %d triangles, not 10,000" % triangles)
    print("many-lamps.json: as the script writes it, %d triangles" % triangles)


def main():
    rtvk, src, work = sys.argv[1:4]
    os.makedirs(work, exist_ok=True)
    check_exr_reader(rtvk, src, work)
    check_plot(rtvk, src, work)
    check_many_lamps(src, work)


if __name__ == "__main__":
    sys.exit(main())
