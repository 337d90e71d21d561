// A PBR material (RTVK_MATERIAL_PBR) at a hit, for both backends: its parameters with their
// textures applied (pbr_surface, pbr.h's), the frame they are shaded in, the path step that
// samples pbr.h's BSDF (ray_color.h's path_hit for the other kinds), and KHR_materials_volume's
// absorption inside. host/cpu/shading.cpp and shaders/shading.glsl call them.
//
// The parameters a material has beyond the base color are a pbr_record: GLSL reads gpu_pbr[] from
// the buffer the including shader declares (`pbrs`, appearance_buffers.glsl), C++ its own records
// at the compilation's precision, the same fields.
#ifndef RTVK_PBR_SHADING_H
#define RTVK_PBR_SHADING_H
#include "appearance_types.h"
#include "kernel_lang.h"
#include "normal_map.h"
#include "pbr.h"
#include "pdf.h"
#include "random.h"
#include "ray.h"
#include "ray_color.h"
#include "texture.h"

RTVK_KERNELS_BEGIN

#ifdef __cplusplus
// gpu_pbr's fields at the compilation's precision (appearance_types.h has their meanings).
struct pbr_record {
  real3 specular_color{1};
  real metallic = 1;
  real3 sheen_color{0};
  real roughness = 1;
  real3 attenuation_color{1};
  real attenuation_distance = 0;  // scene units; 0 stands for infinity
  real ior = real(1.5);
  real specular = 1;
  real transmission = 0;
  real thickness = 0;
  real clearcoat = 0;
  real clearcoat_roughness = 0;
  real sheen_roughness = 0;
  real normal_scale = 1;
  uint metallic_roughness_texture = RTVK_NO_TEXTURE;
  uint normal_texture = RTVK_NO_TEXTURE;
  uint specular_texture = RTVK_NO_TEXTURE;
  uint specular_color_texture = RTVK_NO_TEXTURE;
  uint transmission_texture = RTVK_NO_TEXTURE;
  uint thickness_texture = RTVK_NO_TEXTURE;
  uint clearcoat_texture = RTVK_NO_TEXTURE;
  uint clearcoat_roughness_texture = RTVK_NO_TEXTURE;
  uint clearcoat_normal_texture = RTVK_NO_TEXTURE;
  uint sheen_color_texture = RTVK_NO_TEXTURE;
  uint sheen_roughness_texture = RTVK_NO_TEXTURE;
  real clearcoat_normal_scale = 1;
};
#else
#define pbr_record gpu_pbr
#endif

// bounce >= 1: the three numbers pbr_sample draws its direction from (its lobe, then the
// direction in it). The mixture with the lights draws dim_mixture and the lights' own (pdf.h).
const uint dim_pbr_lobe = 10u;
const uint dim_pbr_a = 11u;
const uint dim_pbr_b = 12u;

// What a parameter's texture holds at the hit: its RGB and alpha (texture_value and
// texture_alpha, at the first texture coordinates), 1 where the parameter has none, so that the
// factor it multiplies stays as it is. Color textures hold linear values already: an image is
// decoded by its color space when it is loaded (texture.h).
inline precise real4 pbr_map(TABLES_PARAM uint index, hit_record rec) {
  if (index == RTVK_NO_TEXTURE) return real4(1.0);
  return real4(texture_value(TABLES index, rec.uv, rec.p), texture_alpha(TABLES index, rec.uv));
}

// The maps a PBR material reads at a hit (pbr_map's, 1 where it has none), in the order of
// pbr_texels_at's loop.
const int pbr_map_count = 11;
struct pbr_texels {
  real4 metallic_roughness;   // G roughness, B metallic
  real4 specular;             // A
  real4 specular_color;       // RGB
  real4 transmission;         // R
  real4 thickness;            // G
  real4 clearcoat;            // R
  real4 clearcoat_roughness;  // G
  real4 sheen_color;          // RGB
  real4 sheen_roughness;      // A
  real4 normal;               // RGB: the normal map's texel
  real4 clearcoat_normal;     // RGB: the coat's
};

// Map k of the material (pbr_texels_at's order): its texture's index, RTVK_NO_TEXTURE for none.
inline uint pbr_map_index(pbr_record q, int k) {
  switch (k) {
    case 0:
      return q.metallic_roughness_texture;
    case 1:
      return q.specular_texture;
    case 2:
      return q.specular_color_texture;
    case 3:
      return q.transmission_texture;
    case 4:
      return q.thickness_texture;
    case 5:
      return q.clearcoat_texture;
    case 6:
      return q.clearcoat_roughness_texture;
    case 7:
      return q.sheen_color_texture;
    case 8:
      return q.sheen_roughness_texture;
    case 9:
      return q.normal_texture;
    default:
      return q.clearcoat_normal_texture;
  }
}

