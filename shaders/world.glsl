// Mirrors bvh_world::hit (host/cpu/bvh_world.cpp) and hittable_list::hit. Expects `spheres`
// (gpu_sphere[]), `bvh_nodes`, `bvh_index`, `pc` (render_push) and the specialization constant
// `use_bvh` declared by the including shader.
#ifndef RTVK_WORLD_GLSL
#define RTVK_WORLD_GLSL
#include "sphere.glsl"

// Mirrors bvh_world::hit: the same nodes, the same order, ties to the later sphere, the record
// filled once for the winner. Every node visit and sphere test counts against the loop budget.
bool hit_bvh(ray r, float t_min, float t_max, precise inout hit_record rec, inout uint iterations) {
  if (pc.sphere_count == 0u) return false;
  precise vec3 o = r.origin;
  precise vec3 inv_d = safe_inverse(r.direction);
  precise float margin = origin_margin(o);
  precise float box_min = t_min * (1.0 - 1.0 / 1048576.0);
  uint stack_node[RTVK_BVH_STACK];
  float stack_entry[RTVK_BVH_STACK];
  int top = 0;
  uint node = 0u;
  precise float closest = t_max;
  int best = -1;
  while (true) {
    if (++iterations > pc.loop_budget) return false;
    bvh_node n = bvh_nodes[node];
    if (n.count > 0u) {
      for (uint k = n.first; k < n.first + n.count; ++k) {
        if (++iterations > pc.loop_budget) return false;
        uint i = bvh_index[k];
        precise float t;
        if (hit_distance(spheres[i], r, t_min, closest, t) && (t < closest || int(i) > best)) {
          closest = t;
          best = int(i);
        }
      }
    } else {
      precise float box_max = closest * (1.0 + 1.0 / 1048576.0);
      uint left = node + 1u;
      uint right = n.first;
      precise float t_left = ray_box_entry(o, inv_d, bvh_nodes[left], box_min, box_max, margin);
      precise float t_right = ray_box_entry(o, inv_d, bvh_nodes[right], box_min, box_max, margin);
      if (t_left >= 0.0 && t_right >= 0.0) {
        bool left_first = t_left <= t_right;
        stack_node[top] = left_first ? right : left;
        stack_entry[top] = left_first ? t_right : t_left;
        ++top;
        node = left_first ? left : right;
        continue;
      }
      if (t_left >= 0.0 || t_right >= 0.0) {
        node = t_left >= 0.0 ? left : right;
        continue;
      }
    }
    precise float box_max = closest * (1.0 + 1.0 / 1048576.0);
    while (top > 0 && stack_entry[top - 1] > box_max) {
      if (++iterations > pc.loop_budget) return false;
      --top;
    }
    if (top == 0) break;
    node = stack_node[--top];
  }
  if (best < 0) return false;
  record_hit(spheres[best], r, closest, rec);
  return true;
}

// The closest hit over every sphere, as hittable_list::hit (or, with use_bvh, as
// bvh_world::hit).
// Each iteration counts against the loop budget; over budget, the search stops and `iterations`
// tells the caller.
bool hit_world(ray r, float t_min, float t_max, precise inout hit_record rec,
               inout uint iterations) {
  if (use_bvh) return hit_bvh(r, t_min, t_max, rec, iterations);
  bool hit_anything = false;
  precise float closest_so_far = t_max;
  uint closest_sphere = 0u;
  for (uint i = 0u; i < pc.sphere_count; ++i) {
    if (++iterations > pc.loop_budget) return false;
    precise float t;
    if (hit_distance(spheres[i], r, t_min, closest_so_far, t)) {
      hit_anything = true;
      closest_so_far = t;
      closest_sphere = i;
    }
  }
  if (hit_anything) record_hit(spheres[closest_sphere], r, closest_so_far, rec);
  return hit_anything;
}

#endif
