#!/usr/bin/python3
"""Writes rtvk's test environment map: a Radiance RGBE (.hdr) equirectangular image of a sky
gradient over a dim ground, and a small, very bright sun disk.

    python3 scripts/make-test-environment.py [OUT.hdr] [--width 256] [--height 128]

The default output is docs/scenes/sky-sun.hdr (committed: 256x128, flat RGBE
scanlines, 131 KB), which the environment tests and docs/scenes/environment-sun.json use.

The map's convention is rtvk's (docs/lighting.md, Blender's equirectangular axes with y up): texel
(x, y), counted from the top left, looks along
    u = (x + 0.5) / width, t = (y + 0.5) / height, phi = (2u - 1) pi, theta = t pi,
    d = (sin(theta) cos(phi), cos(theta), sin(theta) sin(phi)),
so the image's center looks along +x, its top row up (+y), u = 3/4 along +z.

The sun: centered on SUN_DIRECTION (elevation 35 degrees, azimuth 60 degrees from +x toward +z,
i.e. (0.4096, 0.5736, 0.7094)), SUN_RADIUS_DEGREES = 3 degrees in radius (a few texels across),
radiance SUN_RADIANCE = 5000 in each channel (warm white). The sky: HORIZON (0.9, 0.95, 1.0) at
the horizon blending to ZENITH (0.25, 0.45, 1.0) overhead as sin(elevation); the ground below the
horizon GROUND (0.2, 0.18, 0.15). Python 3 and numpy only; the RGBE encoding is written here.
"""
import argparse
import os

import numpy as np

SUN_ELEVATION_DEGREES = 35.0
SUN_AZIMUTH_DEGREES = 60.0  # from +x toward +z, about +y
SUN_RADIUS_DEGREES = 3.0
SUN_RADIANCE = np.array([5000.0, 4800.0, 4500.0])
HORIZON = np.array([0.9, 0.95, 1.0])
ZENITH = np.array([0.25, 0.45, 1.0])
GROUND = np.array([0.2, 0.18, 0.15])


def sun_direction():
    e = np.radians(SUN_ELEVATION_DEGREES)
    a = np.radians(SUN_AZIMUTH_DEGREES)
    return np.array([np.cos(e) * np.cos(a), np.sin(e), np.cos(e) * np.sin(a)])


def texel_directions(width, height):
    u = (np.arange(width) + 0.5) / width
    t = (np.arange(height) + 0.5) / height
    phi = (2.0 * u - 1.0) * np.pi
    theta = t * np.pi
    st = np.sin(theta)[:, None]
    return np.stack(
        [st * np.cos(phi)[None, :], np.cos(theta)[:, None] * np.ones((1, width)),
         st * np.sin(phi)[None, :]], axis=-1)


def radiance(width, height):
    d = texel_directions(width, height)
    up = np.clip(d[..., 1:2], 0.0, 1.0)
    sky = (1.0 - up) * HORIZON + up * ZENITH
    rgb = np.where(d[..., 1:2] >= 0.0, sky, GROUND)
    cos_sun = d @ sun_direction()
    in_sun = cos_sun >= np.cos(np.radians(SUN_RADIUS_DEGREES))
    rgb[in_sun] = SUN_RADIANCE
    return rgb


def rgbe(rgb):
    """Radiance's shared-exponent bytes for float RGB (h, w, 3) >= 0."""
    largest = rgb.max(axis=-1)
    mantissa, exponent = np.frexp(largest)  # largest = mantissa 2^exponent, mantissa in [0.5, 1)
    scale = np.where(largest > 1e-32, np.ldexp(1.0, 8 - exponent), 0.0)
    out = np.zeros(rgb.shape[:-1] + (4,), dtype=np.uint8)
    out[..., :3] = np.clip(np.floor(rgb * scale[..., None]), 0, 255).astype(np.uint8)
    out[..., 3] = np.where(largest > 1e-32, exponent + 128, 0).astype(np.uint8)
    return out


def write_hdr(path, rgb):
    height, width, _ = rgb.shape
    header = ("#?RADIANCE\n# rtvk scripts/make-test-environment.py\nFORMAT=32-bit_rle_rgbe\n\n"
              "-Y %d +X %d\n" % (height, width)).encode("ascii")
    with open(path, "wb") as f:
        f.write(header)
        f.write(rgbe(rgb).tobytes())  # flat scanlines: no run-length encoding


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    default = os.path.join(here, "..", "docs", "scenes", "sky-sun.hdr")
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("out", nargs="?", default=default)
    p.add_argument("--width", type=int, default=256)
    p.add_argument("--height", type=int, default=128)
    a = p.parse_args()
    write_hdr(a.out, radiance(a.width, a.height))
    print("wrote %s: %dx%d, sun along %s" % (a.out, a.width, a.height,
                                             np.round(sun_direction(), 4).tolist()))


if __name__ == "__main__":
    main()
