#include "scene_tree.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "leaf_layout.h"

namespace rtvk {
namespace {

// The box of a tree's root: its lanes' boxes together.
std::array<point3, 2> root_box(const wide_bvh& tree) {
  point3 lo(std::numeric_limits<double>::infinity()), hi(-lo);
  const wide_node& n = tree.nodes().front();
  for (int c = 0; c < 4; ++c)
    if (n.lanes & (1u << c))
      for (int k = 0; k < 3; ++k) {
        lo[k] = std::min(lo[k], double(n.lo[k][c]));
        hi[k] = std::max(hi[k], double(n.hi[k][c]));
      }
  return {lo, hi};
}

// The box around the 8 corners of `box` placed by t: it holds every placed point of the box.
std::array<point3, 2> placed_box(const std::array<point3, 2>& box, const transform& t) {
  point3 lo(std::numeric_limits<double>::infinity()), hi(-lo);
  for (int c = 0; c < 8; ++c) {
    const point3 p = t.apply_point(point3(c & 1 ? box[1].x : box[0].x, c & 2 ? box[1].y : box[0].y,
                                          c & 4 ? box[1].z : box[0].z));
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  // A little room for the rounding of the placement (the box tests round outward again).
  const vec3 slack = (glm::abs(lo) + glm::abs(hi)) * 0x1p-40 + vec3(1e-300);
  return {lo - slack, hi + slack};
}

// Appends `slots` of kind positions [first, first + n) of a layout list.
void append_slots(std::vector<object_slot>& to, const std::vector<std::uint32_t>& order,
                  std::uint32_t group) {
  for (const std::uint32_t i : order) to.push_back({group, i});
}

}  // namespace

instance_frame frame_of(const transform& placement) {
  const glm::dmat3 to_group = glm::inverse(placement.linear);
  const vec3 offset = -(to_group * placement.offset);
  // Rows of the column-major matrices: row r of m is (m[0][r], m[1][r], m[2][r]); the normal
  // matrix is the transpose of to_group, so its rows are to_group's columns.
  const auto row = [&](int r) { return vec3(to_group[0][r], to_group[1][r], to_group[2][r]); };
  double frobenius = 0;
  for (int c = 0; c < 3; ++c) frobenius += glm::dot(placement.linear[c], placement.linear[c]);
  return instance_frame{row(0),      row(1),      row(2),      offset,
                        to_group[0], to_group[1], to_group[2], std::sqrt(frobenius)};
}

scene_tree build_scene_tree(const primitive_spans& world, std::span<const object_group> groups,
                            std::span<const instance> instances, bool use_bvh, int threads,
                            time_span motion) {
  scene_tree out;
  out.groups.resize(groups.size());
  if (instances.size() >= std::size_t(RTVK_LEAF_INDEX_MASK))
    throw std::invalid_argument(std::to_string(instances.size()) +
                                " instances are more than a leaf reference holds");
  // Only the groups some instance places get a tree and a place in the arrays: one nothing
  // places costs nothing and limits nothing.
  std::vector<bool> placed(groups.size(), false);
  for (const instance& i : instances) {
    if (i.group >= groups.size() || empty(groups[i.group]))
      throw std::invalid_argument("an instance places a group that does not exist or is empty");
    placed[i.group] = true;
  }
  // Each group's tree first (its box places the instances), then the world's over its objects
  // and the instances' boxes; the world's nodes go first in the shared array.
  std::vector<wide_bvh> group_trees(groups.size());
  std::vector<leaf_layout> group_layouts(groups.size());
  int group_depth = 0;
  for (std::size_t g = 0; g < groups.size(); ++g) {
    if (!placed[g]) continue;
    const bvh tree(use_bvh ? spans_of(groups[g]) : primitive_spans{}, threads);
    group_layouts[g] = use_bvh ? make_leaf_layout(tree, spans_of(groups[g]))
                               : make_leaf_layout(bvh(primitive_spans{}), spans_of(groups[g]));
    if (use_bvh) {
      group_trees[g] = wide_bvh(tree, group_layouts[g].refs);
      group_depth = std::max(group_depth, group_trees[g].depth());
    }
  }
  std::vector<std::array<point3, 2>> boxes;
  if (use_bvh) {
    boxes.reserve(instances.size());
    for (const instance& i : instances)
      boxes.push_back(placed_box(root_box(group_trees[i.group]), i.placement));
  }
  primitive_spans top = world;
  top.boxes = boxes;
  leaf_layout layout;
  if (use_bvh) {
    const bvh tree(top, threads, motion);
    layout = make_leaf_layout(tree, top);
    const wide_bvh wide(tree, layout.refs);
    out.nodes = wide.nodes();
    out.world_nodes = std::uint32_t(out.nodes.size());
    out.depth = wide.depth() + group_depth;
  } else {
    layout = make_leaf_layout(bvh(primitive_spans{}), world);
  }
  if (3 * out.depth + (instances.empty() ? 0 : 1) > wide_bvh::max_stack)
    throw std::invalid_argument(
        "the scene's trees are " + std::to_string(out.depth) +
        " levels deep with an instance's: more than a traversal's stack holds");
  for (std::size_t k = 0; k < shape_kinds; ++k)
    append_slots(out.slots[k], layout.kinds[k], world_objects);
  for (std::size_t g = 0; g < groups.size(); ++g) {
    if (!placed[g]) continue;
    group_span& span = out.groups[g];
    const leaf_layout& l = group_layouts[g];
    kind_counts base{};
    for (std::size_t k = 0; k < shape_kinds; ++k) {
      base[k] = std::uint32_t(out.slots[k].size());
      span.count[k] = std::uint32_t(l.kinds[k].size());
      append_slots(out.slots[k], l.kinds[k], std::uint32_t(g));
    }
    span.first = base;
    if (!use_bvh) continue;
    // The group's nodes after those before: interior children move by the node base, leaf
    // references by their kind's base.
    const std::uint32_t node_base = std::uint32_t(out.nodes.size());
    span.root = node_base;
    for (wide_node n : group_trees[g].nodes()) {
      for (int c = 0; c < 4; ++c) {
        if (!(n.lanes & (1u << c))) continue;
        std::uint32_t& child = n.child[c];
        if (child & wide_node::leaf_bit) {
          const std::uint32_t ref = child & ~wide_node::leaf_bit;
          const std::uint32_t kind = ref & RTVK_LEAF_KIND_MASK;
          const std::uint32_t at = base[kind >> RTVK_LEAF_KIND_SHIFT];
          child = wide_node::leaf_bit | kind | ((ref & RTVK_LEAF_INDEX_MASK) + at);
        } else {
          child += node_base;
        }
      }
      out.nodes.push_back(n);
    }
  }
  for (const std::vector<object_slot>& list : out.slots)
    if (list.size() > std::size_t(RTVK_LEAF_INDEX_MASK) + 1)
      throw std::invalid_argument("more objects of a kind than a leaf reference's 28 bits hold");
  return out;
}

}  // namespace rtvk
