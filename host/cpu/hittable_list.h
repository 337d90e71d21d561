#pragma once
#include <memory>
#include <vector>

#include "hittable.h"

namespace rtvk {

class hittable_list final : public hittable {
 public:
  hittable_list() = default;

  void clear() { objects.clear(); }
  void add(std::shared_ptr<hittable> object) { objects.push_back(std::move(object)); }

  // The closest hit over all objects.
  bool hit(const ray& r, double t_min, double t_max, hit_record& rec) const override;

  std::vector<std::shared_ptr<hittable>> objects;  // every object in the world
};

}  // namespace rtvk
