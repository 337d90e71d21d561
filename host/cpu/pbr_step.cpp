// The CPU's steps at a hit on a PBR material (pbr_shading.h's kernels), in a translation unit of
// their own: in shading.cpp their calls into the shared kernels (the lights' densities, the onb)
// would change what GCC inlines into ray_color's loop for the books' materials, which measured
// 4% slower on the Cornell box with them there.
#include <cmath>

#include "nee_pbr.h"
#include "shading.h"

namespace rtvk {

pbr_record pbr_record_of(const pbr_material& q) {
  const auto tex = [](int t) { return t < 0 ? RTVK_NO_TEXTURE : uint(t); };
  pbr_record r;
  r.specular_color = q.specular_color;
  r.metallic = q.metallic;
  r.sheen_color = q.sheen_color;
  r.roughness = q.roughness;
  r.attenuation_color = q.attenuation_color;
  r.attenuation_distance = std::isfinite(q.attenuation_distance) ? q.attenuation_distance : 0;
  r.ior = q.ior;
  r.specular = q.specular;
  r.transmission = q.transmission;
  r.thickness = q.thickness;
  r.clearcoat = q.clearcoat;
  r.clearcoat_roughness = q.clearcoat_roughness;
  r.sheen_roughness = q.sheen_roughness;
  r.normal_scale = q.normal_scale;
  r.metallic_roughness_texture = tex(q.metallic_roughness_texture);
  r.normal_texture = tex(q.normal_texture);
  r.specular_texture = tex(q.specular_texture);
  r.specular_color_texture = tex(q.specular_color_texture);
  r.transmission_texture = tex(q.transmission_texture);
  r.thickness_texture = tex(q.thickness_texture);
  r.clearcoat_texture = tex(q.clearcoat_texture);
  r.clearcoat_roughness_texture = tex(q.clearcoat_roughness_texture);
  r.clearcoat_normal_texture = tex(q.clearcoat_normal_texture);
  r.sheen_color_texture = tex(q.sheen_color_texture);
  r.sheen_roughness_texture = tex(q.sheen_roughness_texture);
  r.clearcoat_normal_scale = q.clearcoat_normal_scale;
  return r;
}

// One trip of ray_color's loop at a hit on a PBR material: the absorption of its volume first, then
// the generic steps (alpha, emission) as the loop takes them, then the PBR bounce. True: the path
// ended, its color in `c`.
bool pbr_step(const scene_shading& shading, const texture_tables& tables, const light_table& lights,
              path_state& p, const hit_record& rec, color& c, const nee_tables* nee) {
  const material& m = shading.materials[rec.material];
  const pbr_record& q = shading.pbr[rec.material];
  c = p.radiance;
  p.throughput *= pbr_volume_transmittance(q, rec, p.r);
  const uint flags = material_flags(m);
  if ((flags & RTVK_MATERIAL_SEE_THROUGH) != 0u &&
      path_passes(p, rec, uint(m.type), flags,
                  surface_alpha(tables, m.opacity, uint(m.texture), rec), m.alpha_cutoff))
    return false;
  if ((flags & RTVK_MATERIAL_EMISSIVE) != 0u)
    path_emits(p, m.emission * emission_color(tables, uint(m.emission_texture), rec));
  const color base = material_color(tables, m.albedo, uint(m.texture), rec) * color(rec.color);
  const vec3 wo = -unit_vector(p.r.direction);
  const pbr_texels t = pbr_texels_at(tables, q, rec);
  const pbr_surface surface = pbr_surface_from(q, base, rec, t);
  const vec3 n = pbr_shading_normal(q, rec, t, wo), coat_n = pbr_coat_normal(q, rec, t, wo);
  if (nee)
    return path_hit_pbr_nee(lights, nee->punctual, nee->environment, p, rec, surface, n, coat_n, c);
  return path_hit_pbr(lights, p, rec, surface, n, coat_n, c);
}

}  // namespace rtvk
