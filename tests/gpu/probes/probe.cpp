#include "probe.h"

#include <cstring>

#include "bsdf_tables.h"
#include "buffer.h"
#include "compute_pipeline.h"
#include "gpu_scene.h"
#include "packing.h"
#include "probe_shaders.h"

namespace rtvk::gpu {
namespace {

// Runs a probe shader once over a host-visible buffer it reads and writes in place.
void run_in_place(gpu_context& ctx, std::span<const std::uint32_t> spirv, void* data,
                  std::size_t bytes, std::uint32_t groups, const gpu_buffer* ubo,
                  const gpu_buffer* tables = nullptr, std::span<const buffer_binding> more = {}) {
  gpu_buffer buf(ctx, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, memory_use::upload);
  buf.write(data, bytes);
  std::vector<buffer_binding> bindings{
      {RTVK_BINDING_PROBE, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, buf.get()}};
  if (ubo) bindings.push_back({RTVK_BINDING_CAMERA, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, ubo->get()});
  if (tables)
    bindings.push_back(
        {RTVK_BINDING_BSDF_TABLES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, tables->get()});
  bindings.insert(bindings.end(), more.begin(), more.end());
  const compute_pipeline pipeline(ctx, spirv, bindings, 0);
  ctx.submit_and_wait([&](VkCommandBuffer cb) {
    pipeline.bind(cb);
    pipeline.dispatch(cb, {groups, 1, 1});
    VkMemoryBarrier b{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    b.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
    b.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(cb, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1,
                         &b, 0, nullptr, 0, nullptr);
  });
  std::memcpy(data, buf.read(), bytes);
}

}  // namespace

probe_io run_probe(gpu_context& ctx, const camera& cam,
                   const std::array<glm::vec4, RTVK_PROBE_POINTS>& uv_lens) {
  const camera_ubo ubo = to_ubo(cam);
  gpu_buffer ubo_buf(ctx, sizeof ubo, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, memory_use::upload);
  ubo_buf.write(&ubo, sizeof ubo);
  probe_io io{};
  for (int k = 0; k < RTVK_PROBE_POINTS; ++k) io.uv[k] = uv_lens[k];
  run_in_place(ctx, probe_shader(), &io, sizeof io, 1, &ubo_buf);
  return io;
}

std::vector<rng_probe_entry> run_rng_probe(gpu_context& ctx, std::vector<rng_probe_entry> entries) {
  run_in_place(ctx, rng_probe_shader(), entries.data(), entries.size() * sizeof(rng_probe_entry),
               std::uint32_t((entries.size() + 63) / 64), nullptr);
  return entries;
}

std::vector<sobol_probe_entry> run_sobol_probe(gpu_context& ctx,
                                               std::vector<sobol_probe_entry> entries) {
  run_in_place(ctx, sobol_probe_shader(), entries.data(),
               entries.size() * sizeof(sobol_probe_entry),
               std::uint32_t((entries.size() + 63) / 64), nullptr);
  return entries;
}

std::vector<hit_probe_entry> run_hit_probe(gpu_context& ctx, std::vector<hit_probe_entry> entries) {
  run_in_place(ctx, hit_probe_shader(), entries.data(), entries.size() * sizeof(hit_probe_entry),
               std::uint32_t((entries.size() + 63) / 64), nullptr);
  return entries;
}

std::vector<kernel_probe_entry> run_kernel_probe(gpu_context& ctx,
                                                 std::vector<kernel_probe_entry> entries) {
  run_in_place(ctx, kernel_probe_shader(), entries.data(),
               entries.size() * sizeof(kernel_probe_entry),
               std::uint32_t((entries.size() + 63) / 64), nullptr);
  return entries;
}

std::vector<light_probe_entry> run_light_probe(gpu_context& ctx,
                                               std::vector<light_probe_entry> entries) {
  run_in_place(ctx, light_probe_shader(), entries.data(),
               entries.size() * sizeof(light_probe_entry),
               std::uint32_t((entries.size() + 63) / 64), nullptr);
  return entries;
}

std::vector<pbr_probe_entry> run_pbr_probe(gpu_context& ctx, std::vector<pbr_probe_entry> entries) {
  gpu_buffer tables(ctx, sizeof bsdf_table_data, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                    memory_use::upload);
  tables.write(bsdf_table_data, sizeof bsdf_table_data);
  run_in_place(ctx, pbr_probe_shader(), entries.data(), entries.size() * sizeof(pbr_probe_entry),
               std::uint32_t((entries.size() + 63) / 64), nullptr, &tables);
  return entries;
}

std::vector<light_tree_probe_entry> run_light_tree_probe(
    gpu_context& ctx, const std::vector<gpu_light>& lamps, const std::vector<gpu_light_node>& nodes,
    std::vector<light_tree_probe_entry> entries) {
  gpu_buffer l(ctx, lamps.size() * sizeof(gpu_light), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
               memory_use::upload);
  l.write(lamps.data(), lamps.size() * sizeof(gpu_light));
  gpu_buffer n(ctx, nodes.size() * sizeof(gpu_light_node), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
               memory_use::upload);
  n.write(nodes.data(), nodes.size() * sizeof(gpu_light_node));
  const buffer_binding more[] = {
      {RTVK_BINDING_LIGHTS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, l.get()},
      {RTVK_BINDING_LIGHT_TREE, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, n.get()}};
  run_in_place(ctx, light_tree_probe_shader(), entries.data(),
               entries.size() * sizeof(light_tree_probe_entry),
               std::uint32_t((entries.size() + 63) / 64), nullptr, nullptr, more);
  return entries;
}

std::vector<punctual_probe_entry> run_punctual_probe(gpu_context& ctx,
                                                     const std::vector<gpu_punctual>& lights,
                                                     std::vector<punctual_probe_entry> entries) {
  const std::size_t light_bytes = lights.size() * sizeof(gpu_punctual);
  gpu_buffer buf(ctx, light_bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, memory_use::upload);
  buf.write(lights.data(), light_bytes);
  const buffer_binding binding{RTVK_BINDING_PUNCTUAL, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, buf.get()};
  run_in_place(ctx, punctual_probe_shader(), entries.data(),
               entries.size() * sizeof(punctual_probe_entry),
               std::uint32_t((entries.size() + 63) / 64), nullptr, nullptr,
               std::span<const buffer_binding>(&binding, 1));
  return entries;
}

std::vector<environment_probe_entry> run_environment_probe(
    gpu_context& ctx, const std::vector<std::uint32_t>& texels, const std::vector<float>& table,
    std::vector<environment_probe_entry> entries) {
  gpu_buffer t(ctx, texels.size() * sizeof(std::uint32_t), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
               memory_use::upload);
  t.write(texels.data(), texels.size() * sizeof(std::uint32_t));
  gpu_buffer c(ctx, table.size() * sizeof(float), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
               memory_use::upload);
  c.write(table.data(), table.size() * sizeof(float));
  const buffer_binding more[] = {
      {RTVK_BINDING_ENVIRONMENT, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, t.get()},
      {RTVK_BINDING_ENVIRONMENT_CDF, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, c.get()}};
  run_in_place(ctx, environment_probe_shader(), entries.data(),
               entries.size() * sizeof(environment_probe_entry),
               std::uint32_t((entries.size() + 63) / 64), nullptr, nullptr, more);
  return entries;
}

std::vector<world_probe_entry> run_world_probe(gpu_context& ctx, const scene& s, bool use_bvh,
                                               std::vector<world_probe_entry> entries) {
  const gpu_scene g(ctx, s, use_bvh);
  const std::size_t bytes = entries.size() * sizeof(world_probe_entry);
  gpu_buffer buf(ctx, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, memory_use::upload);
  buf.write(entries.data(), bytes);
  std::uint32_t spec[RTVK_SPEC_COUNT] = {};
  spec[RTVK_SPEC_USE_BVH] = use_bvh;
  g.specialize(spec);
  std::vector<buffer_binding> bindings = g.object_bindings();
  bindings.push_back({RTVK_BINDING_PROBE, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, buf.get()});
  const compute_pipeline pipeline(ctx, world_probe_shader(), bindings, sizeof(render_push), spec);
  render_push push{};
  g.set_counts(push);
  push.loop_budget = 0xffffffffu;  // one ray an invocation: no loop cap to respect
  ctx.submit_and_wait([&](VkCommandBuffer cb) {
    g.record_upload(cb);
    VkMemoryBarrier upload{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    upload.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    upload.dstAccessMask = VK_ACCESS_SHADER_READ_BIT;
    vkCmdPipelineBarrier(cb, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                         0, 1, &upload, 0, nullptr, 0, nullptr);
    pipeline.bind(cb);
    pipeline.push(cb, &push, sizeof push);
    pipeline.dispatch(cb, {std::uint32_t((entries.size() + 63) / 64), 1, 1});
    VkMemoryBarrier done{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    done.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
    done.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(cb, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1,
                         &done, 0, nullptr, 0, nullptr);
  });
  std::memcpy(entries.data(), buf.read(), bytes);
  return entries;
}

}  // namespace rtvk::gpu
