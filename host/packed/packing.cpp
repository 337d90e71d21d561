#include "packing.h"
#include "punctual.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace rtvk::gpu {

camera_ubo to_ubo(const camera& cam) {
  camera_ubo u{};
  const camera_frame& f = cam.frame();  // get_ray's vectors: camera_ubo's fields, by their names
#define RTVK_PACK_CAMERA_FIELD(type, name) u.name = type(f.name);
  RTVK_CAMERA_FIELDS(RTVK_PACK_CAMERA_FIELD)
#undef RTVK_PACK_CAMERA_FIELD
  return u;
}

namespace {

// The lists a slot refers to: the scene's own, or its group's.
const shape_lists& list_of(const scene& s, object_slot o) {
  return o.group == world_objects ? static_cast<const shape_lists&>(s) : s.groups[o.group];
}

// Appends `extras` (three items a triangle) after every triangle's own entry in `buffer` (three
// items each) and returns the first one's entry there; throws where the last one's is not below
// 2^bits (what a float's w can hold exactly).
template <class T>
std::size_t append_triples(std::vector<T>& buffer, const std::vector<T>& extras, int bits,
                           const std::string& what) {
  const std::size_t first = buffer.size() / 3;
  if (first + extras.size() / 3 > (std::size_t(1) << bits))
    throw std::runtime_error("more than 2^" + std::to_string(bits) + " shaded triangles with " +
                             what);
  buffer.insert(buffer.end(), extras.begin(), extras.end());
  return first;
}

}  // namespace

std::vector<gpu_sphere> to_gpu_spheres(const scene& s, std::span<const object_slot> slots) {
  std::vector<gpu_sphere> out;
  out.reserve(slots.size());
  for (const object_slot o : slots) {
    const sphere& sp = list_of(s, o).spheres[o.index];
    out.push_back({vec3(sp.center), float(sp.radius), uint(sp.material), o.index, 0, 0});
  }
  return out;
}

std::vector<vec4> to_gpu_velocities(const scene& s, std::span<const object_slot> slots) {
  std::vector<vec4> out;
  if (!scene_moves(s)) return out;
  out.reserve(slots.size());
  for (const object_slot o : slots)
    out.push_back(o.group == world_objects ? vec4(vec3(s.spheres[o.index].velocity()), 0)
                                           : vec4(0));
  return out;
}

std::vector<gpu_quad> to_gpu_quads(const scene& s, std::span<const object_slot> slots) {
  std::vector<gpu_quad> out;
  out.reserve(slots.size());
  for (const object_slot o : slots) {
    const shape_lists& l = list_of(s, o);
    const quad& q = l.quads[o.index];
    const quad_geometry g = q.geometry();
    out.push_back({vec3(g.Q), uint(q.material), vec3(g.u), uint(l.spheres.size()) + o.index,
                   vec3(g.v), float(g.D), vec3(g.normal), 0, vec3(g.w), 0});
  }
  return out;
}

std::vector<gpu_triangle> to_gpu_triangles(const scene& s, std::span<const object_slot> slots,
                                           std::vector<vec4>& normals, std::vector<glm::vec2>& uvs,
                                           std::vector<vec4>& tangents) {
  std::vector<gpu_triangle> out;
  out.reserve(slots.size());
  normals.clear();
  uvs.clear();
  tangents.clear();
  std::vector<vec4> colors;          // vertex colors, three each, stored after all the normals
  std::vector<std::size_t> colored;  // the normals' entries whose colors those are, in order
  std::vector<glm::vec2> seconds;    // second texture coordinates, three each, after all the uvs
  std::vector<std::size_t> mapped;   // the entries whose second sets those are, in order
  for (const object_slot o : slots) {
    const shape_lists& l = list_of(s, o);
    const triangle& t = l.triangles[o.index];
    uint smooth = RTVK_FLAT;
    if (t.shading >= 0) {
      const triangle_attributes a = attributes_of(l.shading[std::size_t(t.shading)]);
      smooth = uint(normals.size() / 3);
      for (std::size_t k = 0; k < 3; ++k) {
        // w flags (geometry_types.h, gpu_triangle::normals): blended on the first, uv on the
        // second (its bit 0; the entries are set below).
        const float flag = k == 0 ? float(a.smooth) : k == 1 ? float(a.has_uv) : 0.0f;
        normals.push_back(vec4(vec3(a.smooth ? a.normal[k] : rtvk::vec3(0)), flag));
        uvs.push_back(glm::vec2(a.uv[k]));
      }
      if (a.has_tangent) {
        // The first normal's w, above its bit 0: the tangents' entry + 1 (exact below 2^23).
        if (tangents.size() / 3 + 1 >= (std::size_t(1) << 23))
          throw std::runtime_error("more than 2^23 shaded triangles with tangents");
        normals[3 * smooth].w += float(2 * (tangents.size() / 3 + 1));
        for (std::size_t k = 0; k < 3; ++k) tangents.push_back(vec4(a.tangent[k]));
      }
      if (a.has_color) {
        colored.push_back(smooth);
        for (std::size_t k = 0; k < 3; ++k) colors.push_back(vec4(a.color[k]));
      }
      if (a.has_uv1) {
        mapped.push_back(smooth);
        for (std::size_t k = 0; k < 3; ++k) seconds.push_back(glm::vec2(a.uv1[k]));
      }
    }
    const uint first = uint(l.spheres.size() + l.quads.size());
    out.push_back(
        {vec3(t.p[0]), uint(t.material), vec3(t.p[1]), first + o.index, vec3(t.p[2]), smooth});
  }
  // The third normal's w: the colors' entry (3 * w; 0 for none, entry 0 being some triangle's
  // normals). The second normal's w: bit 0 the uv flag, the bits above it the second set's entry
  // in the uvs (3 * (w >> 1); 0 for none). Both exact in a float below 2^24.
  const std::size_t color_entry = append_triples(normals, colors, 24, "vertex colors");
  for (std::size_t k = 0; k < colored.size(); ++k)
    normals[3 * colored[k] + 2].w = float(color_entry + k);
  const std::size_t second_entry = append_triples(uvs, seconds, 23, "a second texture set");
  for (std::size_t k = 0; k < mapped.size(); ++k)
    normals[3 * mapped[k] + 1].w += float(2 * (second_entry + k));
  return out;
}

