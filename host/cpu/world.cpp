#include "world.h"

#include "bvh_world.h"
#include "hittable_disk.h"
#include "hittable_instance.h"
#include "hittable_quad.h"
#include "hittable_sphere.h"
#include "hittable_triangle.h"

namespace rtvk {

namespace {

// Objects of one list (the scene's, or a group's), in order: spheres, quads, triangles, disks.
void add_objects(hittable_list& to, const shape_lists& l) {
  const auto& [spheres, quads, triangles, shading, disks] = l;
  for (const sphere& sp : spheres) to.add(std::make_shared<hittable_sphere>(sp));
  for (const quad& q : quads) to.add(std::make_shared<hittable_quad>(q));
  for (const triangle& t : triangles)
    to.add(std::make_shared<hittable_triangle>(
        t, t.shading >= 0 ? &shading[std::size_t(t.shading)] : nullptr));
  for (const disk& d : disks) to.add(std::make_shared<hittable_disk>(d));
}

}  // namespace

hittable_list make_world(const scene& s) {
  hittable_list world;
  add_objects(world, s);
  std::vector<std::shared_ptr<const hittable>> groups;
  for (const object_group& g : s.groups) {
    auto list = std::make_shared<hittable_list>();
    add_objects(*list, g);
    groups.push_back(std::move(list));
  }
  for (const instance& i : s.instances)
    world.add(std::make_shared<hittable_instance>(groups[i.group], i.placement));
  return world;
}

std::unique_ptr<hittable> make_accelerated_world(const scene& s, bool use_bvh, int threads) {
  if (use_bvh) return std::make_unique<bvh_world>(s, threads);
  return std::make_unique<hittable_list>(make_world(s));
}

}  // namespace rtvk
