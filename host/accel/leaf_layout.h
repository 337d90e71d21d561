#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "bvh.h"

namespace rtvk {

// Where each object of the scene sits in the arrays a traversal reads: one array per kind, each
// in the BVH's leaf order (objects met together in the tree lie together in memory), and for
// each leaf slot the reference a wide node stores (RTVK_LEAF_* kind | position in its array).
// Without a BVH the arrays are in scene order.
struct leaf_layout {
  std::vector<std::uint32_t> refs;  // leaf slot -> kind | position (empty without a BVH)
  // Per shape kind (shape_kind): array position -> index into that kind's scene list.
  std::array<std::vector<std::uint32_t>, shape_kinds> kinds;
};

// The layout of `tree`'s leaves over `objects` (tree.order() in their numbering); with no tree
// nodes, scene order.
leaf_layout make_leaf_layout(const bvh& tree, const primitive_spans& objects);

}  // namespace rtvk