// Sets map k's texel of t to v.
inline void pbr_set_texel(INOUT(pbr_texels) t, int k, real4 v) {
  switch (k) {
    case 0:
      t.metallic_roughness = v;
      break;
    case 1:
      t.specular = v;
      break;
    case 2:
      t.specular_color = v;
      break;
    case 3:
      t.transmission = v;
      break;
    case 4:
      t.thickness = v;
      break;
    case 5:
      t.clearcoat = v;
      break;
    case 6:
      t.clearcoat_roughness = v;
      break;
    case 7:
      t.sheen_color = v;
      break;
    case 8:
      t.sheen_roughness = v;
      break;
    case 9:
      t.normal = v;
      break;
    default:
      t.clearcoat_normal = v;
      break;
  }
}

// Every map of the material at the hit, read in one loop: the texture code (its Perlin noise
// included) is then compiled once into the render shader rather than once per parameter. No local
// array is indexed by the loop's counter: lavapipe then unrolls the loop whole (to make the index
// constant), eleven copies of the texture code that took it 4 to 10 minutes to compile; through
// the two switches, 20 seconds. A loop of pbr_map_count trips (the caller counts them against the
// GPU's loop budget).
inline pbr_texels pbr_texels_at(TABLES_PARAM pbr_record q, hit_record rec) {
  pbr_texels t;
  for (int k = 0; k < pbr_map_count; ++k)
    pbr_set_texel(t, k, pbr_map(TABLES pbr_map_index(q, k), rec));
  return t;
}

// The texels of a material without maps (pbr_map's 1 for each): where no material has a texture,
// the GPU reads these and compiles no texture code.
inline pbr_texels pbr_no_texels() {
  pbr_texels t;
  for (int k = 0; k < pbr_map_count; ++k) pbr_set_texel(t, k, real4(1.0));
  return t;
}

// The material's parameters at the hit from its maps there, t (glTF's channels: metallic_roughness
// G roughness and B metallic, specular A, specular_color RGB, transmission R, thickness G,
// clearcoat R, clearcoat_roughness G, sheen_color RGB, sheen_roughness A; each times its factor),
// with base_color its color there (material_color times the vertex colors, as for every kind). The
// ray sees ior entering (front_face) and 1 / ior leaving; a thickness of 0 is thin-walled.
inline pbr_surface pbr_surface_from(pbr_record q, real3 base_color, hit_record rec, pbr_texels t) {
  // Every product precise (ShaderPrecision): the GPU rounds them as the CPU does.
  precise real metallic = q.metallic * t.metallic_roughness.z;
  precise real roughness = q.roughness * t.metallic_roughness.y;
  precise pbr_surface m = pbr_surface_of(base_color, metallic, roughness);
  m.eta = rec.front_face ? q.ior : real(1.0) / q.ior;
  m.specular = q.specular * t.specular.w;
  m.specular_color = q.specular_color * real3(t.specular_color);
  m.transmission = q.transmission * t.transmission.x;
  m.thin = q.thickness * t.thickness.y == real(0.0);
  m.clearcoat = q.clearcoat * t.clearcoat.x;
  m.clearcoat_roughness = q.clearcoat_roughness * t.clearcoat_roughness.y;
  m.sheen_color = q.sheen_color * real3(t.sheen_color);
  m.sheen_roughness = q.sheen_roughness * t.sheen_roughness.w;
  return m;
}

// The same from the material's record alone: its maps read here.
inline pbr_surface pbr_surface_at(TABLES_PARAM pbr_record q, real3 base_color, hit_record rec) {
  return pbr_surface_from(q, base_color, rec, pbr_texels_at(TABLES q, rec));
}

// The normal the material is shaded about at the hit (the frame's z), facing the side the ray
// came from: the hit's own, or where the material has a normal map, the map's normal there (its
// texel t.normal) kept visible from wo, the unit direction back toward the viewer (normal_map.h).
inline precise real3 pbr_shading_normal(pbr_record q, hit_record rec, pbr_texels t, real3 wo) {
  if (q.normal_texture == RTVK_NO_TEXTURE) return rec.normal;
  return normal_mapped(rec, real3(t.normal), q.normal_scale, wo);
}

// The clearcoat's normal (scene space): its own map's where it has one, else the hit's own normal
// (glTF: without clearcoatNormalTexture the coat is not normal-mapped, even where the base is).
inline precise real3 pbr_coat_normal(pbr_record q, hit_record rec, pbr_texels t, real3 wo) {
  if (q.clearcoat_normal_texture == RTVK_NO_TEXTURE) return rec.normal;
  return normal_mapped(rec, real3(t.clearcoat_normal), q.clearcoat_normal_scale, wo);
}

