#!/usr/bin/env python3
"""rtvk against Blender's Cycles on the same Cornell box, the same CPU cores: the time each needs
to reach an equal error (docs/benchmarks.md, "rtvk against Blender's Cycles"). By hand, never in
CI (Blender is not one of rtvk's dependencies).

  compare-cycles.py RTVK OUTDIR [--width 150] [--seconds 8] [--threads 2] [--modes lights,nee]
                    [--spp-factor 4] [--precision auto|fast|reference]
                    [--rtvk-reference REF.exr | --rtvk-reference-spp 32768]
                    [--rtvk-reference-mode lights] [--cycles-reference-spp 8192]
                    [--blender blender] [--agree 0.03] [--from-json compare-cycles.json]

1. `RTVK scene dump cornell-box` to OUTDIR/cornell-box.json, which scripts/blender-cornell.py
   builds in Blender (`blender -b --factory-startup --debug-cycles -P scripts/blender-cornell.py
   -- OUTDIR/cornell-box.json OUT.exr --width W --spp N --seed S --threads T`).
2. Each renderer's own converged reference: rtvk's (`--sampling lights`, seed 0; or the one
   given) and Cycles' (seed 0), reused from OUTDIR when there already.
3. The two references must agree: the mean of each channel over the whole image and over a 3x3
   grid of regions within --agree (relative) of each other, else the script stops (exit 1)
   before measuring anything: a gap there is a difference of scene, units or camera, not noise.
4. Each renderer's curve: renders at 1, 4, 16, ... samples per pixel (seed 7; --spp-factor 2:
   1, 2, 4, ...; rtvk's lights and nee stratify pixels whole only at square counts), taking
   turns at each count, until one takes more than --seconds; each one's mean squared error
   against its own reference (the linear RGB values, over pixels and channels;
   scripts/exr_pixels.py reads both renderers' files) and its render time: rtvk's summary line
   (`in S s`: the render alone) and Cycles' own report ("Rendered N samples in S seconds": path
   tracing alone, not Blender's start-up nor the scene's synchronisation).
5. Each reference's own error taken out of its renderer's points (it adds sigma_ref^2 / N to
   every one: up to a fifth of the last points' error with N 32 times their samples), then the
   time each needs to reach equal errors, interpolated in log-log between measured points,
   at errors spaced over the range both curves cover, and Cycles' time over rtvk's (above 1: rtvk
   gets there sooner).

Writes OUTDIR/compare-cycles.json (every point) and OUTDIR/compare-cycles.svg (the curves, drawn
by plot-sampling-noise.py's plot).
"""
import argparse
import importlib.util
import json
import math
import os
import re
import resource
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import exr_pixels  # noqa: E402

SEED = 7  # the measured renders' seed: not the references' 0