std::vector<gpu_disk> to_gpu_disks(const scene& s, std::span<const object_slot> slots) {
  std::vector<gpu_disk> out;
  out.reserve(slots.size());
  for (const object_slot o : slots) {
    const shape_lists& l = list_of(s, o);
    const disk& d = l.disks[o.index];
    const disk_geometry g = d.geometry();
    const uint first = uint(l.spheres.size() + l.quads.size() + l.triangles.size());
    out.push_back({vec3(g.center), float(g.radius), vec3(g.normal), uint(d.material), vec3(g.u),
                   first + o.index, vec3(g.v), float(g.D)});
  }
  return out;
}

std::vector<gpu_instance> to_gpu_instances(const scene& s, std::span<const group_span> groups) {
  std::vector<gpu_instance> out;
  out.reserve(s.instances.size());
  for (const instance& i : s.instances) {
    const instance_frame f = frame_of(i.placement);
    const group_span& g = groups[i.group];
    gpu_instance in{};
    const auto row = [](const rtvk::vec3& v, double w) { return vec4(vec3(v), float(w)); };
    in.to_group_x = row(f.to_group_x, f.to_group_offset.x);
    in.to_group_y = row(f.to_group_y, f.to_group_offset.y);
    in.to_group_z = row(f.to_group_z, f.to_group_offset.z);
    in.normal_x = row(f.normal_x, f.stretch);
    in.normal_y = row(f.normal_y, 0);
    in.normal_z = row(f.normal_z, 0);
    in.root = g.root;
    in.sphere_first = g.first[0];
    in.sphere_count = g.count[0];
    in.quad_first = g.first[1];
    in.quad_count = g.count[1];
    in.triangle_first = g.first[2];
    in.triangle_count = g.count[2];
    in.disk_first = g.first[shape_disk];
    in.disk_count = g.count[shape_disk];
    out.push_back(in);
  }
  return out;
}

namespace {

uint texture_of(int t) {
  return t < 0 ? RTVK_NO_TEXTURE : uint(t);
}

}  // namespace

std::vector<gpu_material> to_gpu_materials(const scene& s) {
  std::vector<gpu_material> out;
  out.reserve(s.materials.size());
  uint pbr = 0;  // the next PBR material's gpu_pbr index
  for (const auto& [name, m] : s.materials)
    out.push_back({vec3(m.albedo), uint(m.type), float(m.fuzz), float(m.ir), texture_of(m.texture),
                   material_flags(m), vec3(m.emission), texture_of(m.emission_texture),
                   float(m.opacity), float(m.alpha_cutoff),
                   m.type == material_type::pbr ? pbr++ : 0u, 0});
  return out;
}

