// The closest hit over the world's spheres: through the four-wide BVH the CPU walks too, or every
// sphere in turn as hittable_list::hit does. The sphere math is the shared kernels'
// (hit_sphere.h); the walk is the GPU's own (bvh.glsl says why). Expects `spheres`
// (gpu_sphere[]: in the BVH's leaf order with use_bvh, else in scene order), `bvh_nodes`
// (bvh_wide_node[]), `pc`
// (render_push) and the specialization constant `use_bvh` declared by the including shader.
#ifndef RTVK_WORLD_GLSL
#define RTVK_WORLD_GLSL
#include "bvh.glsl"
#include "hit_disk.h"
#include "hit_quad.h"
#include "hit_sphere.h"
#include "hit_triangle.h"
#include "instance_space.h"

// Whether some sphere moves: without, the velocities (`velocities`, vec4[] in the spheres' order)
// are never read. The host sets it for
// render.comp; the probes leave it off.
layout(constant_id = RTVK_SPEC_MOTION) const bool motion = false;
// Whether the scene has quads, triangles: without, their tests are compiled out.
layout(constant_id = RTVK_SPEC_QUADS) const bool any_quads = false;
layout(constant_id = RTVK_SPEC_TRIANGLES) const bool any_triangles = false;
layout(constant_id = RTVK_SPEC_DISKS) const bool any_disks = false;
// Whether the scene has instances: without, no walk enters a group's tree.
layout(constant_id = RTVK_SPEC_INSTANCES) const bool any_instances = false;
// Whether sphere hits find their texture coordinates (some image texture reads them).
layout(constant_id = RTVK_SPEC_UV) const bool with_uv = false;
// The entries of hit_bvh's stack a walk may use: 0, all RTVK_WIDE_STACK (a test makes it less
// to force an overflow).
layout(constant_id = RTVK_SPEC_STACK) const uint stack_entries = 0u;
// Set when a walk found its stack full: it stopped, and render_body.glsl drops the sample.
bool stack_overflowed = false;
// A shadow ray's search whose first hit decides it (shading.glsl): it ends at that hit.
bool first_hit_ends = false;

// Where the sphere in slot k is at `time` (sphere::center_at).
precise vec3 center_at(uint k, float time) {
  return motion ? moved_center(spheres[k].center, velocities[k].xyz, time) : spheres[k].center;
}

// The quad at position k with its plane, as the shared kernels take it.
quad_geometry quad_at(uint k) {
  quad_geometry g;
  g.Q = quads[k].Q;
  g.u = quads[k].u;
  g.v = quads[k].v;
  g.normal = quads[k].normal;
  g.w = quads[k].w;
  g.D = quads[k].D;
  return g;
}

// The disk at position k with its plane and axes, as the shared kernels take it.
disk_geometry disk_at(uint k) {
  disk_geometry g;
  g.center = disks[k].center;
  g.normal = disks[k].normal;
  g.u = disks[k].u;
  g.v = disks[k].v;
  g.radius = disks[k].radius;
  g.D = disks[k].D;
  return g;
}

// Which object the last hit found was (its scan-order key) and the instance + 1 it was reached
// through (0: the scene's own): aov.comp reads them; elsewhere the stores are dead and dropped.
uint hit_object;
uint hit_instance;

// Instance k's placement as the shared kernels read it (instance_space.h: to_group, carry_back).
instance_frame frame_of(uint k) {
  instance_frame f;
  f.to_group_x = instances[k].to_group_x.xyz;
  f.to_group_y = instances[k].to_group_y.xyz;
  f.to_group_z = instances[k].to_group_z.xyz;
  f.to_group_offset =
      vec3(instances[k].to_group_x.w, instances[k].to_group_y.w, instances[k].to_group_z.w);
  f.normal_x = instances[k].normal_x.xyz;
  f.normal_y = instances[k].normal_y.xyz;
  f.normal_z = instances[k].normal_z.xyz;
  f.stretch = instances[k].normal_x.w;
  return f;
}

