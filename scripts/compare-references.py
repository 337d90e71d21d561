#!/usr/bin/python3
"""Renders Khronos glTF sample models with rtvk at its default settings and compares each with the
model's own reference screenshot (made by the Khronos sample viewer): the mean color over the
object, in sRGB-encoded 0..1 units, and the ratio of their mean luminances. Not a CI test (the
models are megabytes, and the screenshots are lit by the viewer's environment map, rtvk's by its
default sky): the lead runs it by hand and records the table in docs/mesh-formats.md.

The object's pixels: in rtvk's image, where its --aov object-id is not 0; in a screenshot, where
the color differs from the background, taken as the median of the image's border (uniform
backgrounds), or for a screenshot over a photograph (Suzanne) inside a hand-drawn ellipse and
unsaturated (the model is gray, the grass and sky are not).

usage: compare-references.py RTVK SAMPLES_DIR OUT_DIR [MODEL ...] [-- extra rtvk flags]
  SAMPLES_DIR holds <Model>/glTF-Binary/<Model>.glb or <Model>/glTF/<Model>.gltf and
  <Model>/screenshot/screenshot.{png,jpg} (the layout of KhronosGroup/glTF-Sample-Models).
Writes OUT_DIR/<Model>.png, a side-by-side OUT_DIR/<Model>-side.png (rtvk's render cropped to
the object, then the screenshot, both 200 pixels high), OUT_DIR/sheet.png with every pair two to a
row (the README's picture), and prints a Markdown table.
"""
import importlib.util
import os
import subprocess
import sys

import cv2
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
spec = importlib.util.spec_from_file_location("aov_preview", os.path.join(HERE, "aov-preview.py"))
aov_preview = importlib.util.module_from_spec(spec)
spec.loader.exec_module(aov_preview)

# The models the issue names, and how to find the object in each screenshot.
MODELS = {
    "DamagedHelmet": {"mask": "border"},
    "BoomBox": {"mask": "border"},
    "Avocado": {"mask": "border"},
    # 180 x 135 over a photograph: the head lies inside this ellipse (center, half axes, pixels).
    "Suzanne": {"mask": "ellipse", "ellipse": ((92, 62), (62, 52)), "max_saturation": 70},
    # Issue 45's material tests (MetalRoughSpheres's textured version lacks its .bin in the copy
    # rtvk measured with: its NoTextures twin draws the same grid from factors).
    "MetalRoughSpheresNoTextures": {"mask": "border"},
    "NormalTangentMirrorTest": {"mask": "border"},
    "TransmissionTest": {"mask": "border"},
    "ClearCoatTest": {"mask": "border"},
    "SheenChair": {"mask": "border"},
}


def model_file(samples, name):
    for sub, ext in (("glTF-Binary", ".glb"), ("glTF", ".gltf")):
        path = os.path.join(samples, name, sub, name + ext)
        if os.path.exists(path):
            return path
    raise SystemExit(f"{name}: no glTF-Binary/{name}.glb or glTF/{name}.gltf under {samples}")


def screenshot(samples, name):
    folder = os.path.join(samples, name, "screenshot")
    for f in sorted(os.listdir(folder)):
        if f.startswith("screenshot."):
            return cv2.imread(os.path.join(folder, f), cv2.IMREAD_COLOR)
    raise SystemExit(f"{name}: no screenshot in {folder}")


def screenshot_mask(img, how):
    if how["mask"] == "border":
        border = np.concatenate([img[:3].reshape(-1, 3), img[-3:].reshape(-1, 3),
                                 img[:, :3].reshape(-1, 3), img[:, -3:].reshape(-1, 3)])
        background = np.median(border, axis=0)
        return np.abs(img.astype(np.float64) - background).max(axis=2) > 20
    (cx, cy), (ax, ay) = how["ellipse"]
    yy, xx = np.mgrid[0:img.shape[0], 0:img.shape[1]]
    inside = ((xx - cx) / ax) ** 2 + ((yy - cy) / ay) ** 2 <= 1
    saturation = cv2.cvtColor(img, cv2.COLOR_BGR2HSV)[:, :, 1]
    return inside & (saturation <= how["max_saturation"])


def mean_rgb(img, mask):
    return img[mask][:, ::-1].astype(np.float64).mean(axis=0) / 255.0  # BGR -> RGB, 0..1


HEIGHT = 200  # pixels of each picture in the side-by-sides


def crop(img, mask):
    """The object's bounding box in the image, grown by a tenth a side, squared where it fits."""
    ys, xs = np.nonzero(mask)
    y0, y1, x0, x1 = ys.min(), ys.max() + 1, xs.min(), xs.max() + 1
    m = int(0.1 * max(y1 - y0, x1 - x0))
    return img[max(y0 - m, 0):y1 + m, max(x0 - m, 0):x1 + m]


def fit(img):
    w = max(1, round(img.shape[1] * HEIGHT / img.shape[0]))
    return cv2.resize(img, (w, HEIGHT), interpolation=cv2.INTER_AREA)


def sheet(pairs):
    """The pairs two to a row, 8 white pixels between them."""
    gap = 8
    rows = [pairs[i:i + 2] for i in range(0, len(pairs), 2)]
    width = max(sum(p.shape[1] for p in r) + gap * (len(r) - 1) for r in rows)
    out = []
    for r in rows:
        line = np.full((HEIGHT, width, 3), 255, np.uint8)
        x = 0
        for p in r:
            line[:, x:x + p.shape[1]] = p
            x += p.shape[1] + gap
        out += [line, np.full((gap, width, 3), 255, np.uint8)]
    return np.vstack(out[:-1])


def luminance(rgb):
    return float(np.dot(rgb, [0.2126, 0.7152, 0.0722]))


def main(argv):
    extra = []
    if "--" in argv:
        extra = argv[argv.index("--") + 1:]
        argv = argv[:argv.index("--")]
    if len(argv) < 4:
        raise SystemExit(__doc__)
    rtvk, samples, out = argv[1], argv[2], argv[3]
    names = argv[4:] or list(MODELS)
    os.makedirs(out, exist_ok=True)
    pairs = []
    print("| model | rtvk mean RGB | screenshot mean RGB | largest channel difference | "
          "luminance ratio |")
    print("|---|---|---|---|---|")
    for name in names:
        png = os.path.join(out, name + ".png")
        subprocess.run([rtvk, "render", "--scene", model_file(samples, name), "-o", png, "--aov",
                        "object-id"] + extra, check=True, stdout=subprocess.DEVNULL)
        ids = aov_preview.read_exr(os.path.join(out, name + ".object-id.exr"))
        ids = next(iter(ids.values())) if isinstance(ids, dict) else ids
        mine = cv2.imread(png, cv2.IMREAD_COLOR)
        mask = np.asarray(ids).reshape(mine.shape[:2]) != 0
        ref = screenshot(samples, name)
        ref_mask = screenshot_mask(ref, MODELS.get(name, {"mask": "border"}))
        a, b = mean_rgb(mine, mask), mean_rgb(ref, ref_mask)
        side = np.hstack([fit(crop(mine, mask)), fit(ref)])
        cv2.imwrite(os.path.join(out, name + "-side.png"), side)
        pairs.append(side)
        fmt = lambda v: "(" + ", ".join(f"{x:.2f}" for x in v) + ")"
        print(f"| {name} | {fmt(a)} | {fmt(b)} | {np.abs(a - b).max():.2f} | "
              f"{luminance(a) / max(luminance(b), 1e-6):.2f} |")
    cv2.imwrite(os.path.join(out, "sheet.png"), sheet(pairs))


if __name__ == "__main__":
    main(sys.argv)
