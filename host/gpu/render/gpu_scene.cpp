#include "gpu_scene.h"

#include <algorithm>
#include <chrono>

#include <cstring>
#include "bvh.h"
#include "elapsed.h"
#include "packing.h"
#include "scene_tree.h"
#include "wide_bvh.h"

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

template <typename T>
void write_array(gpu_buffer& b, const std::vector<T>& v) {
  if (!v.empty()) b.write(v.data(), v.size() * sizeof(T));
}

// Allocation numbers for check_device_fits (the render targets' sets use others).
enum : int { staging_set = 1, array_set };

}  // namespace

gpu_scene::host_arrays gpu_scene::build(const scene& s, bool use_bvh) {
  const auto start = std::chrono::steady_clock::now();
  const scene_tree tree = build_scene_tree(primitive_spans{s.spheres, s.quads, s.triangles},
                                           s.groups, s.instances, use_bvh, 0, s.motion);
  const double seconds = seconds_since(start);
  std::vector<bvh_wide_node> nodes(tree.nodes.size());
  static_assert(sizeof(bvh_wide_node) == sizeof(wide_node));
  if (!nodes.empty())
    std::memcpy(nodes.data(), tree.nodes.data(), nodes.size() * sizeof(wide_node));
  host_arrays a{to_gpu_spheres(s, tree.spheres),
                to_gpu_materials(s),
                std::move(nodes),
                to_gpu_velocities(s, tree.spheres),
                to_gpu_quads(s, tree.quads),
                {},
                {},
                seconds,
                scene_moves(s),
                to_gpu_instances(s, tree.groups),
                std::uint32_t(s.spheres.size()),
                std::uint32_t(s.quads.size()),
                std::uint32_t(s.triangles.size())};
  a.triangles = to_gpu_triangles(s, tree.triangles, a.normals, a.uvs);
  a.textures = to_gpu_textures(s, a.texels);
  a.perlin = {to_gpu_perlin(make_perlin(s.noise_seed))};
  a.media = to_gpu_media(s);
  a.lights = to_gpu_lights(scene_lights(s));
  a.with_uv = scene_reads_uv(s);
  return a;
}

gpu_scene::gpu_scene(const gpu_context& ctx, const scene& s, bool use_bvh)
    : gpu_scene(ctx, build(s, use_bvh)) {}

gpu_scene::gpu_scene(const gpu_context& ctx, const host_arrays& a)
    : sphere_count_(std::uint32_t(a.spheres.size())),
      quad_count_(std::uint32_t(a.quads.size())),
      triangle_count_(std::uint32_t(a.triangles.size())),
      own_spheres_(a.own_spheres),
      own_quads_(a.own_quads),
      own_triangles_(a.own_triangles),
      instance_count_(std::uint32_t(a.instances.size())),
      medium_count_(std::uint32_t(a.media.size())),
      light_count_(std::uint32_t(a.lights.size())),
      with_uv_(a.with_uv),
      any_textures_(
          std::any_of(a.materials.begin(), a.materials.end(),
                      [](const gpu_material& m) { return m.texture != RTVK_NO_TEXTURE; })),
      build_seconds_(a.build_seconds),
      moves_(a.moves),
      specs_{{bytes_of(a.spheres), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT},
             {bytes_of(a.materials), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT},
             {bytes_of(a.nodes), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT},
             {bytes_of(a.velocities), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT},
             {bytes_of(a.quads), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT},
             {bytes_of(a.triangles), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT},
             {bytes_of(a.normals), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT},
             {bytes_of(a.instances), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT},
             {bytes_of(a.uvs), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT},
             {bytes_of(a.textures), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT},
             {bytes_of(a.texels), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT},
             {bytes_of(a.perlin), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT},
             {bytes_of(a.media), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT},
             {bytes_of(a.lights), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT}},
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
  write_array(to[0], a.spheres);
  write_array(to[1], a.materials);
  write_array(to[2], a.nodes);
  write_array(to[3], a.velocities);
  write_array(to[4], a.quads);
  write_array(to[5], a.triangles);
  write_array(to[6], a.normals);
  write_array(to[7], a.instances);
  write_array(to[8], a.uvs);
  write_array(to[9], a.textures);
  write_array(to[10], a.texels);
  write_array(to[11], a.perlin);
  write_array(to[12], a.media);
  write_array(to[13], a.lights);
}

