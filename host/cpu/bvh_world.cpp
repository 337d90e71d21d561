#include "bvh_world.h"

#if defined(__SSE2__)
#include <xmmintrin.h>
#endif

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>

#include "hit_triangle.h"
#include "hittable_sphere.h"
#include "hittable_triangle.h"
#include "leaf_layout.h"
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

// Where the sphere at position k is at the ray's instant (sphere::center_at).
template <typename Sphere>
inline point3 center_at(std::uint32_t k, const std::vector<Sphere>& spheres,
                        const std::vector<vec3>& velocities, double time) {
  return velocities.empty() ? spheres[k].center
                            : moved_center(spheres[k].center, velocities[k], time);
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

// The search's state: the nearest hit so far, and its object.
struct bvh_world::nearest {
  double t;                                   // the hit's distance (t_max while there is none)
  int index = -1;                             // its object's place in the scan order; -1: none
  std::uint32_t ref = 0;                      // and its leaf reference (RTVK_LEAF_* | position)
  std::uint32_t instance = RTVK_OWN_OBJECTS;  // the instance + 1 it was reached through
  std::uint32_t current = RTVK_OWN_OBJECTS;   // the instance + 1 the walk is in now

  // Keeps a hit at t on object `i` (reference `r`) of the instance walked now when it is
  // nearer, or as near and later in the scan (instance_space.h, the GPU's rule too), so the order
  // of the tests never matters.
  void offer(double t_hit, std::uint32_t i, std::uint32_t r) {
    if (t_hit < t || later_in_scan(current, int(i), instance, index)) {
      t = t_hit;
      index = int(i);
      ref = r;
      instance = current;
    }
  }
};

bvh_world::bvh_world(const std::vector<sphere>& spheres, int threads, time_span motion)
    : bvh_world(primitive_spans{spheres, {}, {}}, {}, threads, motion) {}

bvh_world::bvh_world(const primitive_spans& objects, std::span<const triangle_shading> shading,
                     int threads, time_span motion) {
  build(objects, shading, {}, {}, threads, motion);
}

bvh_world::bvh_world(const scene& s, int threads) : with_uv_(scene_reads_uv(s)) {
  build(spans_of(s), s.shading, s.groups, s.instances, threads, s.motion);
}

void bvh_world::build(const primitive_spans& objects, std::span<const triangle_shading> shading,
                      std::span<const object_group> groups, std::span<const instance> instances,
                      int threads, time_span motion) {
  scene_tree tree = build_scene_tree(objects, groups, instances, true, threads, motion);
  // No tree of the world's own (no objects, no instances): nothing to hit, whatever groups
  // follow at node 0.
  if (tree.world_nodes == 0) tree.nodes.clear();
  nodes_ = std::move(tree.nodes);
  const std::uint32_t first_quad = std::uint32_t(objects.spheres.size());
  const std::uint32_t first_triangle = first_quad + std::uint32_t(objects.quads.size());
  const std::uint32_t first_disk = first_triangle + std::uint32_t(objects.triangles.size());
  // Each object's data and its key: the scene index for the world's, the group-order index for
  // a group's.
  const auto sphere_of = [&](object_slot o) -> const sphere& {
    return o.group == world_objects ? objects.spheres[o.index] : groups[o.group].spheres[o.index];
  };
  const std::vector<object_slot>& sphere_slots = tree.slots[shape_sphere];
  spheres_.resize(sphere_slots.size());
  sphere_index_.resize(sphere_slots.size());
  const bool moves = std::any_of(objects.spheres.begin(), objects.spheres.end(),
                                 [](const sphere& s) { return s.center1.has_value(); });
  if (moves) velocities_.resize(spheres_.size());
  parallel_for(spheres_.size(), threads, 1 << 14, [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k) {
      const sphere& s = sphere_of(sphere_slots[k]);
      spheres_[k] = {s.center, s.radius, s.material};
      sphere_index_[k] = sphere_slots[k].index;
      if (moves) velocities_[k] = s.velocity();
    }
  });
  quads_.reserve(tree.slots[shape_quad].size());
  for (const object_slot o : tree.slots[shape_quad]) {
    const bool own = o.group == world_objects;
    const quad& q = own ? objects.quads[o.index] : groups[o.group].quads[o.index];
    quads_.push_back({q.geometry(), q.material});
    quad_index_.push_back(o.index +
                          (own ? first_quad : std::uint32_t(groups[o.group].spheres.size())));
  }
  // Triangles' shading, normals normalized once per shading entry of the world or a group.
  std::vector<std::vector<std::int32_t>> attributes_at(groups.size() + 1);
  triangles_.resize(tree.slots[shape_triangle].size());
  for (std::size_t k = 0; k < triangles_.size(); ++k) {
    const object_slot o = tree.slots[shape_triangle][k];
    const bool own = o.group == world_objects;
    const triangle& t = own ? objects.triangles[o.index] : groups[o.group].triangles[o.index];
    const std::span<const triangle_shading> sh = own ? shading : groups[o.group].shading;
    std::vector<std::int32_t>& at_list = attributes_at[own ? 0 : o.group + 1];
    if (at_list.size() != sh.size()) at_list.assign(sh.size(), -1);
    std::int32_t n = -1;
    if (t.shading >= 0) {
      std::int32_t& at = at_list[std::size_t(t.shading)];
      if (at < 0) {
        at = std::int32_t(attributes_.size());
        attributes_.push_back(attributes_of(sh[std::size_t(t.shading)]));
      }
      n = at;
    }
    triangles_[k] = {t.p, t.material, n};
    triangle_index_.push_back(o.index + (own ? first_triangle
                                             : std::uint32_t(groups[o.group].spheres.size() +
                                                             groups[o.group].quads.size())));
  }
  for (const object_slot o : tree.slots[shape_disk]) {
    const bool own = o.group == world_objects;
    const object_group* g = own ? nullptr : &groups[o.group];
    const disk& d = own ? objects.disks[o.index] : g->disks[o.index];
    disks_.push_back({d.geometry(), d.material});
    disk_index_.push_back(
        o.index + (own ? first_disk
                       : std::uint32_t(g->spheres.size() + g->quads.size() + g->triangles.size())));
  }
  instances_.reserve(instances.size());
  for (const instance& i : instances)
    instances_.push_back({frame_of(i.placement), tree.groups[i.group].root});
}

