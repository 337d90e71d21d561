#include "gpu_scene.h"

#include <algorithm>

namespace rtvk::gpu {
namespace {

// A buffer cannot be empty: an empty array still takes one element.
template <typename T>
VkDeviceSize bytes_of(const std::vector<T>& v) {
  return std::max<std::size_t>(v.size(), 1) * sizeof(T);
}

std::vector<buffer_spec> with_usage(std::vector<buffer_spec> specs, VkBufferUsageFlags usage) {
  for (buffer_spec& b : specs) b.usage = usage;
  return specs;
}

// Every array of the scene on the device, in one list, in allocation order: what its binding
// is, what messages call it and its upload copy, and its bytes. A new array is one line here
// and one accessor in gpu_scene.h.
enum class role { objects, appearance, materials };
struct array_entry {
  std::uint32_t binding;  // layout(binding = N) in the shaders
  role bound_as;          // which binding list carries it
  const char* array;      // "the sphere array": for device-fit messages
  const char* copy;       // "the spheres' upload copy"
  const void* data;       // the host array (may be empty)
  VkDeviceSize used;      // its bytes (0: empty)
  VkDeviceSize bytes;     // the buffer's (an empty array still takes one element)
};

template <typename T>
array_entry entry(std::uint32_t binding, role r, const char* array, const char* copy,
                  const std::vector<T>& v) {
  return {binding, r, array, copy, v.data(), v.size() * sizeof(T), bytes_of(v)};
}

std::vector<array_entry> arrays_of(const gpu_scene::host_arrays& a) {
  using r = role;
  return {
      entry(RTVK_BINDING_SPHERES, r::objects, "the sphere array", "the spheres' upload copy",
            a.spheres),
      entry(RTVK_BINDING_MATERIALS, r::materials, "the material array",
            "the materials' upload copy", a.materials),
      entry(RTVK_BINDING_BVH_NODES, r::objects, "the BVH", "the BVH's upload copy", a.nodes),
      entry(RTVK_BINDING_VELOCITIES, r::objects, "the velocity array",
            "the velocities' upload copy", a.velocities),
      entry(RTVK_BINDING_QUADS, r::objects, "the quad array", "the quads' upload copy", a.quads),
      entry(RTVK_BINDING_TRIANGLES, r::objects, "the triangle array", "the triangles' upload copy",
            a.triangles),
      entry(RTVK_BINDING_NORMALS, r::objects, "the vertex normal array",
            "the vertex normals' upload copy", a.normals),
      entry(RTVK_BINDING_INSTANCES, r::objects, "the instance array", "the instances' upload copy",
            a.instances),
      entry(RTVK_BINDING_TEXCOORDS, r::objects, "the texture coordinate array",
            "the texture coordinates' upload copy", a.uvs),
      entry(RTVK_BINDING_TEXTURES, r::appearance, "the texture array", "the textures' upload copy",
            a.textures),
      entry(RTVK_BINDING_TEXELS, r::appearance, "the image textures' texels",
            "the texels' upload copy", a.texels),
      entry(RTVK_BINDING_PERLIN, r::appearance, "the noise tables", "the noise tables' upload copy",
            a.perlin),
      entry(RTVK_BINDING_MEDIA, r::appearance, "the media array", "the media's upload copy",
            a.media),
      entry(RTVK_BINDING_LIGHTS, r::appearance, "the light array", "the lights' upload copy",
            a.lights),
      entry(RTVK_BINDING_DISKS, r::objects, "the disk array", "the disks' upload copy", a.disks),
      entry(RTVK_BINDING_TANGENTS, r::objects, "the vertex tangent array",
            "the vertex tangents' upload copy", a.tangents),
      entry(RTVK_BINDING_PBR, r::appearance, "the PBR material array",
            "the PBR materials' upload copy", a.pbr),
      entry(RTVK_BINDING_BSDF_TABLES, r::appearance, "the BSDF tables",
            "the BSDF tables' upload copy", a.bsdf_tables),
      entry(RTVK_BINDING_PUNCTUAL, r::appearance, "the punctual light array",
            "the punctual lights' upload copy", a.punctual),
      entry(RTVK_BINDING_ENVIRONMENT, r::appearance, "the environment map's texels",
            "the environment map's upload copy", a.environment_texels),
      entry(RTVK_BINDING_ENVIRONMENT_CDF, r::appearance, "the environment map's sampling table",
            "the environment table's upload copy", a.environment_table),
      entry(RTVK_BINDING_LIGHT_TREE, r::appearance, "the light tree",
            "the light tree's upload copy", a.light_nodes),
  };
}

// Allocation numbers for check_device_fits (the render targets' sets use others).
enum : int { staging_set = 1, array_set };

std::vector<buffer_spec> specs_of(const std::vector<array_entry>& arrays) {
  std::vector<buffer_spec> out;
  for (const array_entry& e : arrays) out.push_back({e.bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT});
  return out;
}

// Whether some material reads a texture (RTVK_SPEC_TEXTURES): its color or emission's, or one of a
// PBR material's maps. Without, the shader compiles no texture code.
bool reads_textures(const gpu_scene::host_arrays& a) {
  for (const gpu_material& m : a.materials)
    if (m.texture != RTVK_NO_TEXTURE || m.emission_texture != RTVK_NO_TEXTURE) return true;
  for (const gpu_pbr& p : a.pbr)
    for (std::uint32_t t :
         {p.metallic_roughness_texture, p.normal_texture, p.specular_texture,
          p.specular_color_texture, p.transmission_texture, p.thickness_texture,
          p.clearcoat_texture, p.clearcoat_roughness_texture, p.clearcoat_normal_texture,
          p.sheen_color_texture, p.sheen_roughness_texture})
      if (t != RTVK_NO_TEXTURE) return true;
  return false;
}

// Whether every surface blocks a shadow ray it meets (RTVK_SPEC_OPAQUE_SHADOWS, with no media): no
// material lets rays through (alpha mask or blend, a culled back face), so whatever a shadow ray
// hits first decides it, and its search may end there.
bool every_hit_blocks(const gpu_scene::host_arrays& a) {
  for (const gpu_material& m : a.materials)
    if ((m.flags & RTVK_MATERIAL_SEE_THROUGH) != 0u) return false;
  return true;
}

}  // namespace

gpu_scene::host_arrays gpu_scene::build(const scene& s, bool use_bvh) {
  return build_scene_arrays(s, use_bvh);
}

gpu_scene::gpu_scene(const gpu_context& ctx, const scene& s, bool use_bvh)
    : gpu_scene(ctx, build(s, use_bvh)) {}

gpu_scene::gpu_scene(const gpu_context& ctx, const host_arrays& a)
    : counts_{std::uint32_t(a.spheres.size()), std::uint32_t(a.quads.size()),
              std::uint32_t(a.triangles.size()), std::uint32_t(a.disks.size())},
      own_(a.own),
      instance_count_(std::uint32_t(a.instances.size())),
      medium_count_(std::uint32_t(a.media.size())),
      light_count_(std::uint32_t(a.lights.size()) - a.group_lamps),
      lamp_count_(std::uint32_t(
          std::count_if(a.lights.begin(), a.lights.end(),
                        [](const gpu_light& l) { return (l.flags & RTVK_LIGHT_EMITS) != 0u; }))),
      with_uv_(a.with_uv),
      any_textures_(reads_textures(a)),
      any_pbr_(!a.pbr.empty()),
      any_punctual_(!a.punctual.empty() && a.punctual[0].count > 0),
      any_environment_(!a.environment_table.empty()),
      opaque_shadows_(a.media.empty() && every_hit_blocks(a)),
      build_seconds_(a.build_seconds),
      moves_(a.moves),
      specs_(specs_of(arrays_of(a))),
      staging_(
          host_writes_device_memory(ctx)
              ? std::nullopt
              : std::optional<buffer_set>(std::in_place, ctx, memory_use::staging,
                                          with_usage(specs_, VK_BUFFER_USAGE_TRANSFER_SRC_BIT))),
      arrays_(ctx, staging_ ? memory_use::device_local : memory_use::device_mapped,
              staging_ ? with_usage(specs_, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT |
                                                VK_BUFFER_USAGE_TRANSFER_DST_BIT)
                       : specs_) {
  buffer_set& to = staging_ ? *staging_ : arrays_;
  const std::vector<array_entry> arrays = arrays_of(a);
  for (std::size_t i = 0; i < arrays.size(); ++i) {
    if (arrays[i].used > 0) to[i].write(arrays[i].data, arrays[i].used);
    const role r = arrays[i].bound_as;
    (r == role::objects      ? objects_
     : r == role::appearance ? appearance_
                             : material_binding_)
        .push_back({arrays[i].binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, arrays_[i].get()});
  }
}

std::vector<buffer_request> gpu_scene::buffers(const gpu_context& ctx, const host_arrays& a) {
  using u = memory_use;
  std::vector<buffer_request> out;
  const bool in_place = host_writes_device_memory(ctx);
  for (const array_entry& e : arrays_of(a)) {
    if (!in_place) out.push_back({e.copy, e.bytes, false, u::staging, staging_set});
    out.push_back(
        {e.array, e.bytes, true, in_place ? u::device_mapped : u::device_local, array_set});
  }
  return out;
}

std::vector<buffer_binding> gpu_scene::object_bindings() const {
  return objects_;
}

std::vector<buffer_binding> gpu_scene::appearance_bindings() const {
  return appearance_;
}

void gpu_scene::specialize(std::span<std::uint32_t> spec) const {
  spec[RTVK_SPEC_MOTION] = moves_;
  spec[RTVK_SPEC_QUADS] = counts_[shape_quad] > 0;
  spec[RTVK_SPEC_TRIANGLES] = counts_[shape_triangle] > 0;
  spec[RTVK_SPEC_DISKS] = counts_[shape_disk] > 0;
  spec[RTVK_SPEC_INSTANCES] = instance_count_ > 0;
  spec[RTVK_SPEC_UV] = with_uv_;
  spec[RTVK_SPEC_TEXTURES] = any_textures_;
  spec[RTVK_SPEC_MEDIA] = medium_count_ > 0;
  spec[RTVK_SPEC_PBR] = any_pbr_;
  spec[RTVK_SPEC_PUNCTUAL] = any_punctual_;
  spec[RTVK_SPEC_ENVIRONMENT] = any_environment_;
  spec[RTVK_SPEC_OPAQUE_SHADOWS] = opaque_shadows_;
}

void gpu_scene::set_counts(render_push& push) const {
  // The scene's own: a scan without the BVH tests them, then each instance's group.
  push.sphere_count = own_[shape_sphere];
  push.quad_count = own_[shape_quad];
  push.triangle_count = own_[shape_triangle];
  push.disk_count = own_[shape_disk];
  push.instance_count = instance_count_;
  push.medium_count = medium_count_;
}

void gpu_scene::record_upload(VkCommandBuffer cb) const {
  if (!staging_) return;
  for (std::size_t i = 0; i < specs_.size(); ++i) {
    const VkBufferCopy copy{0, 0, specs_[i].size};
    vkCmdCopyBuffer(cb, (*staging_)[i].get(), arrays_[i].get(), 1, &copy);
  }
}

}  // namespace rtvk::gpu