// Tests the object of leaf reference `ref` (RTVK_LEAF_* kind | position), keeping the nearest
// hit (`closest`; `best` its index in the scan order, `best_ref` its reference, `best_inst` the
// instance + 1 it was reached through, 0 for the scene's own). Ties go to the later object in
// the scan: the scene's own, then each instance's. The kinds a scene lacks are compiled out.
void test_object(uint ref, ray r, sheared_ray sr, float t_min, precise inout float closest,
                 inout int best, inout uint best_ref, uint inst, inout uint best_inst) {
  uint k = ref & RTVK_LEAF_INDEX_MASK;
  uint kind = ref & RTVK_LEAF_KIND_MASK;
  precise float t;
  int i;  // the object's scene index, read only when it is hit
  if ((!any_quads && !any_triangles && !any_disks) || kind == RTVK_LEAF_SPHERE) {
    if (!hit_sphere(center_at(k, r.time), spheres[k].radius, r, t_min, closest, t)) return;
    i = int(spheres[k].scene_index);
  } else if (any_quads && (kind == RTVK_LEAF_QUAD || (!any_triangles && !any_disks))) {
    precise vec2 uv;
    if (!hit_quad(quad_at(k), r, t_min, closest, t, uv)) return;
    i = int(quads[k].scene_index);
  } else if (any_disks && (kind == RTVK_LEAF_DISK || !any_triangles)) {
    if (!hit_disk(disk_at(k), r, t_min, closest, t)) return;
    i = int(disks[k].scene_index);
  } else {
    precise vec3 weights;
    if (!hit_triangle(triangles[k].a, triangles[k].b, triangles[k].c, r, sr, t_min, closest, t,
                      weights))
      return;
    i = int(triangles[k].scene_index);
  }
  if (t < closest || later_in_scan(inst, i, best_inst, best)) {
    closest = t;
    best = i;
    best_ref = ref;
    best_inst = inst;
  }
}

// The record of a hit at t on the object of leaf reference `ref` (host/cpu/bvh_world.cpp's
// bvh_world::record).
void record_object(uint ref, ray r, sheared_ray sr, float t, precise inout hit_record rec) {
  uint k = ref & RTVK_LEAF_INDEX_MASK;
  uint kind = ref & RTVK_LEAF_KIND_MASK;
  if ((!any_quads && !any_triangles && !any_disks) || kind == RTVK_LEAF_SPHERE) {
    record_hit(center_at(k, r.time), spheres[k].radius, spheres[k].material, r, t, with_uv, rec);
  } else if (any_quads && (kind == RTVK_LEAF_QUAD || (!any_triangles && !any_disks))) {
    record_quad_hit(quad_at(k), quads[k].material, r, t, rec);
  } else if (any_disks && (kind == RTVK_LEAF_DISK || !any_triangles)) {
    record_disk_hit(disk_at(k), disks[k].material, r, t, rec);
  } else {
    gpu_triangle tri = triangles[k];
    // The blend's weights found again, as on the CPU (hittable_triangle.h's record_triangle).
    precise float again;
    precise vec3 weights = vec3(0.0);
    bool found = hit_triangle(tri.a, tri.b, tri.c, r, sr, -3.402823466e+38, 3.402823466e+38, again,
                              weights);
    bool shaded = tri.normals != RTVK_FLAT;
    bool blended = found && shaded && vertex_normals[3u * tri.normals].w != 0.0;
    bool has_uv = shaded && (uint(vertex_normals[3u * tri.normals + 1u].w) & 1u) != 0u;
    vec3 n0 = vec3(0.0), n1 = vec3(0.0), n2 = vec3(0.0);  // read only where they exist
    if (blended) {
      n0 = vertex_normals[3u * tri.normals].xyz;
      n1 = vertex_normals[3u * tri.normals + 1u].xyz;
      n2 = vertex_normals[3u * tri.normals + 2u].xyz;
    }
    vec2 uv0 = vec2(0.0), uv1 = vec2(0.0), uv2 = vec2(0.0);
    if (has_uv) {
      uv0 = vertex_uvs[3u * tri.normals];
      uv1 = vertex_uvs[3u * tri.normals + 1u];
      uv2 = vertex_uvs[3u * tri.normals + 2u];
    }
    precise vec3 shading = shading_normal(tri.a, tri.b, tri.c, blended, n0, n1, n2, weights);
    precise vec2 uv = triangle_uv(has_uv, uv0, uv1, uv2, weights);
    record_triangle_hit(tri.a, tri.b, tri.c, shading, uv, tri.material, r, t, rec);
    record_vertex_extras(tri.normals, weights, rec);
  }
}

