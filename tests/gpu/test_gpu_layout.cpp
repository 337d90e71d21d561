// The GPU's view of the shared structs and of the camera. The layout check reads the Offset
// decorations glslang wrote into the embedded SPIR-V and holds them against the C++ compiler's
// offsetof: an independent witness, where an echo of the uniform buffer would come back
// unchanged whatever the offsets were.
#include <gtest/gtest.h>
#include <spirv_cross/spirv_cross_c.h>

#include <algorithm>
#include <cstddef>
#include <map>
#include <set>
#include <span>
#include <string>
#include <tuple>
#include <vector>

#include "gpu_fixture.h"
#include "overlay_push.h"
#include "overlay_shader.h"
#include "packing.h"
#include "probe.h"
#include "probe_shaders.h"
#include "shaders.h"

namespace rtvk {
namespace {

// --- What the C++ compiler made of the shared structs (shaders/shared/shared_types.h) ----------

struct cpp_member {
  std::string name;
  std::size_t offset;  // bytes
};

struct cpp_struct {
  std::size_t size;                 // bytes
  std::vector<cpp_member> members;  // in declaration order
};

#define RTVK_MEMBER(type, member)        \
  cpp_member {                           \
#member, offsetof(gpu::type, member) \
  }

// Every struct that crosses to the GPU (shared_types.h's headers, the viewer's overlay_push.h and
// the probes' probe_types.h), every member. Listed by hand on purpose: a member added to the
// header but not here makes the member counts differ, and a renamed one is missing by name, so
// this table cannot fall behind silently.
const std::map<std::string, cpp_struct>& cpp_layouts() {
  static const std::map<std::string, cpp_struct> layouts = {
      {"camera_ubo",
       {sizeof(gpu::camera_ubo),
        {RTVK_MEMBER(camera_ubo, origin),        RTVK_MEMBER(camera_ubo, image_width),
         RTVK_MEMBER(camera_ubo, horizontal),    RTVK_MEMBER(camera_ubo, image_height),
         RTVK_MEMBER(camera_ubo, vertical),      RTVK_MEMBER(camera_ubo, lens_radius),
         RTVK_MEMBER(camera_ubo, lower_left),    RTVK_MEMBER(camera_ubo, projection),
         RTVK_MEMBER(camera_ubo, lens_u),        RTVK_MEMBER(camera_ubo, aspect),
         RTVK_MEMBER(camera_ubo, lens_v),        RTVK_MEMBER(camera_ubo, fisheye_fov),
         RTVK_MEMBER(camera_ubo, axis_w),        RTVK_MEMBER(camera_ubo, focus_dist),
         RTVK_MEMBER(camera_ubo, to_lower_left), RTVK_MEMBER(camera_ubo, time_open),
         RTVK_MEMBER(camera_ubo, shutter),       RTVK_MEMBER(camera_ubo, readout),
         RTVK_MEMBER(camera_ubo, lens_limit),    RTVK_MEMBER(camera_ubo, lens_angle),
         RTVK_MEMBER(camera_ubo, intrinsics),    RTVK_MEMBER(camera_ubo, distortion_a),
         RTVK_MEMBER(camera_ubo, distortion_b)}}},
      {"gpu_sphere",
       {sizeof(gpu::gpu_sphere),
        {RTVK_MEMBER(gpu_sphere, center), RTVK_MEMBER(gpu_sphere, radius),
         RTVK_MEMBER(gpu_sphere, material), RTVK_MEMBER(gpu_sphere, scene_index),
         RTVK_MEMBER(gpu_sphere, pad1), RTVK_MEMBER(gpu_sphere, pad2)}}},
      {"gpu_material",
       {sizeof(gpu::gpu_material),
        {RTVK_MEMBER(gpu_material, albedo), RTVK_MEMBER(gpu_material, type),
         RTVK_MEMBER(gpu_material, fuzz), RTVK_MEMBER(gpu_material, ir),
         RTVK_MEMBER(gpu_material, texture), RTVK_MEMBER(gpu_material, flags),
         RTVK_MEMBER(gpu_material, emission), RTVK_MEMBER(gpu_material, emission_texture),
         RTVK_MEMBER(gpu_material, opacity), RTVK_MEMBER(gpu_material, alpha_cutoff),
         RTVK_MEMBER(gpu_material, pbr), RTVK_MEMBER(gpu_material, pad1)}}},
      {"gpu_texture",
       {sizeof(gpu::gpu_texture),
        {RTVK_MEMBER(gpu_texture, even), RTVK_MEMBER(gpu_texture, type),
         RTVK_MEMBER(gpu_texture, odd), RTVK_MEMBER(gpu_texture, scale),
         RTVK_MEMBER(gpu_texture, first), RTVK_MEMBER(gpu_texture, width),
         RTVK_MEMBER(gpu_texture, height), RTVK_MEMBER(gpu_texture, style)}}},
      {"gpu_perlin",
       {sizeof(gpu::gpu_perlin),
        {RTVK_MEMBER(gpu_perlin, vectors), RTVK_MEMBER(gpu_perlin, perm)}}},
      {"gpu_medium",
       {sizeof(gpu::gpu_medium),
        {RTVK_MEMBER(gpu_medium, to_local_x), RTVK_MEMBER(gpu_medium, to_local_y),
         RTVK_MEMBER(gpu_medium, to_local_z), RTVK_MEMBER(gpu_medium, lo),
         RTVK_MEMBER(gpu_medium, shape), RTVK_MEMBER(gpu_medium, hi),
         RTVK_MEMBER(gpu_medium, neg_inv_density), RTVK_MEMBER(gpu_medium, material),
         RTVK_MEMBER(gpu_medium, index), RTVK_MEMBER(gpu_medium, pad0),
         RTVK_MEMBER(gpu_medium, pad1)}}},
      {"bvh_wide_node",
       {sizeof(gpu::bvh_wide_node),
        {RTVK_MEMBER(bvh_wide_node, lo_x), RTVK_MEMBER(bvh_wide_node, lo_y),
         RTVK_MEMBER(bvh_wide_node, lo_z), RTVK_MEMBER(bvh_wide_node, hi_x),
         RTVK_MEMBER(bvh_wide_node, hi_y), RTVK_MEMBER(bvh_wide_node, hi_z),
         RTVK_MEMBER(bvh_wide_node, child), RTVK_MEMBER(bvh_wide_node, lanes),
         RTVK_MEMBER(bvh_wide_node, pad0), RTVK_MEMBER(bvh_wide_node, pad1),
         RTVK_MEMBER(bvh_wide_node, pad2)}}},
      {"render_push",
       {sizeof(gpu::render_push),
        {RTVK_MEMBER(render_push, sky_horizon),    RTVK_MEMBER(render_push, sphere_count),
         RTVK_MEMBER(render_push, sky_zenith),     RTVK_MEMBER(render_push, sample_begin),
         RTVK_MEMBER(render_push, seed),           RTVK_MEMBER(render_push, max_depth),
         RTVK_MEMBER(render_push, loop_budget),    RTVK_MEMBER(render_push, band_y0),
         RTVK_MEMBER(render_push, band_rows),      RTVK_MEMBER(render_push, region_x0),
         RTVK_MEMBER(render_push, region_width),   RTVK_MEMBER(render_push, sample_target),
         RTVK_MEMBER(render_push, sum_scale),      RTVK_MEMBER(render_push, sample_limit),
         RTVK_MEMBER(render_push, sums_row0),      RTVK_MEMBER(render_push, quad_count),
         RTVK_MEMBER(render_push, triangle_count), RTVK_MEMBER(render_push, instance_count),
         RTVK_MEMBER(render_push, medium_count),   RTVK_MEMBER(render_push, light_count),
         RTVK_MEMBER(render_push, strata),         RTVK_MEMBER(render_push, trace_cost),
         RTVK_MEMBER(render_push, probe_trips),    RTVK_MEMBER(render_push, disk_count)}}},
      {"gpu_quad",
       {sizeof(gpu::gpu_quad),
        {RTVK_MEMBER(gpu_quad, Q), RTVK_MEMBER(gpu_quad, material), RTVK_MEMBER(gpu_quad, u),
         RTVK_MEMBER(gpu_quad, scene_index), RTVK_MEMBER(gpu_quad, v), RTVK_MEMBER(gpu_quad, D),
         RTVK_MEMBER(gpu_quad, normal), RTVK_MEMBER(gpu_quad, pad0), RTVK_MEMBER(gpu_quad, w),
         RTVK_MEMBER(gpu_quad, pad1)}}},
      {"gpu_triangle",
       {sizeof(gpu::gpu_triangle),
        {RTVK_MEMBER(gpu_triangle, a), RTVK_MEMBER(gpu_triangle, material),
         RTVK_MEMBER(gpu_triangle, b), RTVK_MEMBER(gpu_triangle, scene_index),
         RTVK_MEMBER(gpu_triangle, c), RTVK_MEMBER(gpu_triangle, normals)}}},
      {"gpu_instance",
       {sizeof(gpu::gpu_instance),
        {RTVK_MEMBER(gpu_instance, to_group_x), RTVK_MEMBER(gpu_instance, to_group_y),
         RTVK_MEMBER(gpu_instance, to_group_z), RTVK_MEMBER(gpu_instance, normal_x),
         RTVK_MEMBER(gpu_instance, normal_y), RTVK_MEMBER(gpu_instance, normal_z),
         RTVK_MEMBER(gpu_instance, root), RTVK_MEMBER(gpu_instance, sphere_first),
         RTVK_MEMBER(gpu_instance, sphere_count), RTVK_MEMBER(gpu_instance, quad_first),
         RTVK_MEMBER(gpu_instance, quad_count), RTVK_MEMBER(gpu_instance, triangle_first),
         RTVK_MEMBER(gpu_instance, triangle_count), RTVK_MEMBER(gpu_instance, disk_first),
         RTVK_MEMBER(gpu_instance, disk_count), RTVK_MEMBER(gpu_instance, pad0),
         RTVK_MEMBER(gpu_instance, pad1), RTVK_MEMBER(gpu_instance, pad2)}}},
      {"gpu_disk",
       {sizeof(gpu::gpu_disk),
        {RTVK_MEMBER(gpu_disk, center), RTVK_MEMBER(gpu_disk, radius),
         RTVK_MEMBER(gpu_disk, normal), RTVK_MEMBER(gpu_disk, material), RTVK_MEMBER(gpu_disk, u),
         RTVK_MEMBER(gpu_disk, scene_index), RTVK_MEMBER(gpu_disk, v), RTVK_MEMBER(gpu_disk, D)}}},
      {"pixel_sum",
       {sizeof(gpu::pixel_sum),
        {RTVK_MEMBER(pixel_sum, r), RTVK_MEMBER(pixel_sum, g), RTVK_MEMBER(pixel_sum, b),
         RTVK_MEMBER(pixel_sum, samples), RTVK_MEMBER(pixel_sum, rays),
         RTVK_MEMBER(pixel_sum, r_top), RTVK_MEMBER(pixel_sum, g_top),
         RTVK_MEMBER(pixel_sum, b_top), RTVK_MEMBER(pixel_sum, pad)}}},
      {"overlay_push",
       {sizeof(gpu::overlay_push),
        {RTVK_MEMBER(overlay_push, width), RTVK_MEMBER(overlay_push, height),
         RTVK_MEMBER(overlay_push, image_width), RTVK_MEMBER(overlay_push, mask_words)}}},
      {"tonemap_push",
       {sizeof(gpu::tonemap_push),
        {RTVK_MEMBER(tonemap_push, first), RTVK_MEMBER(tonemap_push, pixels),
         RTVK_MEMBER(tonemap_push, row_invocations), RTVK_MEMBER(tonemap_push, transform),
         RTVK_MEMBER(tonemap_push, mean_scale)}}},
      {"render_status",
       {sizeof(gpu::render_status),
        {RTVK_MEMBER(render_status, starved_pixels), RTVK_MEMBER(render_status, unfinished_pixels),
         RTVK_MEMBER(render_status, starved_budget), RTVK_MEMBER(render_status, overflowed_samples),
         RTVK_MEMBER(render_status, dropped_samples), RTVK_MEMBER(render_status, rays_low),
         RTVK_MEMBER(render_status, rays_high), RTVK_MEMBER(render_status, cut_traversals),
         RTVK_MEMBER(render_status, stack_overflows)}}},
      {"gpu_aov",
       {sizeof(gpu::gpu_aov),
        {RTVK_MEMBER(gpu_aov, normal), RTVK_MEMBER(gpu_aov, distance), RTVK_MEMBER(gpu_aov, albedo),
         RTVK_MEMBER(gpu_aov, depth), RTVK_MEMBER(gpu_aov, object), RTVK_MEMBER(gpu_aov, instance),
         RTVK_MEMBER(gpu_aov, material), RTVK_MEMBER(gpu_aov, hit)}}},
      {"gpu_light",
       {sizeof(gpu::gpu_light),
        {RTVK_MEMBER(gpu_light, a), RTVK_MEMBER(gpu_light, kind), RTVK_MEMBER(gpu_light, u),
         RTVK_MEMBER(gpu_light, radius), RTVK_MEMBER(gpu_light, v), RTVK_MEMBER(gpu_light, area),
         RTVK_MEMBER(gpu_light, normal), RTVK_MEMBER(gpu_light, flags),
         RTVK_MEMBER(gpu_light, emission), RTVK_MEMBER(gpu_light, pmf),
         RTVK_MEMBER(gpu_light, alias_q), RTVK_MEMBER(gpu_light, alias),
         RTVK_MEMBER(gpu_light, pad0), RTVK_MEMBER(gpu_light, pad1)}}},
      {"light_tree_probe_entry",
       {sizeof(gpu::light_tree_probe_entry),
        {RTVK_MEMBER(light_tree_probe_entry, p), RTVK_MEMBER(light_tree_probe_entry, u),
         RTVK_MEMBER(light_tree_probe_entry, n), RTVK_MEMBER(light_tree_probe_entry, t_hit),
         RTVK_MEMBER(light_tree_probe_entry, d), RTVK_MEMBER(light_tree_probe_entry, lamp),
         RTVK_MEMBER(light_tree_probe_entry, pmf), RTVK_MEMBER(light_tree_probe_entry, found),
         RTVK_MEMBER(light_tree_probe_entry, leaf),
         RTVK_MEMBER(light_tree_probe_entry, leaf_pmf)}}},
      {"gpu_light_node",
       {sizeof(gpu::gpu_light_node),
        {RTVK_MEMBER(gpu_light_node, lo), RTVK_MEMBER(gpu_light_node, power),
         RTVK_MEMBER(gpu_light_node, hi), RTVK_MEMBER(gpu_light_node, cos_o),
         RTVK_MEMBER(gpu_light_node, axis), RTVK_MEMBER(gpu_light_node, cos_e),
         RTVK_MEMBER(gpu_light_node, second), RTVK_MEMBER(gpu_light_node, lamp),
         RTVK_MEMBER(gpu_light_node, leaf), RTVK_MEMBER(gpu_light_node, pad0)}}},
      {"light_probe_entry",
       {sizeof(gpu::light_probe_entry),
        {RTVK_MEMBER(light_probe_entry, light), RTVK_MEMBER(light_probe_entry, origin),
         RTVK_MEMBER(light_probe_entry, time), RTVK_MEMBER(light_probe_entry, direction),
         RTVK_MEMBER(light_probe_entry, r1), RTVK_MEMBER(light_probe_entry, normal),
         RTVK_MEMBER(light_probe_entry, r2), RTVK_MEMBER(light_probe_entry, sampled),
         RTVK_MEMBER(light_probe_entry, pdf), RTVK_MEMBER(light_probe_entry, cosine_sampled),
         RTVK_MEMBER(light_probe_entry, cosine), RTVK_MEMBER(light_probe_entry, sampled_pdf),
         RTVK_MEMBER(light_probe_entry, pad0), RTVK_MEMBER(light_probe_entry, pad1),
         RTVK_MEMBER(light_probe_entry, pad2)}}},
      {"pbr_probe_entry",
       {sizeof(gpu::pbr_probe_entry),
        {RTVK_MEMBER(pbr_probe_entry, base_color),
         RTVK_MEMBER(pbr_probe_entry, metallic),
         RTVK_MEMBER(pbr_probe_entry, specular_color),
         RTVK_MEMBER(pbr_probe_entry, roughness),
         RTVK_MEMBER(pbr_probe_entry, clearcoat_normal),
         RTVK_MEMBER(pbr_probe_entry, eta),
         RTVK_MEMBER(pbr_probe_entry, sheen_color),
         RTVK_MEMBER(pbr_probe_entry, specular),
         RTVK_MEMBER(pbr_probe_entry, transmission),
         RTVK_MEMBER(pbr_probe_entry, thin),
         RTVK_MEMBER(pbr_probe_entry, clearcoat),
         RTVK_MEMBER(pbr_probe_entry, clearcoat_roughness),
         RTVK_MEMBER(pbr_probe_entry, sheen_roughness),
         RTVK_MEMBER(pbr_probe_entry, sampled),
         RTVK_MEMBER(pbr_probe_entry, delta),
         RTVK_MEMBER(pbr_probe_entry, pdf),
         RTVK_MEMBER(pbr_probe_entry, wo),
         RTVK_MEMBER(pbr_probe_entry, pdf_query),
         RTVK_MEMBER(pbr_probe_entry, u),
         RTVK_MEMBER(pbr_probe_entry, pdf_sampled),
         RTVK_MEMBER(pbr_probe_entry, wi_query),
         RTVK_MEMBER(pbr_probe_entry, pad0),
         RTVK_MEMBER(pbr_probe_entry, wi),
         RTVK_MEMBER(pbr_probe_entry, pad1),
         RTVK_MEMBER(pbr_probe_entry, weight),
         RTVK_MEMBER(pbr_probe_entry, pad2),
         RTVK_MEMBER(pbr_probe_entry, eval_query),
         RTVK_MEMBER(pbr_probe_entry, pad3),
         RTVK_MEMBER(pbr_probe_entry, eval_sampled),
         RTVK_MEMBER(pbr_probe_entry, pad4)}}},
      {"probe_io",
       {sizeof(gpu::probe_io),
        {RTVK_MEMBER(probe_io, uv), RTVK_MEMBER(probe_io, direction),
         RTVK_MEMBER(probe_io, ray_origin)}}},
      {"rng_probe_entry",
       {sizeof(gpu::rng_probe_entry),
        {RTVK_MEMBER(rng_probe_entry, pixel), RTVK_MEMBER(rng_probe_entry, sample_index),
         RTVK_MEMBER(rng_probe_entry, bounce), RTVK_MEMBER(rng_probe_entry, dim),
         RTVK_MEMBER(rng_probe_entry, bits), RTVK_MEMBER(rng_probe_entry, value),
         RTVK_MEMBER(rng_probe_entry, turn_cos), RTVK_MEMBER(rng_probe_entry, turn_sin)}}},
      {"sobol_probe_entry",
       {sizeof(gpu::sobol_probe_entry),
        {RTVK_MEMBER(sobol_probe_entry, pixel), RTVK_MEMBER(sobol_probe_entry, sample_index),
         RTVK_MEMBER(sobol_probe_entry, bounce), RTVK_MEMBER(sobol_probe_entry, dim),
         RTVK_MEMBER(sobol_probe_entry, bits), RTVK_MEMBER(sobol_probe_entry, bits_x),
         RTVK_MEMBER(sobol_probe_entry, bits_y), RTVK_MEMBER(sobol_probe_entry, value),
         RTVK_MEMBER(sobol_probe_entry, value_x), RTVK_MEMBER(sobol_probe_entry, value_y)}}},
      {"hit_probe_entry",
       {sizeof(gpu::hit_probe_entry),
        {RTVK_MEMBER(hit_probe_entry, origin), RTVK_MEMBER(hit_probe_entry, t_min),
         RTVK_MEMBER(hit_probe_entry, direction), RTVK_MEMBER(hit_probe_entry, t_max),
         RTVK_MEMBER(hit_probe_entry, center), RTVK_MEMBER(hit_probe_entry, radius),
         RTVK_MEMBER(hit_probe_entry, t), RTVK_MEMBER(hit_probe_entry, hit),
         RTVK_MEMBER(hit_probe_entry, pad0), RTVK_MEMBER(hit_probe_entry, pad1)}}},
      {"kernel_probe_entry",
       {sizeof(gpu::kernel_probe_entry),
        {RTVK_MEMBER(kernel_probe_entry, p),
         RTVK_MEMBER(kernel_probe_entry, offset),
         RTVK_MEMBER(kernel_probe_entry, normal),
         RTVK_MEMBER(kernel_probe_entry, front_face),
         RTVK_MEMBER(kernel_probe_entry, direction),
         RTVK_MEMBER(kernel_probe_entry, type),
         RTVK_MEMBER(kernel_probe_entry, albedo),
         RTVK_MEMBER(kernel_probe_entry, fuzz),
         RTVK_MEMBER(kernel_probe_entry, ir),
         RTVK_MEMBER(kernel_probe_entry, key),
         RTVK_MEMBER(kernel_probe_entry, bounce),
         RTVK_MEMBER(kernel_probe_entry, scattered),
         RTVK_MEMBER(kernel_probe_entry, attenuation),
         RTVK_MEMBER(kernel_probe_entry, disk_x),
         RTVK_MEMBER(kernel_probe_entry, origin_out),
         RTVK_MEMBER(kernel_probe_entry, disk_y),
         RTVK_MEMBER(kernel_probe_entry, direction_out),
         RTVK_MEMBER(kernel_probe_entry, sample_value),
         RTVK_MEMBER(kernel_probe_entry, sky),
         RTVK_MEMBER(kernel_probe_entry, fixed_low),
         RTVK_MEMBER(kernel_probe_entry, ball),
         RTVK_MEMBER(kernel_probe_entry, fixed_high),
         RTVK_MEMBER(kernel_probe_entry, fixed_top),
         RTVK_MEMBER(kernel_probe_entry, overflows),
         RTVK_MEMBER(kernel_probe_entry, pad0),
         RTVK_MEMBER(kernel_probe_entry, pad1)}}},
      {"world_probe_entry",
       {sizeof(gpu::world_probe_entry),
        {RTVK_MEMBER(world_probe_entry, origin), RTVK_MEMBER(world_probe_entry, t),
         RTVK_MEMBER(world_probe_entry, direction), RTVK_MEMBER(world_probe_entry, hit),
         RTVK_MEMBER(world_probe_entry, normal), RTVK_MEMBER(world_probe_entry, material),
         RTVK_MEMBER(world_probe_entry, iterations), RTVK_MEMBER(world_probe_entry, pad0),
         RTVK_MEMBER(world_probe_entry, pad1), RTVK_MEMBER(world_probe_entry, pad2),
         RTVK_MEMBER(world_probe_entry, tangent), RTVK_MEMBER(world_probe_entry, texel),
         RTVK_MEMBER(world_probe_entry, scale), RTVK_MEMBER(world_probe_entry, mapped),
         RTVK_MEMBER(world_probe_entry, pad3)}}},
  };
  return layouts;
}

#undef RTVK_MEMBER

// --- What glslang made of it, read back from the SPIR-V ---------------------------------------

// One spirv-cross context per shader; everything it hands out lives as long as the context.
class spirv_reflection {
 public:
  explicit spirv_reflection(std::span<const std::uint32_t> words) {
    if (spvc_context_create(&context_) != SPVC_SUCCESS) {
      context_ = nullptr;
      throw std::runtime_error("spvc_context_create failed");
    }
    spvc_parsed_ir ir = nullptr;
    check(spvc_context_parse_spirv(context_, words.data(), words.size(), &ir));
    check(spvc_context_create_compiler(context_, SPVC_BACKEND_NONE, ir,
                                       SPVC_CAPTURE_MODE_TAKE_OWNERSHIP, &compiler_));
  }
  ~spirv_reflection() {
    if (context_) spvc_context_destroy(context_);
  }
  spirv_reflection(const spirv_reflection&) = delete;
  spirv_reflection& operator=(const spirv_reflection&) = delete;

