// Punctual lights (KHR_lights_punctual's point, spot and directional lights, and a sun: a
// directional light with an angular diameter), seen from a shading point: one light_sample each.
// Units and the conversion to rtvk's radiance are docs/lighting.md's ("Punctual lights"): the
// Khronos sample viewer's, intensity * color / d^2 for a point or spot light (candela),
// intensity * color for a directional one (lux), no 683 lm/W.
//
// The lights are the backend's table: GLSL reads `punctuals[]`, which the including shader
// declares at RTVK_BINDING_PUNCTUAL (shaders/punctual_buffers.glsl), C++ a punctual_table passed
// along. The functions that read the table take PUNCTUAL_PARAM first and pass PUNCTUALS on.
#ifndef RTVK_PUNCTUAL_H
#define RTVK_PUNCTUAL_H
#include "kernel_lang.h"
#include "light_sample.h"
#include "lights_types.h"
#include "random.h"
#include "ray.h"

RTVK_KERNELS_BEGIN

#ifdef __cplusplus
// gpu_punctual's fields at the compilation's precision (lights_types.h has their meanings).
struct punctual_record {
  real3 position;
  uint kind = RTVK_PUNCTUAL_POINT;
  real3 direction;
  real angle_scale = 0;
  real3 intensity;
  real angle_offset = 0;
  real cone_gap = 0;
};
// The punctual lights a render sees (host/scene/light_sources.h makes them).
struct punctual_table {
  const punctual_record* lights = nullptr;  // by index
  uint count = 0;
};
#define PUNCTUAL_PARAM const punctual_table &punctual_in,
#define PUNCTUAL_PARAM_ONLY const punctual_table& punctual_in
#define PUNCTUALS punctual_in,
#define PUNCTUALS_ONLY punctual_in
#define PUNCTUAL_AT(k) punctual_in.lights[k]
#define PUNCTUAL_COUNT punctual_in.count
#else
#define punctual_record gpu_punctual
#define PUNCTUAL_PARAM
#define PUNCTUAL_PARAM_ONLY
#define PUNCTUALS
#define PUNCTUALS_ONLY
#define PUNCTUAL_AT(k) punctuals[k]
#define PUNCTUAL_COUNT punctuals[0].count
#endif

inline uint punctual_count(PUNCTUAL_PARAM_ONLY) {
  return PUNCTUAL_COUNT;
}

// KHR_lights_punctual's smooth falloff between the cones (its README's reference code): 1 inside
// the inner cone, 0 outside the outer, between them the square of a linear ramp in the cosine.
// `cd` is the cosine between the spot's direction and the way from it to the point.
inline precise real spot_attenuation(punctual_record l, real cd) {
  precise real a = min(max(cd * l.angle_scale + l.angle_offset, real(0.0)), real(1.0));
  return a * a;
}

// sin^2 of a sun's angular radius, from its cone gap g = 1 - cos: (1 - cos)(1 + cos), without the
// cancellation of 1 - cos^2 for a small sun.
inline precise real sun_sin2(real gap) {
  return gap * (real(2.0) - gap);
}

// A sun's radiance: uniform over its disk, E / (pi sin^2 theta_max), so that a surface facing
// it receives the irradiance E (its lux) whatever its size.
inline precise real3 sun_disk_radiance(punctual_record l) {
  return l.intensity / (pi * sun_sin2(l.cone_gap));
}

// Whether `direction` (any length) lies in sun l's disk, by the cross product as sphere_light_pdf
// tests a cone (|d x w|^2 <= sin^2 |d|^2 with d . w > 0), which keeps a small sun's edge in
// float where cos >= 1 - gap would round it away.
inline bool in_sun(punctual_record l, real3 direction) {
  precise real3 w = -l.direction;
  if (dot3(direction, w) <= real(0.0)) return false;
  precise real3 across = cross3(direction, w);
  precise real reach = sun_sin2(l.cone_gap) * dot3(direction, direction);
  return dot3(across, across) <= reach;
}