// Tests the object of leaf reference `ref`, keeping the nearest hit.
inline void bvh_world::visit(std::uint32_t ref, const ray& r, const sheared_ray& sheared,
                             double t_min, nearest& best) const {
  if ((ref & RTVK_LEAF_KIND_MASK) != RTVK_LEAF_SPHERE) {
    if ((ref & RTVK_LEAF_KIND_MASK) == RTVK_LEAF_INSTANCE)
      return enter(ref & RTVK_LEAF_INDEX_MASK, r, t_min, best);
    return visit_flat(ref, r, sheared, t_min, best);
  }
  const std::uint32_t k = ref & RTVK_LEAF_INDEX_MASK;
  double t;
  if (hit_sphere(center_at(k, spheres_, velocities_, r.time), spheres_[k].radius, r, t_min, best.t,
                 t))
    best.offer(t, sphere_index_[k], ref);
}

// Quads, triangles and disks, out of the sphere path's way: a scene of spheres keeps the loop it
// had.
void bvh_world::visit_flat(std::uint32_t ref, const ray& r, const sheared_ray& sheared,
                           double t_min, nearest& best) const {
  const std::uint32_t k = ref & RTVK_LEAF_INDEX_MASK;
  double t;
  if ((ref & RTVK_LEAF_KIND_MASK) == RTVK_LEAF_QUAD) {
    real2 uv;
    if (hit_quad(quads_[k].g, r, t_min, best.t, t, uv)) best.offer(t, quad_index_[k], ref);
    return;
  }
  if ((ref & RTVK_LEAF_KIND_MASK) == RTVK_LEAF_DISK) {
    if (hit_disk(disks_[k].g, r, t_min, best.t, t)) best.offer(t, disk_index_[k], ref);
    return;
  }
  const leaf_triangle& tri = triangles_[k];
  real3 weights;
  if (hit_triangle(tri.p[0], tri.p[1], tri.p[2], r, sheared, t_min, best.t, t, weights))
    best.offer(t, triangle_index_[k], ref);
}

