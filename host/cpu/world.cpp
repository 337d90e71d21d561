#include "world.h"

#include "bvh_world.h"
#include "hittable_quad.h"
#include "hittable_sphere.h"
#include "hittable_triangle.h"

namespace rtvk {

hittable_list make_world(const scene& s) {
  hittable_list world;
  for (const sphere& sp : s.spheres) world.add(std::make_shared<hittable_sphere>(sp));
  for (const quad& q : s.quads) world.add(std::make_shared<hittable_quad>(q));
  for (const triangle& t : s.triangles) {
    const bool smooth = t.shading >= 0 && s.shading[std::size_t(t.shading)].has_normals();
    world.add(std::make_shared<hittable_triangle>(
        t, smooth ? &s.shading[std::size_t(t.shading)].normal : nullptr));
  }
  return world;
}

std::unique_ptr<hittable> make_accelerated_world(const scene& s, bool use_bvh, int threads) {
  if (use_bvh)
    return std::make_unique<bvh_world>(primitive_spans{s.spheres, s.quads, s.triangles}, s.shading,
                                       threads, s.motion);
  return std::make_unique<hittable_list>(make_world(s));
}

}  // namespace rtvk
