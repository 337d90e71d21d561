// The four-wide tree both backends walk (host/accel/wide_bvh.h builds it; bvh.glsl and
// world.glsl walk it on the GPU, host/cpu/bvh_world.cpp on the CPU), and its references.
#ifndef RTVK_BVH_TYPES_H
#define RTVK_BVH_TYPES_H

#include "glsl_types.h"

// Traversal stack entries. The BVH builder keeps every tree at most this many interior levels
// deep (bvh::max_depth), and a traversal remembers at most one child per level on its path; that
// depth holds up to 2^RTVK_BVH_STACK spheres.
#define RTVK_BVH_STACK 32
// Spheres in one BVH leaf (bvh::max_leaf): exactly this many, as the shader's stack takes it.
#define RTVK_BVH_LEAF 1

// bvh_wide_node::child[c] with this bit set: a leaf, else a wide node index.
#define RTVK_WIDE_LEAF 0x80000000u
// A leaf's reference below RTVK_WIDE_LEAF: the object's kind in three bits (room for eight:
// the shapes, and instances last), and its position in that kind's array (each in the BVH's
// leaf order). A new shape takes the next free code.
#define RTVK_LEAF_KIND_MASK 0x70000000u
#define RTVK_LEAF_KIND_SHIFT 28
#define RTVK_LEAF_SPHERE 0x00000000u
#define RTVK_LEAF_QUAD 0x10000000u
#define RTVK_LEAF_TRIANGLE 0x20000000u
#define RTVK_LEAF_DISK 0x30000000u
#define RTVK_SHAPE_KINDS 4              // shape kinds in use: codes 0 to RTVK_SHAPE_KINDS - 1
#define RTVK_LEAF_INSTANCE 0x70000000u  // position: the instance's index (gpu_instance[])
#define RTVK_LEAF_INDEX_MASK 0x0fffffffu
// Not a child: what a walk remembers when it enters an instance, so that it goes back to the
// scene's ray when it comes off the stack (the instance leaf RTVK_LEAF_INSTANCE | 0x0fffffff, with
// the leaf bit: no instance has that index).
#define RTVK_WIDE_EXIT 0xffffffffu
// Remembered children of a four-wide walk: three at most per level of its path, which is at most
// RTVK_BVH_STACK levels long.
#define RTVK_WIDE_STACK (3 * RTVK_BVH_STACK)

RTVK_GPU_TYPES_BEGIN

// std430 array element: one node of the four-wide tree the CPU walks too (host/accel/wide_bvh.h,
// wide_node, the same 128 bytes): its children's boxes side by side per axis, lane c child c.
// child[c]: a wide node index, or with RTVK_WIDE_LEAF set the leaf's sphere slot (one sphere);
// `lanes` bit c: child c is in use. Node 0 is the root; nodes are stored depth first.
struct bvh_wide_node {
  vec4 lo_x;    // children's box minima on x, scene units (rounded outward)
  vec4 lo_y;    // on y
  vec4 lo_z;    // on z
  vec4 hi_x;    // children's box maxima on x
  vec4 hi_y;    // on y
  vec4 hi_z;    // on z
  uvec4 child;  // per child: wide node index, or RTVK_WIDE_LEAF | sphere slot
  uint lanes;   // bit c: child c is in use
  uint pad0;    // unused
  uint pad1;    // unused
  uint pad2;    // unused
};
#ifdef __cplusplus
static_assert(offsetof(bvh_wide_node, hi_x) == 48);
static_assert(offsetof(bvh_wide_node, child) == 96);
static_assert(offsetof(bvh_wide_node, lanes) == 112);
static_assert(sizeof(bvh_wide_node) == 128);
#endif

RTVK_GPU_TYPES_END

#endif  // RTVK_BVH_TYPES_H
