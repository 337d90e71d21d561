// Textures: the color a material has at a hit, from the hit's point p and its texture
// coordinates (u, v). The second book's checker_texture, image_texture and noise_texture (with its
// perlin class), written once for both backends.
//
// The tables they read (the textures, the images' texels, the noise's lattice) are the
// backend's: GLSL reads the storage buffers the including shader declares (`textures`, `texels`,
// `perlin`: scene_buffers.glsl), C++ a texture_tables passed along. The functions that read
// them take TABLES_PARAM first and pass TABLES on, which is empty in GLSL.
#ifndef RTVK_TEXTURE_H
#define RTVK_TEXTURE_H
#include "appearance_types.h"
#include "kernel_lang.h"
#include "ray.h"

RTVK_KERNELS_BEGIN

#ifdef __cplusplus
// gpu_texture's fields at the compilation's precision.
struct texture_record {
  real3 even;       // checker: even cells' color; noise: the color noise 1 has
  uint type = 0;    // RTVK_TEXTURE_*
  real3 odd;        // checker: odd cells' color
  real scale = 1;   // checker: a cell's size, scene units; noise: frequency, per scene unit
  uint first = 0;   // image: first texel
  uint width = 0;   // image: texels across
  uint height = 0;  // image: rows
  uint style = 0;   // noise: RTVK_NOISE_*
};
// Where the texture kernels find their tables on the host (scene_textures owns them).
struct texture_tables {
  const texture_record* textures = nullptr;  // by material's texture index
  const uint* texels = nullptr;              // RGBA8, a byte per channel, red lowest
  const real3* perlin_vectors = nullptr;     // RTVK_PERLIN_POINTS random unit vectors
  const uint* perlin_perm = nullptr;         // three permutations of RTVK_PERLIN_POINTS
};
#define TABLES_PARAM const texture_tables &tables,
#define TABLES tables,
#define TEXTURE_AT(i) tables.textures[i]
#define TEXEL_AT(i) tables.texels[i]
#define PERLIN_VECTOR_AT(i) tables.perlin_vectors[i]
#define PERLIN_PERM_AT(i) tables.perlin_perm[i]
#else
#define TABLES_PARAM
#define TABLES
#define TEXTURE_AT(i) textures[i]
#define TEXEL_AT(i) texels[i]
#define PERLIN_VECTOR_AT(i) perlin.vectors[i].xyz
#define PERLIN_PERM_AT(i) perlin.perm[i]
#endif

// x's whole part modulo 256, as a lattice index (no integer overflow however large x is).
inline uint lattice_index(real x) {
  precise real f = floor(x);
  precise real m = f - real(256.0) * floor(f / real(256.0));
  return uint(max(real(0.0), min(real(255.0), m)));
}

// The book's checker_texture: which of two colors the cell of size `scale` around p has (cells
// whose integer coordinates sum to an even number are `even`).
inline precise real3 checker_value(real scale, real3 even, real3 odd, real3 p) {
  precise real inv = real(1.0) / scale;
  precise real cells = floor(inv * p.x) + floor(inv * p.y) + floor(inv * p.z);
  return cells - real(2.0) * floor(real(0.5) * cells) == real(0.0) ? even : odd;
}

// One lattice corner's term of perlin_noise: corner (di, dj, dk) of the cell at (i, j, k), whose
// point p is at f within it, with Hermite weights w.
inline precise real perlin_corner(TABLES_PARAM uint i, uint j, uint k, uint di, uint dj, uint dk,
                                  real3 f, real3 w) {
  uint hash = PERLIN_PERM_AT((i + di) & 255u) ^ PERLIN_PERM_AT(256u + ((j + dj) & 255u)) ^
              PERLIN_PERM_AT(512u + ((k + dk) & 255u));
  precise real3 corner = real3(real(di), real(dj), real(dk));
  precise real3 weight = corner * w + (real3(1.0) - corner) * (real3(1.0) - w);
  return weight.x * weight.y * weight.z * dot3(PERLIN_VECTOR_AT(hash), f - corner);
}

