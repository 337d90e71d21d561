// The world searched through the driver's acceleration structure (--accel rt-query and
// rt-pipeline), built by host/gpu/scene/scene_accel.cpp: in the top level the scene's own objects
// (custom index 0) and each instance k (custom index k + 1, its placement as the instance's
// transform); in each bottom level one geometry of boxes -- the group's spheres, quads, disks --
// and one of triangles, which the driver tests itself. The driver only proposes candidates: each
// is tested by the very test_object the compute BVH calls, on the ray in its group's space as
// frame_of and to_group make it, and the nearest is kept by test_object's tie rule. So the hit and
// its t are the compute path's, bit for bit; only a triangle the driver's own test misses (at an
// edge, by rounding) can differ. Included by world.glsl.
#ifndef RTVK_WORLD_RT_GLSL
#define RTVK_WORLD_RT_GLSL

#if defined(RTVK_RAY_QUERY) || defined(RTVK_RAY_PIPELINE) || defined(RTVK_RT_OBJECT_STAGE)

#ifndef RTVK_RT_OBJECT_STAGE
layout(set = 0, binding = RTVK_BINDING_TLAS) uniform accelerationStructureEXT tlas;
#endif

// The leaf reference (RTVK_LEAF_* kind | position) of a candidate: primitive `p` of instance
// `inst`'s box geometry (`box`) or triangle geometry; `inst` 0 is the scene's own objects.
uint candidate_ref(uint inst, bool box, uint p) {
  uint sphere_first = 0u, sphere_count = pc.sphere_count, quad_first = 0u,
       quad_count = pc.quad_count, triangle_first = 0u, disk_first = 0u;
  if (any_instances && inst != 0u) {
    sphere_first = instances[inst - 1u].sphere_first;
    sphere_count = instances[inst - 1u].sphere_count;
    quad_first = instances[inst - 1u].quad_first;
    quad_count = instances[inst - 1u].quad_count;
    triangle_first = instances[inst - 1u].triangle_first;
    disk_first = instances[inst - 1u].disk_first;
  }
  if (!box) return RTVK_LEAF_TRIANGLE | (triangle_first + p);
  if (p < sphere_count) return RTVK_LEAF_SPHERE | (sphere_first + p);
  if (p < sphere_count + quad_count) return RTVK_LEAF_QUAD | (quad_first + p - sphere_count);
  return RTVK_LEAF_DISK | (disk_first + p - sphere_count - quad_count);
}

// The ray in the space of instance `inst`'s group, as hit_bvh makes it (0: the scene's ray).
ray group_ray(uint inst, ray r) {
  return (any_instances && inst != 0u) ? to_group(frame_of(inst - 1u), r) : r;
}

// The nearest hit so far, as hit_bvh keeps it: what the hardware paths carry through a traversal
// (rt-pipeline: the ray's payload, which the any-hit shader updates).
struct nearest_hit {
  float closest;   // its t
  int best;        // its object's scene index (the tie rule's key); -1: none yet
  uint best_ref;   // its leaf reference
  uint best_inst;  // the instance + 1 it was reached through; 0: the scene's own
  uint trips;      // rt-pipeline: candidates the any-hit shader may still test (loop budget)
};

// hit_world's answer once the traversal is over: the nearest hit's record, made as hit_bvh makes
// it (in its instance's space when it was reached through one), and the AOVs' ids.
bool record_nearest(nearest_hit n, ray r, precise inout hit_record rec) {
  if (n.best < 0) return false;
  sheared_ray world_sr;
  if (any_triangles) world_sr = shear_ray(r);
  record_winner(n.best_ref, n.best_inst, r, world_sr, n.closest, rec);
  hit_object = uint(n.best);
  hit_instance = n.best_inst;
  return true;
}

// Whether a ray may go to the driver: the specification asks for a finite origin and direction
// (anything else is undefined, a hang on some GPUs); the compute path takes any ray, so the
// others take its walk instead (the BVH is built and uploaded on every path) and find what it
// finds.
bool driver_takes(ray r) {
  return is_finite(r.origin.x) && is_finite(r.origin.y) && is_finite(r.origin.z) &&
         is_finite(r.direction.x) && is_finite(r.direction.y) && is_finite(r.direction.z);
}

// Tests candidate `ref` of instance `inst` on ray `g` (in that instance's group space) with
// test_object, updating `n`; true when it became the nearest.
bool try_candidate(uint ref, uint inst, ray g, float t_min, inout nearest_hit n) {
  sheared_ray sr;
  if (any_triangles) sr = shear_ray(g);
  precise float closest = n.closest;
  int best = n.best;
  uint best_ref = n.best_ref, best_inst = n.best_inst;
  test_object(ref, g, sr, t_min, closest, best, best_ref, inst, best_inst);
  if (best == n.best && best_ref == n.best_ref && best_inst == n.best_inst && closest == n.closest)
    return false;
  n.closest = closest;
  n.best = best;
  n.best_ref = best_ref;
  n.best_inst = best_inst;
  return true;
}

