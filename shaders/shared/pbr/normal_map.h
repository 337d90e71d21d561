// Tangent-space normal maps (glTF's normalTexture), for both backends: the shading normal a map's
// texel gives at a hit, in the hit's tangent frame (hit_record::tangent), kept from leaking light:
// the viewer's direction stays above the plane the normal shades (docs/materials.md, "Normal
// maps").
#ifndef RTVK_NORMAL_MAP_H
#define RTVK_NORMAL_MAP_H
#include "kernel_lang.h"
#include "ray.h"

RTVK_KERNELS_BEGIN

// The least cosine between the viewer's direction and a mapped normal: wo stays this far above
// the shading normal's tangent plane (about 0.57 degrees), so wo.z > 0 in the shading frame.
const real normal_map_margin = real(0.01);

// The unit vector at `cosine` from the unit d in the plane of d and m (unit, perpendicular to
// the unit n), between m and n: cos(phi) m + sin(phi) n, where a = dot(d, m), b = dot(d, n) and
// phi is the elevation from m toward n at which the cosine with d rises to `cosine` (the
// rising crossing, past the elevation of d when `past`). No trigonometry: phi = delta -+ alpha
// for delta the elevation of d's projection, cos(alpha) = cosine / |projection|.
inline precise real3 at_cosine(real3 m, real3 n, real a, real b, real cosine, bool past) {
  precise real r2 = a * a + b * b;
  precise real s = sqrt(max(r2 - cosine * cosine, real(0.0)));
  precise real c = past ? a * cosine - b * s : a * cosine + b * s;
  precise real e = past ? b * cosine + a * s : b * cosine - a * s;
  return unit_vector((c / r2) * m + (e / r2) * n);
}

// The no-leak rule: n (unit) as it is where the viewer's direction wo sees it at a cosine of at
// least normal_map_margin; else n rotated toward the interpolated normal N (in their plane) until
// the cosine is the margin; and where even N falls short (wo grazes the surface), N tilted
// toward wo until it is. The result never leans further from N than n does, nor than it must.
inline precise real3 keep_visible(real3 n, real3 N, real3 wo, real3 T) {
  if (dot3(wo, n) >= normal_map_margin) return n;
  precise real b = dot3(wo, N);
  if (b >= normal_map_margin) {
    precise real3 along = n - dot3(n, N) * N;  // n's lean, in the tangent plane
    precise real len = length3(along);
    precise real3 m = len > real(0.0) ? divide(along, len) : T;
    return at_cosine(m, N, dot3(wo, m), b, normal_map_margin, false);
  }
  precise real3 toward = wo - b * N;  // wo's lean
  precise real len = length3(toward);
  precise real3 m = len > real(0.0) ? divide(toward, len) : T;
  return at_cosine(m, N, dot3(wo, m), b, normal_map_margin, true);
}

// The unit shading normal at the hit rec for a normal map's texel (its linear RGB in [0, 1]),
// glTF's normalTexture.scale `scale` (scaling the map's x and y) and wo, the unit direction back
// toward the viewer (scene space): the map's normal (2 texel - 1, x and y scaled) in the hit's
// frame T, B = cross(N, T) * w, N = rec.normal, then kept visible from wo. A flat texel (0.5,
// 0.5, 1) gives N exactly; a hit without tangents, rec.normal unchanged.
inline precise real3 normal_mapped(hit_record rec, real3 texel, real scale, real3 wo) {
  if (rec.tangent.w == real(0.0)) return rec.normal;
  precise real3 N = rec.normal;
  precise real3 T = real3(rec.tangent.x, rec.tangent.y, rec.tangent.z);
  precise real3 B = rec.tangent.w * cross3(N, T);
  precise real3 c = real(2.0) * texel - real3(1.0);
  precise real x = c.x * scale;
  precise real y = c.y * scale;
  if (x == real(0.0) && y == real(0.0) && c.z > real(0.0)) return keep_visible(N, N, wo, T);
  precise real3 n = x * T + y * B + c.z * N;
  precise real len = length3(n);
  if (!(len > real(0.0) && is_finite(len))) return keep_visible(N, N, wo, T);
  return keep_visible(divide(n, len), N, wo, T);
}

RTVK_KERNELS_END

#endif  // RTVK_NORMAL_MAP_H