// The book's perlin::noise: random vectors at the lattice points around p, blended with Hermite
// weights; in about [-1, 1]. Written out corner by corner and octave by octave below: lavapipe
// counts every loop trip against its per-invocation limit.
inline precise real perlin_noise(TABLES_PARAM real3 p) {
  precise real3 f = p - floor(p);
  uint i = lattice_index(p.x), j = lattice_index(p.y), k = lattice_index(p.z);
  precise real3 w = f * f * (real(3.0) - real(2.0) * f);
  precise real x0 = (perlin_corner(TABLES i, j, k, 0u, 0u, 0u, f, w) +
                     perlin_corner(TABLES i, j, k, 0u, 0u, 1u, f, w)) +
                    (perlin_corner(TABLES i, j, k, 0u, 1u, 0u, f, w) +
                     perlin_corner(TABLES i, j, k, 0u, 1u, 1u, f, w));
  precise real x1 = (perlin_corner(TABLES i, j, k, 1u, 0u, 0u, f, w) +
                     perlin_corner(TABLES i, j, k, 1u, 0u, 1u, f, w)) +
                    (perlin_corner(TABLES i, j, k, 1u, 1u, 0u, f, w) +
                     perlin_corner(TABLES i, j, k, 1u, 1u, 1u, f, w));
  return x0 + x1;
}

// The book's perlin::turb: |sum of seven octaves|, each twice the frequency and half the weight
// of the one before (the scalings are exact).
inline precise real perlin_turbulence(TABLES_PARAM real3 p) {
  precise real accum = perlin_noise(TABLES p);
  accum += real(0.5) * perlin_noise(TABLES real(2.0) * p);
  accum += real(0.25) * perlin_noise(TABLES real(4.0) * p);
  accum += real(0.125) * perlin_noise(TABLES real(8.0) * p);
  accum += real(0.0625) * perlin_noise(TABLES real(16.0) * p);
  accum += real(0.03125) * perlin_noise(TABLES real(32.0) * p);
  accum += real(0.015625) * perlin_noise(TABLES real(64.0) * p);
  return abs(accum);
}

// The book's noise_texture at p: a gray level in [0, 1] (about) times `tint`. The turbulence and
// marble styles share one perlin_turbulence, at the point each takes: the shader compilers inline
// every call, and each is 56 lattice corners written out, which lavapipe compiles for tens of
// seconds (per call site of texture_value).
inline precise real3 noise_value(TABLES_PARAM real scale, uint style, real3 tint, real3 p) {
  precise real level;
  if (style == RTVK_NOISE_SMOOTH) {
    level = real(0.5) * (real(1.0) + perlin_noise(TABLES scale * p));
  } else {
    bool turbulence = style == RTVK_NOISE_TURBULENCE;
    precise real3 q = turbulence ? scale * p : p;
    precise real t = perlin_turbulence(TABLES q);
    level = turbulence ? t : real(0.5) * (real(1.0) + sin(scale * p.z + real(10.0) * t));
  }
  return level * tint;
}

// A texture coordinate brought into [0, 1] by an image's wrap mode (RTVK_WRAP_*); not a finite
// number: 0.
inline precise real wrap_coordinate(real x, uint mode) {
  if (!is_finite(x)) return real(0.0);
  if (mode == RTVK_WRAP_REPEAT) return x - floor(x);
  if (mode == RTVK_WRAP_MIRROR) {
    precise real m = x - real(2.0) * floor(real(0.5) * x);  // in [0, 2)
    return m > real(1.0) ? real(2.0) - m : m;
  }
  return max(real(0.0), min(real(1.0), x));
}