// The winner's record: made in its instance's group space when it was reached through one.
void record_winner(uint ref, uint inst, ray r, sheared_ray sr, float t,
                   precise inout hit_record rec) {
  if (any_instances && inst != 0u) {
    instance_frame f = frame_of(inst - 1u);
    ray g = to_group(f, r);
    sheared_ray gs;
    if (any_triangles) gs = shear_ray(g);
    record_object(ref, g, gs, t, rec);
    carry_back(f, r, t, rec);
    return;
  }
  record_object(ref, r, sr, t, rec);
}

// Puts (key, id) pairs a and b in ascending order of key.
void order_pair(inout uint ka, inout uint ia, inout uint kb, inout uint ib) {
  if (kb < ka) {
    uint k = ka;
    ka = kb;
    kb = k;
    uint i = ia;
    ia = ib;
    ib = i;
  }
}

// A child's sort key: the bits of its entry distance, which order like the distances for floats
// that are not negative; NaN and infinity (a ray from infinity) become the largest finite
// distance, still before every child not entered (which sort last). Integers, so a NaN cannot
// make a child not entered sort among those entered and be visited (and a driver's
// assumption of no NaN cannot break the order).
uint sort_key(bool entered, float t) {
  return entered ? min(floatBitsToUint(t) & 0x7fffffffu, 0x7f7fffffu) : 0xffffffffu;
}

