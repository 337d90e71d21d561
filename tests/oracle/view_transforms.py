#!/usr/bin/env python3
"""An independent reference for rtvk's view transforms (docs/color.md), in plain Python from the
published definitions, not from rtvk's code: the sRGB transfer function (IEC 61966-2-1), Hable's
filmic curve (2010), and AgX as Blender 4 builds it (Rec.709 -> Rec.2020 from the primaries'
chromaticities, Blender's inset and outset matrices as Filament publishes them, the log2
encoding of -10 to +6.5 stops around 0.18, and Eary Chow's sigmoid, whose scales are found here
by bisection rather than by rtvk's closed form). Prints the bytes that
tests/base/test_view_transform.cpp expects: python3 tests/oracle/view_transforms.py"""
import math


def to_byte(c):  # the lesson's int(255.999 c) after clamping
    if not c > 0:
        return 0
    if c >= 1:
        return 255
    return int(255.999 * c)


def srgb(c):
    if not c > 0:
        return 0.0
    return 12.92 * c if c <= 0.0031308 else 1.055 * c ** (1 / 2.4) - 0.055


def hable(x):
    a, b, c, d, e, f = 0.15, 0.50, 0.10, 0.20, 0.02, 0.30
    return (x * (a * x + c * b) + d * e) / (x * (a * x + b) + d * f) - e / f


def filmic(c):
    return 0.0 if not c > 0 else hable(2 * c) / hable(11.2)


def mat_mul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(3)) for j in range(3)] for i in range(3)]


def inverse(m):
    (a, b, c), (d, e, f), (g, h, i) = m
    det = a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g)
    return [[(e * i - f * h) / det, (c * h - b * i) / det, (b * f - c * e) / det],
            [(f * g - d * i) / det, (a * i - c * g) / det, (c * d - a * f) / det],
            [(d * h - e * g) / det, (b * g - a * h) / det, (a * e - b * d) / det]]


def rgb_to_xyz(primaries, white):
    p = [[x / y for x, y in primaries], [1, 1, 1], [(1 - x - y) / y for x, y in primaries]]
    w = [white[0] / white[1], 1, (1 - white[0] - white[1]) / white[1]]
    s = [sum(inverse(p)[i][k] * w[k] for k in range(3)) for i in range(3)]
    return [[p[i][j] * s[j] for j in range(3)] for i in range(3)]


D65 = (0.3127, 0.3290)
REC709 = rgb_to_xyz([(0.64, 0.33), (0.30, 0.60), (0.15, 0.06)], D65)
REC2020 = rgb_to_xyz([(0.708, 0.292), (0.170, 0.797), (0.131, 0.046)], D65)
TO_2020 = mat_mul(inverse(REC2020), REC709)
TO_709 = inverse(TO_2020)
INSET = [[0.856627153315983, 0.0951212405381588, 0.0482516061458583],
         [0.137318972929847, 0.761241990602591, 0.101439036467562],
         [0.11189821299995, 0.0767994186031903, 0.811302368396859]]
OUTSET = [[1.1271005818144368, -0.11060664309660323, -0.016493938717834573],
          [-0.1413297634984383, 1.157823702216272, -0.016493938717834257],
          [-0.14132976349843826, -0.11060664309660294, 1.2519364065950405]]


def apply(m, v):
    return [sum(m[i][k] * v[k] for k in range(3)) for i in range(3)]


SLOPE, POWER = 2.4, 1.5
X_PIVOT = 10 / 16.5
Y_PIVOT = 0.18 ** (1 / 2.4)


def sigmoid_side(d, k):
    return Y_PIVOT + SLOPE * d / (1 + (SLOPE * abs(d) / k) ** POWER) ** (1 / POWER)


def solve_scale(d_end, y_end):  # the k with sigmoid_side(d_end, k) == y_end, by bisection
    lo, hi = 1e-6, 1e6
    for _ in range(200):
        mid = math.sqrt(lo * hi)
        # larger k: less compression, |y - y_pivot| larger
        if abs(sigmoid_side(d_end, mid) - Y_PIVOT) > abs(y_end - Y_PIVOT):
            hi = mid
        else:
            lo = mid
    return math.sqrt(lo * hi)


K_TOE = solve_scale(-X_PIVOT, 0.0)
K_SHOULDER = solve_scale(1 - X_PIVOT, 1.0)


def agx(rgb):
    c = apply(INSET, apply(TO_2020, [max(v, 0.0) for v in rgb]))
    lo, hi = math.log2(0.18) - 10, math.log2(0.18) + 6.5
    x = [min(max((math.log2(max(v, 1e-10)) - lo) / (hi - lo), 0.0), 1.0) for v in c]
    y = [sigmoid_side(v - X_PIVOT, K_TOE if v < X_PIVOT else K_SHOULDER) for v in x]
    lin = apply(TO_709, apply(OUTSET, [max(v, 0.0) ** 2.4 for v in y]))
    return [to_byte(srgb(min(max(v, 0.0), 1.0))) for v in lin]


if __name__ == "__main__":
    for c in [0.0, 0.001, 0.0031308, 0.0031309, 0.01, 0.18, 0.5, 1.0]:
        print(f"standard {c!r}: {to_byte(srgb(c))}")
    for c in [0.01, 0.18, 1.0, 4.0, 5.6]:
        print(f"filmic {c!r}: {to_byte(srgb(filmic(c)))}")
    for rgb in [(0.18, 0.18, 0.18), (1.0, 0.0, 0.0), (4.0, 1.0, 0.25), (0.02, 0.05, 0.3),
                (16.0, 16.0, 16.0), (0.0, 0.0, 0.0)]:
        print(f"agx {rgb}: {agx(rgb)}")
