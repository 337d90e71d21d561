#include "packing.h"

namespace rtvk::gpu {

camera_ubo to_ubo(const camera& cam) {
  camera_ubo u{};
  const camera_frame& f = cam.frame();  // get_ray's vectors, each field by its name
  u.origin = vec3(f.origin);
  u.horizontal = vec3(f.horizontal);
  u.vertical = vec3(f.vertical);
  u.lower_left = vec3(f.lower_left);
  u.to_lower_left = vec3(f.to_lower_left);
  u.lens_u = vec3(f.lens_u);
  u.lens_v = vec3(f.lens_v);
  u.axis_w = vec3(f.axis_w);
  u.lens_radius = float(f.lens_radius);
  u.aspect = float(f.aspect);
  u.fisheye_fov = float(f.fisheye_fov);
  u.focus_dist = float(f.focus_dist);
  u.projection = f.projection;
  u.image_width = uint(cam.image_width());
  u.image_height = uint(cam.image_height());
  u.time_open = float(f.time_open);
  u.shutter = float(f.shutter);
  return u;
}

std::vector<gpu_sphere> to_gpu_spheres(const scene& s, std::span<const std::uint32_t> order) {
  std::vector<gpu_sphere> out;
  out.reserve(order.size());
  for (const std::uint32_t i : order) {
    const sphere& sp = s.spheres[i];
    out.push_back({vec3(sp.center), float(sp.radius), uint(sp.material), i, 0, 0});
  }
  return out;
}

std::vector<vec4> to_gpu_velocities(const scene& s, std::span<const std::uint32_t> order) {
  std::vector<vec4> out;
  if (!scene_moves(s)) return out;
  out.reserve(order.size());
  for (const std::uint32_t i : order) out.push_back(vec4(vec3(s.spheres[i].velocity()), 0));
  return out;
}

std::vector<gpu_quad> to_gpu_quads(const scene& s, std::span<const std::uint32_t> order) {
  std::vector<gpu_quad> out;
  out.reserve(order.size());
  const std::uint32_t first = std::uint32_t(s.spheres.size());
  for (const std::uint32_t i : order) {
    const quad& q = s.quads[i];
    const quad_geometry g = q.geometry();
    out.push_back({vec3(g.Q), uint(q.material), vec3(g.u), first + i, vec3(g.v), float(g.D),
                   vec3(g.normal), 0, vec3(g.w), 0});
  }
  return out;
}

std::vector<gpu_triangle> to_gpu_triangles(const scene& s, std::span<const std::uint32_t> order,
                                           std::vector<vec4>& normals) {
  std::vector<gpu_triangle> out;
  out.reserve(order.size());
  normals.clear();
  const std::uint32_t first = std::uint32_t(s.spheres.size() + s.quads.size());
  for (const std::uint32_t i : order) {
    const triangle& t = s.triangles[i];
    uint smooth = RTVK_FLAT;
    if (t.shading >= 0 && s.shading[std::size_t(t.shading)].has_normals()) {
      smooth = uint(normals.size() / 3);
      for (const rtvk::vec3& n : s.shading[std::size_t(t.shading)].normal)
        normals.push_back(vec4(vec3(glm::normalize(n)), 0));
    }
    out.push_back({vec3(t.p[0]), uint(t.material), vec3(t.p[1]), first + i, vec3(t.p[2]), smooth});
  }
  return out;
}

std::vector<gpu_material> to_gpu_materials(const scene& s) {
  std::vector<gpu_material> out;
  out.reserve(s.materials.size());
  for (const auto& [name, m] : s.materials)
    out.push_back({vec3(m.albedo), uint(m.type), float(m.fuzz), float(m.ir), 0, 0});
  return out;
}

}  // namespace rtvk::gpu
