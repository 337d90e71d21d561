#include "bvh_world.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include <cstdint>

#include "hittable_sphere.h"

namespace rtvk {
namespace {

// The slab test of ray_box_entry for both children of n at once: t[0] is where the ray enters
// the left child's box, t[1] the right's, or -1 where it misses it. Same float operations, same
// results, as ray_box_entry for each child, which is the fallback without SSE.
inline void child_entries(const gpu::bvh_node& n, const glm::vec3& o, const glm::vec3& inv_d,
                          float t_min, float t_max, float margin, float (&t)[2]) {
#if defined(__SSE2__)
  const __m128 grow = _mm_setr_ps(-margin, -margin, margin, margin);  // mins down, maxes up
  const auto axis = [&](const gpu::vec4& v, float origin, float inv, __m128& near, __m128& far) {
    const __m128 corner = _mm_add_ps(_mm_loadu_ps(&v[0]), grow);
    const __m128 d = _mm_mul_ps(_mm_sub_ps(corner, _mm_set1_ps(origin)), _mm_set1_ps(inv));
    const __m128 swapped =
        _mm_shuffle_ps(d, d, _MM_SHUFFLE(1, 0, 3, 2));  // min lanes <-> max lanes
    near = _mm_min_ps(d, swapped);
    far = _mm_max_ps(d, swapped);
  };
  __m128 nx, fx, ny, fy, nz, fz;
  axis(n.x, o.x, inv_d.x, nx, fx);
  axis(n.y, o.y, inv_d.y, ny, fy);
  axis(n.z, o.z, inv_d.z, nz, fz);
  const __m128 enter = _mm_max_ps(_mm_max_ps(_mm_set1_ps(t_min), nx), _mm_max_ps(ny, nz));
  const __m128 leave = _mm_min_ps(_mm_min_ps(_mm_set1_ps(t_max), fx), _mm_min_ps(fy, fz));
  alignas(16) float e[4], l[4];
  _mm_store_ps(e, enter);
  _mm_store_ps(l, leave);
  t[0] = e[0] <= l[0] ? e[0] : -1.0f;
  t[1] = e[1] <= l[1] ? e[1] : -1.0f;
#else
  t[0] = ray_box_entry(o, inv_d, n, 0, t_min, t_max, margin);
  t[1] = ray_box_entry(o, inv_d, n, 1, t_min, t_max, margin);
#endif
}

// Box tests run in float; their interval is widened a little so no box holding a hit is culled.
inline float widen_down(double t) {
  return float(t) * (1.0f - 0x1p-20f);
}
inline float widen_up(double t) {
  return float(t) * (1.0f + 0x1p-20f);
}

// A child of some node: an interior node (count 0, `first` its index) or a leaf.
struct child_ref {
  std::uint32_t first;  // node index, or the leaf's first sphere slot
  std::uint32_t count;  // 0, or the leaf's spheres
};

// The children still to visit, each with the distance at which the ray enters its box: children
// of the interior nodes on the path from the root, one per node at most, and the builder keeps
// that path at most bvh::max_depth nodes long.
struct node_stack {
  child_ref ref[RTVK_BVH_STACK];  // the child
  float entry[RTVK_BVH_STACK];    // where the ray enters its box
  int top = 0;                    // entries in use
};
static_assert(bvh::max_depth <= RTVK_BVH_STACK);

// The search's state: the nearest hit so far, and its sphere.
struct nearest {
  double t;                 // the hit's distance (t_max while there is none)
  std::int64_t scene = -1;  // the sphere's index in the scene, -1 for none
  std::uint32_t slot = 0;   // and its leaf slot
};

// Tests a leaf's spheres, slots first .. first + count - 1, keeping the nearest hit. Ties go to
// the later sphere in the scene, as in a linear scan.
inline void visit_leaf(std::uint32_t first, std::uint32_t count, const std::vector<sphere>& spheres,
                       const std::vector<std::uint32_t>& order, const ray& r, double t_min,
                       nearest& best) {
  for (std::uint32_t k = first; k < first + count; ++k) {
    const std::int64_t i = order[k];
    double t;
    if (hit_distance(spheres[k], r, t_min, best.t, t) && (t < best.t || i > best.scene)) {
      best.t = t;
      best.scene = i;
      best.slot = k;
    }
  }
}

// Moves `node` to the next remembered node the ray can still reach before box_max (the closest
// hit). False when none is left.
inline bool pop_reachable(node_stack& stack, float box_max, child_ref& next) {
  while (stack.top > 0 && stack.entry[stack.top - 1] > box_max) --stack.top;
  if (stack.top == 0) return false;
  next = stack.ref[--stack.top];
  return true;
}

}  // namespace

bvh_world::bvh_world(const std::vector<sphere>& spheres) : tree_(spheres) {
  spheres_.reserve(spheres.size());
  for (const std::uint32_t i : tree_.order()) spheres_.push_back(spheres[i]);
}

// At each interior node both children's boxes are tested at once; the ray goes on into the
// nearer child it enters, remembering the farther with its entry distance when it enters both.
// A leaf's spheres are tested when it is reached; remembered children behind the closest hit so
// far are dropped. shaders/world.glsl (hit_bvh) takes the same steps.
bool bvh_world::hit(const ray& r, double t_min, double t_max, hit_record& rec) const {
  const std::vector<gpu::bvh_node>& nodes = tree_.nodes();
  const std::vector<std::uint32_t>& order = tree_.order();
  if (nodes.empty()) return false;
  const glm::vec3 o(r.origin()), inv_d = safe_inverse(glm::vec3(r.direction()));
  const float margin = origin_margin(o);
  const float box_min = widen_down(t_min);
  node_stack stack;
  child_ref next{0, 0};  // the root
  nearest best{t_max};
  while (true) {
    if (next.count == 0) {
      const gpu::bvh_node& n = nodes[next.first];
      float t[2];
      child_entries(n, o, inv_d, box_min, widen_up(best.t), margin, t);
      // Nearer first: a is the nearer child when the ray enters both.
      const int a = t[0] <= t[1] ? 0 : 1, b = 1 - a;
      if (t[a] >= 0 && t[b] >= 0) {
        stack.ref[stack.top] = {n.first[b], n.count[b]};
        stack.entry[stack.top++] = t[b];
        next = {n.first[a], n.count[a]};
        continue;
      }
      if (t[a] >= 0 || t[b] >= 0) {
        const int c = t[a] >= 0 ? a : b;
        next = {n.first[c], n.count[c]};
        continue;
      }
    } else {
      visit_leaf(next.first, next.count, spheres_, order, r, t_min, best);
    }
    if (!pop_reachable(stack, widen_up(best.t), next)) break;
  }
  if (best.scene < 0) return false;
  record_hit(spheres_[best.slot], r, best.t, rec);
  return true;
}

}  // namespace rtvk