// KHR_materials_volume's absorption (Beer-Lambert) along a ray that reached the surface from
// inside (rec.front_face false) a material with a volume (thickness > 0) that attenuates
// (attenuation_distance finite, not 0 in gpu_pbr): attenuation_color^(d / attenuation_distance)
// over the distance d the ray ran inside, rec.t times its direction's length; else 1. The inside
// is what the surface closes (a closed mesh); volumes do not nest: a ray is inside one at most.
inline precise real3 pbr_volume_transmittance(pbr_record q, hit_record rec, ray r) {
  if (rec.front_face || !(q.thickness > real(0.0)) || !(q.attenuation_distance > real(0.0)))
    return real3(1.0);
  precise real x = rec.t * length3(r.direction) / q.attenuation_distance;
  precise real3 c = real3(q.attenuation_color);
  return real3(pow(c.x, x), pow(c.y, x), pow(c.z, x));
}

// The direction wi (a unit vector in the frame b) in world space, and back.
inline precise real3 to_frame(onb b, real3 d) {
  return real3(dot3(d, b.u), dot3(d, b.v), dot3(d, b.w));
}

// p.r hit `rec` on a PBR material whose parameters there are `m`, shaded about the unit normal
// n (pbr_shading_normal), its coat about coat_n (pbr_coat_normal, scene space): scatters the path
// for the next trip (false), or ends it (true, its color in `c`: the light it gathered). Without
// lights it follows pbr_sample (throughput times its weight). With lights (LIGHT_COUNT > 0), half
// the time toward the lights (pdf.h) and half by pbr_sample, as the third book mixes: a non-delta
// direction is weighted by pbr_eval over the mixture's density, half the BSDF's plus half the
// lights'; a delta direction (a smooth lobe, which the lights' half never draws) by pbr_sample's
// weight over 1/2, the chance of the BSDF's half (the lights' half leaves it out: pbr_eval has no
// delta lobe). A direction on the wrong side of the surface for its lobe (a reflection below the
// hit's normal, a transmission above it) ends the path black: the no-leak rule.
inline bool path_hit_pbr(LIGHTS_PARAM precise INOUT(path_state) p, hit_record rec, pbr_surface m,
                         real3 n, real3 coat_n, precise OUT(real3) c) {
  c = p.radiance;
  onb b = onb_from_w(n);
  precise real3 wo = to_frame(b, -unit_vector(p.r.direction));
  if (m.clearcoat > real(0.0)) m.clearcoat_normal = unit_vector(to_frame(b, coat_n));
  if (!(wo.z > real(0.0))) return true;
  pbr_lobes l = pbr_lobes_of(m, wo);
  random_stream s = at_bounce(p.s, p.depth + 1u);
  precise real3 direction;
  precise real3 wi;
  precise real3 weight;
  bool delta = false;
  bool toward_lights = LIGHT_COUNT > 0u && real(rnd(s, dim_mixture)) < real(0.5);
  // The lights' densities are measured from where the book's mixture measures them.
  precise real3 origin = rec.p + rec.offset * rec.normal;
  uint own = LIGHT_COUNT;
  precise real own_pdf = real(0.0);
  if (toward_lights) {
    direction = light_list_random(LIGHTS origin, p.r.time, s, own, own_pdf);
    wi = to_frame(b, unit_vector(direction));
  } else {
    precise real3 u =
        real3(real(rnd(s, dim_pbr_lobe)), real(rnd(s, dim_pbr_a)), real(rnd(s, dim_pbr_b)));
    precise real delta_pdf;
    if (!pbr_draw_direction(m, l, wo, u, wi, weight, delta_pdf, delta)) return true;
    direction = onb_local(b, wi);
  }
  // One evaluation and one density for both halves (each compiled once: see pbr_draw_direction).
  if (delta) {
    if (LIGHT_COUNT > 0u) weight = real(2.0) * weight;
  } else {
    precise real mixture = pbr_pdf_lobes(m, l, wo, wi);
    if (LIGHT_COUNT > 0u)
      mixture = real(0.5) * mixture +
                real(0.5) * light_list_pdf(LIGHTS origin, direction, p.r.time, own, own_pdf);
    if (!(mixture > real(0.0))) return true;
    weight = pbr_eval_lobes(m, l, wo, wi) / mixture;
  }
  // The no-leak rule, against the surface's own normal (rec.normal).
  precise real facing = dot3(direction, rec.normal);
  if (wi.z > real(0.0) ? !(facing > real(0.0)) : !(facing < real(0.0))) return true;
  precise real total = weight.x + weight.y + weight.z;
  if (!(total > real(0.0))) return true;  // absorbed (or not a number)
  p.r = ray(scatter_origin(rec, direction), direction, p.r.time);
  p.throughput *= weight;
  ++p.depth;
  return false;
}

RTVK_KERNELS_END

#endif  // RTVK_PBR_SHADING_H
