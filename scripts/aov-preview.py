#!/usr/bin/python3
"""PNG previews of the AOVs rtvk render --aov writes (docs/aov.md): depth as a color ramp, normals
as 0.5 (n + 1), albedo as is, ids as a color per id. Reads the OpenEXR files itself (scanline,
ZIP or no compression, FLOAT and UINT channels: what rtvk writes), so it needs only numpy and
OpenCV for the PNGs.

usage: aov-preview.py FILE.exr OUT_PREFIX   (writes OUT_PREFIX-<channel group>.png)
"""
import struct
import sys
import zlib

import cv2
import numpy as np


def read_exr(path):
    data = open(path, "rb").read()
    assert struct.unpack_from("<I", data, 0)[0] == 20000630, "not OpenEXR"
    pos, header = 8, {}
    while data[pos] != 0:
        end = data.index(b"\0", pos)
        name = data[pos:end].decode()
        tend = data.index(b"\0", end + 1)
        kind = data[end + 1:tend].decode()
        size = struct.unpack_from("<i", data, tend + 1)[0]
        header[name] = (kind, data[tend + 5:tend + 5 + size])
        pos = tend + 5 + size
    pos += 1
    channels, c = [], header["channels"][1]
    i = 0
    while c[i] != 0:
        end = c.index(b"\0", i)
        pixel_type = struct.unpack_from("<i", c, end + 1)[0]
        channels.append((c[i:end].decode(), pixel_type))
        i = end + 17
    x0, y0, x1, y1 = struct.unpack("<iiii", header["dataWindow"][1])
    w, h = x1 - x0 + 1, y1 - y0 + 1
    compression = header["compression"][1][0]
    lines = {0: 1, 2: 1, 3: 16}[compression]
    blocks = (h + lines - 1) // lines
    offsets = struct.unpack_from("<%dQ" % blocks, data, pos)
    out = {name: np.zeros((h, w), np.uint32 if t == 0 else np.float32) for name, t in channels}
    for off in offsets:
        y, size = struct.unpack_from("<ii", data, off)
        raw = data[off + 8:off + 8 + size]
        rows = min(lines, y1 - y + 1)
        expected = rows * w * 4 * len(channels)
        if compression != 0 and size < expected:
            t = np.frombuffer(zlib.decompress(raw), np.uint8).astype(np.int64)
            # OpenEXR's predictor: each byte stored as the difference to the last, plus 128.
            p = ((np.cumsum(t) - 128 * np.arange(len(t))) & 255).astype(np.uint8)
            half = (len(p) + 1) // 2
            b = np.empty_like(p)
            b[0::2], b[1::2] = p[:half], p[half:]
            raw = b.tobytes()
        k = 0
        for r in range(rows):
            for name, t in channels:  # channels are stored sorted by name, as listed
                v = np.frombuffer(raw, np.uint32 if t == 0 else np.float32, w, k)
                out[name][y - y0 + r] = v
                k += 4 * w
    return out


def ramp(v):
    finite = np.isfinite(v)
    lo, hi = (np.percentile(v[finite], 1), np.percentile(v[finite], 99)) if finite.any() else (0, 1)
    g = np.clip((v - lo) / max(hi - lo, 1e-9), 0, 1)
    img = cv2.applyColorMap((255 * (1 - g)).astype(np.uint8), cv2.COLORMAP_VIRIDIS)
    img[~finite] = 0
    return img


def ids(v):
    rng = np.random.default_rng(7)
    table = rng.integers(40, 256, size=(int(v.max()) + 1, 3), dtype=np.uint8)
    table[0] = 0
    return table[v]


def main():
    src, prefix = sys.argv[1], sys.argv[2]
    c = read_exr(src)
    if "Z" in c:
        cv2.imwrite(prefix + "-depth.png", ramp(c["Z"]))
    if "N.X" in c:
        n = np.dstack([c["N.Z"], c["N.Y"], c["N.X"]])
        cv2.imwrite(prefix + "-normal.png", (255 * np.clip(0.5 * (n + 1), 0, 1)).astype(np.uint8))
    if "albedo.R" in c:
        a = np.dstack([c["albedo.B"], c["albedo.G"], c["albedo.R"]])
        cv2.imwrite(prefix + "-albedo.png", (255 * np.sqrt(np.clip(a, 0, 1))).astype(np.uint8))
    for name in ("object_id", "material_id"):
        if name in c:
            cv2.imwrite(prefix + "-" + name.replace("_", "-") + ".png", ids(c[name]))


if __name__ == "__main__":
    main()
