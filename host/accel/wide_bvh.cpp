#include "wide_bvh.h"

#include <array>
#include <cmath>

namespace rtvk {
namespace {

// One child of a binary node: its box as stored there, and what it refers to.
struct binary_child {
  float lo[3], hi[3];   // the float box of the binary node's lane
  std::uint32_t first;  // interior node index, or leaf slot
  std::uint32_t count;  // 0 interior, else spheres in the leaf
};

binary_child child_of(const bvh_node& n, int c) {
  binary_child b{};
  const glm::vec4* const axes[3] = {&n.x, &n.y, &n.z};
  for (int k = 0; k < 3; ++k) {
    b.lo[k] = (*axes[k])[c];
    b.hi[k] = (*axes[k])[c + 2];
  }
  b.first = n.first[c];
  b.count = n.count[c];
  return b;
}

float half_area(const binary_child& b) {
  const float x = b.hi[0] - b.lo[0], y = b.hi[1] - b.lo[1], z = b.hi[2] - b.lo[2];
  return x * y + y * z + z * x;
}

class collapser {
 public:
  collapser(const bvh& tree, std::span<const std::uint32_t> refs, std::vector<wide_node>& out)
      : binary_(tree.nodes()), refs_(refs), out_(out) {}

  // Makes the wide node for binary node `b`, `level` wide levels below the root (root: 1), and
  // below it the wide nodes of its interior children; returns its index. The widest interior
  // child (by surface) is opened first: large boxes are the ones worth testing together.
  std::uint32_t collapse(std::uint32_t b, int level) {
    depth_ = std::max(depth_, level);
    std::array<binary_child, 4> kids{};
    int n = 0;
    kids[std::size_t(n++)] = child_of(binary_[b], 0);
    kids[std::size_t(n++)] = child_of(binary_[b], 1);
    while (n < 4) {
      int open = -1;
      for (int c = 0; c < n; ++c)
        if (kids[std::size_t(c)].count == 0 &&
            (open < 0 || half_area(kids[std::size_t(c)]) > half_area(kids[std::size_t(open)])))
          open = c;
      if (open < 0) break;
      const bvh_node& inner = binary_[kids[std::size_t(open)].first];
      kids[std::size_t(open)] = child_of(inner, 0);
      kids[std::size_t(n++)] = child_of(inner, 1);
    }
    const std::uint32_t at = std::uint32_t(out_.size());
    out_.push_back(empty_node());
    for (int c = 0; c < n; ++c) place(at, c, kids[std::size_t(c)], level);
    return at;
  }

  int depth() const { return depth_; }

 private:
  static wide_node empty_node() {
    wide_node w{};
    for (int k = 0; k < 3; ++k)
      for (int c = 0; c < 4; ++c) {
        w.lo[k][c] = INFINITY;  // unused lanes: an empty box, and no lanes bit
        w.hi[k][c] = -INFINITY;
      }
    return w;
  }

  void place(std::uint32_t at, int c, const binary_child& kid, int level) {
    for (int k = 0; k < 3; ++k) {
      out_[at].lo[k][c] = kid.lo[k];
      out_[at].hi[k][c] = kid.hi[k];
    }
    out_[at].lanes |= 1u << c;
    // The leaf's one sphere (bvh::max_leaf is 1); a root whose children are the same leaf keeps
    // both lanes, as the binary tree does, and the traversal's tie rule makes that harmless.
    const std::uint32_t leaf = refs_.empty() ? kid.first : refs_[kid.first];
    const std::uint32_t child =
        kid.count > 0 ? (leaf | wide_node::leaf_bit) : collapse(kid.first, level + 1);
    out_[at].child[c] = child;  // out_ may have grown: index, not a reference held across
  }

  const std::vector<bvh_node>& binary_;
  std::span<const std::uint32_t> refs_;  // leaf slot -> reference; empty: the slot
  std::vector<wide_node>& out_;
  int depth_ = 0;
};

}  // namespace

wide_bvh::wide_bvh(const bvh& tree, std::span<const std::uint32_t> refs) {
  if (tree.nodes().empty()) return;
  nodes_.reserve(tree.nodes().size() / 2 + 1);
  collapser c(tree, refs, nodes_);
  c.collapse(0, 1);
  depth_ = c.depth();
}

}  // namespace rtvk
