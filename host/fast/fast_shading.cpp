// ray_color in float over the GPU's arrays: the steps are the shared kernels' (ray_color.h,
// nee.h, pbr_shading.h), in the order shaders/shading.glsl and host/cpu/shading.cpp take them;
// a shadow ray is traced to its end before the path goes on, as the CPU reference does.
#include "fast_shading.h"

#include <algorithm>
#include <limits>

namespace rtvk::fast {
namespace {

light_record record_of(const gpu::gpu_light& g) {
  light_record r;
  r.a = g.a, r.kind = g.kind, r.u = g.u, r.radius = g.radius, r.v = g.v, r.area = g.area;
  r.normal = g.normal, r.flags = g.flags, r.emission = g.emission;
  r.pmf = g.pmf, r.alias_q = g.alias_q, r.alias = g.alias;
  return r;
}

texture_record record_of(const gpu::gpu_texture& g) {
  texture_record r;
  r.even = g.even, r.type = g.type, r.odd = g.odd, r.scale = g.scale, r.first = g.first;
  r.width = g.width, r.height = g.height, r.style = g.style;
  return r;
}

medium_geometry record_of(const gpu::gpu_medium& g) {  // shading.glsl's medium_at
  medium_geometry m;
  m.to_local_x = real3(g.to_local_x), m.to_local_y = real3(g.to_local_y);
  m.to_local_z = real3(g.to_local_z);
  m.to_local_offset = real3(g.to_local_x.w, g.to_local_y.w, g.to_local_z.w);
  m.shape = g.shape, m.lo = g.lo, m.hi = g.hi, m.neg_inv_density = g.neg_inv_density;
  m.material = g.material, m.index = g.index;
  return m;
}

// pbr_record in float is gpu_pbr field for field.
pbr_record record_of(const gpu::gpu_pbr& g) {
  static_assert(sizeof(pbr_record) == sizeof(gpu::gpu_pbr));
  pbr_record r;
  std::memcpy(static_cast<void*>(&r), &g, sizeof r);
  return r;
}

punctual_record record_of(const gpu::gpu_punctual& g) {
  return {g.position, g.kind, g.direction, g.angle_scale, g.intensity, g.angle_offset, g.cone_gap};
}

template <typename R, typename G>
std::vector<R> records_of(const std::vector<G>& v, std::size_t n) {
  std::vector<R> out;
  out.reserve(n);
  for (std::size_t k = 0; k < n; ++k) out.push_back(record_of(v[k]));
  return out;
}

// Whether a medium scatters p's shadow ray before t_end.
bool shadow_scattered(const shading_tables& t, const path_state& p, real t_end) {
  const random_stream s = shadow_stream(p);
  hit_record rec{};
  for (const medium_geometry& m : t.media)
    if (hit_medium(m, p.shadow, t_min, t_end, medium_random(s, m.index, dim_shadow_medium), rec))
      return true;
  return false;
}

// Traces p's pending shadow ray to its end (host/cpu/nee_step.cpp's trace_shadow); where every
// hit blocks, the first one Embree finds decides it.
void trace_shadow(const world& w, const shading_tables& t, path_state& p, std::uint64_t& rays) {
  if (t.opaque_shadows) {
    ++rays;
    if (w.blocked(p.shadow, t_min, p.shadow_reach))
      shadow_blocked(p);
    else
      shadow_unblocked(p);
    return;
  }
  while (p.shadow_reach > 0) {
    hit_record rec{};
    ++rays;  // each search counts, as the reference's counting_world counts them
    const bool hit = w.hit(p.shadow, t_min, p.shadow_reach, rec);
    if (shadow_scattered(t, p, hit ? rec.t : p.shadow_reach)) {
      shadow_blocked(p);
      return;
    }
    if (!hit) {
      shadow_unblocked(p);
      return;
    }
    const gpu::gpu_material& m = t.arrays.materials[rec.material];
    const real alpha = (m.flags & RTVK_MATERIAL_SEE_THROUGH) != 0u
                           ? surface_alpha(t.texture_list, m.opacity, m.texture, rec)
                           : real(1);
    shadow_meets(p, rec, m.type, m.flags, alpha, m.alpha_cutoff);
  }
}

// p.r escaped: the sky, the environment map, or under next-event estimation what the lights'
// densities weigh.
real3 missed(const shading_tables& t, const path_state& p) {
  if (t.nee)
    return path_missed_nee(t.light_list, t.punctual_list, t.environment, p, t.horizon, t.zenith);
  if (t.environment.texels != nullptr &&
      path_sees_environment(p, environment_visible(t.environment)))
    return path_missed_into(p, environment_radiance(t.environment, p.r.direction));
  return path_missed(p, t.horizon, t.zenith);
}

// One bounce at a hit: true when the path ended, its color in c.
bool bounce(const shading_tables& t, path_state& p, const hit_record& rec, real3& c) {
  const gpu::gpu_material& m = t.arrays.materials[rec.material];
  const texture_tables& tables = t.texture_list;
  const bool pbr = m.type == RTVK_MATERIAL_PBR;
  c = p.radiance;
  if (pbr) p.throughput *= pbr_volume_transmittance(t.pbr[m.pbr], rec, p.r);
  if ((m.flags & RTVK_MATERIAL_SEE_THROUGH) != 0u &&
      path_passes(p, rec, m.type, m.flags, surface_alpha(tables, m.opacity, m.texture, rec),
                  m.alpha_cutoff))
    return false;
  if ((m.flags & RTVK_MATERIAL_EMISSIVE) != 0u)
    path_emits(p, real3(m.emission) * emission_color(tables, m.emission_texture, rec));
  const real3 albedo = material_color(tables, m.albedo, m.texture, rec) * real3(rec.color);
  if (pbr) {
    const pbr_record& q = t.pbr[m.pbr];
    const real3 wo = -unit_vector(p.r.direction);
    const pbr_texels x = pbr_texels_at(tables, q, rec);
    const pbr_surface surface = pbr_surface_from(q, albedo, rec, x);
    const real3 n = pbr_shading_normal(q, rec, x, wo), coat_n = pbr_coat_normal(q, rec, x, wo);
    if (t.nee)
      return path_hit_pbr_nee(t.light_list, t.punctual_list, t.environment, p, rec, surface, n,
                              coat_n, c);
    return path_hit_pbr(t.light_list, p, rec, surface, n, coat_n, c);
  }
  if (t.nee)
    return path_hit_nee(t.light_list, t.punctual_list, t.environment, p, rec, m.type, m.flags,
                        albedo, m.fuzz, m.ir, c);
  return path_hit(t.light_list, p, rec, m.type, m.flags, albedo, m.fuzz, m.ir, c);
}

}  // namespace

shading_tables::shading_tables(const gpu::scene_arrays& a, const fast_settings& s)
    : arrays(a), nee(s.nee), horizon(s.horizon), zenith(s.zenith) {
  // The lights the mixture aims at are scene_lights (the groups' lamps, appended, are next-event
  // estimation's only); next-event estimation draws the lamps, which lead the array.
  const std::size_t groups = a.group_lamps;
  const std::size_t aimed = a.lights.size() - groups;
  const std::size_t lamps =
      std::size_t(std::count_if(a.lights.begin(), a.lights.end(), [](const gpu::gpu_light& l) {
        return (l.flags & RTVK_LIGHT_EMITS) != 0u;
      }));
  const std::size_t n = s.nee ? lamps : s.sample_lights ? aimed : 0;
  lights = records_of<light_record>(a.lights, n);
  light_list = {lights.data(), uint(n),
                s.nee && !a.light_nodes.empty() ? a.light_nodes.data() : nullptr};
  const std::size_t punctuals = a.punctual.empty() ? 0 : a.punctual[0].count;
  punctual = records_of<punctual_record>(a.punctual, punctuals);
  punctual_list = {punctual.data(), uint(punctuals)};
  if (!a.environment_table.empty())
    environment = {a.environment_texels.data(), a.environment_table.data()};
  textures = records_of<texture_record>(a.textures, a.textures.size());
  for (const glm::vec4& v : a.perlin[0].vectors) perlin_vectors.push_back(real3(v));
  texture_list = {textures.data(), a.texels.data(), perlin_vectors.data(), a.perlin[0].perm};
  media = records_of<medium_geometry>(a.media, a.media.size());
  pbr = records_of<pbr_record>(a.pbr, a.pbr.size());
  opaque_shadows =
      a.media.empty() &&
      std::none_of(a.materials.begin(), a.materials.end(), [](const gpu::gpu_material& m) {
        return (m.flags & RTVK_MATERIAL_SEE_THROUGH) != 0u;
      });
}

real3 ray_color(const ray& r_in, const world& w, const shading_tables& t, uint max_depth,
                const random_stream& rnd, std::uint64_t& rays) {
  const real infinity = std::numeric_limits<real>::max();  // the GPU's max_float
  path_state p = start_path(r_in, rnd, max_depth);
  while (!path_ends_unlit(p, max_depth)) {
    hit_record rec{};
    ++rays;
    bool hit = w.hit(p.r, t_min, infinity, rec);
    if (!t.media.empty()) {  // the media within the world's hit
      const random_stream s = at_bounce(p.s, p.depth + 1u);
      for (const medium_geometry& m : t.media)
        if (hit_medium(m, p.r, t_min, hit ? rec.t : infinity, medium_random(s, m.index, dim_medium),
                       rec))
          hit = true;
    }
    if (!hit) return missed(t, p);
    real3 c;
    if (bounce(t, p, rec, c)) return c;
    if (t.nee && p.shadow_reach > 0) trace_shadow(w, t, p, rays);
  }
  return p.radiance;  // out of bounces, or ended after its last shadow ray
}

}  // namespace rtvk::fast
