#pragma once
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "buffer.h"
#include "bvh.h"
#include "compute_pipeline.h"
#include "context.h"
#include "device_fit.h"
#include "lights_types.h"
#include "scene.h"
#include "scene_arrays.h"
#include "shared_types.h"

namespace rtvk::gpu {

// The scene on the device: its objects (spheres, quads, triangles, disks) and materials in the
// shared header's layout, and the four-wide BVH over the objects that the CPU walks too (none when
// the render tests every object). With the BVH each kind's array is stored in its leaf order
// (leaf_layout), each object with its scene index; without it, in scene order. Where the
// host can write the device's main memory (unified memory, resizable BAR:
// host_writes_device_memory) the arrays are written there in place, once; elsewhere they are
// written to host-visible copies, and the copies to the device-local arrays are recorded into
// the first submission.
class gpu_scene {
 public:
  // What goes to the device, made on the host (scene_arrays.h).
  using host_arrays = scene_arrays;
  // The scene's arrays, its BVH built (over no spheres when !use_bvh).
  static host_arrays build(const scene& s, bool use_bvh);
  // The buffers a gpu_scene of `a` allocates, for check_device_fits.
  static std::vector<buffer_request> buffers(const gpu_context& ctx, const host_arrays& a);

  gpu_scene(const gpu_context& ctx, const host_arrays& a);
  gpu_scene(const gpu_context& ctx, const scene& s, bool use_bvh);

  // The copies to the device, when the arrays were not written in place (else nothing).
  void record_upload(VkCommandBuffer cb) const;
  bool in_place() const { return !staging_; }  // written straight into device memory

  std::uint32_t sphere_count() const { return counts_[shape_sphere]; }
  std::uint32_t quad_count() const { return counts_[shape_quad]; }
  std::uint32_t triangle_count() const { return counts_[shape_triangle]; }
  bool moves() const { return moves_; }  // some sphere has a velocity (RTVK_SPEC_MOTION)
  double build_seconds() const { return build_seconds_; }
  VkBuffer materials() const { return arrays_[1].get(); }
  std::uint32_t light_count() const { return light_count_; }
  // The lamps among them (the first, RTVK_LIGHT_EMITS): what next-event estimation draws.
  std::uint32_t lamp_count() const { return lamp_count_; }
  // The bindings of the objects and the BVH (shaders/scene_buffers.glsl's), for every shader
  // that traces rays through the scene.
  std::vector<buffer_binding> object_bindings() const;
  // The bindings of what shading reads besides the materials (textures, texels, the noise's
  // tables, media, lights, the PBR materials' parameters, the punctual lights): render.comp's
  // and aov.comp's.
  std::vector<buffer_binding> appearance_bindings() const;
  // The switches render.comp and the probes are specialized with (RTVK_SPEC_MOTION, QUADS,
  // TRIANGLES), written into `spec` (indexed by constant id, at least RTVK_SPEC_TRIANGLES + 1).
  void specialize(std::span<std::uint32_t> spec) const;
  // The object counts of the push constants (light_count aside: a render's sampling sets it).
  void set_counts(render_push& push) const;

 private:
  kind_counts counts_;                 // objects of each kind (shape_kind) the arrays hold
  kind_counts own_;                    // of them, the scene's own
  std::uint32_t instance_count_;       // instances
  std::uint32_t medium_count_;         // media
  std::uint32_t light_count_;          // lights sampling aims at (scene_lights)
  std::uint32_t lamp_count_;           // lamps next-event estimation draws (the groups' too)
  bool with_uv_;                       // RTVK_SPEC_UV
  bool any_textures_;                  // RTVK_SPEC_TEXTURES
  bool any_pbr_;                       // RTVK_SPEC_PBR
  bool any_punctual_;                  // RTVK_SPEC_PUNCTUAL
  bool any_environment_;               // RTVK_SPEC_ENVIRONMENT
  bool opaque_shadows_;                // RTVK_SPEC_OPAQUE_SHADOWS
  double build_seconds_;               // building the BVH took
  bool moves_;                         // some sphere has a velocity
  std::vector<buffer_spec> specs_;     // the arrays' sizes (gpu_scene.cpp's arrays_of), for copies
  std::optional<buffer_set> staging_;  // host copies; none when written in place
  buffer_set arrays_;                  // what the shader reads
  std::vector<buffer_binding> objects_, appearance_, material_binding_;  // arrays_ bound
};

}  // namespace rtvk::gpu
