#!/usr/bin/env python3
"""Noise against time, plain against lights sampling: the mean squared error of rtvk's renders
against a converged reference as the render time grows, drawn as docs/images/sampling-noise.svg.

  plot-sampling-noise.py RTVK REFERENCE.exr OUTDIR [--scene cornell-box] [--width 150]
                         [--backends cpu,gpu] [--seconds 32] [--crop X,Y,W,H] [--gpu-label NAME]

REFERENCE.exr is the same scene at the same width rendered long enough that its own noise is far
below the curves' (docs/benchmarks.md says how it was made). For each backend and each sampling
mode the script renders at 1, 2, 4, ... samples per pixel (`RTVK render --scene S --width W
--spp N --sampling M --backend B --seed 7 -o OUT.exr`; time from rtvk's summary line, the render
alone) until one render takes longer than --seconds, and measures each against the reference
(`RTVK compare OUT.exr REFERENCE.exr`: the linear mean squared error over pixels and channels).

Writes OUTDIR/sampling-noise.json (every point), OUTDIR/sampling-noise.svg (log-log, one line
per backend and mode), and for each backend two crops at equal time (--crop, through --region:
the same pixels the whole image has) as OUTDIR/crop-BACKEND-MODE.png; prints the mean squared
error ratio at equal time (plain / lights, interpolated in log-log over the times both reach).
Plain SVG, no plotting library.
"""
import argparse
import json
import math
import os
import re
import subprocess
import sys

SEED = "7"  # not the reference's seed 0: the measured samples must not be the reference's own


def render(rtvk, args, backend, mode, spp, out, region=None):
    cmd = [rtvk, "render", "--scene", args.scene, "--width", str(args.width), "--spp", str(spp),
           "--sampling", mode, "--backend", backend, "--seed", SEED, "-o", out]
    if region:
        cmd += ["--region", region]
    err = subprocess.run(cmd, check=True, capture_output=True, text=True).stderr
    return float(re.search(r" in ([0-9.]+) s -> ", err).group(1))


def mse(rtvk, image, reference):
    out = subprocess.run([rtvk, "compare", image, reference], capture_output=True, text=True).stdout
    return float(re.search(r"^mse\s+([0-9.e+-]+)", out, re.M).group(1))


def curve(rtvk, args, backend, mode):
    points, spp = [], 1
    image = os.path.join(args.outdir, "noise-%s-%s.exr" % (backend, mode))
    while True:
        seconds = render(rtvk, args, backend, mode, spp, image)
        points.append({"spp": spp, "seconds": seconds, "mse": mse(rtvk, image, args.reference)})
        print("%-4s %-6s %6d spp %8.3f s  mse %.4e" % (backend, mode, spp, seconds,
                                                        points[-1]["mse"]), flush=True)
        if seconds > args.seconds:
            return points
        spp *= 2


def log_interp(points, t):
    """log mse at time t, linear in log-log between the measured points (None outside them)."""
    for a, b in zip(points, points[1:]):
        if a["seconds"] <= t <= b["seconds"] and b["seconds"] > a["seconds"]:
            f = (math.log(t) - math.log(a["seconds"])) / (math.log(b["seconds"]) -
                                                            math.log(a["seconds"]))
            return math.log(a["mse"]) + f * (math.log(b["mse"]) - math.log(a["mse"]))
    return None


def equal_time_ratios(plain, lights):
    """plain / lights mean squared error at the times both curves reach."""
    lo = max(plain[0]["seconds"], lights[0]["seconds"])
    hi = min(plain[-1]["seconds"], lights[-1]["seconds"])
    out = []
    for k in range(9):
        t = lo * (hi / lo) ** (k / 8)
        p, l = log_interp(plain, t), log_interp(lights, t)
        if p is not None and l is not None:
            out.append((t, math.exp(p - l)))
    return out


def spp_for(points, seconds):
    """The largest measured spp whose render took at most `seconds`."""
    return max([p["spp"] for p in points if p["seconds"] <= seconds] or [1])