gpu_pbr to_gpu_pbr(const pbr_material& q) {
  gpu_pbr g{};
  g.specular_color = vec3(q.specular_color);
  g.metallic = float(q.metallic);
  g.sheen_color = vec3(q.sheen_color);
  g.roughness = float(q.roughness);
  g.attenuation_color = vec3(q.attenuation_color);
  // gpu_pbr's 0 stands for infinity: float would keep it, but a shader may not see it (a driver
  // may assume no float is infinite).
  g.attenuation_distance =
      std::isfinite(q.attenuation_distance) ? float(q.attenuation_distance) : 0;
  g.ior = float(q.ior);
  g.specular = float(q.specular);
  g.transmission = float(q.transmission);
  g.thickness = float(q.thickness);
  g.clearcoat = float(q.clearcoat);
  g.clearcoat_roughness = float(q.clearcoat_roughness);
  g.sheen_roughness = float(q.sheen_roughness);
  g.normal_scale = float(q.normal_scale);
  g.metallic_roughness_texture = texture_of(q.metallic_roughness_texture);
  g.normal_texture = texture_of(q.normal_texture);
  g.specular_texture = texture_of(q.specular_texture);
  g.specular_color_texture = texture_of(q.specular_color_texture);
  g.transmission_texture = texture_of(q.transmission_texture);
  g.thickness_texture = texture_of(q.thickness_texture);
  g.clearcoat_texture = texture_of(q.clearcoat_texture);
  g.clearcoat_roughness_texture = texture_of(q.clearcoat_roughness_texture);
  g.clearcoat_normal_texture = texture_of(q.clearcoat_normal_texture);
  g.sheen_color_texture = texture_of(q.sheen_color_texture);
  g.sheen_roughness_texture = texture_of(q.sheen_roughness_texture);
  g.clearcoat_normal_scale = float(q.clearcoat_normal_scale);
  return g;
}

std::vector<gpu_pbr> to_gpu_pbrs(const scene& s) {
  std::vector<gpu_pbr> out;
  for (const auto& [name, m] : s.materials)
    if (m.type == material_type::pbr) out.push_back(to_gpu_pbr(m.pbr));
  return out;
}

gpu_punctual to_gpu_punctual(const punctual_record& r, std::uint32_t count) {
  gpu_punctual g{};
  g.position = vec3(r.position);
  g.kind = r.kind;
  g.direction = vec3(r.direction);
  g.angle_scale = float(r.angle_scale);
  g.intensity = vec3(r.intensity);
  g.angle_offset = float(r.angle_offset);
  g.cone_gap = float(r.cone_gap);
  g.count = count;
  return g;
}

std::vector<gpu_punctual> to_gpu_punctuals(const scene& s) {
  const auto count = std::uint32_t(s.punctual_lights.size());
  std::vector<gpu_punctual> out;
  for (const punctual_record& r : punctual_records(s.punctual_lights))
    out.push_back(to_gpu_punctual(r, count));
  if (out.empty()) out.push_back(gpu_punctual{});  // count 0
  return out;
}

std::vector<gpu_texture> to_gpu_textures(const scene& s, std::vector<std::uint32_t>& texels) {
  packed_textures packed = pack_textures(s.textures);
  std::vector<gpu_texture> out;
  for (const texture_record& r : packed.records)
    out.push_back(
        {vec3(r.even), r.type, vec3(r.odd), float(r.scale), r.first, r.width, r.height, r.style});
  texels = std::move(packed.texels);
  return out;
}

gpu_perlin to_gpu_perlin(const perlin_tables& p) {
  gpu_perlin out{};
  for (std::size_t i = 0; i < p.vectors.size(); ++i) out.vectors[i] = vec4(vec3(p.vectors[i]), 0);
  for (std::size_t i = 0; i < p.perm.size(); ++i) out.perm[i] = p.perm[i];
  return out;
}

std::vector<gpu_medium> to_gpu_media(const scene& s) {
  std::vector<gpu_medium> out;
  for (std::size_t k = 0; k < s.media.size(); ++k) {
    const medium_geometry g = geometry_of(s.media[k], uint(k));
    out.push_back({vec4(vec3(g.to_local_x), float(g.to_local_offset.x)),
                   vec4(vec3(g.to_local_y), float(g.to_local_offset.y)),
                   vec4(vec3(g.to_local_z), float(g.to_local_offset.z)), vec3(g.lo), g.shape,
                   vec3(g.hi), float(g.neg_inv_density), g.material, g.index, 0, 0});
  }
  return out;
}

std::vector<gpu_light> to_gpu_lights(const std::vector<light_record>& lights) {
  std::vector<gpu_light> out;
  for (const light_record& l : lights)
    out.push_back({vec3(l.a), l.kind, vec3(l.u), float(l.radius), vec3(l.v), float(l.area),
                   vec3(l.normal), l.flags, vec3(l.emission), float(l.pmf), float(l.alias_q),
                   l.alias, 0, 0});
  return out;
}

}  // namespace rtvk::gpu
