#!/usr/bin/env python3
"""Noise against time, any set of sampling modes: the mean squared error of rtvk's renders against
a converged reference as the render time grows, drawn as an SVG (docs/images/sampling-noise-*.svg).

  plot-sampling-noise.py RTVK REFERENCE.exr OUTDIR [--scene cornell-box | --scene-file FILE]
                         [--environment FILE[:STRENGTH]] [--modes plain,lights] [--against lights]
                         [--width 150] [--backends cpu,gpu] [--seconds 32] [--gpu-seconds S]
                         [--spp-factor 2|4] [--crop X,Y,W,H] [--gpu-label NAME] [--name NAME]

The scene is a built-in name (--scene) or a .json scene file or mesh file (--scene-file; rtvk
takes either in the same place); --environment is passed to every render (an HDR map lighting a
mesh file or replacing a scene's sky). REFERENCE.exr is the same scene at the same width (and
environment) rendered long enough that its own noise is far below the curves' (docs/benchmarks.md
says how each was made). For each backend and each mode the script renders at 1, 2, 4, ...
samples per pixel (1, 4, 16, ... with --spp-factor 4; `RTVK render SCENE --width W --spp N
--sampling M --backend B --seed 7 [--environment E] -o OUT.exr`; time from rtvk's summary line,
the render alone) until one render takes longer than --seconds (--gpu-seconds on the GPU), and
measures each against the reference (`RTVK compare OUT.exr REFERENCE.exr`: the linear mean
squared error over pixels and channels). The curves take turns at each sample count (1 spp of
each, then 2 of each, ...), so that other work on the machine slows them alike; the load average
before and after is printed and kept, and each point keeps the render process's CPU time (user +
system) beside rtvk's wall-clock figure. A mode rtvk refuses for
the scene (exit 2: `lights` or `nee` past their lamp limits, `nee` with media) is reported with
rtvk's message and left out; the others go on.

Writes, with NAME the scene's name (--name, else the built-in name or the file's stem):
OUTDIR/sampling-noise-NAME.json (every point and ratio), OUTDIR/sampling-noise-NAME.svg (log-log,
one line per backend and mode), and for each backend one crop per mode at equal time (--crop,
through --region: the same pixels the whole image has) as OUTDIR/crop-NAME-BACKEND-MODE.png;
prints each mode's mean squared error over the --against mode's (`lights`, the book's mixture,
when it is among the modes, else the first) at equal time, interpolated in log-log over the times
both reach: below 1, that mode reaches a lower error in the same time. Plain SVG, no plotting
library.
"""
import argparse
import json
import math
import os
import re
import resource
import subprocess
import sys

SEED = "7"  # not the reference's seed 0: the measured samples must not be the reference's own
COLORS = {"plain": "#c0392b", "lights": "#2471a3", "nee": "#1e8449", "auto": "#7d3c98"}


class Refused(Exception):
    """rtvk refused a render of the scene in this mode (exit 2); its message."""


def render(rtvk, args, backend, mode, spp, out, region=None):
    cmd = [rtvk, "render", args.scene, "--width", str(args.width), "--spp", str(spp),
           "--sampling", mode, "--backend", backend, "--seed", SEED, "-o", out]
    if args.environment:
        cmd += ["--environment", args.environment]
    if region:
        cmd += ["--region", region]
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    done = subprocess.run(cmd, capture_output=True, text=True)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    args.last_cpu_seconds = (after.ru_utime + after.ru_stime) - (before.ru_utime +
                                                                 before.ru_stime)
    if done.returncode == 2:
        raise Refused(done.stderr.strip())
    if done.returncode != 0:
        sys.exit("plot-sampling-noise.py: %s failed (exit %d): %s" % (" ".join(cmd),
                                                                       done.returncode,
                                                                       done.stderr.strip()))
    return float(re.search(r" in ([0-9.]+) s -> ", done.stderr).group(1))


def mse(rtvk, image, reference):
    out = subprocess.run([rtvk, "compare", image, reference], capture_output=True, text=True).stdout
    return float(re.search(r"^mse\s+([0-9.e+-]+)", out, re.M).group(1))