def plot_module():
    spec = importlib.util.spec_from_file_location("plot_sampling_noise",
                                                  os.path.join(HERE, "plot-sampling-noise.py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def rtvk_render(args, mode, spp, seed, out):
    cmd = [args.rtvk, "render", "cornell-box", "--width", str(args.width), "--spp", str(spp),
           "--sampling", mode, "--backend", "cpu", "--precision", args.precision, "--threads",
           str(args.threads), "--seed", str(seed), "-o", out]
    before = cpu_of_children()
    err = subprocess.run(cmd, check=True, capture_output=True, text=True).stderr
    args.last_cpu_seconds = cpu_of_children() - before
    return float(re.search(r" in ([0-9.]+) s -> ", err).group(1))


def cpu_of_children():
    """User and system CPU seconds of the finished child processes so far."""
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def cycles_render(args, spp, seed, out):
    cmd = [args.blender, "-b", "--factory-startup", "--debug-cycles", "-P",
           os.path.join(HERE, "blender-cornell.py"), "--", args.scene_json, out, "--width",
           str(args.width), "--spp", str(spp), "--seed", str(seed), "--threads",
           str(args.threads)]
    start, before = time.perf_counter(), cpu_of_children()
    log = subprocess.run(cmd, check=True, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                         text=True).stdout
    wall = time.perf_counter() - start
    args.last_cpu_seconds = cpu_of_children() - before
    m = re.search(r"^Rendered (\d+) samples in ([0-9.]+) seconds$", log, re.M)
    if not m or int(m.group(1)) != spp:
        sys.exit("compare-cycles.py: no 'Rendered %d samples in S seconds' in Cycles' log (run "
                 "with --debug-cycles):\n%s" % (spp, log[-2000:]))
    return float(m.group(2)), wall


def blender_version(args):
    """Blender's version, as `blender --version` prints it first (e.g. 3.4.1)."""
    out = subprocess.run([args.blender, "--version"], capture_output=True, text=True).stdout
    m = re.search(r"Blender (\S+)", out)
    return m.group(1) if m else "?"


def regions_agree(args, a, b, width, height):
    """Each channel's mean over the image and a 3x3 grid, rtvk's against Cycles'; True when all
    are within args.agree (relative) of each other."""
    boxes = [("whole", 0, 0, width, height)]
    for j in range(3):
        for i in range(3):
            boxes.append(("r%d c%d" % (j, i), i * width // 3, j * height // 3,
                          (i + 1) * width // 3, (j + 1) * height // 3))
    worst = 0.0
    for name, x0, y0, x1, y1 in boxes:
        means = []
        for img in (a, b):
            s = [0.0, 0.0, 0.0]
            for y in range(y0, y1):
                for x in range(x0, x1):
                    for c in range(3):
                        s[c] += img[3 * (y * width + x) + c]
            n = (x1 - x0) * (y1 - y0)
            means.append([v / n for v in s])
        gaps = [(p - q) / max(q, 1e-6) for p, q in zip(means[0], means[1])]
        worst = max(worst, max(abs(g) for g in gaps))
        print("%-8s rtvk %s  cycles %s  rtvk/cycles - 1: %s" % (
            name, " ".join("%.4f" % v for v in means[0]), " ".join("%.4f" % v for v in means[1]),
            " ".join("%+.3f" % g for g in gaps)))
    print("largest gap %.2f%% (allowed %.1f%%)" % (100 * worst, 100 * args.agree))
    return worst <= args.agree


def curves(makers, seconds, factor):
    """Each renderer's points at 1, factor, factor^2, ... samples per pixel until one render takes
    more than `seconds`. The renderers take turns at each sample count, so that other work on the
    machine slows them alike. makers: name -> (render_one(spp) -> (seconds, extra with "out"),
    reference)."""
    points = {name: [] for name in makers}
    active, spp = list(makers), 1
    while active:
        for name in list(active):
            render_one, reference = makers[name]
            t, extra = render_one(spp)
            _, _, img = exr_pixels.read_rgb(extra["out"])
            point = {"spp": spp, "seconds": t, "mse": exr_pixels.mse(img, reference)}
            point.update({k: v for k, v in extra.items() if k != "out"})
            points[name].append(point)
            print("%-14s %6d spp %8.3f s  mse %.4e" % (name, spp, t, point["mse"]), flush=True)
            if t > seconds:
                active.remove(name)
        spp *= factor
    return points


def by_marginal_cpu(points):
    """The points past 1 spp, each timed by its process's CPU time less the 1-spp process's
    (empty when the points carry no CPU times)."""
    if not points or "process_cpu_seconds" not in points[0]:
        return []
    first = points[0]["process_cpu_seconds"]
    return [dict(p, seconds=p["process_cpu_seconds"] - first) for p in points[1:]
            if p["process_cpu_seconds"] > first]


def log_time_at(points, e):
    """The render time at which the curve's error is e, linear in log-log (None outside it)."""
    for a, b in zip(points, points[1:]):
        lo, hi = sorted((a["mse"], b["mse"]))
        if lo <= e <= hi and a["mse"] != b["mse"]:
            f = (math.log(e) - math.log(a["mse"])) / (math.log(b["mse"]) - math.log(a["mse"]))
            return math.exp(math.log(a["seconds"]) + f * (math.log(b["seconds"]) -
                                                           math.log(a["seconds"])))
    return None


def equal_error(cycles, mine):
    """Cycles' time over rtvk's at nine errors spaced over the range both curves cover."""
    hi = min(max(p["mse"] for p in cycles), max(p["mse"] for p in mine))
    lo = max(min(p["mse"] for p in cycles), min(p["mse"] for p in mine))
    out = []
    for k in range(9):
        e = min(max(hi * (lo / hi) ** (k / 8), lo), hi)
        tc, tr = log_time_at(cycles, e), log_time_at(mine, e)
        if tc is not None and tr is not None:
            out.append({"mse": e, "cycles_seconds": tc, "rtvk_seconds": tr,
                        "cycles_over_rtvk": tc / tr})
    return out


def parse():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("rtvk")
    ap.add_argument("outdir")
    ap.add_argument("--width", type=int, default=150)
    ap.add_argument("--seconds", type=float, default=8)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--spp-factor", type=int, default=4, choices=(2, 4),
                    help="samples per pixel grow by this factor (4: rtvk's pixels stratify whole)")
    ap.add_argument("--modes", default="lights,nee")
    ap.add_argument("--precision", default="auto", choices=("auto", "fast", "reference"),
                    help="the CPU's mode (--precision); auto: the reference, for a built-in scene")
    ap.add_argument("--rtvk-reference", help="rtvk's reference, made with --sampling"
                    " --rtvk-reference-mode at --rtvk-reference-spp (default: rendered so)")
    ap.add_argument("--rtvk-reference-spp", type=int, default=32768)
    ap.add_argument("--rtvk-reference-mode", default="lights")
    ap.add_argument("--from-json", help="a compare-cycles.json to measure again from, rendering"
                    " nothing but the references (when absent)")
    ap.add_argument("--cycles-reference-spp", type=int, default=8192)
    ap.add_argument("--blender", default="blender")
    ap.add_argument("--agree", type=float, default=0.03)
    return ap.parse_args()


def references(args):
    if not args.rtvk_reference:
        args.rtvk_reference = os.path.join(args.outdir, "rtvk-ref-%d-%d.exr" % (
            args.width, args.rtvk_reference_spp))
        if not os.path.exists(args.rtvk_reference):
            t = rtvk_render(args, args.rtvk_reference_mode, args.rtvk_reference_spp, 0,
                            args.rtvk_reference)
            print("rtvk reference: %d spp, %s, %.1f s" % (args.rtvk_reference_spp,
                                                         args.rtvk_reference_mode, t))
    cycles_ref = os.path.join(args.outdir, "cycles-ref-%d-%d.exr" % (args.width,
                                                                     args.cycles_reference_spp))
    if not os.path.exists(cycles_ref):
        t, wall = cycles_render(args, args.cycles_reference_spp, 0, cycles_ref)
        print("Cycles reference: %d spp, %.1f s (%.1f s with Blender's start)" % (
            args.cycles_reference_spp, t, wall))
    return cycles_ref


def measure(args, rtvk_ref, cyc_ref):
    """The curves, rtvk's modes' and Cycles' taking turns; with the load average around them."""
    makers = {}
    for mode in args.modes.split(","):
        out = os.path.join(args.outdir, "rtvk-%s.exr" % mode)
        makers["rtvk/" + mode] = (
            lambda n, mode=mode, out=out: (rtvk_render(args, mode, n, SEED, out), {
                "out": out, "process_cpu_seconds": args.last_cpu_seconds}),
            rtvk_ref)
    out = os.path.join(args.outdir, "cycles.exr")

    def one_cycles(n):
        t, wall = cycles_render(args, n, SEED, out)
        return t, {"out": out, "process_seconds": wall,
                   "process_cpu_seconds": args.last_cpu_seconds}

    makers["cycles/cycles"] = (one_cycles, cyc_ref)
    load_before = os.getloadavg()
    measured = curves(makers, args.seconds, args.spp_factor)
    return load_before, measured, os.getloadavg()


def without_reference_noise(measured, own, prefix, reference_spp):
    """Takes each reference's own error out of its renderer's points. A point's error against a
    reference of N samples of an independent seed is sigma^2 / n + sigma_ref^2 / N (the mean of the
    two images' variances; the bias is gone at these counts); sigma_ref^2 is the per-sample
    variance of the reference's estimator, measured on the curve of that same estimator (`own`)
    at its most samples: mse / (1 / n + 1 / N). Keeps the measured value as mse_measured."""
    if own not in measured:
        print("%s: no curve of the reference's estimator; its error is left in" % own)
        return
    last = measured[own][-1]
    share = (last["mse"] / (1 / last["spp"] + 1 / reference_spp)) / reference_spp
    for name, pts in measured.items():
        if not name.startswith(prefix):
            continue
        for p in pts:
            p["mse_measured"] = p["mse"]
            p["mse"] = max(p["mse"] - share, 0.1 * p["mse"])
        print("%s: its reference's own error %.3e taken out (%.0f%% of its last point's)" % (
            name, share, 100 * share / pts[-1]["mse_measured"]))


def check_references(args, cycles_ref):
    """Stops unless the two references have one size and agree region by region."""
    w, h, rtvk_ref = exr_pixels.read_rgb(args.rtvk_reference)
    w2, h2, cyc_ref = exr_pixels.read_rgb(cycles_ref)
    if (w, h) != (w2, h2):
        sys.exit("compare-cycles.py: the references differ in size: %dx%d, %dx%d" % (w, h, w2, h2))
    if not regions_agree(args, rtvk_ref, cyc_ref, w, h):
        sys.exit("compare-cycles.py: the two converged images disagree beyond --agree %g: find"
                 " why (units, camera, materials) before measuring" % args.agree)


def main():
    args = parse()
    os.makedirs(args.outdir, exist_ok=True)
    args.scene_json = os.path.join(args.outdir, "cornell-box.json")
    with open(args.scene_json, "w") as f:
        subprocess.run([args.rtvk, "scene", "dump", "cornell-box"], check=True, stdout=f)
    if args.from_json:  # the run's own references, when still there; nothing rendered
        cycles_ref = os.path.join(args.outdir, "cycles-ref-%d-%d.exr" % (
            args.width, args.cycles_reference_spp))
        have = args.rtvk_reference and os.path.exists(args.rtvk_reference) and os.path.exists(
            cycles_ref)
    else:
        cycles_ref, have = references(args), True
    if have:
        check_references(args, cycles_ref)
    else:
        print("the references are not both there: their agreement is not checked again")
    if args.from_json:
        with open(args.from_json) as f:
            old = json.load(f)
        measured, load_before, load_after = old["curves"], old["load_before"], old["load_after"]
        measured = {n: [dict(p, mse=p.get("mse_measured", p["mse"])) for p in pts]
                    for n, pts in measured.items()}
    else:
        load_before, measured, load_after = measure(args, exr_pixels.read_rgb(
            args.rtvk_reference)[2], exr_pixels.read_rgb(cycles_ref)[2])
    print("load average (1, 5, 15 min) before the curves %.2f %.2f %.2f, after %.2f %.2f %.2f" %
          (tuple(load_before) + tuple(load_after)))
    without_reference_noise(measured, "rtvk/" + args.rtvk_reference_mode, "rtvk/",
                            args.rtvk_reference_spp)
    without_reference_noise(measured, "cycles/cycles", "cycles/", args.cycles_reference_spp)
    summary = {"width": args.width, "threads": args.threads, "curves": measured,
               "load_before": load_before, "load_after": load_after, "equal_error": {},
               "equal_error_by_cpu": {}}
    for mode in args.modes.split(","):
        rows = equal_error(measured["cycles/cycles"], measured["rtvk/" + mode])
        summary["equal_error"][mode] = rows
        for r in rows:
            print("mse %.3e: Cycles %.3f s, rtvk %s %.3f s: Cycles takes %.2fx rtvk's time" % (
                r["mse"], r["cycles_seconds"], mode, r["rtvk_seconds"], r["cycles_over_rtvk"]))
        # By CPU time, which other work on the machine changes little: each process's user and
        # system time less that of its 1-sample render (start-up, scene, BVH: Blender's is 2 s).
        marginal = {n: by_marginal_cpu(measured[n]) for n in ("cycles/cycles", "rtvk/" + mode)}
        if all(marginal.values()):
            rows = equal_error(marginal["cycles/cycles"], marginal["rtvk/" + mode])
            summary["equal_error_by_cpu"][mode] = rows
            print("by CPU time, Cycles' over rtvk %s's: %s" % (mode, ", ".join(
                "%.2f (mse %.2e)" % (r["cycles_over_rtvk"], r["mse"]) for r in rows)))
    for name, pts in measured.items():
        p = pts[-1]
        print("%-14s at %d spp: %.4f s a sample, mse x spp %.4f" % (
            name, p["spp"], p["seconds"] / p["spp"], p["mse"] * p["spp"]))
    with open(os.path.join(args.outdir, "compare-cycles.json"), "w") as f:
        json.dump(summary, f, indent=1)
    plot = plot_module()
    plot.COLORS["cycles"] = "#e67e22"
    with open(os.path.join(args.outdir, "compare-cycles.svg"), "w") as f:
        f.write(plot.svg(measured, "cornell-box, %d wide, %d threads: rtvk and Cycles" % (
            args.width, args.threads), {"rtvk": "rtvk CPU",
                                        "cycles": "Blender " + blender_version(args)}))


if __name__ == "__main__":
    sys.exit(main())
