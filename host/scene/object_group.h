#pragma once
#include <optional>
#include <string>
#include <vector>

#include "quad.h"
#include "sphere.h"
#include "transform.h"
#include "triangle.h"

namespace rtvk {

struct scene;

// A group of objects defined once and placed any number of times, each placement an instance
// with a transform of its own (the book's `translate` and `rotate_y` generalised): a tree, a
// chair, a mesh read from one file. Its materials are the scene's.
struct object_group {
  std::vector<sphere> spheres;
  std::vector<quad> quads;
  std::vector<triangle> triangles;        // shading indices refer to `shading`
  std::vector<triangle_shading> shading;  // the triangles' vertex normals and uv
};

inline bool empty(const object_group& g) {
  return g.spheres.empty() && g.quads.empty() && g.triangles.empty();
}

// Objects placed by t. Quads and triangles stay exact (a parallelogram maps to a parallelogram);
// a mirroring t swaps a quad's edges and a triangle's last two vertices (normals and uv with
// them), so that the front stays where it was. A sphere stays a sphere only under a rotation
// and one scale: nothing otherwise (an ellipsoid).
std::optional<sphere> placed(const sphere& sp, const transform& t);
quad placed(const quad& q, const transform& t);
triangle placed(const triangle& tri, const transform& t);
triangle_shading placed(const triangle_shading& sh, const transform& t);

// Appends the objects of `g`, placed by `t`, to the scene (each kind after the scene's own).
// Renderers see the placed copies: a group placed N times costs N times its objects' memory.
// Returns why it cannot (a sphere of the group under a non-uniform scale), or nothing.
std::optional<std::string> place_group(scene& s, const object_group& g, const transform& t);

}  // namespace rtvk
