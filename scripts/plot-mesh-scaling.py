#!/usr/bin/env python3
"""Measures how rtvk's ray rate falls as a mesh grows, and draws it: docs/images/mesh-scaling.svg.

  plot-mesh-scaling.py RTVK [OUT.svg]

For each size it writes a torus knot (make-mesh.py) to a temporary folder, runs
`RTVK bench --scene knotN.obj --width 320 --aspect 1 --spp 32 --backend B` on the CPU and on the
GPU (the default Vulkan device), and takes the render's Mrays/s with the BVH build left out (on
the CPU: rays / (time - build); on the GPU: rays / device time). Plain SVG, no plotting library.
"""
import os
import re
import subprocess
import sys
import tempfile

SIZES = [1000, 3000, 10000, 30000, 100000, 300000, 1000000]
HERE = os.path.dirname(os.path.abspath(__file__))


def measure(rtvk, obj, backend):
    out = subprocess.run([rtvk, "bench", "--scene", obj, "--width", "320", "--aspect", "1", "--spp",
                          "32", "--backend", backend], check=True, capture_output=True,
                         text=True).stdout
    line = next(l for l in out.splitlines() if l.startswith(backend))
    rays = float(re.search(r"([0-9.]+) M rays in", line).group(1))
    if backend == "cpu":
        total = float(re.search(r"in ([0-9.]+) s", line).group(1))
        build = float(re.search(r"BVH build ([0-9.]+) s", line).group(1))
        return rays / (total - build)
    return rays / float(re.search(r"device time ([0-9.]+) s", line).group(1))


def svg(series, out):
    import math
    w, h, left, bottom, top, right = 640, 360, 60, 50, 20, 140
    ymax = max(v for _, pts in series for _, v in pts) * 1.1
    x0, x1 = math.log10(SIZES[0]), math.log10(SIZES[-1])
    px = lambda n: left + (math.log10(n) - x0) / (x1 - x0) * (w - left - right)
    py = lambda v: h - bottom - v / ymax * (h - top - bottom)
    s = ['<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" font-family="sans-serif" '
         'font-size="12"><rect width="100%%" height="100%%" fill="white"/>' % (w, h)]
    s.append('<line x1="%d" y1="%d" x2="%d" y2="%d" stroke="black"/>' % (left, h - bottom, w - right, h - bottom))
    s.append('<line x1="%d" y1="%d" x2="%d" y2="%d" stroke="black"/>' % (left, top, left, h - bottom))
    for n in [1000, 10000, 100000, 1000000]:
        s.append('<text x="%.1f" y="%d" text-anchor="middle">%s</text>' % (px(n), h - bottom + 16, "{:,}".format(n)))
    step = 2 if ymax > 8 else 1
    for v in range(0, int(ymax) + 1, step):
        s.append('<text x="%d" y="%.1f" text-anchor="end">%d</text>' % (left - 6, py(v) + 4, v))
        s.append('<line x1="%d" y1="%.1f" x2="%d" y2="%.1f" stroke="#ddd"/>' % (left, py(v), w - right, py(v)))
    s.append('<text x="%d" y="%d" text-anchor="middle">triangles (torus knot)</text>' % ((left + w - right) // 2, h - 12))
    s.append('<text x="14" y="%d" transform="rotate(-90 14 %d)" text-anchor="middle">Mrays/s</text>' % (h // 2, h // 2))
    for k, (name, pts) in enumerate(series):
        color = ["#c0392b", "#2471a3"][k % 2]
        s.append('<polyline fill="none" stroke="%s" stroke-width="2" points="%s"/>' % (
            color, " ".join("%.1f,%.1f" % (px(n), py(v)) for n, v in pts)))
        for n, v in pts:
            s.append('<circle cx="%.1f" cy="%.1f" r="3" fill="%s"/>' % (px(n), py(v), color))
        s.append('<text x="%d" y="%d" fill="%s">%s</text>' % (w - right + 10, top + 20 + 18 * k, color, name))
    s.append("</svg>")
    with open(out, "w") as f:
        f.write("\n".join(s) + "\n")


def main():
    if len(sys.argv) not in (2, 3):
        sys.exit(__doc__)
    rtvk = sys.argv[1]
    out = sys.argv[2] if len(sys.argv) == 3 else os.path.join(HERE, "..", "docs", "images", "mesh-scaling.svg")
    cpu, gpu = [], []
    with tempfile.TemporaryDirectory() as tmp:
        for n in SIZES:
            obj = os.path.join(tmp, "knot%d.obj" % n)
            subprocess.run([sys.executable, os.path.join(HERE, "make-mesh.py"), "knot", str(n), obj], check=True)
            cpu.append((n, measure(rtvk, obj, "cpu")))
            gpu.append((n, measure(rtvk, obj, "gpu")))
            print("%8d triangles: cpu %.2f, gpu %.2f Mrays/s" % (n, cpu[-1][1], gpu[-1][1]))
    svg([("CPU (all threads)", cpu), ("GPU (Vulkan)", gpu)], out)


if __name__ == "__main__":
    main()