// The book's image_texture: the nearest texel to (u, v), v = 1 the image's top row, coordinates
// outside [0, 1] wrapped by `wrap` (RTVK_WRAP_* of u, and of v shifted left by 2; the book
// clamps). Texels hold linear values, a byte a channel (/ 255).
inline precise real3 image_value(TABLES_PARAM uint first, uint width, uint height, uint wrap,
                                 real2 uv) {
  precise real u = wrap_coordinate(uv.x, wrap & 3u);
  precise real v = real(1.0) - wrap_coordinate(uv.y, (wrap >> 2u) & 3u);
  precise real x = u * real(width);
  precise real y = v * real(height);
  uint i = min(uint(x), width - 1u);
  uint j = min(uint(y), height - 1u);
  uint texel = TEXEL_AT(first + j * width + i);
  return real3(real(texel & 255u), real((texel >> 8u) & 255u), real((texel >> 16u) & 255u)) *
         real(1.0 / 255.0);
}

// The color of texture `index` at a hit at p with texture coordinates uv.
inline precise real3 texture_value(TABLES_PARAM uint index, real2 uv, real3 p) {
  uint type = TEXTURE_AT(index).type;
  if (type == RTVK_TEXTURE_CHECKER)
    return checker_value(real(TEXTURE_AT(index).scale), real3(TEXTURE_AT(index).even),
                         real3(TEXTURE_AT(index).odd), p);
  if (type == RTVK_TEXTURE_IMAGE)
    return image_value(TABLES TEXTURE_AT(index).first, TEXTURE_AT(index).width,
                       TEXTURE_AT(index).height, TEXTURE_AT(index).style, uv) *
           real3(TEXTURE_AT(index).even);
  return noise_value(TABLES real(TEXTURE_AT(index).scale), TEXTURE_AT(index).style,
                     real3(TEXTURE_AT(index).even), p);
}

// A material's color at a hit: its albedo, or its texture's value there.
inline precise real3 material_color(TABLES_PARAM real3 albedo, uint texture, hit_record rec) {
  if (texture == RTVK_NO_TEXTURE) return albedo;
  return texture_value(TABLES texture, rec.uv, rec.p);
}

// What a material's emission is multiplied by at a hit: its emission texture's value at the hit's
// second texture coordinates (uv1: the first where the object has no second set), else 1.
inline precise real3 emission_color(TABLES_PARAM uint texture, hit_record rec) {
  if (texture == RTVK_NO_TEXTURE) return real3(1.0);
  return texture_value(TABLES texture, rec.uv1, rec.p);
}

// The alpha texture `index` has at uv: an image's texel's top byte / 255 (its alpha), else 1.
inline precise real texture_alpha(TABLES_PARAM uint index, real2 uv) {
  if (index == RTVK_NO_TEXTURE || TEXTURE_AT(index).type != RTVK_TEXTURE_IMAGE) return real(1.0);
  precise real u = wrap_coordinate(uv.x, TEXTURE_AT(index).style & 3u);
  precise real v = real(1.0) - wrap_coordinate(uv.y, (TEXTURE_AT(index).style >> 2u) & 3u);
  uint width = TEXTURE_AT(index).width, height = TEXTURE_AT(index).height;
  precise real x = u * real(width);  // as image_value finds the texel
  precise real y = v * real(height);
  uint i = min(uint(x), width - 1u);
  uint j = min(uint(y), height - 1u);
  return real(TEXEL_AT(TEXTURE_AT(index).first + j * width + i) >> 24u) * real(1.0 / 255.0);
}

// A surface's alpha at a hit (0 transparent to 1 opaque): its material's opacity, times its
// color texture's alpha there (an image's), times the hit's vertex alpha.
inline precise real surface_alpha(TABLES_PARAM real opacity, uint texture, hit_record rec) {
  return opacity * texture_alpha(TABLES texture, rec.uv) * rec.color.w;
}

RTVK_KERNELS_END

#endif  // RTVK_TEXTURE_H
