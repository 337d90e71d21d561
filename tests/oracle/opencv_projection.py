#!/usr/bin/python3
"""OpenCV (and COLMAP's camera model) as the oracle for rtvk's calibrated cameras.

Small white markers (lamps on black) stand at 3D points. OpenCV's own projectPoints
(cv2.projectPoints, cv2.fisheye.projectPoints) says where each lands; rtvk renders them through a
calibration that OpenCV's own cv2.FileStorage wrote; each marker's centroid in rtvk's image (its
antialiased coverage, many samples per pixel) must sit on OpenCV's pixel, on both backends. For
COLMAP, the views of a text model (cameras.txt, images.txt) land their points where COLMAP's
camera model (its formula, written out below) puts them, with COLMAP's pixel convention (the
image's corner at 0, not the first pixel's center).

usage: opencv_projection.py RTVK_EXE WORK_DIR [cpu|gpu ...]
"""
import json
import os
import subprocess
import sys

import cv2
import numpy as np

TOLERANCE_PX = 0.05  # a marker's centroid from OpenCV's pixel, on both backends
MARKER_PX = 4.0      # marker radius in pixels, about
SPP = 256
W, H = 400, 300

rng = np.random.default_rng(29)


def scene(points, radii, path):
    spheres = [{"center": [float(c) for c in p], "radius": float(r), "material": "marker"}
               for p, r in zip(points, radii)]
    doc = {
        # OpenCV's camera frame is the world's: x right, y down, z forward.
        "camera": {"lookfrom": [0, 0, 0], "lookat": [0, 0, 1], "vup": [0, -1, 0]},
        "render": {"spp": SPP, "max_depth": 2, "gamma": 1, "seed": 1, "jitter": True},
        "background": [0, 0, 0],
        "materials": {"marker": {"type": "diffuse_light", "emit": [1, 1, 1]}},
        "spheres": spheres,
    }
    with open(path, "w") as f:
        json.dump(doc, f)


def silhouette(center, radius, eye, n=720):
    """The circle where the cone from `eye` touches the sphere: its outline in any image."""
    c = np.asarray(center, float) - eye
    d2 = c @ c
    mid = eye + c * (1 - radius * radius / d2)
    r = radius * np.sqrt(1 - radius * radius / d2)
    e1 = np.cross(c, [0.0, 0.0, 1.0] if abs(c[2]) < 0.9 * np.sqrt(d2) else [1.0, 0.0, 0.0])
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(c, e1) / np.sqrt(d2)
    phi = np.linspace(0, 2 * np.pi, n, endpoint=False)
    return mid + r * (np.outer(np.cos(phi), e1) + np.outer(np.sin(phi), e2))


def outline_centroid(project, center, radius, eye):
    """Where the oracle puts the marker's centroid: the area centroid of its projected outline
    (not the projected center, which a wide lens moves off the centroid by a few hundredths)."""
    outline = np.array([project(p) for p in silhouette(center, radius, eye)], np.float32)
    m = cv2.moments(outline.reshape(-1, 1, 2))
    return m["m10"] / m["m00"], m["m01"] / m["m00"]


def centroids(image_path, expected):
    """The coverage-weighted centroid of the marker around each expected pixel."""
    img = cv2.imread(image_path, cv2.IMREAD_GRAYSCALE).astype(np.float64) / 255.0
    count, labels = cv2.connectedComponents((img > 0.0).astype(np.uint8))
    found = []
    for x, y in expected:
        xi, yi = int(round(x)), int(round(y))
        label = labels[yi, xi]
        if label == 0:
            found.append(None)
            continue
        ys, xs = np.nonzero(labels == label)
        w = img[ys, xs]
        found.append((float((xs * w).sum() / w.sum()), float((ys * w).sum() / w.sum())))
    return found, count - 1


def render(rtvk, backend, scene_path, out, extra):
    cmd = [rtvk, "render", "--scene", scene_path, "--backend", backend, "-o", out] + extra
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit("rtvk failed (%d): %s\n%s" % (r.returncode, " ".join(cmd), r.stderr))


def check(label, expected, found, markers_seen):
    worst = 0.0
    for (x, y), c in zip(expected, found):
        if c is None:
            sys.exit("%s: no marker at OpenCV's pixel (%.2f, %.2f)" % (label, x, y))
        worst = max(worst, float(np.hypot(c[0] - x, c[1] - y)))
    if markers_seen != len(expected):
        sys.exit("%s: %d markers in the image, %d placed" % (label, markers_seen, len(expected)))
    status = "ok" if worst <= TOLERANCE_PX else "FAILED"
    print("%s: %d markers, worst %.4f px from OpenCV's pixel (tolerance %.2f): %s"
          % (label, len(expected), worst, TOLERANCE_PX, status))
    return worst <= TOLERANCE_PX


