#pragma once
#include <cstddef>
#include <vector>

#include "disk.h"
#include "quad.h"
#include "sphere.h"
#include "triangle.h"

namespace rtvk {

// The objects of a scene, or of a group, one list per kind of shape. The kinds are numbered in
// this order -- an object's scene index counts the lists before its own -- and hits are tested
// as if in one list in this order, an exact tie going to the later object. A new kind is one
// list here and one call in for_each_kind, after the others (scenes without it keep their
// numbering).
struct shape_lists {
  std::vector<sphere> spheres;            // the first book's
  std::vector<quad> quads;                // the second book's (a box is six)
  std::vector<triangle> triangles;        // given alone, or faces of meshes
  std::vector<triangle_shading> shading;  // triangles' vertex normals and uv (not a kind)
  std::vector<disk> disks;                // docs/geometry.md
};

// Calls f(list) for each kind's list of `lists` (a shape_lists, const or not), in scene-index
// order.
template <class Lists, class F>
void for_each_kind(Lists& lists, F&& f) {
  f(lists.spheres);
  f(lists.quads);
  f(lists.triangles);
  f(lists.disks);
}

// Objects of every kind in the lists.
inline std::size_t shape_count(const shape_lists& l) {
  std::size_t n = 0;
  for_each_kind(l, [&](const auto& list) { n += list.size(); });
  return n;
}

}  // namespace rtvk