def svg(curves, title, gpu_label):
    w, h, left, right, top, bottom = 640, 420, 70, 170, 30, 50
    xs = [p["seconds"] for c in curves.values() for p in c]
    ys = [p["mse"] for c in curves.values() for p in c]
    x0, x1 = math.floor(math.log10(min(xs))), math.ceil(math.log10(max(xs)))
    y0, y1 = math.floor(math.log10(min(ys))), math.ceil(math.log10(max(ys)))
    px = lambda v: left + (math.log10(v) - x0) / (x1 - x0) * (w - left - right)
    py = lambda v: h - bottom - (math.log10(v) - y0) / (y1 - y0) * (h - top - bottom)
    out = ['<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" font-family="sans-serif"'
           ' font-size="12"><rect width="100%%" height="100%%" fill="white"/>' % (w, h),
           '<text x="%d" y="18" font-size="14">%s</text>' % (left, title)]
    for e in range(x0, x1 + 1):
        x = px(10 ** e)
        out.append('<line x1="%.1f" y1="%d" x2="%.1f" y2="%d" stroke="#ddd"/>' % (x, top, x,
                                                                               h - bottom))
        out.append('<text x="%.1f" y="%d" text-anchor="middle">%g s</text>' % (x, h - bottom + 16,
                                                                            10 ** e))
    for e in range(y0, y1 + 1):
        y = py(10 ** e)
        out.append('<line x1="%d" y1="%.1f" x2="%d" y2="%.1f" stroke="#ddd"/>' % (left, y,
                                                                               w - right, y))
        out.append('<text x="%d" y="%.1f" text-anchor="end">1e%d</text>' % (left - 6, y + 4, e))
    out.append('<text x="%d" y="%d" text-anchor="middle">render time (log)</text>' %
               ((left + w - right) // 2, h - 12))
    out.append('<text x="16" y="%d" transform="rotate(-90 16 %d)" text-anchor="middle">mean '
               'squared error (log)</text>' % ((top + h - bottom) // 2, (top + h - bottom) // 2))
    colors = {"plain": "#c0392b", "lights": "#2471a3"}
    dashes = {"cpu": "", "gpu": ' stroke-dasharray="6 4"'}
    for k, (name, pts) in enumerate(curves.items()):
        backend, mode = name.split("/")
        path = " ".join("%s%.1f,%.1f" % ("M" if i == 0 else "L", px(p["seconds"]), py(p["mse"]))
                        for i, p in enumerate(pts))
        out.append('<path d="%s" fill="none" stroke="%s" stroke-width="2"%s/>' %
                   (path, colors[mode], dashes[backend]))
        for p in pts:
            out.append('<circle cx="%.1f" cy="%.1f" r="2.5" fill="%s"/>' % (px(p["seconds"]),
                                                                           py(p["mse"]),
                                                                           colors[mode]))
        y = top + 20 + 20 * k
        out.append('<line x1="%d" y1="%d" x2="%d" y2="%d" stroke="%s" stroke-width="2"%s/>' %
                   (w - right + 10, y, w - right + 40, y, colors[mode], dashes[backend]))
        out.append('<text x="%d" y="%d">%s, %s</text>' % (w - right + 46, y + 4,
                                                         "CPU" if backend == "cpu" else gpu_label,
                                                         mode))
    out.append("</svg>")
    return "\n".join(out) + "\n"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("rtvk")
    ap.add_argument("reference")
    ap.add_argument("outdir")
    ap.add_argument("--scene", default="cornell-box")
    ap.add_argument("--width", type=int, default=150)
    ap.add_argument("--backends", default="cpu,gpu")
    ap.add_argument("--seconds", type=float, default=32)
    ap.add_argument("--crop", default="40,40,64,64")
    ap.add_argument("--gpu-label", default="GPU", help="the GPU's name in the legend")
    args = ap.parse_args()
    os.makedirs(args.outdir, exist_ok=True)
    curves = {}
    for backend in args.backends.split(","):
        for mode in ("plain", "lights"):
            curves[backend + "/" + mode] = curve(args.rtvk, args, backend, mode)
    summary = {"scene": args.scene, "width": args.width, "curves": curves, "ratios": {}}
    for backend in args.backends.split(","):
        plain, lights = curves[backend + "/plain"], curves[backend + "/lights"]
        ratios = equal_time_ratios(plain, lights)
        summary["ratios"][backend] = [{"seconds": t, "plain_over_lights": r} for t, r in ratios]
        for t, r in ratios:
            print("%s: at %.2f s, plain's mse is %.1fx lights'" % (backend, t, r))
        # Crops at equal time: the longest lights render, and plain's render of about that time.
        t = lights[-2]["seconds"] if len(lights) > 1 else lights[-1]["seconds"]
        for mode, pts in (("plain", plain), ("lights", lights)):
            spp = spp_for(pts, t * 1.05)
            render(args.rtvk, args, backend, mode, spp,
                   os.path.join(args.outdir, "crop-%s-%s.png" % (backend, mode)), args.crop)
            summary.setdefault("crops", {})["%s/%s" % (backend, mode)] = spp
            print("%s crop, %s: %d spp (about %.2f s for the whole image)" % (backend, mode, spp, t))
    with open(os.path.join(args.outdir, "sampling-noise.json"), "w") as f:
        json.dump(summary, f, indent=1)
    with open(os.path.join(args.outdir, "sampling-noise.svg"), "w") as f:
        f.write(svg(curves, "%s, %d wide: noise against time, plain vs lights sampling" %
                    (args.scene, args.width), args.gpu_label))


if __name__ == "__main__":
    sys.exit(main())
