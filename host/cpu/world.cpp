#include "world.h"

#include "bvh_world.h"
#include "hittable_sphere.h"

namespace rtvk {

hittable_list make_world(const scene& s) {
  hittable_list world;
  for (const sphere& sp : s.spheres) world.add(std::make_shared<hittable_sphere>(sp));
  return world;
}

std::unique_ptr<hittable> make_accelerated_world(const scene& s, bool use_bvh, int threads) {
  if (use_bvh) return std::make_unique<bvh_world>(s.spheres, threads, s.motion);
  return std::make_unique<hittable_list>(make_world(s));
}

}  // namespace rtvk