  void check(spvc_result r) const {
    if (r != SPVC_SUCCESS)
      throw std::runtime_error(std::string("spirv-cross: ") +
                               spvc_context_get_last_error_string(context_));
  }
  spvc_compiler compiler() const { return compiler_; }

 private:
  spvc_context context_ = nullptr;
  spvc_compiler compiler_ = nullptr;
};

// Where a shared struct was met, for failure messages: "render.comp: camera_block.cams".
struct found_struct {
  std::string where;
  spvc_type_id id;  // the struct itself, not an array of it
};

// Every struct type reachable from the shader's uniform buffers, storage buffers and push
// constants, through members and arrays, by name. glslang gives a struct used under two layouts
// (std140 and std430) two type ids, so one name may be found more than once.
class struct_walker {
 public:
  struct_walker(const spirv_reflection& r, std::string shader) : r_(r), shader_(std::move(shader)) {
    spvc_resources resources = nullptr;
    r_.check(spvc_compiler_create_shader_resources(r_.compiler(), &resources));
    for (spvc_resource_type kind :
         {SPVC_RESOURCE_TYPE_UNIFORM_BUFFER, SPVC_RESOURCE_TYPE_STORAGE_BUFFER,
          SPVC_RESOURCE_TYPE_PUSH_CONSTANT}) {
      const spvc_reflected_resource* list = nullptr;
      std::size_t count = 0;
      r_.check(spvc_resources_get_resource_list_for_type(resources, kind, &list, &count));
      for (std::size_t i = 0; i < count; ++i) {
        ++blocks_;
        push_blocks_ += kind == SPVC_RESOURCE_TYPE_PUSH_CONSTANT;
        walk(list[i].base_type_id, shader_ + ": " + list[i].name);
      }
    }
  }

