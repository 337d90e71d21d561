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
