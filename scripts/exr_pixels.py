"""The R, G and B channels of a scanline OpenEXR file, in pure Python (no numpy, no OpenEXR
module): enough for rtvk's renders (ZIP-compressed float) and Blender's (uncompressed float or
half) in scripts/compare-cycles.py. Compressions NONE, ZIPS and ZIP; pixel types HALF and FLOAT;
no tiles, no multi-part files.

  width, height, rgb = read_rgb("x.exr")   # rgb: a flat list, r g b per pixel, rows top down
  width, height, planes = read_channels("x.exr")   # every channel by name (UINT ones too)
"""
import array
import struct
import zlib

_LINES = {0: 1, 2: 1, 3: 16}  # compression (NONE, ZIPS, ZIP): scanlines per chunk


def _header(data):
    if data[:4] != b"\x76\x2f\x31\x01":
        raise ValueError("not an OpenEXR file")
    if data[5] & 0x1A:  # the version field's flags: tiled 0x200, deep 0x800, multi-part 0x1000
        raise ValueError("tiled, deep or multi-part OpenEXR files are not read")
    pos, attrs = 8, {}
    while data[pos] != 0:
        end = data.index(b"\0", pos)
        name = data[pos:end].decode()
        end2 = data.index(b"\0", end + 1)
        kind = data[end + 1:end2].decode()
        size = struct.unpack_from("<i", data, end2 + 1)[0]
        attrs[name] = (kind, data[end2 + 5:end2 + 5 + size])
        pos = end2 + 5 + size
    return attrs, pos + 1


def _channels(raw):
    out, pos = [], 0
    while raw[pos] != 0:
        end = raw.index(b"\0", pos)
        name = raw[pos:end].decode()
        pixel_type = struct.unpack_from("<i", raw, end + 1)[0]
        out.append((name, pixel_type))
        pos = end + 1 + 16
    return out


def _unzip(block, size):
    t = bytearray(zlib.decompress(block))
    for i in range(1, len(t)):  # the predictor: each byte stored as a difference from the last
        t[i] = (t[i - 1] + t[i] - 128) & 0xFF
    out = bytearray(len(t))
    half = (len(t) + 1) // 2
    out[0::2] = t[:half]  # the two halves interleaved back
    out[1::2] = t[half:]
    return bytes(out)


def read_channels(path):
    """Every channel of the file, by name: a flat list a channel, rows top down."""
    with open(path, "rb") as f:
        data = f.read()
    attrs, pos = _header(data)
    compression = attrs["compression"][1][0]
    if compression not in _LINES:
        raise ValueError("%s: compression %d is not read (NONE, ZIPS, ZIP are)" % (path,
                                                                                  compression))
    x0, y0, x1, y1 = struct.unpack("<4i", attrs["dataWindow"][1])
    width, height = x1 - x0 + 1, y1 - y0 + 1
    chans = _channels(attrs["channels"][1])  # sorted by name, as stored
    sizes = [2 if t == 1 else 4 for _, t in chans]
    lines = _LINES[compression]
    chunks = (height + lines - 1) // lines
    offsets = struct.unpack_from("<%dQ" % chunks, data, pos)
    planes = {name: [0] * (width * height) for name, _ in chans}
    for off in offsets:
        y, size = struct.unpack_from("<ii", data, off)
        block = data[off + 8:off + 8 + size]
        n = min(lines, y1 + 1 - y)
        raw_size = n * width * sum(sizes)
        if size < raw_size:
            block = _unzip(block, raw_size)
        p = 0
        for row in range(y - y0, y - y0 + n):
            for (name, t), s in zip(chans, sizes):
                vals = array.array({0: "I", 1: "e"}.get(t, "f"))  # UINT, HALF, FLOAT
                vals.frombytes(block[p:p + width * s])
                p += width * s
                planes[name][row * width:(row + 1) * width] = vals.tolist()
    return width, height, planes


def read_rgb(path):
    width, height, planes = read_channels(path)
    r, g, b = (planes[c] for c in ("R", "G", "B"))
    rgb = [0.0] * (3 * width * height)
    rgb[0::3], rgb[1::3], rgb[2::3] = r, g, b
    return width, height, rgb


def mse(a, b):
    """The mean squared difference of two flat lists."""
    return sum((x - y) ** 2 for x, y in zip(a, b)) / len(a)
