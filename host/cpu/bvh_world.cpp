#include "bvh_world.h"

#if defined(__SSE2__)
#include <xmmintrin.h>
#endif

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>

#include "hittable_sphere.h"
#include "parallel.h"

namespace rtvk {
namespace {

// What every box test of one ray needs, in float, prepared once per ray: for each axis, which
// of a wide node's corner arrays the ray meets first (lo when it travels up the axis, else hi),
// and the origin moved by origin_margin (accel/bvh.h) so that every box is tested grown by it.
struct ray_slabs {
  int near[3], far[3];  // per axis: offset of the near and far corner arrays in a wide_node
  float o_near[3];      // per axis: the origin, minus the margin where the near corner is hi ...
  float o_far[3];       // ... and plus it where the far corner is lo
  float inv[3];         // inverse direction (safe_inverse)

  explicit ray_slabs(const ray& r) {
    const glm::vec3 o(r.origin), inv_d = safe_inverse(glm::vec3(r.direction));
    const float margin = origin_margin(o);
    constexpr int lo = offsetof(wide_node, lo) / sizeof(float),
                  hi = offsetof(wide_node, hi) / sizeof(float);
    for (int k = 0; k < 3; ++k) {
      const bool up = inv_d[k] >= 0;
      near[k] = (up ? lo : hi) + 4 * k;
      far[k] = (up ? hi : lo) + 4 * k;
      o_near[k] = up ? o[k] + margin : o[k] - margin;
      o_far[k] = up ? o[k] - margin : o[k] + margin;
      inv[k] = inv_d[k];
    }
  }
};

// The slab test of all four children of n at once: t[c] is where the ray enters child c's box
// between t_min and t_max; the result has bit c set for each child whose box it enters there.
// (corner - (o -+ margin)) * inv differs from ray_box_entry's ((corner -+ margin) - o) * inv by
// an ulp of |o| at most, well inside the margin, so no box holding a hit is culled.
inline unsigned child_entries(const wide_node& n, const ray_slabs& r, float t_min, float t_max,
                              float (&t)[4]) {
  const float* const corners = &n.lo[0][0];
#if defined(__SSE2__)
  __m128 enter = _mm_set1_ps(t_min), leave = _mm_set1_ps(t_max);
  for (int k = 0; k < 3; ++k) {
    const __m128 inv = _mm_set1_ps(r.inv[k]);
    const __m128 t0 =
        _mm_mul_ps(_mm_sub_ps(_mm_load_ps(corners + r.near[k]), _mm_set1_ps(r.o_near[k])), inv);
    const __m128 t1 =
        _mm_mul_ps(_mm_sub_ps(_mm_load_ps(corners + r.far[k]), _mm_set1_ps(r.o_far[k])), inv);
    enter = _mm_max_ps(enter, t0);
    leave = _mm_min_ps(leave, t1);
  }
  _mm_storeu_ps(t, enter);
  return unsigned(_mm_movemask_ps(_mm_cmple_ps(enter, leave))) & n.lanes;
#else
  unsigned mask = 0;
  for (int c = 0; c < 4; ++c) {
    float enter = t_min, leave = t_max;
    for (int k = 0; k < 3; ++k) {
      enter = std::max(enter, (corners[r.near[k] + c] - r.o_near[k]) * r.inv[k]);
      leave = std::min(leave, (corners[r.far[k] + c] - r.o_far[k]) * r.inv[k]);
    }
    t[c] = enter;
    if (enter <= leave) mask |= 1u << c;
  }
  return mask & n.lanes;
#endif
}

// Box tests run in float; their interval is widened a little so no box holding a hit is culled.
inline float widen_down(double t) {
  return float(t) * (1.0f - 0x1p-20f);
}
inline float widen_up(double t) {
  return float(t) * (1.0f + 0x1p-20f);
}

// The children still to visit, each with the distance at which the ray enters its box: at most
// three per node on the path from the root, which is at most bvh::max_depth nodes long.
struct node_stack {
  std::uint32_t node[wide_bvh::max_stack];  // the child: wide_node::child
  float entry[wide_bvh::max_stack];         // where the ray enters its box
  int top = 0;                              // entries in use
};

// The search's state: the nearest hit so far, and its sphere.
struct nearest {
  double t;                 // the hit's distance (t_max while there is none)
  std::int64_t scene = -1;  // the sphere's index in the scene, -1 for none
  std::uint32_t slot = 0;   // and its leaf slot
};

// Where the sphere in leaf slot k is at the ray's instant (sphere::center_at).
template <typename Sphere>
inline point3 center_at(std::uint32_t k, const std::vector<Sphere>& spheres,
                        const std::vector<vec3>& velocities, double time) {
  return velocities.empty() ? spheres[k].center
                            : moved_center(spheres[k].center, velocities[k], time);
}

// Tests the sphere in leaf slot k, keeping the nearest hit. Ties go to the later sphere in the
// scene, as in a linear scan, so the order of the tests never matters.
template <typename Sphere>
inline void visit_sphere(std::uint32_t k, const std::vector<Sphere>& spheres,
                         const std::vector<vec3>& velocities,
                         const std::vector<std::uint32_t>& order, const ray& r, double t_min,
                         nearest& best) {
  const std::int64_t i = order[k];
  double t;
  if (hit_sphere(center_at(k, spheres, velocities, r.time), spheres[k].radius, r, t_min, best.t,
                 t) &&
      (t < best.t || i > best.scene)) {
    best.t = t;
    best.scene = i;
    best.slot = k;
  }
}

// Takes the next remembered node the ray can still reach before box_max (the closest hit).
// False when none is left.
inline bool pop_reachable(node_stack& stack, float box_max, std::uint32_t& next) {
  while (stack.top > 0 && stack.entry[stack.top - 1] > box_max) --stack.top;
  if (stack.top == 0) return false;
  next = stack.node[--stack.top];
  return true;
}

// Of the children in `entered` (entered at t[c]), goes on into the nearest and remembers the
// others, farthest deepest, so they come off the stack front to back. False when none.
inline bool descend(const wide_node& n, unsigned entered, const float (&t)[4], node_stack& stack,
                    std::uint32_t& next) {
  if (entered == 0) return false;
  if ((entered & (entered - 1)) == 0) {  // one child: no order to find
    next = n.child[std::countr_zero(entered)];
    return true;
  }
  int lane[4], k = 0;
  for (; entered; entered &= entered - 1) {
    const int c = std::countr_zero(entered);
    int at = k++;
    for (; at > 0 && t[lane[at - 1]] < t[c]; --at) lane[at] = lane[at - 1];  // far to near
    lane[at] = c;
  }
  if (k == 0) return false;
  for (int j = 0; j < k - 1; ++j) {
    stack.node[stack.top] = n.child[lane[j]];
    stack.entry[stack.top++] = t[lane[j]];
  }
  next = n.child[lane[k - 1]];
  return true;
}

}  // namespace

bvh_world::bvh_world(const std::vector<sphere>& spheres, int threads, time_span motion) {
  {
    const bvh tree(spheres, threads, motion);
    wide_ = wide_bvh(tree);
    order_ = tree.order();
  }  // the binary tree is freed before the spheres are copied: a lower peak
  spheres_.resize(spheres.size());
  const bool moves = std::any_of(spheres.begin(), spheres.end(),
                                 [](const sphere& s) { return s.center1.has_value(); });
  if (moves) velocities_.resize(spheres.size());
  parallel_for(spheres.size(), threads, 1 << 14, [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k) {
      const sphere& s = spheres[order_[k]];
      spheres_[k] = {s.center, s.radius, s.material};
      if (moves) velocities_[k] = s.velocity();
    }
  });
}