  const std::multimap<std::string, found_struct>& structs() const { return structs_; }
  int blocks() const { return blocks_; }
  int push_blocks() const { return push_blocks_; }

  // An array member's stride, where the member is an array of a shared struct: the shader
  // indexes with it, the host with sizeof.
  struct array_use {
    std::string where;
    std::string element;
    unsigned stride;
  };
  const std::vector<array_use>& arrays() const { return arrays_; }

 private:
  void walk(spvc_type_id type_id, const std::string& where) {
    const spvc_compiler c = r_.compiler();
    const spvc_type type = spvc_compiler_get_type_handle(c, type_id);
    if (spvc_type_get_basetype(type) != SPVC_BASETYPE_STRUCT) return;
    // An array's base type id is its element struct, which holds the names and decorations.
    const spvc_type_id id = spvc_type_get_base_type_id(type);
    if (!visited_.insert(id).second) return;
    const spvc_type st = spvc_compiler_get_type_handle(c, id);
    const std::string name = spvc_compiler_get_name(c, id);
    structs_.emplace(name, found_struct{where, id});
    for (unsigned i = 0; i < spvc_type_get_num_member_types(st); ++i) {
      const spvc_type_id member = spvc_type_get_member_type(st, i);
      const std::string member_where = where + "." + spvc_compiler_get_member_name(c, id, i);
      const spvc_type mt = spvc_compiler_get_type_handle(c, member);
      if (spvc_type_get_num_array_dimensions(mt) > 0 &&
          spvc_type_get_basetype(mt) == SPVC_BASETYPE_STRUCT) {
        unsigned stride = 0;
        r_.check(spvc_compiler_type_struct_member_array_stride(c, st, i, &stride));
        arrays_.push_back(
            {member_where, spvc_compiler_get_name(c, spvc_type_get_base_type_id(mt)), stride});
      }
      walk(member, member_where);
    }
  }