def measure(args):
    """Every backend's and mode's points at 1, 2, 4, ... samples per pixel, each until one render
    takes longer than --seconds. The curves take turns at each sample count, so that other work
    on the machine slows them alike. Returns the curves (BACKEND/MODE: points) and the modes rtvk
    refused (BACKEND/MODE: its message)."""
    curves, refused, spp = {}, {}, 1
    active = [b + "/" + m for b in args.backends for m in args.modes]
    while active:
        for name in list(active):
            backend, mode = name.split("/")
            image = os.path.join(args.outdir, "noise-%s-%s-%s.exr" % (args.name, backend, mode))
            try:
                seconds = render(args.rtvk, args, backend, mode, spp, image)
            except Refused as e:
                refused[name] = str(e)
                active.remove(name)
                print("%-4s %-6s refused by rtvk: %s" % (backend, mode, e), flush=True)
                continue
            point = {"spp": spp, "seconds": seconds, "mse": mse(args.rtvk, image, args.reference),
                     "process_cpu_seconds": args.last_cpu_seconds}
            curves.setdefault(name, []).append(point)
            print("%-4s %-6s %6d spp %8.3f s  mse %.4e  (process: %.2f CPU s)" % (
                backend, mode, spp, seconds, point["mse"], args.last_cpu_seconds), flush=True)
            if seconds > (args.gpu_seconds if backend == "gpu" else args.seconds):
                active.remove(name)
        spp *= args.spp_factor
    # In the order asked for (the plot's legend), whatever order they finished in.
    order = [b + "/" + m for b in args.backends for m in args.modes]
    return {n: curves[n] for n in order if n in curves}, refused


def log_interp(points, t):
    """log mse at time t, linear in log-log between the measured points (None outside them)."""
    for a, b in zip(points, points[1:]):
        if a["seconds"] <= t <= b["seconds"] and b["seconds"] > a["seconds"]:
            f = (math.log(t) - math.log(a["seconds"])) / (math.log(b["seconds"]) -
                                                            math.log(a["seconds"]))
            return math.log(a["mse"]) + f * (math.log(b["mse"]) - math.log(a["mse"]))
    return None


def equal_time_ratios(mode, base):
    """mode / base mean squared error at nine times, log-spaced over those both curves reach."""
    lo = max(mode[0]["seconds"], base[0]["seconds"])
    hi = min(mode[-1]["seconds"], base[-1]["seconds"])
    out = []
    if hi <= lo:
        return out
    for k in range(9):
        t = min(max(lo * (hi / lo) ** (k / 8), lo), hi)
        p, l = log_interp(mode, t), log_interp(base, t)
        if p is not None and l is not None:
            out.append((t, math.exp(p - l)))
    return out


def by_cpu_time(points):
    """The points with the render process's CPU time as their time."""
    return [dict(p, seconds=p["process_cpu_seconds"]) for p in points]


def spp_for(points, seconds):
    """The largest measured spp whose render took at most `seconds`."""
    return max([p["spp"] for p in points if p["seconds"] <= seconds] or [1])


def svg(curves, title, labels):
    """A log-log plot of each curve; `labels` maps a backend to its legend name. Curves are named
    BACKEND/MODE; a mode draws in its own color, a backend in its own dashes."""
    w, h, left, right, top, bottom = 640, 420, 70, 170, 30, 50
    xs = [p["seconds"] for c in curves.values() for p in c]
    ys = [p["mse"] for c in curves.values() for p in c]
    x0, x1 = math.floor(math.log10(min(xs))), math.ceil(math.log10(max(xs)))
    y0, y1 = math.floor(math.log10(min(ys))), math.ceil(math.log10(max(ys)))
    x1, y1 = max(x1, x0 + 1), max(y1, y0 + 1)
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
    dash_cycle = ["", ' stroke-dasharray="6 4"', ' stroke-dasharray="2 3"']
    backends = list(dict.fromkeys(name.split("/")[0] for name in curves))
    for k, (name, pts) in enumerate(curves.items()):
        backend, mode = name.split("/")
        color = COLORS.get(mode, "#555")
        dashes = dash_cycle[backends.index(backend) % len(dash_cycle)]
        path = " ".join("%s%.1f,%.1f" % ("M" if i == 0 else "L", px(p["seconds"]), py(p["mse"]))
                        for i, p in enumerate(pts))
        out.append('<path d="%s" fill="none" stroke="%s" stroke-width="2"%s/>' %
                   (path, color, dashes))
        for p in pts:
            out.append('<circle cx="%.1f" cy="%.1f" r="2.5" fill="%s"/>' % (px(p["seconds"]),
                                                                           py(p["mse"]), color))
        y = top + 20 + 20 * k
        out.append('<line x1="%d" y1="%d" x2="%d" y2="%d" stroke="%s" stroke-width="2"%s/>' %
                   (w - right + 10, y, w - right + 40, y, color, dashes))
        out.append('<text x="%d" y="%d">%s, %s</text>' % (w - right + 46, y + 4,
                                                         labels.get(backend, backend), mode))
    out.append("</svg>")
    return "\n".join(out) + "\n"


