#pragma once
#include <cstdint>
#include <vector>

#include "scene.h"

namespace rtvk {

// The ids of --aov object-id: 1, 2, ... one per object as the scene names it -- a sphere, a
// quad, a box (its six quads), a triangle, a mesh file (all its triangles), an instance (all of
// its group) -- in the order the renderers scan them: spheres, quads, triangles, disks, then the
// instances. 0: nothing was hit.
class object_ids {
 public:
  explicit object_ids(const scene& s);

  // The id of the object a search found: `object` its place in the scan order (the scene index
  // of the scene's own; its place in the group for an instance's), `instance` the instance + 1
  // it was reached through (0: the scene's own). 0 for keys the scene does not have.
  std::uint32_t of(std::uint32_t object, std::uint32_t instance) const;

  std::uint32_t count() const { return count_; }  // ids in use, 1..count

 private:
  std::vector<std::uint32_t> own_;    // id by scene index of the scene's own objects
  std::uint32_t first_instance_ = 0;  // the id of instance 0
  std::uint32_t instances_ = 0;       // how many
  std::uint32_t count_ = 0;
};

}  // namespace rtvk
