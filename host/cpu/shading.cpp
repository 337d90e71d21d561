#include "shading.h"

#include <cmath>
#include <limits>

namespace rtvk {

scene_shading::scene_shading(const scene& s, bool sample_lights)
    : materials(scene_materials(s)),
      textures(pack_textures(s.textures)),
      perlin(make_perlin(s.noise_seed)) {
  for (std::size_t k = 0; k < s.media.size(); ++k)
    media.push_back(geometry_of(s.media[k], std::uint32_t(k)));
  if (sample_lights) lights = scene_lights(s);
  for (const material& m : materials) pbr.push_back(pbr_record_of(m.pbr));
}

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

// The book's recursion as a loop over the shared steps (ray_color.h); shaders/shading.glsl runs
// the same steps, a bounce per trip. The media are tested after the world, within its hit: the
// nearest of the world's hit and the media's scattering points wins.
color ray_color(const ray& r_in, const hittable& world, const scene_shading& shading,
                const sky& background, int max_depth, const random_stream& rnd) {
  const double infinity = std::numeric_limits<double>::infinity();
  const texture_tables tables = shading.tables();
  const light_table lights = shading.light_list();
  path_state p = start_path(r_in, rnd);
  while (!path_ends_unlit(p, uint(max_depth))) {
    hit_record rec{};
    bool hit = world.hit(p.r, t_min, infinity, rec);
    if (!shading.media.empty()) {
      const random_stream s = at_bounce(p.s, p.depth + 1u);
      for (const medium_geometry& m : shading.media)
        if (hit_medium(m, p.r, t_min, hit ? rec.t : infinity, medium_random(s, m.index), rec))
          hit = true;
    }
    if (!hit) return path_missed(p, background.horizon, background.zenith);
    const material& m = shading.materials[rec.material];
    const bool pbr = m.type == material_type::pbr;
    // Absorbed on the way through a PBR volume, before anything else at its surface.
    if (pbr) p.throughput *= pbr_volume_transmittance(shading.pbr[rec.material], rec, p.r);
    const uint flags = material_flags(m);
    if ((flags & RTVK_MATERIAL_SEE_THROUGH) != 0u &&
        path_passes(p, rec, uint(m.type), flags,
                    surface_alpha(tables, m.opacity, uint(m.texture), rec), m.alpha_cutoff))
      continue;
    if ((flags & RTVK_MATERIAL_EMISSIVE) != 0u)
      path_emits(p, m.emission * emission_color(tables, uint(m.emission_texture), rec));
    const color albedo = material_color(tables, m.albedo, uint(m.texture), rec) * color(rec.color);
    color c;
    if (pbr ? path_hit_pbr(lights, p, rec,
                           pbr_surface_at(tables, shading.pbr[rec.material], albedo, rec),
                           pbr_shading_normal(rec), c)
            : path_hit(lights, p, rec, uint(m.type), flags, albedo, m.fuzz, m.ir, c))
      return c;
  }
  return p.radiance;  // out of bounces, or no ray: the light gathered on the way
}

color ray_color(const ray& r, const hittable& world) {
  static const scene_shading normal_shading = [] {
    scene s;
    s.materials.push_back({"normal", material{}});
    return scene_shading(s);
  }();
  return ray_color(r, world, normal_shading, sky{}, 1, random_stream{});
}

}  // namespace rtvk