  const spirv_reflection& r_;
  std::string shader_;
  std::set<spvc_type_id> visited_;
  std::multimap<std::string, found_struct> structs_;
  std::vector<array_use> arrays_;
  int blocks_ = 0;
  int push_blocks_ = 0;
};

TEST(ShaderLayout, EveryOffsetTheShadersUseIsTheOffsetOfTheCppStruct) {
  const std::vector<std::pair<std::string, std::span<const std::uint32_t>>> shaders = {
      {"render.comp", gpu::render_shader()},
      {"tonemap.comp", gpu::tonemap_shader()},
      {"aov.comp", gpu::aov_shader()},
      {"overlay.comp", view::overlay_shader()},
      {"probe.comp", gpu::probe_shader()},
      {"rng_probe.comp", gpu::rng_probe_shader()},
      {"hit_probe.comp", gpu::hit_probe_shader()},
      {"world_probe.comp", gpu::world_probe_shader()},
      {"kernel_probe.comp", gpu::kernel_probe_shader()},
      {"light_probe.comp", gpu::light_probe_shader()},
      {"light_tree_probe.comp", gpu::light_tree_probe_shader()},
      {"pbr_probe.comp", gpu::pbr_probe_shader()},
      {"sobol_probe.comp", gpu::sobol_probe_shader()},
      {"render_query.comp", gpu::render_query_shader()},
      {"render_ray.rgen", gpu::render_ray_shaders().raygen},
      {"rt_object.rint", gpu::render_ray_shaders().intersection},
      {"rt_object.rahit", gpu::render_ray_shaders().any_hit}};
  std::map<std::string, int> checked;  // struct name -> times compared
  int blocks = 0, push_blocks = 0;
  for (const auto& [shader, words] : shaders) {
    SCOPED_TRACE(shader);
    ASSERT_FALSE(words.empty());
    const spirv_reflection reflection(words);
    const spvc_compiler c = reflection.compiler();
    const struct_walker walker(reflection, shader);
    blocks += walker.blocks();
    push_blocks += walker.push_blocks();
    for (const auto& [name, found] : walker.structs()) {
      const auto want = cpp_layouts().find(name);
      if (want == cpp_layouts().end()) continue;  // a block, or a struct of the shader's own
      ++checked[name];
      const cpp_struct& cpp = want->second;
      const spvc_type st = spvc_compiler_get_type_handle(c, found.id);
      const unsigned members = spvc_type_get_num_member_types(st);
      EXPECT_EQ(members, cpp.members.size()) << name << " at " << found.where << ": member count";
      // By name, so the table's order does not matter; with equal counts every member is matched.
      for (unsigned i = 0; i < members; ++i) {
        const std::string member = spvc_compiler_get_member_name(c, found.id, i);
        const auto same = std::find_if(cpp.members.begin(), cpp.members.end(),
                                       [&](const cpp_member& m) { return m.name == member; });
        if (same == cpp.members.end()) {
          ADD_FAILURE() << name << "." << member << " at " << found.where
                        << ": no member of that name in the C++ struct";
          continue;
        }
        ASSERT_TRUE(spvc_compiler_has_member_decoration(c, found.id, i, SpvDecorationOffset))
            << name << "." << member << " at " << found.where << " has no Offset";
        const unsigned offset =
            spvc_compiler_get_member_decoration(c, found.id, i, SpvDecorationOffset);
        EXPECT_EQ(offset, same->offset)
            << name << "." << member << " at " << found.where << ": SPIR-V Offset " << offset
            << ", C++ offsetof " << same->offset;
      }
      std::size_t size = 0;
      reflection.check(spvc_compiler_get_declared_struct_size(c, st, &size));
      EXPECT_EQ(size, cpp.size) << name << " at " << found.where << ": SPIR-V size " << size
                                << ", C++ sizeof " << cpp.size;
    }
    for (const auto& a : walker.arrays()) {
      const auto want = cpp_layouts().find(a.element);
      if (want == cpp_layouts().end()) continue;
      EXPECT_EQ(a.stride, want->second.size)
          << a.where << ": array of " << a.element << " with SPIR-V ArrayStride " << a.stride
          << ", C++ sizeof " << want->second.size;
    }
  }
  // Coverage cannot shrink unnoticed: every shared struct is checked in some shader, and the
  // push constants (render.comp's, tonemap.comp's, aov.comp's, overlay.comp's, world_probe.comp's
  // and the hardware paths' four: render_query.comp, render_ray.rgen, rt_object.rint and .rahit)
  // are among the blocks walked.
  for (const auto& [name, layout] : cpp_layouts())
    EXPECT_GT(checked[name], 0) << name << " was found in no shader's buffers or push constants";
  EXPECT_GE(blocks, 15) << "uniform, storage and push-constant blocks walked";
  EXPECT_EQ(push_blocks, 9) << "push-constant blocks walked";
}

// --- The camera on the GPU ---------------------------------------------------------------------

class GpuLayout : public test::GpuTest {};

void expect_near_vec(const glm::vec3& gpu, const vec3& cpu, const char* what) {
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(gpu[k], cpu[k], 1e-6 * (1 + std::abs(cpu[k]))) << what << " component " << k;
}

TEST_F(GpuLayout, GetRayGivesTheCpuCamerasRays) {
  // (u, v, lens x, lens y): the corners and the center, then two lens samples.
  const std::array<glm::vec4, RTVK_PROBE_POINTS> uv = {
      glm::vec4(0, 0, 0, 0), glm::vec4(1, 0, 0, 0), glm::vec4(0, 1, 0, 0),
      glm::vec4(1, 1, 0.6f, -0.3f), glm::vec4(0.5f, 0.5f, -0.25f, 0.5f)};
  camera_pose posed;
  posed.lookfrom = point3(13, 2, 3);
  posed.lookat = point3(0, 0, 0);
  posed.vfov = 20;
  posed.aperture = 0.1;
  posed.focus_dist = 10;
  for (auto [pose, aspect, width] :
       {std::tuple{camera_pose{}, 16.0 / 9.0, 400}, {camera_pose{}, 2.0, 7}, {posed, 0.37, 333}}) {
    const camera cam(pose, aspect, width);
    const gpu::probe_io io = gpu::run_probe(gpu(), cam, uv);
    for (int k = 0; k < RTVK_PROBE_POINTS; ++k) {
      SCOPED_TRACE("probe point " + std::to_string(k) + ", width " + std::to_string(width));
      const ray r = cam.get_ray(uv[k].x, uv[k].y, glm::dvec2(uv[k].z, uv[k].w));
      expect_near_vec(glm::vec3(io.ray_origin[k]), r.origin, "origin");
      expect_near_vec(glm::vec3(io.direction[k]), r.direction, "direction");
    }
  }
}

TEST_F(GpuLayout, ValidationLayerFindingsAreCaughtAndCounted) {
  // The GPU tests' "validation-clean" verdict means something only if a finding is seen: make
  // one on purpose (a zero-sized buffer is invalid usage) and check that it is counted.
  ASSERT_TRUE(gpu().validating());
  const auto before = gpu().validation_messages();
  VkBufferCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
  info.size = 0;
  info.usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
  VkBuffer buffer = VK_NULL_HANDLE;
  vkCreateBuffer(gpu().vk(), &info, nullptr, &buffer);
  EXPECT_GT(gpu().validation_messages(), before);
  if (buffer) vkDestroyBuffer(gpu().vk(), buffer, nullptr);
  ctx_.reset();  // this test's own finding must not fail it in TearDown
}

}  // namespace
}  // namespace rtvk

#include "buffer.h"

namespace rtvk {
namespace {

TEST_F(GpuLayout, SynchronizationValidationCatchesAMissingBarrier) {
  // A fill and then a copy out of the same buffer with no barrier between them: a read-after-write
  // hazard that only synchronization validation sees. It must be reported, or the GPU tests'
  // "validation-clean" says nothing about rtvk's barriers.
  const auto before = gpu().validation_messages();
  {
    const VkBufferUsageFlags usage =
        VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    gpu::gpu_buffer a(gpu(), 256, usage, gpu::memory_use::device_local);
    gpu::gpu_buffer b(gpu(), 256, usage, gpu::memory_use::device_local);
    gpu().submit_and_wait([&](VkCommandBuffer cb) {
      vkCmdFillBuffer(cb, a.get(), 0, VK_WHOLE_SIZE, 7);
      const VkBufferCopy copy{0, 0, 256};
      vkCmdCopyBuffer(cb, a.get(), b.get(), 1, &copy);  // no barrier after the fill
    });
  }  // everything is released before the device goes
  EXPECT_GT(gpu().validation_messages(), before);
  ctx_.reset();  // this test's own finding must not fail it in TearDown
}

}  // namespace
}  // namespace rtvk