std::vector<buffer_request> gpu_scene::buffers(const gpu_context& ctx, const host_arrays& a) {
  const VkDeviceSize spheres = bytes_of(a.spheres), materials = bytes_of(a.materials),
                     nodes = bytes_of(a.nodes), velocities = bytes_of(a.velocities),
                     quads = bytes_of(a.quads), triangles = bytes_of(a.triangles),
                     normals = bytes_of(a.normals), instances = bytes_of(a.instances),
                     uvs = bytes_of(a.uvs), textures = bytes_of(a.textures),
                     texels = bytes_of(a.texels), perlin = bytes_of(a.perlin),
                     media = bytes_of(a.media), lights = bytes_of(a.lights);
  using u = memory_use;
  if (host_writes_device_memory(ctx))
    return {{"the sphere array", spheres, true, u::device_mapped, array_set},
            {"the material array", materials, true, u::device_mapped, array_set},
            {"the BVH", nodes, true, u::device_mapped, array_set},
            {"the velocity array", velocities, true, u::device_mapped, array_set},
            {"the quad array", quads, true, u::device_mapped, array_set},
            {"the triangle array", triangles, true, u::device_mapped, array_set},
            {"the vertex normal array", normals, true, u::device_mapped, array_set},
            {"the instance array", instances, true, u::device_mapped, array_set},
            {"the texture coordinate array", uvs, true, u::device_mapped, array_set},
            {"the texture array", textures, true, u::device_mapped, array_set},
            {"the image textures' texels", texels, true, u::device_mapped, array_set},
            {"the noise tables", perlin, true, u::device_mapped, array_set},
            {"the media array", media, true, u::device_mapped, array_set},
            {"the light array", lights, true, u::device_mapped, array_set}};
  return {{"the spheres' upload copy", spheres, false, u::staging, staging_set},
          {"the sphere array", spheres, true, u::device_local, array_set},
          {"the materials' upload copy", materials, false, u::staging, staging_set},
          {"the material array", materials, true, u::device_local, array_set},
          {"the BVH's upload copy", nodes, false, u::staging, staging_set},
          {"the BVH", nodes, true, u::device_local, array_set},
          {"the velocities' upload copy", velocities, false, u::staging, staging_set},
          {"the velocity array", velocities, true, u::device_local, array_set},
          {"the quads' upload copy", quads, false, u::staging, staging_set},
          {"the quad array", quads, true, u::device_local, array_set},
          {"the triangles' upload copy", triangles, false, u::staging, staging_set},
          {"the triangle array", triangles, true, u::device_local, array_set},
          {"the vertex normals' upload copy", normals, false, u::staging, staging_set},
          {"the vertex normal array", normals, true, u::device_local, array_set},
          {"the instances' upload copy", instances, false, u::staging, staging_set},
          {"the instance array", instances, true, u::device_local, array_set},
          {"the texture coordinates' upload copy", uvs, false, u::staging, staging_set},
          {"the texture coordinate array", uvs, true, u::device_local, array_set},
          {"the textures' upload copy", textures, false, u::staging, staging_set},
          {"the texture array", textures, true, u::device_local, array_set},
          {"the texels' upload copy", texels, false, u::staging, staging_set},
          {"the image textures' texels", texels, true, u::device_local, array_set},
          {"the noise tables' upload copy", perlin, false, u::staging, staging_set},
          {"the noise tables", perlin, true, u::device_local, array_set},
          {"the media's upload copy", media, false, u::staging, staging_set},
          {"the media array", media, true, u::device_local, array_set},
          {"the lights' upload copy", lights, false, u::staging, staging_set},
          {"the light array", lights, true, u::device_local, array_set}};
}

std::vector<buffer_binding> gpu_scene::object_bindings() const {
  constexpr VkDescriptorType storage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
  return {{RTVK_BINDING_SPHERES, storage, spheres()},
          {RTVK_BINDING_VELOCITIES, storage, velocities()},
          {RTVK_BINDING_QUADS, storage, quads()},
          {RTVK_BINDING_TRIANGLES, storage, triangles()},
          {RTVK_BINDING_NORMALS, storage, normals()},
          {RTVK_BINDING_BVH_NODES, storage, nodes()},
          {RTVK_BINDING_INSTANCES, storage, instances()},
          {RTVK_BINDING_TEXCOORDS, storage, uvs()}};
}

std::vector<buffer_binding> gpu_scene::appearance_bindings() const {
  constexpr VkDescriptorType storage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
  return {{RTVK_BINDING_TEXTURES, storage, textures()},
          {RTVK_BINDING_TEXELS, storage, texels()},
          {RTVK_BINDING_PERLIN, storage, perlin()},
          {RTVK_BINDING_MEDIA, storage, media()},
          {RTVK_BINDING_LIGHTS, storage, lights()}};
}

void gpu_scene::specialize(std::span<std::uint32_t> spec) const {
  spec[RTVK_SPEC_MOTION] = moves_;
  spec[RTVK_SPEC_QUADS] = quad_count_ > 0;
  spec[RTVK_SPEC_TRIANGLES] = triangle_count_ > 0;
  spec[RTVK_SPEC_INSTANCES] = instance_count_ > 0;
  spec[RTVK_SPEC_UV] = with_uv_;
  spec[RTVK_SPEC_TEXTURES] = any_textures_;
  spec[RTVK_SPEC_MEDIA] = medium_count_ > 0;
}

void gpu_scene::set_counts(render_push& push) const {
  // The scene's own: a scan without the BVH tests them, then each instance's group.
  push.sphere_count = own_spheres_;
  push.quad_count = own_quads_;
  push.triangle_count = own_triangles_;
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