// As bvh_world::hit, over the same four-wide tree: all four children's boxes tested at once, the
// nearest entered child visited next and the others remembered with their entry distances,
// remembered children behind the closest hit dropped, ties to the later sphere, the record
// filled once for the winner. The loop is flat (each trip visits one node or leaf, or drops one
// remembered child now behind the closest hit), so a SIMD group's invocations step together,
// each trip one iteration of the loop budget (13 to 15% faster than a binary tree on lavapipe).
bool hit_bvh(ray r, float t_min, float t_max, precise inout hit_record rec, inout uint iterations) {
  if (pc.sphere_count + pc.quad_count + pc.triangle_count + pc.disk_count + pc.instance_count == 0u)
    return false;
  sheared_ray world_sr, sr;
  if (any_triangles) world_sr = shear_ray(r);
  sr = world_sr;
  // The ray of the tree being walked: the scene's, or inside an instance its group's (`inst`:
  // that instance + 1, 0 for the scene's own tree).
  ray rc = r;
  uint inst = 0u;
  precise vec3 o = r.origin;
  precise vec3 inv_d = safe_inverse(r.direction);
  precise float margin = origin_margin(o);
  precise float box_min = t_min * (1.0 - 1.0 / 1048576.0);
  // The host's builder caps the tree's depth so that RTVK_WIDE_STACK is enough; each push is
  // bounded all the same, so a deeper tree is a sample dropped and counted, never a write past
  // the stack or a wrong hit.
  int room = int(stack_entries == 0u ? RTVK_WIDE_STACK : min(stack_entries, RTVK_WIDE_STACK));
  uint stack_node[RTVK_WIDE_STACK];
  float stack_entry[RTVK_WIDE_STACK];
  int top = 0;
  uint next = 0u;          // the root
  float next_entry = 0.0;  // where the ray enters it
  precise float closest = t_max;
  int best = -1;
  uint best_ref = 0u;
  uint best_inst = 0u;
  while (true) {
    if (++iterations > pc.loop_budget) return false;
    precise float box_max = closest * (1.0 + 1.0 / 1048576.0);
    bool pop = true;
    if (any_instances && next == RTVK_WIDE_EXIT) {
      // out of an instance's group tree: the scene's ray again
      rc = r;
      inst = 0u;
      o = r.origin;
      inv_d = safe_inverse(r.direction);
      margin = origin_margin(o);
      sr = world_sr;
    } else if (next_entry > box_max) {
      // remembered before a closer hit was found: dropped unvisited
    } else if (any_instances && (next & (RTVK_WIDE_LEAF | RTVK_LEAF_KIND_MASK)) ==
                                    (RTVK_WIDE_LEAF | RTVK_LEAF_INSTANCE)) {
      // into an instance's group tree, with the ray in its space, until the marker comes off
      uint k = next & RTVK_LEAF_INDEX_MASK;
      if (top >= room) {
        stack_overflowed = true;
        return false;
      }
      stack_node[top] = RTVK_WIDE_EXIT;
      stack_entry[top++] = 0.0;
      rc = to_group(frame_of(k), r);
      inst = k + 1u;
      o = rc.origin;
      inv_d = safe_inverse(rc.direction);
      margin = origin_margin(o);
      if (any_triangles) sr = shear_ray(rc);
      next = instances[k].root;
      next_entry = 0.0;
      pop = false;
    } else if ((next & RTVK_WIDE_LEAF) != 0u) {
      test_object(next & ~RTVK_WIDE_LEAF, rc, sr, t_min, closest, best, best_ref, inst, best_inst);
      if (first_hit_ends && best >= 0) break;
    } else {
      bvh_wide_node n = bvh_nodes[next];
      precise vec4 t;
      uint entered = wide_entries(o, inv_d, n, box_min, box_max, margin, t);
      if (entered != 0u) {
        // The entered children in ascending order of entry (a sorting network on integer keys:
        // no branches to diverge on), the others last; the nearest is visited next, the rest remembered with
        // the farthest deepest.
        uint k0 = sort_key((entered & 1u) != 0u, t.x), k1 = sort_key((entered & 2u) != 0u, t.y);
        uint k2 = sort_key((entered & 4u) != 0u, t.z), k3 = sort_key((entered & 8u) != 0u, t.w);
        uint i0 = 0u, i1 = 1u, i2 = 2u, i3 = 3u;
        order_pair(k0, i0, k1, i1);
        order_pair(k2, i2, k3, i3);
        order_pair(k0, i0, k2, i2);
        order_pair(k1, i1, k3, i3);
        order_pair(k1, i1, k2, i2);
        int count = bitCount(entered);
        if (top + count - 1 > room) {
          stack_overflowed = true;
          return false;
        }
        if (count > 3) {
          stack_node[top] = n.child[i3];
          stack_entry[top++] = uintBitsToFloat(k3);
        }
        if (count > 2) {
          stack_node[top] = n.child[i2];
          stack_entry[top++] = uintBitsToFloat(k2);
        }
        if (count > 1) {
          stack_node[top] = n.child[i1];
          stack_entry[top++] = uintBitsToFloat(k1);
        }
        next = n.child[i0];
        next_entry = 0.0;  // entered now, before any closer hit can be found
        pop = false;
      }
    }
    if (!pop) continue;
    if (top == 0) break;
    --top;
    next = stack_node[top];
    next_entry = stack_entry[top];
  }
  if (best < 0) return false;
  record_winner(best_ref, best_inst, r, world_sr, closest, rec);
  hit_object = uint(best);
  hit_instance = best_inst;
  return true;
}

#include "world_rt.glsl"