def spread_points(project, fx, count, theta_max):
    """3D points in the camera frame whose projections are inside the image, apart."""
    pts, pix = [], []
    while len(pts) < count:
        theta = theta_max * np.sqrt(rng.uniform(0, 1))
        phi = rng.uniform(0, 2 * np.pi)
        depth = rng.uniform(4, 12)
        d = np.array([np.sin(theta) * np.cos(phi), np.sin(theta) * np.sin(phi), np.cos(theta)])
        p = d * depth
        x, y = project(p)
        if not (12 <= x <= W - 13 and 12 <= y <= H - 13):
            continue
        if any(np.hypot(x - a, y - b) < 24 for a, b in pix):
            continue
        pts.append(p)
        pix.append((x, y))
    radii = [np.linalg.norm(p) * MARKER_PX / fx for p in pts]
    return np.array(pts), pix, radii


def write_calibration(path, K, D, model=None):
    fs = cv2.FileStorage(path, cv2.FILE_STORAGE_WRITE)
    fs.write("image_width", W)
    fs.write("image_height", H)
    fs.write("camera_matrix", K)
    fs.write("distortion_coefficients", D)
    if model:
        fs.write("model", model)
    fs.release()


def opencv_cases(rtvk, work, backends):
    ok = True
    # A wide-angle lens with OpenCV's rational model and tangential terms.
    K = np.array([[260.0, 0, 201.3], [0, 258.0, 148.9], [0, 0, 1]])
    D = np.array([[-0.12, 0.03, 0.0012, -0.0008, 0.004, 0.05, -0.01, 0.002]])
    fisheye_K = np.array([[115.0, 0, 199.2], [0, 116.0, 150.7], [0, 0, 1]])
    fisheye_D = np.array([[0.03, -0.008, 0.002, -0.0003]])

    def pinhole(p):
        x, _ = cv2.projectPoints(p.reshape(1, 1, 3), np.zeros(3), np.zeros(3), K, D)
        return x.reshape(2)

    def fisheye(p):
        x, _ = cv2.fisheye.projectPoints(p.reshape(1, 1, 3), np.zeros((3, 1)), np.zeros((3, 1)),
                                         fisheye_K, fisheye_D)
        return x.reshape(2)

    cases = [("opencv", "opencv.yml", K, D, None, pinhole, 0.75),
             ("opencv-fisheye", "fisheye.json", fisheye_K, fisheye_D, "fisheye", fisheye, 1.35)]
    for name, file_name, k, d, model, project, theta_max in cases:
        cal = os.path.join(work, file_name)
        write_calibration(cal, k, d, model)
        pts, pix, radii = spread_points(project, k[0, 0], 40, theta_max)
        pix = [outline_centroid(project, p, r, np.zeros(3)) for p, r in zip(pts, radii)]
        scene_path = os.path.join(work, name + ".json")
        scene(pts, radii, scene_path)
        for backend in backends:
            out = os.path.join(work, "%s-%s.png" % (name, backend))
            render(rtvk, backend, scene_path, out, ["--calibration", cal])
            found, seen = centroids(out, pix)
            ok &= check("%s (%s, %s)" % (name, backend, file_name), pix, found, seen)
    return ok


