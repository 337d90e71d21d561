// The closest hit over the world's spheres: through the binary BVH, or every sphere in turn as
// hittable_list::hit does. The sphere math is the shared kernels' (hit_sphere.h); the traversal is
// the GPU's own (bvh.glsl says why). Expects `spheres`
// (gpu_sphere[]: in the BVH's leaf order with use_bvh, else in scene order), `bvh_nodes`, `pc`
// (render_push) and the specialization constant `use_bvh` declared by the including shader.
#ifndef RTVK_WORLD_GLSL
#define RTVK_WORLD_GLSL
#include "bvh.glsl"
#include "hit_sphere.h"

// Tests the sphere in slot k, keeping the nearest hit (`closest`; `best` its scene index,
// `best_slot` its slot). Ties go to the later sphere in the scene.
void test_sphere(uint k, ray r, float t_min, precise inout float closest, inout int best,
                 inout uint best_slot) {
  precise float t;
  int i = int(spheres[k].scene_index);
  if (hit_sphere(spheres[k].center, spheres[k].radius, r, t_min, closest, t) &&
      (t < closest || i > best)) {
    closest = t;
    best = i;
    best_slot = k;
  }
}

// Tests spheres first .. first + count - 1 of a leaf. False
// when the loop budget ran out.
bool visit_leaf(uint first, uint count, ray r, float t_min, precise inout float closest,
                inout int best, inout uint best_slot, inout uint iterations) {
  for (uint k = first; k < first + count; ++k) {
    if (++iterations > pc.loop_budget) return false;
    test_sphere(k, r, t_min, closest, best, best_slot);
  }
  return true;
}

// A remembered child on the stack: x its node index or first sphere slot, y its entry distance's
// bits with the top bit, the float's sign bit (entry distances are never below 0), set for a
// leaf, which holds RTVK_BVH_LEAF spheres.
const uint stack_leaf = 0x80000000u;

// As bvh_world::hit, with the binary tree: the nearest child first, remembered children behind the
// closest hit dropped, ties to the later sphere (so the winner does not depend on the order of
// visits, which differs from the CPU's four-wide walk), the record filled once for the winner. One node fetch brings both children's
// boxes and references. The loop is flat -- each trip visits one node or leaf, or drops one
// remembered child that is now behind the closest hit -- so the invocations of a SIMD group
// (lavapipe's 8 lanes, a warp) step together instead of waiting for each other in nested loops;
// each trip counts one iteration against the loop budget, as each visit and each drop does on
// the host's side of the mirror.
bool hit_bvh(ray r, float t_min, float t_max, precise inout hit_record rec, inout uint iterations) {
  if (pc.sphere_count == 0u) return false;
  precise vec3 o = r.origin;
  precise vec3 inv_d = safe_inverse(r.direction);
  precise float margin = origin_margin(o);
  precise float box_min = t_min * (1.0 - 1.0 / 1048576.0);
  uvec2 stack[RTVK_BVH_STACK];
  int top = 0;
  uint next = 0u;           // the child to visit: node index, or first sphere slot
  uint next_count = 0u;     // 0 for an interior node, else the leaf's spheres
  float next_entry = 0.0;   // where the ray enters it (the root: 0, always visited)
  precise float closest = t_max;
  int best = -1;
  uint best_slot = 0u;
  while (true) {
    if (++iterations > pc.loop_budget) return false;
    precise float box_max = closest * (1.0 + 1.0 / 1048576.0);
    bool pop = true;
    if (next_entry > box_max) {
      // remembered before a closer hit was found: dropped unvisited
    } else if (next_count == 0u) {
      bvh_node n = bvh_nodes[next];
      precise vec2 t = child_entries(o, inv_d, n, box_min, box_max, margin);
      // Nearer first: a is the nearer child when the ray enters both.
      uint a = t.x <= t.y ? 0u : 1u;
      uint b = 1u - a;
      if (t[a] >= 0.0 && t[b] >= 0.0) {
        uint leaf = n.count[b] > 0u ? stack_leaf : 0u;  // over the sign bit of a -0 entry too
        stack[top++] = uvec2(n.first[b], (floatBitsToUint(t[b]) & ~stack_leaf) | leaf);
      }
      if (t[a] >= 0.0 || t[b] >= 0.0) {
        uint c = t[a] >= 0.0 ? a : b;
        next = n.first[c];
        next_count = n.count[c];
        next_entry = 0.0;  // entered now, before any closer hit can be found
        pop = false;
      }
    } else {
#if RTVK_BVH_LEAF == 1
      // One sphere: visit_leaf without its loop.
      if (++iterations > pc.loop_budget) return false;
      test_sphere(next, r, t_min, closest, best, best_slot);
#else
      if (!visit_leaf(next, next_count, r, t_min, closest, best, best_slot, iterations))
        return false;
#endif
    }
    if (!pop) continue;
    if (top == 0) break;
    --top;
    next = stack[top].x;
    next_count = (stack[top].y & stack_leaf) != 0u ? uint(RTVK_BVH_LEAF) : 0u;
    next_entry = uintBitsToFloat(stack[top].y & ~stack_leaf);
  }
  if (best < 0) return false;
  gpu_sphere s = spheres[best_slot];
  record_hit(s.center, s.radius, s.material, r, closest, rec);
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
    if (hit_sphere(spheres[i].center, spheres[i].radius, r, t_min, closest_so_far, t)) {
      hit_anything = true;
      closest_so_far = t;
      closest_sphere = i;
    }
  }
  if (hit_anything) {
    gpu_sphere s = spheres[closest_sphere];
    record_hit(s.center, s.radius, s.material, r, closest_so_far, rec);
  }
  return hit_anything;
}

#endif
