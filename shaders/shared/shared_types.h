// Every struct that crosses from the host to the GPU, written once and included by both the C++
// host and the GLSL shaders: this header gathers the headers that hold them, one a topic, each
// struct's offsets static_asserted beside it against the std140/std430 rules, so host and shader
// cannot drift apart silently (tests/gpu/test_gpu_layout.cpp reads the shaders' own offsets back
// out of their SPIR-V). A file may include the one header it needs instead.
#ifndef RTVK_SHARED_TYPES_H
#define RTVK_SHARED_TYPES_H

#include "appearance_types.h"  // gpu_material, gpu_texture, gpu_perlin, gpu_light, gpu_medium
#include "bindings.h"          // each pipeline's bindings; the render's specialization constants
#include "bvh_types.h"         // bvh_wide_node and its references, RTVK_BVH_STACK
#include "camera_ubo.h"        // camera_ubo, RTVK_PROJECTION_*, RTVK_MAX_VIEWS
#include "geometry_types.h"    // gpu_sphere, gpu_quad, gpu_triangle, gpu_disk, gpu_instance
#include "render_types.h"      // render_push, pixel_sum, render_status, tonemap_push, gpu_aov

#endif  // RTVK_SHARED_TYPES_H
