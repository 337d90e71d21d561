#!/usr/bin/python3
"""Writes shaders/shared/pbr/bsdf_tables.h: the albedo tables of pbr.h's energy compensation.

Tables (each N x N, row = perceptual roughness r = j / (N - 1), column = cosine
mu = (i / (N - 1))^2, read bilinearly in (sqrt(mu), r): the albedos dip sharply at mu ~ alpha
near grazing, where a linear mu axis had one column; and each N long, the cosine-weighted average 2 * integral of E(mu) mu dmu):
  ggx_e     E(mu, r):  the directional albedo of the single-scattering GGX reflection lobe
                       (height-correlated Smith G2) with Fresnel 1
  ggx_es    Es(mu, r): the same with Fresnel (1 - wo.h)^5, Schlick's weight: with
                       F = F0 + (1 - F0) (1 - wo.h)^5 the lobe's albedo is F0 (E - Es) + Es
  sheen_e   the Charlie sheen lobe's albedo with sheen color 1 (Neubelt's visibility), divided by
            its row's largest value where that exceeds 1
and their averages ggx_e_avg, ggx_es_avg, sheen_e_avg, and sheen_norm: 1 / max(1, the row's
largest albedo), the factor pbr.h puts on the sheen lobe. Charlie with Neubelt's visibility
reflects more than it receives near grazing at low roughness (albedo 4.0 at mu 0, alpha 0.01);
the factor, a function of roughness alone, keeps the lobe reciprocal and its albedo within 1.

Integration: GGX by its visible normals (Heitz 2018, sampled with Dupuy and Benyoub's spherical
caps), a midpoint grid of M x M strata over the two uniform numbers, so the estimate is
E = mean(G2 / G1 over the valid reflections); sheen by a midpoint grid over the half vector's
polar angle and azimuth (its distribution is sharp near grazing half vectors). The averages use a
Gauss-Legendre rule of 48 nodes in mu. Alpha is max(r^2, 1e-3) (pbr.h's delta threshold; below it
E is 1); the sheen's alpha is max(r^2, 1e-2) (pbr.h's sheen_alpha_min). Run: scripts/make-bsdf-tables.py
"""
import numpy as np

N = 32  # table resolution in each of mu and r
M = 256  # strata per dimension of the GGX integration (M^2 samples per entry)
SHEEN_T, SHEEN_P = 384, 96  # sheen grid: half vector polar angle x azimuth over [0, pi]
ALPHA_MIN = 1e-3
SHEEN_ALPHA_MIN = 1e-2
MU_MIN = 1e-4  # the column mu = 0 is evaluated here (grazing)


def ggx_lambda(z2, xy2, alpha):
    return 0.5 * (np.sqrt(1.0 + alpha * alpha * xy2 / z2) - 1.0)


def ggx_albedos(mu, alpha):
    """E and Es at one (mu, alpha): VNDF importance sampling on a midpoint grid."""
    mu = max(mu, MU_MIN)
    o = np.array([np.sqrt(1.0 - mu * mu), 0.0, mu])
    g = (np.arange(M) + 0.5) / M
    # u2 near 1 draws the grazing normals of GGX's long tail: t -> 1 - (1 - t)^4 crowds the grid
    # there (the weight 4 (1 - t)^3 is the substitution's derivative).
    u1, t = np.meshgrid(g, g, indexing="ij")
    u1, t = u1.ravel(), t.ravel()
    u2 = 1.0 - (1.0 - t) ** 4
    jac = 4.0 * (1.0 - t) ** 3
    # Spherical caps in the stretched configuration.
    s = np.array([o[0] * alpha, 0.0, o[2]])
    s /= np.linalg.norm(s)
    phi = 2.0 * np.pi * u1
    z = (1.0 - u2) * (1.0 + s[2]) - s[2]
    st = np.sqrt(np.clip(1.0 - z * z, 0.0, 1.0))
    hx, hy, hz = st * np.cos(phi) + s[0], st * np.sin(phi) + s[1], z + s[2]
    hx, hy = hx * alpha, hy * alpha
    n = np.sqrt(hx * hx + hy * hy + hz * hz)
    hx, hy, hz = hx / n, hy / n, hz / n
    oh = o[0] * hx + o[2] * hz
    ix, iy, iz = 2 * oh * hx - o[0], 2 * oh * hy, 2 * oh * hz - o[2]
    ok = iz > 0
    lo = ggx_lambda(o[2] ** 2, o[0] ** 2, alpha)
    li = ggx_lambda(np.where(ok, iz * iz, 1.0), ix * ix + iy * iy, alpha)
    w = np.where(ok, (1.0 + lo) / (1.0 + lo + li), 0.0)  # G2 / G1(wo)
    schlick = (1.0 - np.clip(oh, 0.0, 1.0)) ** 5
    return (w * jac).mean(), (w * schlick * jac).mean()


def sheen_albedo(mu, alpha):
    """The Charlie lobe's albedo, integrated over the half vector: dw_i = 4 |wo.h| dw_h."""
    mu = max(mu, MU_MIN)
    o = np.array([np.sqrt(1.0 - mu * mu), 0.0, mu])
    t = (np.arange(SHEEN_T) + 0.5) / SHEEN_T * (np.pi / 2)
    p = (np.arange(SHEEN_P) + 0.5) / SHEEN_P * np.pi
    th, ph = np.meshgrid(t, p, indexing="ij")
    hx, hy, hz = np.sin(th) * np.cos(ph), np.sin(th) * np.sin(ph), np.cos(th)
    oh = o[0] * hx + o[2] * hz
    ix, iz = 2 * oh * hx - o[0], 2 * oh * hz - o[2]
    ok = (iz > 0) & (oh > 0)
    d = (2.0 + 1.0 / alpha) * np.sin(th) ** (1.0 / alpha) / (2 * np.pi)
    izc = np.where(ok, iz, 0.0)
    v = 1.0 / (4.0 * (izc + mu - izc * mu))
    f = np.where(ok, d * v * izc * 4 * oh, 0.0)
    dw = np.sin(th) * (np.pi / 2 / SHEEN_T) * (np.pi / SHEEN_P)
    return 2.0 * (f * dw).sum()  # the azimuth's other half by symmetry