def ratios_and_crops(args, curves, summary):
    """Each mode's error over the --against mode's at equal time, and the crops at one time."""
    for backend in args.backends:
        base = curves.get(backend + "/" + args.against)
        if base is None:
            continue
        for mode in args.modes:
            pts = curves.get(backend + "/" + mode)
            if pts is None or mode == args.against:
                continue
            ratios = equal_time_ratios(pts, base)
            summary["ratios"]["%s/%s" % (backend, mode)] = [
                {"seconds": t, "over_" + args.against: r} for t, r in ratios]
            for t, r in ratios:
                print("%s: at %.2f s, %s's mse is %.3gx %s's (%s's is %.3gx %s's)" %
                      (backend, t, mode, r, args.against, args.against, 1 / r, mode))
            # The same by the processes' CPU time, which other work on the machine changes less
            # than the wall clock (it counts set-up too: the GPU's shader compiles).
            cpu = equal_time_ratios(by_cpu_time(pts), by_cpu_time(base))
            summary["ratios_by_cpu_time"]["%s/%s" % (backend, mode)] = [
                {"cpu_seconds": t, "over_" + args.against: r} for t, r in cpu]
            print("%s, by CPU time: %s's mse over %s's: %s" % (
                backend, mode, args.against, ", ".join("%.3g (%.2f s)" % (r, t) for t, r in cpu)))
        # Crops at equal time: the --against mode's second longest render, each mode about then.
        t = base[-2]["seconds"] if len(base) > 1 else base[-1]["seconds"]
        for mode in args.modes:
            pts = curves.get(backend + "/" + mode)
            if pts is None:
                continue
            spp = spp_for(pts, t * 1.05)
            try:
                render(args.rtvk, args, backend, mode, spp, os.path.join(
                    args.outdir, "crop-%s-%s-%s.png" % (args.name, backend, mode)), args.crop)
            except Refused as e:
                print("%s crop, %s: refused by rtvk: %s" % (backend, mode, e))
                continue
            summary["crops"]["%s/%s" % (backend, mode)] = spp
            print("%s crop, %s: %d spp (about %.2f s for the whole image)" % (backend, mode, spp,
                                                                              t))


def parse():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("rtvk")
    ap.add_argument("reference")
    ap.add_argument("outdir")
    where = ap.add_mutually_exclusive_group()
    where.add_argument("--scene", help="a built-in scene (default cornell-box)")
    where.add_argument("--scene-file", help="a .json scene file or a mesh file (.obj, .gltf, .glb)")
    ap.add_argument("--environment", help="FILE[:STRENGTH], passed to every render")
    ap.add_argument("--modes", default="plain,lights", help="sampling modes, comma-separated")
    ap.add_argument("--against", help="the mode the others are measured against (default lights"
                    " when among --modes, else the first)")
    ap.add_argument("--name", help="the scene's name in file names and the title")
    ap.add_argument("--width", type=int, default=150)
    ap.add_argument("--backends", default="cpu,gpu")
    ap.add_argument("--seconds", type=float, default=32)
    ap.add_argument("--gpu-seconds", type=float, help="--seconds for the GPU (default the same)")
    ap.add_argument("--spp-factor", type=int, default=2, choices=(2, 4),
                    help="samples per pixel grow by this factor; 4 keeps to the counts whose"
                    " pixels stratify whole (1, 4, 16, ...: lights and nee cut the pixel into"
                    " floor(sqrt(spp))^2 cells), which make smoother curves")
    ap.add_argument("--crop", default="40,40,64,64")
    ap.add_argument("--gpu-label", default="GPU", help="the GPU's name in the legend")
    args = ap.parse_args()
    args.gpu_seconds = args.gpu_seconds or args.seconds
    args.scene = args.scene_file or args.scene or "cornell-box"
    args.name = args.name or os.path.splitext(os.path.basename(args.scene))[0]
    args.modes = [m for m in args.modes.split(",") if m]
    args.backends = [b for b in args.backends.split(",") if b]
    args.against = args.against or ("lights" if "lights" in args.modes else args.modes[0])
    if args.against not in args.modes:
        ap.error("--against %s: not among --modes %s" % (args.against, ",".join(args.modes)))
    return args


def main():
    args = parse()
    os.makedirs(args.outdir, exist_ok=True)
    load_before = os.getloadavg()
    curves, refused = measure(args)
    load_after = os.getloadavg()
    print("load average (1, 5, 15 min) before the curves %.2f %.2f %.2f, after %.2f %.2f %.2f" %
          (load_before + load_after))
    if not curves:
        sys.exit("plot-sampling-noise.py: every mode was refused")
    summary = {"scene": args.scene, "name": args.name, "environment": args.environment,
               "width": args.width, "spp_factor": args.spp_factor, "against": args.against,
               "curves": curves, "refused": refused, "ratios": {}, "ratios_by_cpu_time": {},
               "crops": {}, "load_before": load_before, "load_after": load_after}
    ratios_and_crops(args, curves, summary)
    stem = os.path.join(args.outdir, "sampling-noise-" + args.name)
    with open(stem + ".json", "w") as f:
        json.dump(summary, f, indent=1)
    with open(stem + ".svg", "w") as f:
        f.write(svg(curves, "%s, %d wide: noise against time, %s sampling" %
                    (args.name, args.width, ", ".join(args.modes)),
                    {"cpu": "CPU", "gpu": args.gpu_label}))


if __name__ == "__main__":
    sys.exit(main())