// The invocation's slot in the band's buffers (render_body.glsl's `index`), from its launch id.
uint launch_slot(uvec3 id) {
  return (id.z * pc.band_rows + pc.sums_row0 + id.y) * pc.region_width + id.x;
}

#ifdef RTVK_RAY_QUERY
// hit_world through a ray query: each candidate proposed is tested as above; a box whose object
// becomes the nearest is committed at our t, a triangle at the driver's (which only bounds the
// rest of the traversal). Each candidate counts a trip against the loop budget, and each ray
// pc.trace_cost more for the driver's own loop.
bool hit_hardware(ray r, float t_min, float t_max, precise inout hit_record rec,
                  inout uint iterations) {
  if (!driver_takes(r)) return hit_bvh(r, t_min, t_max, rec, iterations);
  iterations += pc.trace_cost;
  nearest_hit n = nearest_hit(t_max, -1, 0u, 0u, 0u);
  float committed = t_max;  // the driver's bound on the traversal
  uint inst = 0u;           // the instance of the last candidate, whose group ray `g` is
  ray g = r;
  rayQueryEXT q;
  rayQueryInitializeEXT(q, tlas, gl_RayFlagsNoneEXT, 0xffu, r.origin, t_min, r.direction, t_max);
  while (rayQueryProceedEXT(q)) {
    if (++iterations > pc.loop_budget) {
      rayQueryTerminateEXT(q);
      return false;
    }
    uint at = rayQueryGetIntersectionInstanceCustomIndexEXT(q, false);
    if (at != inst) {
      inst = at;
      g = group_ray(inst, r);
    }
    bool box = rayQueryGetIntersectionTypeEXT(q, false) == gl_RayQueryCandidateIntersectionAABBEXT;
    uint ref = candidate_ref(inst, box, rayQueryGetIntersectionPrimitiveIndexEXT(q, false));
    if (!try_candidate(ref, inst, g, t_min, n)) continue;
    if (first_hit_ends) {  // a shadow ray in a scene whose every hit blocks it: decided
      rayQueryTerminateEXT(q);
      break;
    }
    if (!box) {
      rayQueryConfirmIntersectionEXT(q);
      committed = min(committed, rayQueryGetIntersectionTEXT(q, false));
    } else if (n.closest < committed) {
      rayQueryGenerateIntersectionEXT(q, n.closest);
      committed = n.closest;
    }
  }
  return record_nearest(n, r, rec);
}
#endif

#ifdef RTVK_RAY_PIPELINE
// Each launch's ray time, for the intersection and any-hit shaders, which cannot read the payload's
// caller (written only when some sphere moves).
layout(std430, set = 0, binding = RTVK_BINDING_RAY_TIMES) shadercallcoherent buffer ray_time_block {
  float ray_times[];
};
layout(location = 0) rayPayloadEXT nearest_hit traced;

// hit_world through traceRayEXT: rt_object.rint proposes the boxes' hits, rt_object.rahit tests
// every candidate as the ray query does and keeps the nearest in the payload. Each ray counts
// pc.trace_cost iterations against the loop budget, and each candidate the any-hit shader tests
// one more: it ends the traversal when the budget is spent, and the ray counts as over it.
bool hit_hardware(ray r, float t_min, float t_max, precise inout hit_record rec,
                  inout uint iterations) {
  if (!driver_takes(r)) return hit_bvh(r, t_min, t_max, rec, iterations);
  iterations += pc.trace_cost;
  if (iterations >= pc.loop_budget) {  // no trip left for a candidate: over budget, not a miss
    iterations = pc.loop_budget + 1u;
    return false;
  }
  if (motion) ray_times[launch_slot(gl_LaunchIDEXT)] = r.time;
  uint allowed = pc.loop_budget - iterations;
  traced = nearest_hit(t_max, -1, 0u, 0u, allowed);
  // A shadow ray whose first hit decides it (first_hit_ends) ends at the first candidate the
  // any-hit shader keeps.
  uint flags = first_hit_ends ? gl_RayFlagsTerminateOnFirstHitEXT : gl_RayFlagsNoneEXT;
  traceRayEXT(tlas, flags, 0xffu, 0u, 1u, 0u, r.origin, t_min, r.direction, t_max, 0);
  if (traced.trips == 0u) {  // the budget ran out inside the traversal
    iterations = pc.loop_budget + 1u;
    return false;
  }
  iterations += allowed - traced.trips;
  return record_nearest(traced, r, rec);
}
#endif

#endif
#endif
