// The light tree next-event estimation draws its lamps from (the "many lights" half of issue 46):
// a binary tree over the lamps (host/scene/light_tree.cpp builds it), each node bounding the lamps
// under it by a box, a cone of the ways they emit and their power, as in Conty Estevez and Kulla's
// "Importance Sampling of Many Lights with Adaptive Tree Splitting" (2018) and pbrt-v4's
// BVHLightSampler. A draw descends from the root, taking each child with the probability of its
// importance seen from the shading point (power over squared distance, times the cosines the
// cones and the box leave at best), so that it costs the tree's depth, not the lamp count. The
// probability of a lamp hit by a path (the MIS weight's) comes back the same way: a point query
// finds the leaf whose lamp lies where the path hit, and its trail replays the draw's choices.
//
// The nodes are the backend's: GLSL reads `light_nodes[]`, which the including shader declares
// at RTVK_BINDING_LIGHT_TREE (shaders/light_tree_buffers.glsl), C++ the light_table's `nodes`.
// The GLSL counts the trips of its loops in `light_tree_trips` (LIGHT_TREE_TRIP) for the loop
// budget (lavapipe stops an invocation's loops after 65,535 trips in all; shading.glsl adds them).
#ifndef RTVK_LIGHT_TREE_H
#define RTVK_LIGHT_TREE_H
#include "kernel_lang.h"
#include "lights_types.h"
#include "pdf.h"

#ifndef LIGHT_TREE_TRIP
#define LIGHT_TREE_TRIP()
#endif
// Whether the light table has a tree: C++ tables built without one draw by the alias table
// (gpu_light::pmf, alias_q, alias); the GPU always has one.
#ifdef __cplusplus
#define LIGHT_TREE_PRESENT (lights_in.nodes != nullptr)
#else
#define LIGHT_TREE_PRESENT true
#endif

RTVK_KERNELS_BEGIN

#ifdef __cplusplus
using light_node = gpu::gpu_light_node;  // floats in both languages: the CPU reads the GPU's tree
#else
#define light_node gpu_light_node
#endif

// The tree's deepest leaf is at most this many levels below the root (the builder splits at the
// median past that), which bounds the point query's stack and a trail's bits.
const uint light_tree_depth = 30u;

// sqrt(max(0, x)): a sine from its cosine.
inline precise real sine_of(real c) {
  return sqrt(max(real(0.0), real(1.0) - c * c));
}

// cos(max(0, a - b)) for angles a, b in [0, pi] given by their sines and cosines.
inline precise real cos_less(real sin_a, real cos_a, real sin_b, real cos_b) {
  if (cos_a > cos_b) return real(1.0);
  return cos_a * cos_b + sin_a * sin_b;
}

// sin(max(0, a - b)), likewise.
inline precise real sin_less(real sin_a, real cos_a, real sin_b, real cos_b) {
  if (cos_a > cos_b) return real(0.0);
  return sin_a * cos_b - cos_a * sin_b;
}

// How much light node `nd` can send to point p with unit normal n (zero n: a point in a medium,
// every way alike), up to a constant common to all nodes: its power over the squared distance to
// its box's center (no nearer than the box's half diagonal), times the cosine of the smallest
// angle left between its cone and the way to p once the box's own angular size is taken off,
// times the same at p's normal. 0 where no lamp of it can face p.
inline precise real light_node_importance(light_node nd, real3 p, real3 n) {
  if (!(nd.power > 0.0f)) return real(0.0);
  precise real3 lo = real3(nd.lo);
  precise real3 hi = real3(nd.hi);
  precise real3 half_size = (hi - lo) * real(0.5);
  precise real r2 = dot3(half_size, half_size);  // the bounding sphere's radius, squared
  precise real3 to = p - (lo + hi) * real(0.5);  // from the box's center to p
  precise real dist2 = dot3(to, to);
  precise real d2 = max(max(dist2, r2), real(1e-12));
  // The half angle theta_b of the cone the bounding sphere fills seen from p: all ways inside it.
  precise real cos_b = dist2 > r2 ? sqrt(real(1.0) - r2 / dist2) : real(-1.0);
  precise real sin_b = sine_of(cos_b);
  precise real len = sqrt(dist2);
  precise real3 w = len > real(0.0) ? to / len : real3(0.0);
  precise real cos_w = len > real(0.0) ? dot3(real3(nd.axis), w) : real(1.0);
  precise real sin_w = sine_of(cos_w);
  precise real cos_o = real(nd.cos_o);
  precise real sin_o = sine_of(cos_o);
  // theta' = max(0, theta_w - theta_o - theta_b): the smallest angle from some lamp's normal.
  precise real cos_x = cos_less(sin_w, cos_w, sin_o, cos_o);
  precise real sin_x = sin_less(sin_w, cos_w, sin_o, cos_o);
  precise real cos_p = cos_less(sin_x, cos_x, sin_b, cos_b);
  if (!(cos_p > real(nd.cos_e))) return real(0.0);
  precise real importance = real(nd.power) * cos_p / d2;
  if (dot3(n, n) > real(0.0)) {  // the receiver's cosine, its best over the box (either side)
    precise real cos_i = abs(dot3(n, w));
    importance *= cos_less(sine_of(cos_i), cos_i, sin_b, cos_b);
  }
  return max(importance, real(0.0));
}

