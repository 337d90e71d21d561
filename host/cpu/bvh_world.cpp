#include "bvh_world.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include <cstdint>

#include "hittable_sphere.h"

namespace rtvk {
namespace {

// The slab test of ray_box_entry for both children at once. Lane 0 is the left child, lane 1 the
// right; each gets its entry distance, or -1 when the ray misses it. Same float operations, same
// results, as two calls of ray_box_entry.
#if defined(__SSE2__)
void both_children(const glm::vec3& o, const glm::vec3& inv_d, const float (&x)[4],
                   const float (&y)[4], const float (&z)[4], float t_min, float t_max, float margin,
                   float& t_left, float& t_right) {
  const __m128 grow = _mm_setr_ps(-margin, -margin, margin, margin);  // mins down, maxes up
  const auto axis = [&](const float(&v)[4], float origin, float inv, __m128& near, __m128& far) {
    const __m128 corner = _mm_add_ps(_mm_loadu_ps(v), grow);
    const __m128 t = _mm_mul_ps(_mm_sub_ps(corner, _mm_set1_ps(origin)), _mm_set1_ps(inv));
    const __m128 swapped =
        _mm_shuffle_ps(t, t, _MM_SHUFFLE(1, 0, 3, 2));  // min lanes <-> max lanes
    near = _mm_min_ps(t, swapped);
    far = _mm_max_ps(t, swapped);
  };
  __m128 nx, fx, ny, fy, nz, fz;
  axis(x, o.x, inv_d.x, nx, fx);
  axis(y, o.y, inv_d.y, ny, fy);
  axis(z, o.z, inv_d.z, nz, fz);
  const __m128 enter = _mm_max_ps(_mm_max_ps(_mm_set1_ps(t_min), nx), _mm_max_ps(ny, nz));
  const __m128 leave = _mm_min_ps(_mm_min_ps(_mm_set1_ps(t_max), fx), _mm_min_ps(fy, fz));
  alignas(16) float e[4], l[4];
  _mm_store_ps(e, enter);
  _mm_store_ps(l, leave);
  t_left = e[0] <= l[0] ? e[0] : -1.0f;
  t_right = e[1] <= l[1] ? e[1] : -1.0f;
}
#endif

// Box tests run in float; their interval is widened a little so no box holding a hit is culled.
inline float widen_down(double t) {
  return float(t) * (1.0f - 0x1p-20f);
}
inline float widen_up(double t) {
  return float(t) * (1.0f + 0x1p-20f);
}

// The inner nodes still to visit, each with the distance at which the ray enters its box.
struct node_stack {
  std::uint32_t node[RTVK_BVH_STACK];  // node index
  float entry[RTVK_BVH_STACK];         // where the ray enters the node's box
  int top = 0;                         // entries in use
};

// Tests a leaf's spheres, keeping the nearest hit (`closest`, `best` its sphere index). Ties go
// to the later sphere, as in a linear scan.
inline void visit_leaf(const gpu::bvh_node& n, const std::vector<std::uint32_t>& index,
                       const std::vector<sphere>& spheres, const ray& r, double t_min,
                       double& closest, std::int64_t& best) {
  for (std::uint32_t k = n.first; k < n.first + n.count; ++k) {
    const std::uint32_t i = index[k];
    double t;
    if (hit_distance(spheres[i], r, t_min, closest, t) && (t < closest || i > best)) {
      closest = t;
      best = i;
    }
  }
}

// Where the ray enters each child box of inner node n, or -1 where it misses it.
inline void child_entries(const bvh& tree, std::uint32_t node,
                          [[maybe_unused]] const gpu::bvh_node& n, const glm::vec3& o,
                          const glm::vec3& inv_d, float box_min, float box_max, float margin,
                          float& t_left, float& t_right) {
#if defined(__SSE2__)
  const bvh::child_boxes& c = tree.children()[node];
  both_children(o, inv_d, c.x, c.y, c.z, box_min, box_max, margin, t_left, t_right);
#else
  t_left = ray_box_entry(o, inv_d, tree.nodes()[node + 1], box_min, box_max, margin);
  t_right = ray_box_entry(o, inv_d, tree.nodes()[n.first], box_min, box_max, margin);
#endif
}

// Moves `node` to the nearer child the ray enters, remembering the other if the ray enters it
// at all. False when the ray enters neither.
inline bool descend(std::uint32_t left, std::uint32_t right, float t_left, float t_right,
                    std::uint32_t& node, node_stack& stack) {
  if (t_left >= 0 && t_right >= 0) {
    const bool left_first = t_left <= t_right;
    stack.node[stack.top] = left_first ? right : left;
    stack.entry[stack.top++] = left_first ? t_right : t_left;
    node = left_first ? left : right;
    return true;
  }
  if (t_left >= 0 || t_right >= 0) {
    node = t_left >= 0 ? left : right;
    return true;
  }
  return false;
}

// Moves `node` to the next remembered node the ray can still reach before box_max (the closest
// hit). False when none is left.
inline bool pop_reachable(node_stack& stack, float box_max, std::uint32_t& node) {
  while (stack.top > 0 && stack.entry[stack.top - 1] > box_max) --stack.top;
  if (stack.top == 0) return false;
  node = stack.node[--stack.top];
  return true;
}

}  // namespace

bool bvh_world::hit(const ray& r, double t_min, double t_max, hit_record& rec) const {
  const std::vector<gpu::bvh_node>& nodes = tree_.nodes();
  const std::vector<std::uint32_t>& index = tree_.index();
  if (nodes.empty()) return false;
  const glm::vec3 o(r.origin()), inv_d = safe_inverse(glm::vec3(r.direction()));
  const float margin = origin_margin(o);
  const float box_min = widen_down(t_min);
  node_stack stack;
  std::uint32_t node = 0;
  double closest = t_max;
  std::int64_t best = -1;  // sphere index of the hit so far
  while (true) {
    const gpu::bvh_node& n = nodes[node];
    if (n.count == 0) {
      float t_left, t_right;
      child_entries(tree_, node, n, o, inv_d, box_min, widen_up(closest), margin, t_left, t_right);
      if (descend(node + 1, n.first, t_left, t_right, node, stack)) continue;
    } else {
      visit_leaf(n, index, spheres_, r, t_min, closest, best);
    }
    if (!pop_reachable(stack, widen_up(closest), node)) break;
  }
  if (best < 0) return false;
  record_hit(spheres_[std::size_t(best)], r, closest, rec);
  return true;
}

}  // namespace rtvk
