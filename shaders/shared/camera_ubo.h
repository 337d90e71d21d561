// The camera as the GPU reads it: one camera_ubo per view of a dispatch, in the uniform buffer at
// RTVK_BINDING_CAMERA (bindings.h), filled by gpu::to_ubo (host/gpu/render/packing.cpp) and read
// by get_ray (camera_rays.h).
#ifndef RTVK_CAMERA_UBO_H
#define RTVK_CAMERA_UBO_H

#include "glsl_types.h"

// Views (cameras, animation frames) one dispatch draws, its z index picking the view: 85 camera
// blocks of 192 bytes are 15.94 KiB, inside the 16 KiB uniform buffer every Vulkan device offers.
#define RTVK_MAX_VIEWS 85

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

RTVK_GPU_TYPES_BEGIN

// The camera's fields, each named once: camera_ubo below, camera_frame (camera_rays.h: the C++
// kernels' camera, in their precision) and gpu::to_ubo (host/gpu/render/packing.cpp) are all made
// from this list, so a field added here reaches the shaders, the CPU and the packing together.
// X(type, name), type the GPU's: vec3, vec4, float or uint (camera_frame's real3, real4, real,
// uint). In std140 order: each vec3 takes a 16-byte slot, and the scalar after it packs into the
// slot's last 4 bytes. The long stories: `readout` > 0 opens the top row first, < 0 the bottom
// row first, 0 is a global shutter; `lens_limit` is the calibrated models' valid field
// (camera_rays.h): opencv, the largest undistorted radius^2; opencv-fisheye, the largest
// distorted angle, radians; fisheye-polynomial, the image circle's radius, pixels (0: none).
#define RTVK_CAMERA_FIELDS(X)                                                           \
  X(vec3, origin)        /* eye position, scene units */                                \
  X(uint, image_width)   /* pixels */                                                   \
  X(vec3, horizontal)    /* full viewport width as a vector, scene units */             \
  X(uint, image_height)  /* pixels */                                                   \
  X(vec3, vertical)      /* full viewport height as a vector, scene units */            \
  X(float, lens_radius)  /* aperture / 2, scene units */                                \
  X(vec3, lower_left)    /* lower-left corner of the viewport, scene units */           \
  X(uint, projection)    /* RTVK_PROJECTION_* */                                        \
  X(vec3, lens_u)        /* unit vector to the camera's right */                        \
  X(float, aspect)       /* image width / height */                                     \
  X(vec3, lens_v)        /* unit vector to the camera's up */                           \
  X(float, fisheye_fov)  /* fisheye field of view across the circle, radians */         \
  X(vec3, axis_w)        /* unit vector backwards, away from what the camera sees */    \
  X(float, focus_dist)   /* distance to the plane in perfect focus, scene units */      \
  X(vec3, to_lower_left) /* lower_left - origin, formed in double on the host */        \
  X(float, time_open)    /* the shutter opens, seconds (frame time + shutter open) */   \
  X(float, shutter)      /* each row's shutter stays open, seconds; 0: an instant */    \
  X(float, readout)      /* rolling shutter: first row's opening to last's, seconds */  \
  X(float, lens_limit)   /* calibrated models' valid field (above) */                   \
  X(float, lens_angle)   /* opencv-fisheye: the largest angle from the axis, radians */ \
  X(vec4, intrinsics)    /* calibrated models: fx, fy, cx, cy in this image's pixels */ \
  X(vec4, distortion_a)  /* k[0..3] of lens_intrinsics (opencv: k1 k2 p1 p2) */         \
  X(vec4, distortion_b)  /* k[4..7] of lens_intrinsics (opencv: k3 k4 k5 k6) */

// One member of a struct of the GPU's types.
#define RTVK_CAMERA_UBO_MEMBER(type, name) type name;

// std140: the list above, one per view.
struct camera_ubo {
  RTVK_CAMERA_FIELDS(RTVK_CAMERA_UBO_MEMBER)
};

#ifdef __cplusplus
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
static_assert(RTVK_MAX_VIEWS * sizeof(camera_ubo) <= 16384);
#endif

RTVK_GPU_TYPES_END

#endif  // RTVK_CAMERA_UBO_H
