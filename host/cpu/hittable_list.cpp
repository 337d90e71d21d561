#include "hittable_list.h"

namespace rtvk {

bool hittable_list::hit(const ray& r, double t_min, double t_max, hit_record& rec) const {
  hit_record temp{};
  bool hit_anything = false;
  double closest_so_far = t_max;
  for (const auto& object : objects) {
    // Shrinking t_max to the closest hit so far makes each later hit a closer one.
    if (object->hit(r, t_min, closest_so_far, temp)) {
      hit_anything = true;
      closest_so_far = temp.t;
      rec = temp;
    }
  }
  return hit_anything;
}

}  // namespace rtvk
