#include "packing.h"

namespace rtvk::gpu {

camera_ubo to_ubo(const camera& cam) {
  camera_ubo u{};
  u.origin = vec3(cam.origin());
  u.horizontal = vec3(cam.horizontal());
  u.vertical = vec3(cam.vertical());
  u.lower_left = vec3(cam.lower_left());
  u.image_width = uint(cam.image_width());
  u.image_height = uint(cam.image_height());
  return u;
}

std::vector<gpu_sphere> to_gpu_spheres(const scene& s) {
  std::vector<gpu_sphere> out;
  out.reserve(s.spheres.size());
  for (const sphere& sp : s.spheres) out.push_back({vec3(sp.center), float(sp.radius)});
  return out;
}

}  // namespace rtvk::gpu