// The probability of taking interior node k's first child from (p, n): its importance over both
// children's. Where neither can send p light (the parent's looser bounds said it might), by their
// power, so that every descent ends at a lamp and the lamps' probabilities sum to one (those
// lamps' samples then bring nothing, as any lamp's that faces away); -1 only for a broken tree.
inline precise real light_tree_first(LIGHTS_PARAM uint k, real3 p, real3 n) {
  light_node first = LIGHT_NODE(k + 1u);
  light_node second = LIGHT_NODE(LIGHT_NODE(k).second);
  precise real a = light_node_importance(first, p, n);
  precise real b = light_node_importance(second, p, n);
  precise real both = a + b;
  if (!(both > real(0.0))) {
    a = real(first.power);
    b = real(second.power);
  }
  precise real sum = a + b;
  return sum > real(0.0) ? a / sum : real(-1.0);
}

// A lamp drawn from the tree for the point p with normal n by one uniform number u in [0, 1):
// returns its index in the light table and leaves its probability in `pmf` (0: none drawn). Each
// step rescales u to the child's share, so one number serves the whole descent.
inline uint light_tree_draw(LIGHTS_PARAM real3 p, real3 n, real u, precise OUT(real) pmf) {
  pmf = real(0.0);
  if (!(LIGHT_NODE(0u).power > 0.0f)) return 0u;
  uint k = 0u;
  precise real prob = real(1.0);
  for (uint depth = 0u; depth <= light_tree_depth; ++depth) {
    LIGHT_TREE_TRIP();
    light_node nd = LIGHT_NODE(k);
    if (nd.leaf != 0u) {
      pmf = prob;
      return nd.lamp;
    }
    precise real first = light_tree_first(LIGHTS k, p, n);
    if (!(first >= real(0.0))) return 0u;
    if (u < first) {
      prob *= first;
      u = u / first;
      k = k + 1u;
    } else {
      precise real rest = real(1.0) - first;
      precise real past = u - first;
      prob *= rest;
      u = past / rest;
      k = nd.second;
    }
    u = min(u, real(0.99999994));
  }
  return 0u;
}

// The probability that light_tree_draw from (p, n) ends at the leaf with trail `trail`: the same
// choices, replayed along the trail's bits.
inline precise real light_tree_trail_pmf(LIGHTS_PARAM real3 p, real3 n, uint trail) {
  uint k = 0u;
  precise real prob = real(1.0);
  for (uint depth = 0u; depth <= light_tree_depth; ++depth) {
    LIGHT_TREE_TRIP();
    light_node nd = LIGHT_NODE(k);
    if (nd.leaf != 0u) return prob;
    precise real first = light_tree_first(LIGHTS k, p, n);
    if (!(first >= real(0.0))) return real(0.0);
    if (((trail >> depth) & 1u) == 0u) {
      prob *= first;
      k = k + 1u;
    } else {
      prob *= real(1.0) - first;
      k = nd.second;
    }
  }
  return real(0.0);
}

// Where a ray from `origin` along the unit direction `d` meets lamp l, or -1 where it misses it
// (at the ray's `time`: a sphere's center moves).
inline precise real lamp_distance(light_record l, real3 origin, real3 d, real time) {
  if (l.kind == uint(RTVK_LIGHT_SPHERE)) {
    precise real3 oc = moved_center(l.a, l.u, time) - origin;
    precise real b = dot3(d, oc);
    precise real disc = b * b - (dot3(oc, oc) - l.radius * l.radius);
    if (disc < real(0.0)) return real(-1.0);
    precise real root = sqrt(disc);
    precise real near = b - root;
    precise real far = b + root;
    return near > real(0.0) ? near : far;
  }
  precise real facing = dot3(d, l.normal);
  if (facing == real(0.0)) return real(-1.0);
  return dot3(l.a - origin, l.normal) / facing;
}

// Whether x lies in node nd's box grown by `slack` on every side.
inline bool light_node_holds(light_node nd, real3 x, real slack) {
  precise real3 lo = real3(nd.lo) - real3(slack);
  precise real3 hi = real3(nd.hi) + real3(slack);
  return x.x >= lo.x && x.y >= lo.y && x.z >= lo.z && x.x <= hi.x && x.y <= hi.y && x.z <= hi.z;
}

// The leaf of the lamp whose surface the ray from `origin` along unit direction d meets at
// t_hit (its own test of the ray agreeing within a thousandth, as nee_lamp_pdf's): a depth-first
// search of the nodes whose boxes, grown by that tolerance, hold the hit point. False where no
// drawable lamp lies there.
inline bool light_tree_find(LIGHTS_PARAM real3 origin, real3 d, real time, real t_hit,
                            OUT(uint) leaf) {
  leaf = 0u;
  if (!(LIGHT_NODE(0u).power > 0.0f)) return false;
  precise real3 x = origin + d * t_hit;
  precise real tolerance = real(1e-3) * t_hit + real(1e-6);
  // The boxes are floats: grow them by a few of their units in the last place too.
  precise real slack = tolerance + real(1e-5) * max(abs(x.x), max(abs(x.y), abs(x.z)));
  uint stack[light_tree_depth + 2u];
  uint top = 1u;
  stack[0] = 0u;
  while (top > 0u) {
    LIGHT_TREE_TRIP();
    top = top - 1u;
    uint k = stack[top];
    light_node nd = LIGHT_NODE(k);
    if (!light_node_holds(nd, x, slack)) continue;
    if (nd.leaf != 0u) {
      precise real t = lamp_distance(LIGHT_AT(nd.lamp), origin, d, time);
      precise real off = t - t_hit;
      if (!(abs(off) > tolerance)) {
        leaf = k;
        return true;
      }
      continue;
    }
    if (top + 2u > light_tree_depth + 2u) continue;  // deeper than built: never
    stack[top] = nd.second;
    stack[top + 1u] = k + 1u;
    top = top + 2u;
  }
  return false;
}

RTVK_KERNELS_END

#endif  // RTVK_LIGHT_TREE_H
