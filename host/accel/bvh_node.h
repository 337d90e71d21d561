#pragma once
#include <cstddef>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

namespace rtvk {

// One interior node of the binary bounding volume hierarchy the host builds (bvh.h), 64 bytes,
// holding both children: their boxes per axis as four lanes (left min, right min, left max,
// right max), and for each child c (0 left, 1 right) a reference. count[c] = 0: an interior
// node, nodes[first[c]]; else a leaf, the spheres first[c] .. first[c] + count[c] - 1 (stored in
// leaf order). Node 0 is the root; nodes are stored depth first. Host-only: both backends walk
// the tree collapsed four wide (wide_bvh.h; the GPU reads the same bytes as gpu::bvh_wide_node).
struct bvh_node {
  glm::vec4 x;       // children's box corners on x, scene units (rounded outward)
  glm::vec4 y;       // on y
  glm::vec4 z;       // on z
  glm::uvec2 first;  // per child: interior node index, or the leaf's first sphere slot
  glm::uvec2 count;  // per child: 0 for an interior node, else the leaf's spheres (> 0)
};
// No padding: trees built alike compare equal byte for byte (tests/cpu/test_bvh.cpp).
static_assert(offsetof(bvh_node, x) == 0);
static_assert(offsetof(bvh_node, y) == 16);
static_assert(offsetof(bvh_node, z) == 32);
static_assert(offsetof(bvh_node, first) == 48);
static_assert(offsetof(bvh_node, count) == 56);
static_assert(sizeof(bvh_node) == 64);

}  // namespace rtvk
