#pragma once
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "bvh.h"
#include "instance_space.h"
#include "object_group.h"
#include "wide_bvh.h"

namespace rtvk {

// Which object an array position holds: one of the scene's own (group == world_objects, index in
// scene order: its scene index within the kind), or object `index` of group `group` (in the
// group's own order within the kind).
struct object_slot {
  std::uint32_t group;  // world_objects, or index into scene::groups
  std::uint32_t index;  // in its list of that kind
};
inline constexpr std::uint32_t world_objects = ~0u;

// Where a group's objects are: its tree's root among the wide nodes (with a BVH), and its
// objects' positions in each kind's array (first, count: by shape_kind).
struct group_span {
  std::uint32_t root = 0;
  kind_counts first{}, count{};
};

// Two levels for both backends, as hardware acceleration structures are built: one tree over
// the scene's own objects and its instances (an instance is a leaf: RTVK_LEAF_INSTANCE | its
// index), and one tree per group over the group's objects, stored once however many instances
// place it. All trees' wide nodes share one array (the world's root at 0); each kind's objects
// share one array, the world's first (in leaf order), then each group's (in its leaf order).
// Without a BVH there are no nodes and every array is in scene order, then group order.
struct scene_tree {
  std::vector<wide_node> nodes;
  // Per shape kind (shape_kind): array position -> object.
  std::array<std::vector<object_slot>, shape_kinds> slots;
  std::vector<group_span> groups;  // a group no instance places: an empty span
  std::uint32_t world_nodes = 0;  // the world's tree's nodes (0: no objects, no instances)
  int depth = 0;  // wide levels on the longest world path plus the longest group path
};

// `world`: the scene's own objects (no boxes). Each instance's box is its group's, placed.
scene_tree build_scene_tree(const primitive_spans& world, std::span<const object_group> groups,
                            std::span<const instance> instances, bool use_bvh, int threads,
                            time_span motion);

// A placement as the shared kernels carry rays and hits with it (shaders/shared/instance_space.h).
instance_frame frame_of(const transform& placement);

}  // namespace rtvk