def main():
    mus = (np.arange(N) / (N - 1)) ** 2
    rs = np.arange(N) / (N - 1)
    xg, wg = np.polynomial.legendre.leggauss(48)
    gmu, gw = 0.5 * (xg + 1), 0.5 * wg  # nodes and weights on [0, 1]
    tables = {k: np.zeros((N, N)) for k in ("ggx_e", "ggx_es", "sheen_e")}
    avgs = {k: np.zeros(N) for k in ("ggx_e_avg", "ggx_es_avg", "sheen_e_avg", "sheen_norm")}
    for j, r in enumerate(rs):
        a = max(r * r, ALPHA_MIN)
        sa = max(r * r, SHEEN_ALPHA_MIN)
        for i, mu in enumerate(mus):
            tables["ggx_e"][j, i], tables["ggx_es"][j, i] = ggx_albedos(mu, a)
            tables["sheen_e"][j, i] = sheen_albedo(mu, sa)
        e = np.array([ggx_albedos(m, a) for m in gmu])
        avgs["ggx_e_avg"][j] = 2 * (e[:, 0] * gmu * gw).sum()
        avgs["ggx_es_avg"][j] = 2 * (e[:, 1] * gmu * gw).sum()
        avgs["sheen_e_avg"][j] = 2 * sum(sheen_albedo(m, sa) * m * w for m, w in zip(gmu, gw))
        norm = 1.0 / max(1.0, tables["sheen_e"][j].max(), sheen_albedo(0.0, sa))
        avgs["sheen_norm"][j] = norm
        tables["sheen_e"][j] *= norm
        avgs["sheen_e_avg"][j] *= norm
        print(f"r={r:.3f} E(1)={tables['ggx_e'][j, -1]:.5f} E_avg={avgs['ggx_e_avg'][j]:.5f} "
              f"sheen max={tables['sheen_e'][j].max():.5f}", flush=True)
    write(tables, avgs)


def body(values):
    lines, row = [], []
    for v in values:
        row.append(f"{v:.7f}f")
        if len(row) == 8:
            lines.append("    " + ", ".join(row) + ",")
            row = []
    if row:
        lines.append("    " + ", ".join(row) + ",")
    lines[-1] = lines[-1].rstrip(",")
    return "\n".join(lines)


def write(tables, avgs):
    names = list(tables) + list(avgs)
    sizes = [N * N] * len(tables) + [N] * len(avgs)
    offsets = [sum(sizes[:i]) for i in range(len(sizes))]
    out = [
        "// GENERATED by scripts/make-bsdf-tables.py: do not edit. The albedo tables of pbr.h's",
        "// energy compensation (Kulla and Conty 2017), one source for GLSL and C++. Each 2-D table is",
        f"// {N} x {N}: row j = perceptual roughness j / {N - 1}, column i = cosine (i / {N - 1})^2,",
        "// read bilinearly in (sqrt(cosine), roughness) (table_pos_of in pbr_layers.h); each 1-D",
        "// one holds a row's cosine-weighted average. The script's docstring says how they are",
        "// integrated.",
        "//",
        "// The tables are one array, each at its offset below, read through BSDF_TABLE(i): C++ reads",
        "// bsdf_table_data here, GLSL the storage buffer bsdf_table[] that the including shader",
        "// declares (RTVK_BINDING_BSDF_TABLES), which the host fills from bsdf_table_data. A GLSL",
        "// array initialised in the shader would live in each invocation's private memory: lavapipe",
        "// compiled a shader reading these tables for over 17 minutes, and ran out of memory.",
        "// clang-format off",
        "#ifndef RTVK_BSDF_TABLES_H",
        "#define RTVK_BSDF_TABLES_H",
        '#include "kernel_lang.h"',
        "",
        "#ifdef __cplusplus",
        "#define BSDF_TABLE(i) bsdf_table_data[i]",
        "#else",
        "#define BSDF_TABLE(i) bsdf_table[i]",
        "#endif",
        "",
        "RTVK_KERNELS_BEGIN",
        "",
        f"const int bsdf_table_size = {N};",
    ]
    for k, o in zip(names, offsets):
        out.append(f"const int bsdf_{k} = {o};  // offset of table {k}")
    out += [f"const int bsdf_table_count = {sum(sizes)};  // floats in all", ""]
    out += ["#ifdef __cplusplus", f"inline constexpr float bsdf_table_data[{sum(sizes)}] = {{"]
    parts = [body(t.ravel()) for t in tables.values()] + [body(t) for t in avgs.values()]
    for i, (k, b) in enumerate(zip(names, parts)):
        out += [f"    // {k}", b + ("," if i + 1 < len(parts) else "")]
    out += ["};", "#endif", ""]
    out += ["RTVK_KERNELS_END", "", "#endif  // RTVK_BSDF_TABLES_H", ""]
    with open("shaders/shared/pbr/bsdf_tables.h", "w") as f:
        f.write("\n".join(out))


if __name__ == "__main__":
    main()
