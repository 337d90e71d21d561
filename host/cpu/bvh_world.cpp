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

}  // namespace

bool bvh_world::hit(const ray& r, double t_min, double t_max, hit_record& rec) const {
  const std::vector<gpu::bvh_node>& nodes = tree_.nodes();
  const std::vector<std::uint32_t>& index = tree_.index();
  if (nodes.empty()) return false;
  const glm::vec3 o(r.origin()), inv_d = safe_inverse(glm::vec3(r.direction()));
  const float margin = origin_margin(o);
  // Box tests run in float; widen the interval a little so no box holding a hit is culled.
  auto widen_up = [](double t) { return float(t) * (1.0f + 0x1p-20f); };
  const float box_min = float(t_min) * (1.0f - 0x1p-20f);
  std::uint32_t stack_node[RTVK_BVH_STACK];
  float stack_entry[RTVK_BVH_STACK];
  int top = 0;
  std::uint32_t node = 0;
  double closest = t_max;
  std::int64_t best = -1;  // sphere index of the hit so far
  while (true) {
    const gpu::bvh_node& n = nodes[node];
    if (n.count > 0) {
      for (std::uint32_t k = n.first; k < n.first + n.count; ++k) {
        const std::uint32_t i = index[k];
        double t;
        // Ties go to the later sphere, as in a linear scan.
        if (hit_distance(spheres_[i], r, t_min, closest, t) && (t < closest || i > best)) {
          closest = t;
          best = i;
        }
      }
    } else {
      // Visit the nearer child first; remember the other if the ray enters it at all.
      const float box_max = widen_up(closest);
      const std::uint32_t left = node + 1, right = n.first;
#if defined(__SSE2__)
      float t_left, t_right;
      const bvh::child_boxes& c = tree_.children()[node];
      both_children(o, inv_d, c.x, c.y, c.z, box_min, box_max, margin, t_left, t_right);
#else
      const float t_left = ray_box_entry(o, inv_d, nodes[left], box_min, box_max, margin);
      const float t_right = ray_box_entry(o, inv_d, nodes[right], box_min, box_max, margin);
#endif
      if (t_left >= 0 && t_right >= 0) {
        const bool left_first = t_left <= t_right;
        stack_node[top] = left_first ? right : left;
        stack_entry[top++] = left_first ? t_right : t_left;
        node = left_first ? left : right;
        continue;
      }
      if (t_left >= 0 || t_right >= 0) {
        node = t_left >= 0 ? left : right;
        continue;
      }
    }
    // The next remembered node the ray can still reach before the closest hit.
    const float box_max = widen_up(closest);
    while (top > 0 && stack_entry[top - 1] > box_max) --top;
    if (top == 0) break;
    node = stack_node[--top];
  }
  if (best < 0) return false;
  record_hit(spheres_[std::size_t(best)], r, closest, rec);
  return true;
}

}  // namespace rtvk
