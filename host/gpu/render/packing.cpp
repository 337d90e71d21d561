#include "packing.h"

namespace rtvk::gpu {

static_assert(int(projection::perspective) == RTVK_PROJECTION_PERSPECTIVE);
static_assert(int(projection::orthographic) == RTVK_PROJECTION_ORTHOGRAPHIC);
static_assert(int(projection::equirectangular) == RTVK_PROJECTION_EQUIRECTANGULAR);
static_assert(int(projection::fisheye_equidistant) == RTVK_PROJECTION_FISHEYE_EQUIDISTANT);
static_assert(int(projection::fisheye_equisolid) == RTVK_PROJECTION_FISHEYE_EQUISOLID);

camera_ubo to_ubo(const camera& cam) {
  camera_ubo u{};
  u.origin = vec3(cam.origin());
  u.horizontal = vec3(cam.horizontal());
  u.vertical = vec3(cam.vertical());
  u.lower_left = vec3(cam.lower_left());
  u.lens_u = vec3(cam.lens_u());
  u.lens_v = vec3(cam.lens_v());
  u.lens_radius = float(cam.lens_radius());
  u.projection = uint(cam.projection());
  u.aspect = float(cam.aspect_ratio());
  u.fisheye_fov = float(cam.fisheye_fov());
  u.axis_w = vec3(cam.axis_w());
  u.focus_dist = float(cam.focus_dist());
  u.image_width = uint(cam.image_width());
  u.image_height = uint(cam.image_height());
  return u;
}

std::vector<gpu_sphere> to_gpu_spheres(const scene& s, std::span<const std::uint32_t> order) {
  std::vector<gpu_sphere> out;
  out.reserve(s.spheres.size());
  const auto add = [&](std::uint32_t i) {
    const sphere& sp = s.spheres[i];
    out.push_back({vec3(sp.center), float(sp.radius), uint(sp.material), i, 0, 0});
  };
  if (order.empty())
    for (std::size_t i = 0; i < s.spheres.size(); ++i) add(std::uint32_t(i));
  else
    for (const std::uint32_t i : order) add(i);
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
