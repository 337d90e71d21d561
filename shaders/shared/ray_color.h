// ray_color, the book's path loop, taken one bounce at a time so that both backends run it: the
// CPU walks one path to its end (host/cpu/shading.cpp), the GPU interleaves a pixel's samples
// path after path (shaders/shading.glsl). Each backend searches its world for the hit in
// between; everything else is here.
#ifndef RTVK_RAY_COLOR_H
#define RTVK_RAY_COLOR_H
#include "appearance_types.h"
#include "kernel_lang.h"
#include "pdf.h"
#include "random.h"
#include "ray.h"
#include "scatter.h"

RTVK_KERNELS_BEGIN

// Hits closer than this are ignored: a scattered ray must not hit its own starting point again
// through rounding ("shadow acne").
const real t_min = real(0.001);

// The sky seen along direction d: `horizon` at the horizon blending to `zenith` overhead (the
// book's white to blue by default). Equal colors are a constant background (the second book's),
// exactly that color: the blend could round it by an ulp.
inline precise real3 sky_color(real3 d, real3 horizon, real3 zenith) {
  if (horizon == zenith) return horizon;
  precise real3 unit_direction = unit_vector(d);
  precise real t = real(0.5) * (unit_direction.y + real(1.0));
  return (real(1.0) - t) * horizon + t * zenith;
}

// ray_color's loop variables: a path in flight.
struct path_state {
  ray r;                     // the ray about to be traced
  precise real3 throughput;  // product of the attenuations so far
  precise real3 radiance;    // light gathered so far from emissive surfaces along the path
  uint depth;                // bounces so far
  uint max_depth;            // the rays it may trace (the render's bounce limit)
  uint passes;               // surfaces passed through so far (path_passes)
  random_stream s;           // the path's random numbers (pixel, sample)
  // Next-event estimation's (lights/nee.h; unused in the other modes):
  precise real mis_pdf;           // the BSDF's density for p.r's direction at the vertex it left,
                                  // per steradian; 0 where no light sample could have drawn it
  precise real3 mis_origin;       // that vertex (p.r's origin moves past see-through surfaces)
  precise real3 mis_at;           // where that vertex drew its light sample (the light tree's
                                  // point: a hair from mis_origin)
  precise real3 mis_normal;       // its normal there (zero in a medium)
  ray shadow;                     // the shadow ray of the last light sample, when shadow_reach > 0
  precise real shadow_reach;      // how far it must go unblocked; 0: no shadow ray pending
  precise real3 shadow_radiance;  // what the path gathers when nothing blocks it
  uint shadow_passes;             // see-through surfaces the shadow ray passed so far
};

inline path_state start_path(ray r, random_stream s, uint max_depth) {
  path_state p;
  p.r = r;
  p.throughput = real3(1.0);
  p.radiance = real3(0.0);
  p.depth = 0u;
  p.max_depth = max_depth;
  p.passes = 0u;
  p.s = s;
  p.mis_pdf = real(0.0);
  p.mis_origin = r.origin;
  p.mis_at = r.origin;
  p.mis_normal = real3(0.0);
  p.shadow = r;
  p.shadow_reach = real(0.0);
  p.shadow_radiance = real3(0.0);
  p.shadow_passes = 0u;
  return p;
}

// The path's random number for a blend at the surface it hit now: a dimension of its own at the
// bounce about to be made, the surfaces passed before telling each draw apart.
inline precise real alpha_random(path_state p) {
  return real(rnd(at_bounce(p.s, (p.depth + 1u) | (p.passes << 16u)), dim_alpha));
}

// p.r hit `rec` on a surface with these flags and this alpha (surface_alpha): true, with p.r
// continued from just beyond the surface in the same direction, when the hit does not count.
// No bounce is counted; past max_passes every surface counts.
inline bool path_passes(precise INOUT(path_state) p, hit_record rec, uint type, uint flags,
                        real alpha, real cutoff) {
  if (p.passes >= max_passes) return false;
  real u = (flags & RTVK_MATERIAL_ALPHA_BLEND) != 0u ? alpha_random(p) : real(0.0);
  if (surface_counts(type, flags, rec.front_face, alpha, cutoff, u)) return false;
  p.r.origin = scatter_origin(rec, p.r.direction);
  ++p.passes;
  return true;
}

