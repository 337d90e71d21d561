#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include "bvh.h"

namespace rtvk {

// Four children of one node, their boxes side by side so that one SSE instruction tests a ray
// against all four: the CPU's traversal structure. It is the binary tree (bvh) with levels
// collapsed, each wide node taking up to four of the binary tree's children and grandchildren,
// with the very same float boxes, so its box tests cull exactly what the binary tree's would.
struct alignas(64) wide_node {
  float lo[3][4];  // children's box minima, [axis][child], scene units (rounded outward)
  float hi[3][4];  // and maxima
  // Per child: a wide node index, or with leaf_bit set the leaf's object (one): its reference
  // (RTVK_LEAF_* kind | index in that kind's array), or its leaf slot.
  std::uint32_t child[4];
  std::uint32_t lanes;  // bit c: child c is in use (the first `children` bits)
  std::uint32_t pad[3];

  static constexpr std::uint32_t leaf_bit = 0x80000000u;
};
static_assert(sizeof(wide_node) == 128);

// The binary tree collapsed into wide nodes, node 0 the root, depth first.
class wide_bvh {
 public:
  wide_bvh() = default;  // no objects
  // Leaves refer to `refs[slot]` (leaf_layout::refs), or to the leaf slot itself when empty.
  explicit wide_bvh(const bvh& tree, std::span<const std::uint32_t> refs = {});

  const std::vector<wide_node>& nodes() const { return nodes_; }
  // Wide levels on the longest path from the root (no spheres: 0).
  int depth() const { return depth_; }
  // Most children a traversal may have remembered at once: three per level on its path.
  static constexpr int max_stack = 3 * bvh::max_depth;

 private:
  std::vector<wide_node> nodes_;  // depth first, node 0 the root
  int depth_ = 0;                 // wide levels
};

}  // namespace rtvk