def quaternion_matrix(q):
    w, x, y, z = q / np.linalg.norm(q)
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                     [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                     [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


def colmap_project(model, params, R, t, p):
    """COLMAP's camera models (src/colmap/sensor/models.h), pixel coordinates with the image's
    top-left corner at (0, 0)."""
    c = R @ p + t
    u, v = c[0] / c[2], c[1] / c[2]
    if model == "OPENCV":
        fx, fy, cx, cy, k1, k2, p1, p2 = params
        u2, v2, uv = u * u, v * v, u * v
        r2 = u2 + v2
        radial = k1 * r2 + k2 * r2 * r2
        du = u * radial + 2 * p1 * uv + p2 * (r2 + 2 * u2)
        dv = v * radial + 2 * p2 * uv + p1 * (r2 + 2 * v2)
        u, v = u + du, v + dv
    else:  # OPENCV_FISHEYE
        fx, fy, cx, cy, k1, k2, k3, k4 = params
        r = np.hypot(u, v)
        theta = np.arctan(r)
        t2 = theta * theta
        thetad = theta * (1 + k1 * t2 + k2 * t2 ** 2 + k3 * t2 ** 3 + k4 * t2 ** 4)
        u, v = u * thetad / r, v * thetad / r
    return fx * u + cx, fy * v + cy


def colmap_case(rtvk, work, backends):
    folder = os.path.join(work, "colmap")
    os.makedirs(folder, exist_ok=True)
    cameras = {1: ("OPENCV", [250.0, 252.0, 200.5, 150.5, -0.08, 0.01, 0.0009, -0.0006]),
               2: ("OPENCV_FISHEYE", [120.0, 121.0, 199.0, 151.0, 0.02, -0.005, 0.001, 0.0])}
    with open(os.path.join(folder, "cameras.txt"), "w") as f:
        f.write("# Camera list with one line of data per camera:\n")
        for cid, (model, params) in cameras.items():
            f.write("%d %s %d %d %s\n" % (cid, model, W, H, " ".join(repr(x) for x in params)))
    # Two views of the same markers: one to the side looking across, one from above, turned.
    views = [("left/0001.png", 1, np.array([0.9, 0.1, -0.2, 0.05]), np.array([0.4, -0.3, 6.0])),
             ("top 0002.jpg", 2, np.array([0.7, 0.6, 0.2, -0.3]), np.array([-0.5, 0.2, 7.0]))]
    # Markers near the world's origin, where both views look.
    world = rng.uniform(-2.5, 2.5, size=(400, 3))
    lines, expected = ["# Image list with two lines of data per image:"], {}
    keep = []
    for p in world:
        inside = True
        for _, cid, q, t in views:
            R = quaternion_matrix(q)
            if (R @ p + t)[2] < 2:
                inside = False
                break
            x, y = colmap_project(cameras[cid][0], cameras[cid][1], R, t, p)
            if not (12.5 <= x <= W - 12.5 and 12.5 <= y <= H - 12.5):
                inside = False
        if inside:
            keep.append(p)
    # Apart in both views.
    chosen = []
    for p in keep:
        far = True
        for _, cid, q, t in views:
            R = quaternion_matrix(q)
            a = colmap_project(cameras[cid][0], cameras[cid][1], R, t, p)
            for c in chosen:
                b = colmap_project(cameras[cid][0], cameras[cid][1], R, t, c)
                if np.hypot(a[0] - b[0], a[1] - b[1]) < 30:
                    far = False
        if far:
            chosen.append(p)
        if len(chosen) == 16:
            break
    for i, (name, cid, q, t) in enumerate(views, start=1):
        lines.append("%d %s %s %d %s" % (i, " ".join(repr(x) for x in q),
                                         " ".join(repr(x) for x in t), cid, name))
        lines.append("")
    with open(os.path.join(folder, "images.txt"), "w") as f:
        f.write("\n".join(lines) + "\n")
    # About MARKER_PX pixels in the view that sees them smallest.
    radii = []
    for p in chosen:
        r = 1.0
        for _, cid, q, t in views:
            depth = (quaternion_matrix(q) @ p + t)[2]
            r = min(r, depth * MARKER_PX / cameras[cid][1][0])
        radii.append(r)
    scene_path = os.path.join(work, "colmap.json")
    scene(chosen, radii, scene_path)
    ok = True
    names = {"left/0001.png": "left_0001", "top 0002.jpg": "top_0002"}
    for backend in backends:
        render(rtvk, backend, scene_path, os.path.join(work, "colmap-" + backend + "-{camera}.png"),
               ["--colmap", folder])
        for name, cid, q, t in views:
            R = quaternion_matrix(q)
            eye = -R.T @ t

            def project(p):  # COLMAP's pixel (x, y) is rtvk's and OpenCV's (x - 0.5, y - 0.5)
                return np.array(colmap_project(cameras[cid][0], cameras[cid][1], R, t, p)) - 0.5

            pix = [outline_centroid(project, p, r, eye) for p, r in zip(chosen, radii)]
            out = os.path.join(work, "colmap-%s-%s.png" % (backend, names[name]))
            found, seen = centroids(out, pix)
            ok &= check("colmap %s %s (%s)" % (cameras[cid][0], name, backend), pix, found, seen)
    return ok


def main():
    rtvk, work = sys.argv[1], sys.argv[2]
    backends = sys.argv[3:] or ["cpu", "gpu"]
    os.makedirs(work, exist_ok=True)
    ok = opencv_cases(rtvk, work, backends)
    ok &= colmap_case(rtvk, work, backends)
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