// At each wide node all four children's boxes are tested at once; the ray goes on into the
// nearest child it enters before the closest hit so far (a wide node, or a leaf whose sphere is
// then tested) and remembers the others with their entry distances. Remembered children behind
// the closest hit are dropped when they come up.
bool bvh_world::hit(const ray& r, double t_min, double t_max, hit_record& rec) const {
  const std::vector<wide_node>& nodes = wide_.nodes();
  const std::vector<std::uint32_t>& order = order_;
  if (nodes.empty()) return false;
  const ray_slabs slabs(r);
  const float box_min = widen_down(t_min);
  node_stack stack;
  std::uint32_t next = 0;  // the root
  nearest best{t_max};
  while (true) {
    if (next & wide_node::leaf_bit) {
      visit_sphere(next & ~wide_node::leaf_bit, spheres_, velocities_, order, r, t_min, best);
    } else {
      const wide_node& n = nodes[next];
      float t[4];
      const unsigned entered = child_entries(n, slabs, box_min, widen_up(best.t), t);
      if (descend(n, entered, t, stack, next)) continue;
    }
    if (!pop_reachable(stack, widen_up(best.t), next)) break;
  }
  if (best.scene < 0) return false;
  const leaf_sphere& s = spheres_[best.slot];
  record_hit(center_at(best.slot, spheres_, velocities_, r.time), s.radius, uint(s.material), r,
             best.t, rec);
  return true;
}

}  // namespace rtvk
