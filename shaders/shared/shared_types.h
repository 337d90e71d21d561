// Every struct that crosses from the host to the GPU, written once and included by both the C++
// host and the GLSL shaders. In C++ each offset is static_asserted against the std140/std430
// rules, so host and shader cannot drift apart silently.
#ifndef RTVK_SHARED_TYPES_H
#define RTVK_SHARED_TYPES_H

#ifdef __cplusplus
#include <cstddef>
#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
namespace rtvk::gpu {
using uvec2 = glm::uvec2;
using vec3 = glm::vec3;
using vec4 = glm::vec4;
using uvec4 = glm::uvec4;
using uint = std::uint32_t;
using uvec2 = glm::uvec2;
#endif

// Descriptor bindings, set 0.
#define RTVK_BINDING_CAMERA 0     // uniform buffer: camera_ubo[RTVK_MAX_VIEWS], one per view
#define RTVK_BINDING_SPHERES 1    // storage buffer: gpu_sphere[], in the BVH's leaf order
#define RTVK_BINDING_IMAGE 2      // storage buffer: pixel_sum[] of one band of rows
#define RTVK_BINDING_MATERIALS 3  // storage buffer: gpu_material[]
#define RTVK_BINDING_STATUS 4     // storage buffer: render_status
#define RTVK_BINDING_PROBE 5      // storage buffer: a probe's entries (probes only)
#define RTVK_BINDING_AOV 5        // storage buffer: gpu_aov[] of a window (aov.comp only)
#define RTVK_BINDING_BVH_NODES 6  // storage buffer: bvh_wide_node[]
#define RTVK_BINDING_VELOCITIES \
  7                                 // storage buffer: vec4[], xyz each moving sphere's velocity,
                                    // in the spheres' order; one unused element when none moves
#define RTVK_BINDING_QUADS 8        // storage buffer: gpu_quad[], in the BVH's leaf order
#define RTVK_BINDING_TRIANGLES 13   // storage buffer: gpu_triangle[], in the BVH's leaf order
#define RTVK_BINDING_NORMALS 14     // storage buffer: vec4[], triangles' vertex normals
#define RTVK_BINDING_INSTANCES 15   // storage buffer: gpu_instance[], in scene order
#define RTVK_BINDING_TEXCOORDS 16   // storage buffer: vec2[], triangles' vertex uv (as normals)
#define RTVK_BINDING_TEXTURES 17    // storage buffer: gpu_texture[]
#define RTVK_BINDING_TEXELS 18      // storage buffer: uint[], image textures' RGBA8 texels
#define RTVK_BINDING_PERLIN 19      // storage buffer: gpu_perlin, the noise textures' tables
#define RTVK_BINDING_MEDIA 20       // storage buffer: gpu_medium[], in scene order
#define RTVK_BINDING_LIGHTS 21      // storage buffer: gpu_light[], what lights sampling aims at
#define RTVK_BINDING_TLAS 22        // acceleration structure: the scene's top level (--accel rt-*)
#define RTVK_BINDING_RAY_TIMES 23   // storage buffer: float[], each launch's ray time (rt-pipeline)
#define RTVK_BINDING_DISKS 24       // storage buffer: gpu_disk[], in the BVH's leaf order
#define RTVK_BINDING_BYTES 9        // storage buffer: uint[], tonemap.comp's RGBA8 per pixel
#define RTVK_BINDING_THRESHOLDS 10  // storage buffer: uvec2[256], byte_thresholds (byte_encoding.h)

// Specialization constants of render.comp (0 and 1 are the workgroup's width and height): the
// render's switches, fixed when its pipeline is built.
#define RTVK_SPEC_JITTER 2      // bool: random sample positions inside each pixel
#define RTVK_SPEC_LENS 3        // bool: some view has a lens (aperture > 0)
#define RTVK_SPEC_USE_BVH 4     // bool: traverse the BVH, else test every sphere in order
#define RTVK_SPEC_COUNT_RAYS 5  // bool: count each pixel's rays (pixel_sum::rays)
#define RTVK_SPEC_MOTION 6      // bool: some sphere moves (gpu_sphere::velocity is not zero)
#define RTVK_SPEC_QUADS 7       // bool: the scene has quads
#define RTVK_SPEC_TRIANGLES 8   // bool: the scene has triangles
#define RTVK_SPEC_INSTANCES 9   // bool: the scene has instances
#define RTVK_SPEC_UV \
  10                           // bool: hits on spheres find their texture coordinates (an image
                               // texture reads them)
#define RTVK_SPEC_TEXTURES 11  // bool: some material has a texture (render.comp)
#define RTVK_SPEC_MEDIA 12     // bool: the scene has media (render.comp)
#define RTVK_SPEC_LIGHTS 13    // bool: scattering samples toward the lights (render.comp)
#define RTVK_SPEC_CALIBRATED \
  14  // bool: a view has a calibrated lens or a rolling shutter (render.comp; camera_rays.h)
#define RTVK_SPEC_DISKS 15  // bool: the scene has disks
#define RTVK_SPEC_STACK 16  // uint: entries of hit_bvh's stack in use; 0: all (tests make it less)
#define RTVK_SPEC_COUNT 17  // constant ids in use

// Views (cameras, animation frames) one dispatch draws, its z index picking the view: 85 camera
// blocks of 192 bytes are 15.94 KiB, inside the 16 KiB uniform buffer every Vulkan device offers.
#define RTVK_MAX_VIEWS 85

// Traversal stack entries. The BVH builder keeps every tree at most this many interior levels
// deep (bvh::max_depth), and a traversal remembers at most one child per level on its path; that
// depth holds up to 2^RTVK_BVH_STACK spheres.
#define RTVK_BVH_STACK 32
// Spheres in one BVH leaf (bvh::max_leaf): exactly this many, as the shader's stack takes it.
#define RTVK_BVH_LEAF 1

#define RTVK_PROBE_POINTS 5  // (u, v) pairs probe.comp turns into rays

// Material types, as rtvk::material_type.
#define RTVK_MATERIAL_NORMAL 0
#define RTVK_MATERIAL_LAMBERTIAN 1
#define RTVK_MATERIAL_METAL 2
#define RTVK_MATERIAL_DIELECTRIC 3
#define RTVK_MATERIAL_FLAT 4
#define RTVK_MATERIAL_DIFFUSE_LIGHT 5  // emits its color (any strength); no bounce
#define RTVK_MATERIAL_ISOTROPIC 6      // scatters every way alike: a medium's phase function
// gpu_material::flags.
// diffuse_light: emits from its front side only (the third book's)
#define RTVK_MATERIAL_ONE_SIDED 1u

// What a light is (gpu_light::kind): a shape lights sampling aims directions at.
#define RTVK_LIGHT_SPHERE 0    // by the cone it fills, seen from the point (the book's)
#define RTVK_LIGHT_QUAD 1      // by area
#define RTVK_LIGHT_TRIANGLE 2  // by area
#define RTVK_MAX_LIGHTS 256    // lights one scene may sample: each scattering evaluates them all

// What a material's color is (gpu_material::texture): its albedo, or one of these.
#define RTVK_NO_TEXTURE 0xffffffffu
#define RTVK_TEXTURE_CHECKER 0   // the book's spatial checker: cells of `scale` scene units
#define RTVK_TEXTURE_IMAGE 1     // an image, nearest texel at the hit's (u, v)
#define RTVK_TEXTURE_NOISE 2     // Perlin noise at scale * p, in one of the styles below
#define RTVK_NOISE_SMOOTH 0      // 0.5 * (1 + noise(scale p))
#define RTVK_NOISE_TURBULENCE 1  // turb(scale p), seven octaves
#define RTVK_NOISE_MARBLE 2      // 0.5 * (1 + sin(scale p.z + 10 turb(p))): the book's final one
#define RTVK_PERLIN_POINTS 256   // random vectors (and entries of each permutation) of the noise
// How an image texture reads coordinates outside [0, 1] (gpu_texture::style, u in bits 0-1,
// v in bits 2-3).
#define RTVK_WRAP_CLAMP 0   // the edge's texel (the book's)
#define RTVK_WRAP_REPEAT 1  // the image tiled (glTF's default)
#define RTVK_WRAP_MIRROR 2  // tiled, every other copy mirrored

// What bounds a medium (gpu_medium::shape).
#define RTVK_BOUNDARY_SPHERE 0
#define RTVK_BOUNDARY_BOX 1

// Camera models, as rtvk::projection (host/camera/camera.h).
#define RTVK_PROJECTION_PERSPECTIVE 0
#define RTVK_PROJECTION_ORTHOGRAPHIC 1
#define RTVK_PROJECTION_EQUIRECTANGULAR 2
#define RTVK_PROJECTION_FISHEYE_EQUIDISTANT 3
#define RTVK_PROJECTION_FISHEYE_EQUISOLID 4
#define RTVK_PROJECTION_OPENCV 5              // fx fy cx cy, k1 k2 p1 p2 k3 k4 k5 k6
#define RTVK_PROJECTION_OPENCV_FISHEYE 6      // fx fy cx cy, k1 k2 k3 k4
#define RTVK_PROJECTION_FISHEYE_POLYNOMIAL 7  // cx cy, angle = k0 + k1 r + ... + k4 r^4
#define RTVK_PROJECTION_CYLINDRICAL 8         // fx: pixels per radian across, fy: per unit up

// std140. Each vec3 takes a 16-byte slot; the scalar after it packs into the slot's last 4 bytes.
struct camera_ubo {
  vec3 origin;         // eye position, scene units
  uint image_width;    // pixels
  vec3 horizontal;     // full viewport width as a vector, scene units
  uint image_height;   // pixels
  vec3 vertical;       // full viewport height as a vector, scene units
  float lens_radius;   // aperture / 2, scene units
  vec3 lower_left;     // lower-left corner of the viewport, scene units
  uint projection;     // RTVK_PROJECTION_*
  vec3 lens_u;         // unit vector to the camera's right
  float aspect;        // image width / height
  vec3 lens_v;         // unit vector to the camera's up
  float fisheye_fov;   // fisheye field of view across the circle, radians
  vec3 axis_w;         // unit vector backwards, away from what the camera looks at
  float focus_dist;    // distance to the plane in perfect focus, scene units
  vec3 to_lower_left;  // lower_left - origin, formed in double on the host, scene units
  float time_open;     // the instant the shutter opens, seconds (frame time + shutter open)
  float shutter;       // how long each row's shutter stays open, seconds; 0: an instant
  float readout;       // rolling shutter: seconds from the first row's opening to the last
                       // row's; > 0 top row first, < 0 bottom row first, 0: global shutter
  float lens_limit;    // calibrated models' valid field (camera_rays.h): opencv, the largest
                       // undistorted radius^2; opencv-fisheye, the largest distorted angle,
                       // radians; fisheye-polynomial, the image circle's radius, pixels (0: none)
  float lens_angle;    // opencv-fisheye: the largest angle from the axis, radians
  vec4 intrinsics;     // calibrated models: fx, fy, cx, cy in this image's pixels
  vec4 distortion_a;   // k[0..3] of lens_intrinsics (opencv: k1 k2 p1 p2)
  vec4 distortion_b;   // k[4..7] of lens_intrinsics (opencv: k3 k4 k5 k6)
};

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

// std430 array element: 48 bytes. A triangle's vertices (hit_triangle.h).
struct gpu_triangle {
  vec3 a;            // first vertex, scene units
  uint material;     // index into the materials buffer
  vec3 b;            // second vertex (counter-clockwise from the front)
  uint scene_index;  // the triangle's scene index (spheres and quads first)
  vec3 c;            // third vertex
  uint normals;      // its shading at 3 * normals in the normals and texcoords buffers (vertex
                     // normals; uv); RTVK_FLAT: none (flat, uv barycentric). The first normal's
                     // w is 1 when they blend (else flat), the second's when the uv are given.
};
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

// std430 array element: one placement of a group (host/accel/scene_tree.h), 128 bytes. The ray
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

// std430 array element: 32 bytes.
struct gpu_material {
  vec3 albedo;   // fraction of light kept per channel; diffuse_light: the radiance it emits
  uint type;     // RTVK_MATERIAL_*
  float fuzz;    // metal: blur radius
  float ir;      // dielectric: index of refraction
  uint texture;  // its color's texture (gpu_texture index), or RTVK_NO_TEXTURE: albedo
  uint flags;    // RTVK_MATERIAL_ONE_SIDED or 0
};

// std430 array element: one texture, 48 bytes (shaders/shared/texture.h reads it).
struct gpu_texture {
  vec3 even;    // checker: the color of even cells; noise: the color noise 1 has; image: a
                // tint its texels are multiplied by
  uint type;    // RTVK_TEXTURE_*
  vec3 odd;     // checker: the color of odd cells
  float scale;  // checker: a cell's size, scene units; noise: frequency, per scene unit
  uint first;   // image: its first texel in the texel array
  uint width;   // image: texels across
  uint height;  // image: rows of texels
  uint style;   // noise: RTVK_NOISE_*; image: RTVK_WRAP_* of u | that of v << 2
};

// std430: the noise's tables, made from the scene's noise seed on the host (host/scene/perlin.h).
struct gpu_perlin {
  vec4 vectors[RTVK_PERLIN_POINTS];   // xyz: random unit vectors at the lattice points
  uint perm[3 * RTVK_PERLIN_POINTS];  // permutations of 0..255 for x, y and z, one after another
};

// std430 array element: a shape lights sampling aims at, 64 bytes (shaders/shared/pdf.h). The
// geometry is the scene's object's, copied: a sphere's center moves with its velocity.
struct gpu_light {
  vec3 a;        // sphere: center at time 0; quad: the corner Q; triangle: vertex 0 (scene units)
  uint kind;     // RTVK_LIGHT_*
  vec3 u;        // sphere: velocity (units per second); quad: edge u; triangle: edge to vertex 1
  float radius;  // sphere: radius (scene units)
  vec3 v;        // quad: edge v; triangle: edge to vertex 2
  float area;    // quad, triangle: area (square scene units)
  vec3 normal;   // quad, triangle: unit normal, cross(u, v) normalized
  uint pad0;     // unused
};

// std430 array element: a constant-density medium (the book's constant_medium), 96 bytes.
// Its boundary is in its own space: a point p of the scene is (dot(to_local_x.xyz, p) +
// to_local_x.w, ...) there, and a direction without the w.
struct gpu_medium {
  vec4 to_local_x;        // first row of the inverse placement, translation in w
  vec4 to_local_y;        // second row
  vec4 to_local_z;        // third row
  vec3 lo;                // box: its minimum corner; sphere: its center (local units)
  uint shape;             // RTVK_BOUNDARY_*
  vec3 hi;                // box: its maximum corner; sphere: x is its radius
  float neg_inv_density;  // -1 / density, scene units (the scene's, not the local space's)
  uint material;          // its phase function's material (isotropic)
  uint index;             // its index among the scene's media: picks its random numbers
  uint pad0;              // unused
  uint pad1;              // unused
};

// One interior node of the binary bounding volume hierarchy the host builds (host/accel/bvh.h),
// 64 bytes, holding both children: their boxes per axis as four lanes (left min, right min, left
// max, right max), and for each child c (0 left, 1 right) a reference. count[c] = 0: an interior
// node, nodes[first[c]]; else a leaf, the spheres first[c] .. first[c] + count[c] - 1 (stored in
// leaf order). Node 0 is the root; nodes are stored depth first. Both backends walk the tree
// collapsed four wide (bvh_wide_node below); the GPU no longer reads these.
struct bvh_node {
  vec4 x;       // children's box corners on x, scene units (rounded outward)
  vec4 y;       // on y
  vec4 z;       // on z
  uvec2 first;  // per child: interior node index, or the leaf's first sphere slot
  uvec2 count;  // per child: 0 for an interior node, else the leaf's spheres (> 0)
};

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

// Push constants (std430): the render's settings and what changes from one dispatch to the next.
// Each dispatch brings every pixel of the band up to `sample_target` samples of the window; an
// invocation whose loop budget runs out first keeps what it finished, and a later dispatch goes
// on from there.
struct render_push {
  vec3 sky_horizon;     // linear RGB seen along -y
  uint sphere_count;    // spheres in the storage buffer
  vec3 sky_zenith;      // linear RGB seen along +y
  uint sample_begin;    // the window's first sample index: a pixel's k-th sample is this + k
  uint seed;            // the render's random seed
  uint max_depth;       // most scatter events per path
  uint loop_budget;     // most loop iterations one invocation runs in this dispatch (pacer.h)
  uint band_y0;         // first image row of this band: the image buffers hold rows band_y0 on
  uint band_rows;       // rows in this band
  uint region_x0;       // first image column drawn
  uint region_width;    // columns drawn; the image buffers hold, per view, band_rows x this
  uint sample_target;   // samples of the window each pixel has after this dispatch
  float sum_scale;      // 2^F: a sample's channel c adds floor(c * sum_scale) (sample_sum.h)
  float sample_limit;   // largest channel value a sample may add (sum_sample_limit); past it the
                        // sample overflows and the render fails
  uint sums_row0;       // rows of the sums buffer before this band's first (0, or band_y0 when
                        // the buffer holds the whole image: the viewer's accumulation)
  uint quad_count;      // quads in the storage buffer
  uint triangle_count;  // triangles in the storage buffer
  uint instance_count;  // instances in their storage buffer
  uint medium_count;    // media in their storage buffer
  uint light_count;     // lights in their storage buffer; 0: plain sampling
  uint strata;          // the pixel is cut into strata x strata cells, each of samples 0 to
                        // strata^2 - 1 in its own (camera_rays.h); 0 or 1: not stratified
  uint trace_cost;      // hardware paths: loop iterations each traced ray counts besides its
                        // candidates, for the driver's own traversal loop (world_rt.glsl)
  uint probe_trips;     // 2: the trips of the loop that tells whether a driver's loop limit
                        // cut the invocation short (limit_was_hit); a push constant, not unrolled
  uint disk_count;      // disks in the storage buffer
};

// std430 array element: one pixel's exact running sums, 48 bytes. Each channel is a 96-bit
// fixed-point number of F fractional bits (sample_sum.h): (low word, high word) and a top word.
struct pixel_sum {
  uvec2 r;       // sum of floor(red * 2^F), bits 0-63
  uvec2 g;       // green, likewise
  uvec2 b;       // blue, likewise
  uint samples;  // samples of the window added so far
  uint rays;     // rays traced for them (when counted)
  uint r_top;    // bits 64-95 of the red sum
  uint g_top;    // of the green sum
  uint b_top;    // of the blue sum
  uint pad;      // unused
};

// Push constants of tonemap.comp (std430).
struct tonemap_push {
  uint first;            // the first pixel_sum entry to encode (and RGBA8 entry to write)
  uint pixels;           // pixel_sum entries to encode
  uint row_invocations;  // invocations in x of the whole dispatch (a tile's gl_NumWorkGroups is
                         // less)
};

// std430: written by the shader when something went wrong.
struct render_status {
  uint starved_pixels;      // invocations whose first sample alone overran loop_budget
  uint unfinished_pixels;   // invocations that stopped short of sample_target (counted per pass)
  uint starved_budget;      // the largest loop_budget under which some invocation starved
  uint overflowed_samples;  // samples with a channel past sample_limit (the render fails)
  uint dropped_samples;     // samples with a NaN or infinite channel: they add black
  uint rays_low;            // rays traced for the samples added (when counted), low word
  uint rays_high;           // and high word
  uint cut_traversals;      // invocations a driver's loop limit cut short (limit_was_hit):
                            // nothing of them is kept; the host redraws them
  uint stack_overflows;     // samples whose BVH walk would have pushed past its stack: dropped
                            // (added black, counted in dropped_samples too), never a wrong hit
};

// Push constants of overlay.comp (std430): the viewer's overlay, a band at the top left of the
// image darkened, with white text where the mask's bits are set.
struct overlay_push {
  uint width;        // band's columns
  uint height;       // band's rows
  uint image_width;  // columns of the RGBA8 image under it
  uint mask_words;   // 32-bit words of the mask per band row
};

#define RTVK_BINDING_OVERLAY_MASK 11  // storage buffer: uint[], overlay.comp's text, a bit a pixel
#define RTVK_BINDING_OVERLAY 12       // storage buffer: uint[], overlay.comp's RGBA8 band

// std430, read and written by probe.comp: the host fills uv, the shader fills the rest.
struct probe_io {
  vec4 uv[RTVK_PROBE_POINTS];          // xy: normalized image coordinates; zw: lens sample
  vec4 direction[RTVK_PROBE_POINTS];   // xyz: get_ray(uv).direction
  vec4 ray_origin[RTVK_PROBE_POINTS];  // xyz: get_ray(uv).origin
};

// std430 array element for rng_probe.comp: the host fills the counters, the shader the results.
struct rng_probe_entry {
  uint pixel;         // counter: pixel index
  uint sample_index;  // counter: sample index
  uint bounce;        // counter: bounce
  uint dim;           // counter: dimension
  uint bits;          // random_bits(seed 0x5eed, ...)
  float value;        // random_float(seed 0x5eed, ...)
  float turn_cos;     // turn_cos_sin(value).x: cos(2 pi value)
  float turn_sin;     // turn_cos_sin(value).y: sin(2 pi value)
};

// std430 array element for hit_probe.comp: the host fills a ray, an interval and a sphere; the
// shader runs hit_sphere on them.
struct hit_probe_entry {
  vec3 origin;     // ray origin, scene units
  float t_min;     // interval start
  vec3 direction;  // ray direction (may be degenerate: that is what the probe is for)
  float t_max;     // interval end
  vec3 center;     // sphere center, scene units
  float radius;    // sphere radius, scene units
  float t;         // out: the root hit_sphere found (0 when none)
  uint hit;        // out: 1 when hit_sphere reported a hit
  uint pad0;       // unused
  uint pad1;       // unused
};

// std430 array element for world_probe.comp: the host fills a ray, the shader what hit_world
// finds along it in [0.001, max float].
struct world_probe_entry {
  vec3 origin;      // in: ray origin, scene units
  float t;          // out: the closest hit's t (0 when none)
  vec3 direction;   // in: ray direction
  uint hit;         // out: 1 when something was hit
  vec3 normal;      // out: the hit's normal, facing against the ray
  uint material;    // out: the hit sphere's material index
  uint iterations;  // out: loop trips the search took
  uint pad0;        // unused
  uint pad1;        // unused
  uint pad2;        // unused
};

// std430 array element for aov.comp: what the ray through one pixel's center hits first
// (aov.h), row-major over the render window from its top row.
struct gpu_aov {
  vec3 normal;     // world-space shading normal, facing against the ray; 0 where nothing is hit
  float distance;  // along the camera ray to the hit, scene units; +inf where nothing is hit
  vec3 albedo;     // the material's color there (aov_albedo); 0 where nothing is hit
  float depth;     // z depth: along the camera's axis from its eye, scene units; +inf likewise
  uint object;     // the hit object's place in the scan order (bvh_world's key), if hit
  uint instance;   // the instance + 1 it was reached through; 0: the scene's own objects
  uint material;   // the hit's material index, if hit
  uint hit;        // 1 where something was hit
};

// std430 array element for kernel_probe.comp (kernel_probe.h): the host fills a hit, the ray
// arriving at it, a material and a random stream; the shader runs the shared kernels on them.
struct kernel_probe_entry {
  vec3 p;              // in: the hit point, scene units
  float offset;        // in: hit_record::offset
  vec3 normal;         // in: unit normal, facing against the ray
  uint front_face;     // in: 1 when the ray arrived from outside
  vec3 direction;      // in: the arriving ray's direction
  uint type;           // in: RTVK_MATERIAL_*
  vec3 albedo;         // in: the material's albedo
  float fuzz;          // in: metal's fuzz
  float ir;            // in: dielectric's index of refraction
  uint key;            // in: the random stream's key
  uint bounce;         // in: the random stream's bounce
  uint scattered;      // out: 1 when scatter scattered
  vec3 attenuation;    // out: scatter's attenuation
  float disk_x;        // out: random_in_unit_disk(rnd 0, rnd 1).x
  vec3 origin_out;     // out: the scattered ray's origin
  float disk_y;        // out: and .y
  vec3 direction_out;  // out: the scattered ray's direction
  float sample_value;  // in: a sample's channel for to_fixed (fixed_sum.h)
  vec3 sky;            // out: sky_color(direction, the book's white and blue)
  uint fixed_low;      // out: to_fixed(sample_value, RTVK_PROBE_SUM_SCALE), low word
  vec3 ball;           // out: random_in_unit_sphere(rnd 0, rnd 1, rnd 2)
  uint fixed_high;     // out: and its high word
  uint fixed_top;      // out: and its top word
  uint overflows;      // out: 1 when sum_overflows(sample_value, RTVK_PROBE_SAMPLE_LIMIT)
  uint pad0;           // unused
  uint pad1;           // unused
};
// std430 array element for light_probe.comp (light_probe.h): pdf.h's densities toward one light
// and the cosine density, at a point the host picks, with the host's random numbers.
struct light_probe_entry {
  gpu_light light;      // in: the light
  vec3 origin;          // in: where the directions start, scene units
  float time;           // in: the ray's instant (a sphere light moves)
  vec3 direction;       // in: a direction whose densities are asked
  float r1;             // in: the first random number of the samplers
  vec3 normal;          // in: the cosine density's unit normal
  float r2;             // in: the second
  vec3 sampled;         // out: light_random(light, origin, time, r1, r2)
  float pdf;            // out: light_pdf(light, origin, direction, time)
  vec3 cosine_sampled;  // out: cosine_random(normal, r1, r2)
  float cosine;         // out: cosine_pdf(normal, direction)
  float sampled_pdf;    // out: light_pdf of `sampled`
  uint pad0;            // unused
  uint pad1;            // unused
  uint pad2;            // unused
};

// The kernel probe's to_fixed scale and limit: a render's, F = 42 (sample_sum.h).
#define RTVK_PROBE_SUM_SCALE 4398046511104.0  // 2^42
#define RTVK_PROBE_SAMPLE_LIMIT 8589934592.0  // 2^33

#ifdef __cplusplus
static_assert(offsetof(gpu_aov, normal) == 0);
static_assert(offsetof(gpu_aov, distance) == 12);
static_assert(offsetof(gpu_aov, albedo) == 16);
static_assert(offsetof(gpu_aov, depth) == 28);
static_assert(offsetof(gpu_aov, object) == 32);
static_assert(offsetof(gpu_aov, instance) == 36);
static_assert(offsetof(gpu_aov, material) == 40);
static_assert(offsetof(gpu_aov, hit) == 44);
static_assert(sizeof(gpu_aov) == 48);
static_assert(offsetof(camera_ubo, origin) == 0);
static_assert(offsetof(camera_ubo, image_width) == 12);
static_assert(offsetof(camera_ubo, horizontal) == 16);
static_assert(offsetof(camera_ubo, image_height) == 28);
static_assert(offsetof(camera_ubo, vertical) == 32);
static_assert(offsetof(camera_ubo, lens_radius) == 44);
static_assert(offsetof(camera_ubo, lower_left) == 48);
static_assert(offsetof(camera_ubo, projection) == 60);
static_assert(offsetof(camera_ubo, lens_u) == 64);
static_assert(offsetof(camera_ubo, aspect) == 76);
static_assert(offsetof(camera_ubo, lens_v) == 80);
static_assert(offsetof(camera_ubo, fisheye_fov) == 92);
static_assert(offsetof(camera_ubo, axis_w) == 96);
static_assert(offsetof(camera_ubo, focus_dist) == 108);
static_assert(offsetof(camera_ubo, to_lower_left) == 112);
static_assert(offsetof(camera_ubo, time_open) == 124);
static_assert(offsetof(camera_ubo, shutter) == 128);
static_assert(offsetof(camera_ubo, readout) == 132);
static_assert(offsetof(camera_ubo, lens_limit) == 136);
static_assert(offsetof(camera_ubo, lens_angle) == 140);
static_assert(offsetof(camera_ubo, intrinsics) == 144);
static_assert(offsetof(camera_ubo, distortion_a) == 160);
static_assert(offsetof(camera_ubo, distortion_b) == 176);
static_assert(sizeof(camera_ubo) == 192);
static_assert(offsetof(gpu_sphere, center) == 0);
static_assert(offsetof(gpu_sphere, radius) == 12);
static_assert(offsetof(gpu_sphere, material) == 16);
static_assert(offsetof(gpu_sphere, scene_index) == 20);
static_assert(sizeof(gpu_sphere) == 32);
static_assert(offsetof(gpu_material, albedo) == 0);
static_assert(offsetof(gpu_material, type) == 12);
static_assert(offsetof(gpu_material, fuzz) == 16);
static_assert(offsetof(gpu_material, ir) == 20);
static_assert(offsetof(gpu_material, texture) == 24);
static_assert(offsetof(gpu_material, flags) == 28);
static_assert(sizeof(gpu_material) == 32);
static_assert(offsetof(gpu_texture, type) == 12);
static_assert(offsetof(gpu_texture, odd) == 16);
static_assert(offsetof(gpu_texture, scale) == 28);
static_assert(offsetof(gpu_texture, first) == 32);
static_assert(offsetof(gpu_texture, width) == 36);
static_assert(offsetof(gpu_texture, height) == 40);
static_assert(offsetof(gpu_texture, style) == 44);
static_assert(sizeof(gpu_texture) == 48);
static_assert(offsetof(gpu_perlin, perm) == 16 * RTVK_PERLIN_POINTS);
static_assert(sizeof(gpu_perlin) == 28 * RTVK_PERLIN_POINTS);
static_assert(offsetof(gpu_medium, lo) == 48);
static_assert(offsetof(gpu_medium, shape) == 60);
static_assert(offsetof(gpu_medium, hi) == 64);
static_assert(offsetof(gpu_medium, neg_inv_density) == 76);
static_assert(offsetof(gpu_medium, material) == 80);
static_assert(offsetof(gpu_medium, index) == 84);
static_assert(sizeof(gpu_medium) == 96);
static_assert(offsetof(gpu_light, kind) == 12);
static_assert(offsetof(gpu_light, u) == 16);
static_assert(offsetof(gpu_light, radius) == 28);
static_assert(offsetof(gpu_light, v) == 32);
static_assert(offsetof(gpu_light, area) == 44);
static_assert(offsetof(gpu_light, normal) == 48);
static_assert(sizeof(gpu_light) == 64);
static_assert(offsetof(render_push, sky_horizon) == 0);
static_assert(offsetof(render_push, sphere_count) == 12);
static_assert(offsetof(render_push, sky_zenith) == 16);
static_assert(offsetof(render_push, sample_begin) == 28);
static_assert(offsetof(render_push, seed) == 32);
static_assert(offsetof(render_push, max_depth) == 36);
static_assert(offsetof(render_push, loop_budget) == 40);
static_assert(offsetof(render_push, band_y0) == 44);
static_assert(offsetof(render_push, band_rows) == 48);
static_assert(offsetof(render_push, region_x0) == 52);
static_assert(offsetof(render_push, region_width) == 56);
static_assert(offsetof(render_push, sample_target) == 60);
static_assert(offsetof(render_push, sum_scale) == 64);
static_assert(offsetof(render_push, sample_limit) == 68);
static_assert(offsetof(render_push, sums_row0) == 72);
static_assert(offsetof(render_push, quad_count) == 76);
static_assert(offsetof(render_push, triangle_count) == 80);
static_assert(offsetof(render_push, instance_count) == 84);
static_assert(offsetof(render_push, medium_count) == 88);
static_assert(offsetof(render_push, light_count) == 92);
static_assert(offsetof(render_push, strata) == 96);
static_assert(offsetof(render_push, trace_cost) == 100);
static_assert(offsetof(render_push, probe_trips) == 104);
static_assert(offsetof(render_push, disk_count) == 108);
static_assert(sizeof(render_push) == 112 && sizeof(render_push) <= 128);
static_assert(offsetof(gpu_quad, material) == 12);
static_assert(offsetof(gpu_quad, u) == 16);
static_assert(offsetof(gpu_quad, scene_index) == 28);
static_assert(offsetof(gpu_quad, v) == 32);
static_assert(offsetof(gpu_quad, D) == 44);
static_assert(offsetof(gpu_quad, normal) == 48);
static_assert(offsetof(gpu_quad, w) == 64);
static_assert(sizeof(gpu_quad) == 80);
static_assert(offsetof(gpu_triangle, material) == 12);
static_assert(offsetof(gpu_triangle, b) == 16);
static_assert(offsetof(gpu_triangle, scene_index) == 28);
static_assert(offsetof(gpu_triangle, c) == 32);
static_assert(offsetof(gpu_triangle, normals) == 44);
static_assert(sizeof(gpu_triangle) == 48);
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
static_assert(offsetof(gpu_disk, radius) == 12);
static_assert(offsetof(gpu_disk, normal) == 16);
static_assert(offsetof(gpu_disk, material) == 28);
static_assert(offsetof(gpu_disk, u) == 32);
static_assert(offsetof(gpu_disk, scene_index) == 44);
static_assert(offsetof(gpu_disk, v) == 48);
static_assert(offsetof(gpu_disk, D) == 60);
static_assert(sizeof(gpu_disk) == 64);
static_assert(offsetof(pixel_sum, r) == 0);
static_assert(offsetof(pixel_sum, g) == 8);
static_assert(offsetof(pixel_sum, b) == 16);
static_assert(offsetof(pixel_sum, samples) == 24);
static_assert(offsetof(pixel_sum, rays) == 28);
static_assert(offsetof(pixel_sum, g_top) == 36);
static_assert(offsetof(pixel_sum, b_top) == 40);
static_assert(offsetof(tonemap_push, pixels) == 4);
static_assert(offsetof(tonemap_push, row_invocations) == 8);
static_assert(sizeof(tonemap_push) == 12);
static_assert(offsetof(overlay_push, mask_words) == 12);
static_assert(sizeof(overlay_push) == 16);
static_assert(offsetof(render_status, unfinished_pixels) == 4);
static_assert(offsetof(render_status, starved_budget) == 8);
static_assert(offsetof(render_status, overflowed_samples) == 12);
static_assert(RTVK_MAX_VIEWS * sizeof(camera_ubo) <= 16384);
static_assert(offsetof(bvh_node, x) == 0);
static_assert(offsetof(bvh_node, y) == 16);
static_assert(offsetof(bvh_node, z) == 32);
static_assert(offsetof(bvh_node, first) == 48);
static_assert(offsetof(bvh_node, count) == 56);
static_assert(sizeof(bvh_node) == 64);
static_assert(offsetof(bvh_wide_node, hi_x) == 48);
static_assert(offsetof(bvh_wide_node, child) == 96);
static_assert(offsetof(bvh_wide_node, lanes) == 112);
static_assert(sizeof(bvh_wide_node) == 128);
static_assert(offsetof(render_status, dropped_samples) == 16);
static_assert(offsetof(render_status, rays_low) == 20);
static_assert(offsetof(render_status, rays_high) == 24);
static_assert(offsetof(render_status, cut_traversals) == 28);
static_assert(offsetof(render_status, stack_overflows) == 32);
static_assert(sizeof(render_status) == 36);
static_assert(offsetof(probe_io, direction) == 16 * RTVK_PROBE_POINTS);
static_assert(offsetof(probe_io, ray_origin) == 32 * RTVK_PROBE_POINTS);
static_assert(sizeof(probe_io) == 48 * RTVK_PROBE_POINTS);
static_assert(offsetof(rng_probe_entry, bits) == 16);
static_assert(offsetof(rng_probe_entry, value) == 20);
static_assert(sizeof(rng_probe_entry) == 32);
static_assert(offsetof(hit_probe_entry, t_min) == 12);
static_assert(offsetof(hit_probe_entry, direction) == 16);
static_assert(offsetof(hit_probe_entry, t_max) == 28);
static_assert(offsetof(hit_probe_entry, center) == 32);
static_assert(offsetof(hit_probe_entry, radius) == 44);
static_assert(offsetof(hit_probe_entry, t) == 48);
static_assert(offsetof(hit_probe_entry, hit) == 52);
static_assert(sizeof(hit_probe_entry) == 64);
static_assert(offsetof(world_probe_entry, t) == 12);
static_assert(offsetof(world_probe_entry, direction) == 16);
static_assert(offsetof(world_probe_entry, hit) == 28);
static_assert(offsetof(world_probe_entry, normal) == 32);
static_assert(offsetof(world_probe_entry, material) == 44);
static_assert(offsetof(world_probe_entry, iterations) == 48);
static_assert(sizeof(world_probe_entry) == 64);
static_assert(offsetof(kernel_probe_entry, offset) == 12);
static_assert(offsetof(kernel_probe_entry, normal) == 16);
static_assert(offsetof(kernel_probe_entry, front_face) == 28);
static_assert(offsetof(kernel_probe_entry, direction) == 32);
static_assert(offsetof(kernel_probe_entry, type) == 44);
static_assert(offsetof(kernel_probe_entry, albedo) == 48);
static_assert(offsetof(kernel_probe_entry, fuzz) == 60);
static_assert(offsetof(kernel_probe_entry, ir) == 64);
static_assert(offsetof(kernel_probe_entry, key) == 68);
static_assert(offsetof(kernel_probe_entry, bounce) == 72);
static_assert(offsetof(kernel_probe_entry, scattered) == 76);
static_assert(offsetof(kernel_probe_entry, attenuation) == 80);
static_assert(offsetof(kernel_probe_entry, disk_x) == 92);
static_assert(offsetof(kernel_probe_entry, origin_out) == 96);
static_assert(offsetof(kernel_probe_entry, disk_y) == 108);
static_assert(offsetof(kernel_probe_entry, direction_out) == 112);
static_assert(offsetof(kernel_probe_entry, sample_value) == 124);
static_assert(offsetof(kernel_probe_entry, sky) == 128);
static_assert(offsetof(kernel_probe_entry, fixed_low) == 140);
static_assert(offsetof(kernel_probe_entry, fixed_high) == 156);
static_assert(offsetof(kernel_probe_entry, ball) == 144);
static_assert(offsetof(kernel_probe_entry, fixed_top) == 160);
static_assert(offsetof(kernel_probe_entry, overflows) == 164);
static_assert(sizeof(kernel_probe_entry) == 176);
static_assert(offsetof(light_probe_entry, origin) == 64);
static_assert(offsetof(light_probe_entry, time) == 76);
static_assert(offsetof(light_probe_entry, direction) == 80);
static_assert(offsetof(light_probe_entry, r1) == 92);
static_assert(offsetof(light_probe_entry, normal) == 96);
static_assert(offsetof(light_probe_entry, r2) == 108);
static_assert(offsetof(light_probe_entry, sampled) == 112);
static_assert(offsetof(light_probe_entry, pdf) == 124);
static_assert(offsetof(light_probe_entry, cosine_sampled) == 128);
static_assert(offsetof(light_probe_entry, cosine) == 140);
static_assert(offsetof(light_probe_entry, sampled_pdf) == 144);
static_assert(sizeof(light_probe_entry) == 160);
static_assert(offsetof(pixel_sum, r_top) == 32);
static_assert(sizeof(pixel_sum) == 48);
}  // namespace rtvk::gpu
#endif

#endif  // RTVK_SHARED_TYPES_H