#ifndef RTVK_RT_OBJECT_STAGE
// The closest hit over every object, as hittable_list::hit (or, with use_bvh, as
// bvh_world::hit; on the hardware paths, through the driver's acceleration structure). Each
// iteration counts against the loop budget; over budget, the search stops and `iterations` tells
// the caller.
bool hit_world(ray r, float t_min, float t_max, precise inout hit_record rec,
               inout uint iterations) {
#if defined(RTVK_RAY_QUERY) || defined(RTVK_RAY_PIPELINE)
  return hit_hardware(r, t_min, t_max, rec, iterations);
#endif
  if (use_bvh) return hit_bvh(r, t_min, t_max, rec, iterations);
  sheared_ray sr;
  if (any_triangles) sr = shear_ray(r);
  precise float closest = t_max;
  int best = -1;
  uint best_ref = 0u;
  uint best_inst = 0u;
  // Scene order: each hit is as near as any before it, and later, so it wins (the scan's tie
  // rule) without comparing scene indices. Spheres in a loop of their own, as tight as before
  // quads and triangles came: --accel none renders of spheres keep their speed.
  for (uint i = 0u; i < pc.sphere_count; ++i) {
    if (++iterations > pc.loop_budget) return false;
    precise float t;
    if (hit_sphere(center_at(i, r.time), spheres[i].radius, r, t_min, closest, t)) {
      closest = t;
      best = int(i);
      best_ref = RTVK_LEAF_SPHERE | i;
    }
  }
  if (any_quads)
    for (uint i = 0u; i < pc.quad_count; ++i) {
      if (++iterations > pc.loop_budget) return false;
      test_object(RTVK_LEAF_QUAD | i, r, sr, t_min, closest, best, best_ref, 0u, best_inst);
    }
  if (any_triangles)
    for (uint i = 0u; i < pc.triangle_count; ++i) {
      if (++iterations > pc.loop_budget) return false;
      test_object(RTVK_LEAF_TRIANGLE | i, r, sr, t_min, closest, best, best_ref, 0u, best_inst);
    }
  if (any_disks)
    for (uint i = 0u; i < pc.disk_count; ++i) {
      if (++iterations > pc.loop_budget) return false;
      test_object(RTVK_LEAF_DISK | i, r, sr, t_min, closest, best, best_ref, 0u, best_inst);
    }
  // Then each instance's group, with the ray in its space.
  if (any_instances)
    for (uint k = 0u; k < pc.instance_count; ++k) {
      ray g = to_group(frame_of(k), r);
      sheared_ray gs;
      if (any_triangles) gs = shear_ray(g);
      for (uint i = 0u; i < instances[k].sphere_count; ++i) {
        if (++iterations > pc.loop_budget) return false;
        test_object(RTVK_LEAF_SPHERE | (instances[k].sphere_first + i), g, gs, t_min, closest, best,
                    best_ref, k + 1u, best_inst);
      }
      if (any_quads)
        for (uint i = 0u; i < instances[k].quad_count; ++i) {
          if (++iterations > pc.loop_budget) return false;
          test_object(RTVK_LEAF_QUAD | (instances[k].quad_first + i), g, gs, t_min, closest, best,
                      best_ref, k + 1u, best_inst);
        }
      if (any_triangles)
        for (uint i = 0u; i < instances[k].triangle_count; ++i) {
          if (++iterations > pc.loop_budget) return false;
          test_object(RTVK_LEAF_TRIANGLE | (instances[k].triangle_first + i), g, gs, t_min, closest,
                      best, best_ref, k + 1u, best_inst);
        }
      if (any_disks)
        for (uint i = 0u; i < instances[k].disk_count; ++i) {
          if (++iterations > pc.loop_budget) return false;
          test_object(RTVK_LEAF_DISK | (instances[k].disk_first + i), g, gs, t_min, closest, best,
                      best_ref, k + 1u, best_inst);
        }
    }
  if (best < 0) return false;
  record_winner(best_ref, best_inst, r, sr, closest, rec);
  hit_object = uint(best);
  hit_instance = best_inst;
  return true;
}
#endif

#endif