// A direction uniform in the cone of half-angle theta_max about the unit w: cos theta uniform in
// [cos theta_max, 1], i.e. 1 - u.x * gap.
inline precise real3 sun_cone_direction(real3 w, real gap, real2 u) {
  precise real g = u.x * gap;  // 1 - cos theta
  precise real sin_theta = sqrt(max(real(0.0), g * (real(2.0) - g)));
  precise real2 phi = turn_cos_sin(u.y);
  precise real3 a = abs(w.x) > real(0.9) ? real3(0.0, 1.0, 0.0) : real3(1.0, 0.0, 0.0);
  precise real3 v = unit_vector(cross3(w, a));
  precise real3 t = cross3(w, v);
  return (sin_theta * phi.x) * t + (sin_theta * phi.y) * v + (real(1.0) - g) * w;
}

// Light k seen from p, drawn with u in [0, 1)^2 (only a sun uses it). A point or spot light:
// wi toward it, the irradiance normal to wi, I / d^2 (times the spot's falloff), delta. A
// directional light: -direction and E, delta. A sun: a direction uniform in its disk's cone,
// its radiance and the cone's density 1 / (2 pi (1 - cos theta_max)).
inline light_sample punctual_sample(PUNCTUAL_PARAM uint k, real3 p, real2 u) {
  punctual_record l = PUNCTUAL_AT(k);
  light_sample s = no_light_sample();
  if (l.kind == RTVK_PUNCTUAL_DIRECTIONAL) {
    s.distance = light_at_infinity;
    if (l.cone_gap > real(0.0)) {
      s.wi = sun_cone_direction(-l.direction, l.cone_gap, u);
      s.radiance = sun_disk_radiance(l);
      s.pdf = real(0.5) / (pi * l.cone_gap);
      return s;
    }
    s.wi = -l.direction;
    s.radiance = l.intensity;
    s.pdf = real(1.0);
    s.delta = true;
    return s;
  }
  precise real3 to = l.position - p;
  precise real d2 = dot3(to, to);
  if (!(d2 > real(0.0))) return s;  // at the light itself: no direction
  precise real d = sqrt(d2);
  s.wi = divide(to, d);
  s.distance = d;
  s.radiance = l.intensity / d2;
  if (l.kind == RTVK_PUNCTUAL_SPOT)
    s.radiance = s.radiance * spot_attenuation(l, -dot3(l.direction, s.wi));
  s.pdf = real(1.0);
  s.delta = true;
  return s;
}

// What a ray escaping along `direction` sees of the suns: each disk it points into adds its
// radiance (0 outside every disk; delta directional lights are never seen).
inline precise real3 sun_radiance(PUNCTUAL_PARAM real3 direction) {
  precise real3 sum = real3(0.0);
  uint n = PUNCTUAL_COUNT;
  for (uint k = 0u; k < n; ++k) {
    punctual_record l = PUNCTUAL_AT(k);
    if (l.kind == RTVK_PUNCTUAL_DIRECTIONAL && l.cone_gap > real(0.0) && in_sun(l, direction))
      sum = sum + sun_disk_radiance(l);
  }
  return sum;
}

// Sun k's solid-angle density of `direction` as punctual_sample draws it: 1 / the cone's solid
// angle inside its disk, else 0 (0 for every light that is not a sun).
inline precise real sun_pdf(PUNCTUAL_PARAM uint k, real3 direction) {
  punctual_record l = PUNCTUAL_AT(k);
  if (l.kind != RTVK_PUNCTUAL_DIRECTIONAL || !(l.cone_gap > real(0.0))) return real(0.0);
  if (!in_sun(l, direction)) return real(0.0);
  return real(0.5) / (pi * l.cone_gap);
}

RTVK_KERNELS_END

#endif  // RTVK_PUNCTUAL_H
