// The scene's objects as the GPU reads them, each kind an array in its own storage buffer
// (scene_buffers.glsl; bindings.h), packed by host/gpu/render/packing.cpp in the BVH's leaf order.
#ifndef RTVK_GEOMETRY_TYPES_H
#define RTVK_GEOMETRY_TYPES_H

#include "glsl_types.h"

RTVK_GPU_TYPES_BEGIN

// std430 array element: 32 bytes. With the BVH the buffer holds the spheres in its leaf order,
// else in scene order. A moving sphere's velocity is in the velocity array (the same order), so
// scenes where nothing moves keep 32 bytes a sphere.
struct gpu_sphere {
  vec3 center;       // at time 0, scene units
  float radius;      // scene units, > 0
  uint material;     // index into the materials buffer
  uint scene_index;  // the sphere's index in the scene: exact ties go to the later one
  uint pad1;         // unused
  uint pad2;         // unused
};
#ifdef __cplusplus
static_assert(offsetof(gpu_sphere, center) == 0);
static_assert(offsetof(gpu_sphere, radius) == 12);
static_assert(offsetof(gpu_sphere, material) == 16);
static_assert(offsetof(gpu_sphere, scene_index) == 20);
static_assert(sizeof(gpu_sphere) == 32);
#endif

// std430 array element: 80 bytes. The book's quad with its precomputed plane (quad_geometry,
// shaders/shared/hit_quad.h), formed in double on the host.
struct gpu_quad {
  vec3 Q;            // a corner, scene units
  uint material;     // index into the materials buffer
  vec3 u;            // the edge from Q to the next corner
  uint scene_index;  // the quad's scene index (spheres first): exact ties go to the later one
  vec3 v;            // the other edge from Q
  float D;           // dot(normal, Q)
  vec3 normal;       // unit normal, cross(u, v) normalized
  uint pad0;         // unused
  vec3 w;            // cross(u, v) / |cross(u, v)|^2
  uint pad1;         // unused
};
#ifdef __cplusplus
static_assert(offsetof(gpu_quad, material) == 12);
static_assert(offsetof(gpu_quad, u) == 16);
static_assert(offsetof(gpu_quad, scene_index) == 28);
static_assert(offsetof(gpu_quad, v) == 32);
static_assert(offsetof(gpu_quad, D) == 44);
static_assert(offsetof(gpu_quad, normal) == 48);
static_assert(offsetof(gpu_quad, w) == 64);
static_assert(sizeof(gpu_quad) == 80);
#endif

// std430 array element: 48 bytes. A triangle's vertices (hit_triangle.h).
struct gpu_triangle {
  vec3 a;            // first vertex, scene units
  uint material;     // index into the materials buffer
  vec3 b;            // second vertex (counter-clockwise from the front)
  uint scene_index;  // the triangle's scene index (spheres and quads first)
  vec3 c;            // third vertex
  uint normals;      // its shading at 3 * normals in the normals and texcoords buffers (vertex
                     // normals; uv); RTVK_FLAT: none (flat, uv barycentric). The first normal's
                     // w has bit 0 set when they blend (else flat) and above it the entry + 1 of
  // vertex tangents (3 * entry in tangents; 0: none); the second's, as a uint, has
  // bit 0 set when the uv are given and above it the entry of a second uv set (3 *
  // (w >> 1) in texcoords; 0: none); the third's is the entry of vertex colors (3 *
  // w in normals; 0: none): scene_buffers.glsl.
};
#ifdef __cplusplus
static_assert(offsetof(gpu_triangle, material) == 12);
static_assert(offsetof(gpu_triangle, b) == 16);
static_assert(offsetof(gpu_triangle, scene_index) == 28);
static_assert(offsetof(gpu_triangle, c) == 32);
static_assert(offsetof(gpu_triangle, normals) == 44);
static_assert(sizeof(gpu_triangle) == 48);
#endif
#define RTVK_FLAT 0xffffffffu

// std430 array element: 64 bytes. A disk with its plane and axes (disk_geometry,
// shaders/shared/hit_disk.h), formed in double on the host.
struct gpu_disk {
  vec3 center;       // scene units
  float radius;      // scene units, > 0
  vec3 normal;       // unit normal: the front side
  uint material;     // index into the materials buffer
  vec3 u;            // unit axis in the plane (texture u)
  uint scene_index;  // the disk's scene index (spheres, quads and triangles first)
  vec3 v;            // cross(normal, u) (texture v)
  float D;           // dot(normal, center)
};
#ifdef __cplusplus
static_assert(offsetof(gpu_disk, radius) == 12);
static_assert(offsetof(gpu_disk, normal) == 16);
static_assert(offsetof(gpu_disk, material) == 28);
static_assert(offsetof(gpu_disk, u) == 32);
static_assert(offsetof(gpu_disk, scene_index) == 44);
static_assert(offsetof(gpu_disk, v) == 48);
static_assert(offsetof(gpu_disk, D) == 60);
static_assert(sizeof(gpu_disk) == 64);
#endif

// std430 array element: one placement of a group (host/accel/scene_tree.h), 144 bytes. The ray
// enters the group's space as (dot(to_group_x.xyz, p) + to_group_x.w, ...) for points and without
// the w for directions; normals come back by the rows normal_x, normal_y, normal_z (the inverse
// transpose), whose w holds a bound on the placement's stretch. The group's objects are the
// spans [first, first + count) of each kind's array (its tree, at node `root`, refers to them).
struct gpu_instance {
  vec4 to_group_x;      // first row of the inverse placement, translation in w
  vec4 to_group_y;      // second row
  vec4 to_group_z;      // third row
  vec4 normal_x;        // first row of the normal matrix; w: the placement's stretch bound
  vec4 normal_y;        // second row
  vec4 normal_z;        // third row
  uint root;            // the group's tree root (bvh_wide_node index)
  uint sphere_first;    // the group's spheres in the sphere array
  uint sphere_count;    //
  uint quad_first;      // its quads in the quad array
  uint quad_count;      //
  uint triangle_first;  // its triangles in the triangle array
  uint triangle_count;  //
  uint disk_first;      // its disks in the disk array
  uint disk_count;      //
  uint pad0;            // unused
  uint pad1;            // unused
  uint pad2;            // unused
};
#ifdef __cplusplus
static_assert(offsetof(gpu_instance, to_group_y) == 16);
static_assert(offsetof(gpu_instance, normal_x) == 48);
static_assert(offsetof(gpu_instance, normal_z) == 80);
static_assert(offsetof(gpu_instance, root) == 96);
static_assert(offsetof(gpu_instance, sphere_count) == 104);
static_assert(offsetof(gpu_instance, quad_count) == 112);
static_assert(offsetof(gpu_instance, triangle_count) == 120);
static_assert(offsetof(gpu_instance, disk_first) == 124);
static_assert(offsetof(gpu_instance, disk_count) == 128);
static_assert(sizeof(gpu_instance) == 144);
#endif

RTVK_GPU_TYPES_END

#endif  // RTVK_GEOMETRY_TYPES_H