// A hit on an emissive surface (RTVK_MATERIAL_EMISSIVE) adds what it emits there, seen through
// the path's attenuations; the material then scatters as usual (glTF's emissive surfaces reflect).
inline void path_emits(precise INOUT(path_state) p, real3 emitted) {
  p.radiance += p.throughput * emitted;
}

// Before tracing p.r: true when the path ends without it (with the light it gathered so far), out
// of bounces or without a ray (a camera gives a zero direction where its model sees nothing).
inline bool path_ends_unlit(path_state p, uint max_depth) {
  return p.depth >= max_depth || p.r.direction == real3(0.0);
}

// p.r escaped: the color the path gathers from the sky.
inline precise real3 path_missed(path_state p, real3 horizon, real3 zenith) {
  return p.radiance + p.throughput * sky_color(p.r.direction, horizon, zenith);
}

// p.r escaped where the scene has an environment map (lights/environment.h): whether it sees the
// map (else the sky, path_missed). Every ray does but a camera ray -- one that has not bounced yet,
// whether or not it passed through see-through surfaces on its way -- where the map is not
// `visible` (the product shot's option: the map lights the scene, the sky is the backdrop).
inline bool path_sees_environment(path_state p, bool visible) {
  return visible || p.depth > 0u;
}

// p.r escaped into an environment map that shows `seen` along it (environment_radiance): the
// color the path gathers.
inline precise real3 path_missed_into(path_state p, real3 seen) {
  return p.radiance + p.throughput * seen;
}

// p.r hit `rec`, whose material is of `type` with these parameters (scatter's; albedo is the
// material's color at the hit, its texture's value there when it has one; flags
// RTVK_MATERIAL_*). Either ends the path, its color in `c` (the lesson's normal shading; a flat
// material's albedo, unlit; a lamp's emitted color; black when absorbed; each after the light the
// path gathered from emissive surfaces on its way, p.radiance), or scatters it for the
// next trip (false). With lights to sample (LIGHT_COUNT > 0), lambertian and isotropic scatter
// by the mixture of their density and the lights' (pdf.h); without, as the first two books do.
inline bool path_hit(LIGHTS_PARAM precise INOUT(path_state) p, hit_record rec, uint type,
                     uint flags, real3 albedo, real fuzz, real ir, precise OUT(real3) c) {
  // The light emitted along the way comes first: 0 + x is x exactly, so a path that met no
  // emissive surface ends with the same bits as before emission existed.
  c = p.radiance;
  if (type == RTVK_MATERIAL_NORMAL) {
    c = p.radiance + p.throughput * (real(0.5) * (rec.normal + real3(1.0, 1.0, 1.0)));
    return true;
  }
  // The book's diffuse_light emits on both sides and reflects nothing: its emitted color, seen
  // through the path's attenuations, is all the path gathers (exactly the color, seen directly).
  // The third book's lamps emit from their front only: seen from behind, black.
  if (type == RTVK_MATERIAL_FLAT || type == RTVK_MATERIAL_DIFFUSE_LIGHT) {
    bool dark = (flags & RTVK_MATERIAL_ONE_SIDED) != 0u && !rec.front_face;
    c = dark ? p.radiance : p.radiance + p.throughput * albedo;
    return true;
  }
  // The scattered ray goes straight into p.r (scatter takes the incoming ray by value): no copy
  // through a local, which on the CPU stalled on store forwarding once rays carried a time.
  precise real3 attenuation;
  random_stream s = at_bounce(p.s, p.depth + 1u);
  bool mixed =
      LIGHT_COUNT > 0u && (type == RTVK_MATERIAL_LAMBERTIAN || type == RTVK_MATERIAL_ISOTROPIC);
  if (mixed ? !scatter_mixture(LIGHTS type, albedo, p.r, rec, s, attenuation, p.r)
            : !scatter(type, albedo, fuzz, ir, p.r, rec, s, attenuation, p.r))
    return true;
  p.throughput *= attenuation;
  ++p.depth;
  return false;
}

RTVK_KERNELS_END

#endif  // RTVK_RAY_COLOR_H