// The ray in an instance's group space: the same t reaches the same point (the direction is
// not renormalized), at the same instant.

// Walks instance `i`'s group tree with the ray in group space: hits there count as the
// instance's.
void bvh_world::enter(std::uint32_t i, const ray& r, double t_min, nearest& best) const {
  const leaf_instance& in = instances_[i];
  const ray g = to_group(in.frame, r);
  const sheared_ray sheared = triangles_.empty() ? sheared_ray{} : shear_ray(g);
  const std::uint32_t outer = best.current;
  best.current = i + 1;
  walk(in.root, g, sheared, t_min, best, i);
  best.current = outer;
}

// The record of the winner, `best`: found in its group's space for an instance's object, then
// carried back (the point on the scene-space ray, the normal by the inverse transpose, the
// offset grown by the placement's stretch).
void bvh_world::record(const nearest& best, const ray& r, const sheared_ray& sheared,
                       hit_record& rec) const {
  if (best.instance != RTVK_OWN_OBJECTS) {
    const instance_frame& f = instances_[std::size_t(best.instance - 1)].frame;
    const ray g = to_group(f, r);
    nearest inner = best;
    inner.instance = RTVK_OWN_OBJECTS;
    record(inner, g, triangles_.empty() ? sheared_ray{} : shear_ray(g), rec);
    carry_back(f, r, best.t, rec);
    return;
  }
  const std::uint32_t k = best.ref & RTVK_LEAF_INDEX_MASK;
  switch (best.ref & RTVK_LEAF_KIND_MASK) {
    case RTVK_LEAF_SPHERE:
      record_hit(center_at(k, spheres_, velocities_, r.time), spheres_[k].radius,
                 uint(spheres_[k].material), r, best.t, with_uv_, rec);
      return;
    case RTVK_LEAF_QUAD:
      record_quad_hit(quads_[k].g, uint(quads_[k].material), r, best.t, rec);
      return;
    case RTVK_LEAF_DISK:
      record_disk_hit(disks_[k].g, uint(disks_[k].material), r, best.t, rec);
      return;
    default: {
      const leaf_triangle& tri = triangles_[k];
      record_triangle(tri.p, tri.shading < 0 ? nullptr : &attributes_[std::size_t(tri.shading)],
                      uint(tri.material), r, sheared, best.t, rec);
      return;
    }
  }
}

// At each wide node all four children's boxes are tested at once; the ray goes on into the
// nearest child it enters before the closest hit so far (a wide node, or a leaf whose object is
// then tested, or an instance whose group tree is then walked) and remembers the others with
// their entry distances. Remembered children behind the closest hit are dropped when they come
// up.
void bvh_world::walk(std::uint32_t root, const ray& r, const sheared_ray& sheared, double t_min,
                     nearest& best, std::int64_t) const {
  const ray_slabs slabs(r);
  const float box_min = widen_down(t_min);
  node_stack stack;
  std::uint32_t next = root;
  while (true) {
    if (next & wide_node::leaf_bit) {
      visit(next & ~wide_node::leaf_bit, r, sheared, t_min, best);
    } else {
      const wide_node& n = nodes_[next];
      float t[4];
      const unsigned entered = child_entries(n, slabs, box_min, widen_up(best.t), t);
      if (descend(n, entered, t, stack, next)) continue;
    }
    if (!pop_reachable(stack, widen_up(best.t), next)) break;
  }
}

bool bvh_world::hit(const ray& r, double t_min, double t_max, hit_record& rec) const {
  std::uint32_t object, instance;
  return hit_which(r, t_min, t_max, rec, object, instance);
}

bool bvh_world::hit_which(const ray& r, double t_min, double t_max, hit_record& rec,
                          std::uint32_t& object, std::uint32_t& instance) const {
  if (nodes_.empty()) return false;
  const sheared_ray sheared = triangles_.empty() ? sheared_ray{} : shear_ray(r);
  nearest best{t_max};
  walk(0, r, sheared, t_min, best, -1);
  if (best.index < 0) return false;
  record(best, r, sheared, rec);
  object = std::uint32_t(best.index);
  instance = best.instance;
  return true;
}

}  // namespace rtvk
