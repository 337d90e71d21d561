#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "shape_lists.h"
#include "transform.h"

namespace rtvk {

struct scene;

// A group of objects defined once and placed any number of times, each placement an instance
// with a transform of its own (the book's `translate` and `rotate_y` generalised): a tree, a
// chair, a mesh read from one file. Its materials are the scene's.
// Its spheres are still (a group's spheres do not move); its triangles' shading indices refer
// to its own `shading`.
struct object_group : shape_lists {
  std::string name;  // how instances name it in scene files
};

// One placement of a group: where its objects are, without copying them. The renderers keep
// one copy of each group and one BVH over its objects, and trace a ray that reaches an instance
// in the group's own space (docs/geometry.md, "Instances").
struct instance {
  std::uint32_t group = 0;  // index into scene::groups
  transform placement;      // group space -> scene space; may stretch spheres into ellipsoids
};

inline std::size_t object_count(const object_group& g) {
  return shape_count(g);
}

inline bool empty(const object_group& g) {
  return shape_count(g) == 0;
}

// Objects placed by t. Quads and triangles stay exact (a parallelogram maps to a parallelogram);
// a mirroring t swaps a quad's edges and a triangle's last two vertices (normals and uv with
// them), so that the front stays where it was. A sphere stays a sphere only under a rotation
// and one scale: nothing otherwise (an ellipsoid); a disk the same (an ellipse).
std::optional<sphere> placed(const sphere& sp, const transform& t);
quad placed(const quad& q, const transform& t);
triangle placed(const triangle& tri, const transform& t);
triangle_shading placed(const triangle_shading& sh, const transform& t);
std::optional<disk> placed(const disk& d, const transform& t);

// Appends the objects of `g`, placed by `t`, to the scene (each kind after the scene's own).
// Returns why it cannot (a sphere of the group under a non-uniform scale), or nothing.
std::optional<std::string> place_group(scene& s, const object_group& g, const transform& t);

// The scene with every instance replaced by copies of its group's objects, placed (what the
// renderers draw, written out object by object: tests compare the two). Throws
// std::invalid_argument where a copy cannot be made (an ellipsoid).
scene flatten_instances(const scene& s);

}  // namespace rtvk
