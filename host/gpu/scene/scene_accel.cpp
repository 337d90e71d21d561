#include "scene_accel.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstring>
#include <map>
#include <tuple>

#include "accel_boxes.h"
#include "device_fit.h"
#include "elapsed.h"
#include "errors.h"
#include "format.h"
#include "vk_error.h"

namespace rtvk::gpu {
namespace {

// A group of objects: runs of the sphere, quad, triangle and disk arrays (the scene's own, or
// what an instance places).
struct object_group {
  std::uint32_t sphere_first, sphere_count, quad_first, quad_count, triangle_first, triangle_count,
      disk_first, disk_count;
  auto key() const {
    return std::tie(sphere_first, sphere_count, quad_first, quad_count, triangle_first,
                    triangle_count, disk_first, disk_count);
  }
  bool operator<(const object_group& o) const { return key() < o.key(); }
  // The shapes the driver knows only by their boxes: spheres, then quads, then disks.
  std::uint32_t boxes() const { return sphere_count + quad_count + disk_count; }
};

// The instance's placement, group space to world: the inverse of its to_group rows, in double.
VkTransformMatrixKHR placement(const gpu_instance& in) {
  const glm::dmat3 to_group_t(glm::dvec3(in.to_group_x), glm::dvec3(in.to_group_y),
                              glm::dvec3(in.to_group_z));  // columns are to_group's rows
  const glm::dmat3 a = glm::transpose(to_group_t);
  const glm::dvec3 b(in.to_group_x.w, in.to_group_y.w, in.to_group_z.w);
  const glm::dmat3 inv = glm::inverse(a);
  const glm::dvec3 t = -(inv * b);
  VkTransformMatrixKHR m{};
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) m.matrix[r][c] = float(inv[c][r]);
    m.matrix[r][3] = float(t[r]);
  }
  return m;
}

// A buffer the build reads, written by the host.
std::unique_ptr<gpu_buffer> build_input(const gpu_context& ctx, const void* data,
                                        std::size_t bytes) {
  auto b = std::make_unique<gpu_buffer>(
      ctx, std::max<std::size_t>(bytes, 64),
      VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR |
          VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT,
      memory_use::staging);
  if (data && bytes) b->write(data, bytes);
  return b;
}

void build_barrier(VkCommandBuffer cb) {
  VkMemoryBarrier b{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  b.srcAccessMask = VK_ACCESS_ACCELERATION_STRUCTURE_WRITE_BIT_KHR;
  b.dstAccessMask = VK_ACCESS_ACCELERATION_STRUCTURE_READ_BIT_KHR |
                    VK_ACCESS_ACCELERATION_STRUCTURE_WRITE_BIT_KHR;
  vkCmdPipelineBarrier(cb, VK_PIPELINE_STAGE_ACCELERATION_STRUCTURE_BUILD_BIT_KHR,
                       VK_PIPELINE_STAGE_ACCELERATION_STRUCTURE_BUILD_BIT_KHR, 0, 1, &b, 0, nullptr,
                       0, nullptr);
}

// One structure's build: its geometries, their primitive counts, and the sizes the driver asks.
struct build_plan {
  std::vector<VkAccelerationStructureGeometryKHR> geometries;
  std::vector<VkAccelerationStructureBuildRangeInfoKHR> ranges;
  VkAccelerationStructureBuildSizesInfoKHR sizes{
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_SIZES_INFO_KHR};
  VkAccelerationStructureBuildGeometryInfoKHR info(VkAccelerationStructureTypeKHR type,
                                                   VkBuildAccelerationStructureFlagsKHR flags) {
    VkAccelerationStructureBuildGeometryInfoKHR i{
        VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_GEOMETRY_INFO_KHR};
    i.type = type;
    i.flags = flags;
    i.mode = VK_BUILD_ACCELERATION_STRUCTURE_MODE_BUILD_KHR;
    i.geometryCount = std::uint32_t(geometries.size());
    i.pGeometries = geometries.data();
    return i;
  }
  void size(const gpu_context& ctx, VkAccelerationStructureTypeKHR type,
            VkBuildAccelerationStructureFlagsKHR flags) {
    std::vector<std::uint32_t> counts;
    for (const auto& r : ranges) counts.push_back(r.primitiveCount);
    const auto i = info(type, flags);
    vkGetAccelerationStructureBuildSizesKHR(
        ctx.vk(), VK_ACCELERATION_STRUCTURE_BUILD_TYPE_DEVICE_KHR, &i, counts.data(), &sizes);
  }
};

// The bottom levels' geometries: rt_object.rahit charges one trip of the loop budget per call,
// so a driver that calls it twice for one candidate (the specification allows it unless this is
// set) would make the starved and unfinished counts, and so the passes, depend on the driver.
// The nearest hit is the same either way (test_object keeps the nearest by its tie rule).
constexpr VkGeometryFlagsKHR once_per_candidate =
    VK_GEOMETRY_NO_DUPLICATE_ANY_HIT_INVOCATION_BIT_KHR;

constexpr VkBuildAccelerationStructureFlagsKHR bottom_flags =
    VK_BUILD_ACCELERATION_STRUCTURE_PREFER_FAST_TRACE_BIT_KHR |
    VK_BUILD_ACCELERATION_STRUCTURE_ALLOW_COMPACTION_BIT_KHR;
constexpr VkBuildAccelerationStructureFlagsKHR top_flags =
    VK_BUILD_ACCELERATION_STRUCTURE_PREFER_FAST_TRACE_BIT_KHR;

usage_error past_limit(const std::string& subject, const std::string& what, std::uint64_t n,
                       const std::string& limit, std::uint64_t most, const gpu_context& ctx) {
  return usage_error(subject + ": " + what + " " + std::to_string(n) + ", past " + limit + " " +
                     std::to_string(most) + " of device '" + ctx.device().name + "'");
}

}  // namespace

scene_accel::scene_accel(gpu_context& ctx, const gpu_scene::host_arrays& a, time_span motion,
                         const std::string& subject) {
  const auto start = std::chrono::steady_clock::now();
  const auto limits = acceleration_limits(ctx);

  // The groups, each built once however many instances place it.
  std::vector<object_group> groups{{0, a.own[shape_sphere], 0, a.own[shape_quad], 0,
                                    a.own[shape_triangle], 0, a.own[shape_disk]}};
  std::map<object_group, std::uint32_t> group_index{{groups[0], 0}};
  std::vector<std::uint32_t> instance_group;
  for (const gpu_instance& in : a.instances) {
    const object_group g{in.sphere_first,   in.sphere_count,   in.quad_first, in.quad_count,
                         in.triangle_first, in.triangle_count, in.disk_first, in.disk_count};
    auto [it, fresh] = group_index.try_emplace(g, std::uint32_t(groups.size()));
    if (fresh) groups.push_back(g);
    instance_group.push_back(it->second);
  }

  // Their boxes, group after group, and every triangle's corners (triangle k's at 9k).
  std::vector<VkAabbPositionsKHR> boxes;
  std::vector<std::size_t> first_box;
  for (const object_group& g : groups) {
    first_box.push_back(boxes.size());
    for (std::uint32_t k = g.sphere_first; k < g.sphere_first + g.sphere_count; ++k)
      boxes.push_back(
          sphere_box(a.spheres[k], a.moves ? glm::vec3(a.velocities[k]) : glm::vec3(0.0f), motion));
    for (std::uint32_t k = g.quad_first; k < g.quad_first + g.quad_count; ++k)
      boxes.push_back(quad_box(a.quads[k]));
    for (std::uint32_t k = g.disk_first; k < g.disk_first + g.disk_count; ++k)
      boxes.push_back(disk_box(a.disks[k]));
  }
  std::vector<float> corners;
  corners.reserve(a.triangles.size() * 9);
  for (const gpu_triangle& t : a.triangles)
    for (const glm::vec3& p : {t.a, t.b, t.c}) corners.insert(corners.end(), {p.x, p.y, p.z});
  const auto box_input = build_input(ctx, boxes.data(), boxes.size() * sizeof(VkAabbPositionsKHR));
  const auto corner_input = build_input(ctx, corners.data(), corners.size() * sizeof(float));
  const VkDeviceAddress box_address = device_address(ctx, box_input->get());
  const VkDeviceAddress corner_address = device_address(ctx, corner_input->get());

  // Each group's two bottom levels (one may be empty), as a bottom level holds one kind of
  // geometry: plan 2i its boxes (hit group 0), plan 2i + 1 its triangles (hit group 1).
  std::vector<build_plan> plans(2 * groups.size());
  for (std::size_t i = 0; i < groups.size(); ++i) {
    const object_group& g = groups[i];
    if (std::uint64_t(g.boxes()) > limits.maxPrimitiveCount ||
        g.triangle_count > limits.maxPrimitiveCount)
      throw past_limit(
          subject,
          std::string(i == 0 ? "the scene's own" : "an instanced group's") +
              (g.boxes() > g.triangle_count ? " spheres, quads and disks" : " triangles"),
          std::max<std::uint64_t>(g.boxes(), g.triangle_count), "maxPrimitiveCount",
          limits.maxPrimitiveCount, ctx);
    build_plan& p = plans[2 * i];
    if (g.boxes()) {
      VkAccelerationStructureGeometryKHR geo{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR};
      geo.geometryType = VK_GEOMETRY_TYPE_AABBS_KHR;
      geo.flags = once_per_candidate;
      geo.geometry.aabbs = {VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_AABBS_DATA_KHR};
      geo.geometry.aabbs.data.deviceAddress =
          box_address + first_box[i] * sizeof(VkAabbPositionsKHR);
      geo.geometry.aabbs.stride = sizeof(VkAabbPositionsKHR);
      p.geometries.push_back(geo);
      p.ranges.push_back({g.boxes(), 0, 0, 0});
    }
    build_plan& q = plans[2 * i + 1];
    if (g.triangle_count) {
      VkAccelerationStructureGeometryKHR geo{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR};
      geo.geometryType = VK_GEOMETRY_TYPE_TRIANGLES_KHR;
      geo.flags = once_per_candidate;
      auto& tri = geo.geometry.triangles;
      tri = {VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_TRIANGLES_DATA_KHR};
      tri.vertexFormat = VK_FORMAT_R32G32B32_SFLOAT;
      tri.vertexData.deviceAddress = corner_address + VkDeviceAddress(g.triangle_first) * 36;
      tri.vertexStride = 12;
      tri.maxVertex = 3 * g.triangle_count - 1;
      tri.indexType = VK_INDEX_TYPE_NONE_KHR;
      q.geometries.push_back(geo);
      q.ranges.push_back({g.triangle_count, 0, 0, 0});
    }
    for (build_plan* b : {&p, &q})
      if (!b->geometries.empty())
        b->size(ctx, VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR, bottom_flags);
  }

  // The top level's instances: each group's bottom levels with objects, placed.
  std::vector<VkAccelerationStructureInstanceKHR> placed;
  auto place = [&](std::uint32_t group, std::uint32_t custom, const VkTransformMatrixKHR& m) {
    for (std::uint32_t kind = 0; kind < 2; ++kind) {
      if (plans[2 * group + kind].geometries.empty()) continue;  // nothing to hit
      VkAccelerationStructureInstanceKHR in{};
      in.transform = m;
      in.instanceCustomIndex = custom;
      in.mask = 0xff;
      in.instanceShaderBindingTableRecordOffset = kind;  // boxes' hit group, or triangles'
      in.flags = VK_GEOMETRY_INSTANCE_TRIANGLE_FACING_CULL_DISABLE_BIT_KHR |
                 VK_GEOMETRY_INSTANCE_FORCE_NO_OPAQUE_BIT_KHR;
      in.accelerationStructureReference = 2 * group + kind;  // its address, once built
      placed.push_back(in);
    }
  };
  place(0, 0, VkTransformMatrixKHR{{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}}});
  for (std::size_t k = 0; k < a.instances.size(); ++k)
    place(instance_group[k], std::uint32_t(k + 1), placement(a.instances[k]));
  // An instance's custom index is 24 bits wide (VkAccelerationStructureInstanceKHR).
  if (a.instances.size() >= (1u << 24) - 1)
    throw past_limit(subject, "instances", a.instances.size(),
                     "the 24 bits of instanceCustomIndex, at most", (1u << 24) - 2, ctx);
  if (placed.size() > limits.maxInstanceCount)
    throw past_limit(subject, "top-level instances", placed.size(), "maxInstanceCount",
                     limits.maxInstanceCount, ctx);
  auto instance_input = build_input(ctx, nullptr, placed.size() * sizeof(placed[0]));
  build_plan top;
  {
    VkAccelerationStructureGeometryKHR geo{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR};
    geo.geometryType = VK_GEOMETRY_TYPE_INSTANCES_KHR;
    geo.geometry.instances = {VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_INSTANCES_DATA_KHR};
    geo.geometry.instances.data.deviceAddress = device_address(ctx, instance_input->get());
    top.geometries.push_back(geo);
    top.ranges.push_back({std::uint32_t(placed.size()), 0, 0, 0});
    top.size(ctx, VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR, top_flags);
  }

  // Everything checked against the device before anything of it is allocated.
  const VkDeviceSize align =
      std::max<VkDeviceSize>(limits.minAccelerationStructureScratchOffsetAlignment, 1);
  VkDeviceSize scratch = top.sizes.buildScratchSize;
  std::vector<buffer_request> requests{
      {"the acceleration structures' boxes", boxes.size() * sizeof(VkAabbPositionsKHR), false,
       memory_use::staging},
      {"the acceleration structures' triangles", corners.size() * sizeof(float), false,
       memory_use::staging},
      {"the top-level acceleration structure", top.sizes.accelerationStructureSize, false,
       memory_use::device_local}};
  for (std::size_t i = 0; i < plans.size(); ++i) {
    if (plans[i].geometries.empty()) continue;
    scratch = std::max(scratch, plans[i].sizes.buildScratchSize);
    requests.push_back({i < 2 ? "the scene's acceleration structure"
                              : "an instanced group's acceleration structure",
                        plans[i].sizes.accelerationStructureSize, false, memory_use::device_local});
  }
  requests.push_back(
      {"the acceleration structures' scratch", scratch + align, false, memory_use::device_local});
  check_device_fits(ctx, requests, subject);

  gpu_buffer scratch_buffer(
      ctx, scratch + align,
      VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT,
      memory_use::device_local);
  const VkDeviceAddress scratch_address =
      (device_address(ctx, scratch_buffer.get()) + align - 1) / align * align;

  // The bottom levels, one after another through the one scratch, and their compacted sizes.
  std::vector<std::uint32_t> built;  // groups with a structure
  bottoms_.resize(plans.size());
  for (std::size_t i = 0; i < plans.size(); ++i) {
    if (plans[i].geometries.empty()) continue;
    bottoms_[i] = std::make_unique<acceleration_structure>(
        ctx, VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR,
        plans[i].sizes.accelerationStructureSize);
    built.push_back(std::uint32_t(i));
  }
  VkQueryPoolCreateInfo query_info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
  query_info.queryType = VK_QUERY_TYPE_ACCELERATION_STRUCTURE_COMPACTED_SIZE_KHR;
  query_info.queryCount = std::uint32_t(std::max<std::size_t>(built.size(), 1));
  VkQueryPool raw_pool = VK_NULL_HANDLE;
  vk_check(vkCreateQueryPool(ctx.vk(), &query_info, nullptr, &raw_pool), "vkCreateQueryPool");
  const unique_query_pool pool(ctx.vk(), raw_pool);
  ctx.submit_and_wait([&](VkCommandBuffer cb) {
    vkCmdResetQueryPool(cb, pool.get(), 0, query_info.queryCount);
    for (std::size_t n = 0; n < built.size(); ++n) {
      build_plan& p = plans[built[n]];
      auto info = p.info(VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR, bottom_flags);
      info.dstAccelerationStructure = bottoms_[built[n]]->get();
      info.scratchData.deviceAddress = scratch_address;
      const VkAccelerationStructureBuildRangeInfoKHR* ranges = p.ranges.data();
      if (n) build_barrier(cb);  // the scratch is the last build's
      vkCmdBuildAccelerationStructuresKHR(cb, 1, &info, &ranges);
    }
    if (built.empty()) return;
    build_barrier(cb);
    std::vector<VkAccelerationStructureKHR> handles;
    for (std::uint32_t i : built) handles.push_back(bottoms_[i]->get());
    vkCmdWriteAccelerationStructuresPropertiesKHR(
        cb, std::uint32_t(handles.size()), handles.data(),
        VK_QUERY_TYPE_ACCELERATION_STRUCTURE_COMPACTED_SIZE_KHR, pool.get(), 0);
  });
  if (!built.empty()) {
    std::vector<VkDeviceSize> compact(built.size());
    vk_check(vkGetQueryPoolResults(ctx.vk(), pool.get(), 0, std::uint32_t(built.size()),
                                   compact.size() * sizeof(VkDeviceSize), compact.data(),
                                   sizeof(VkDeviceSize),
                                   VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
             "vkGetQueryPoolResults");
    std::vector<std::unique_ptr<acceleration_structure>> compacted(plans.size());
    for (std::size_t n = 0; n < built.size(); ++n)
      compacted[built[n]] = std::make_unique<acceleration_structure>(
          ctx, VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR, compact[n]);
    ctx.submit_and_wait([&](VkCommandBuffer cb) {
      for (std::uint32_t i : built) {
        VkCopyAccelerationStructureInfoKHR copy{
            VK_STRUCTURE_TYPE_COPY_ACCELERATION_STRUCTURE_INFO_KHR};
        copy.src = bottoms_[i]->get();
        copy.dst = compacted[i]->get();
        copy.mode = VK_COPY_ACCELERATION_STRUCTURE_MODE_COMPACT_KHR;
        vkCmdCopyAccelerationStructureKHR(cb, &copy);
      }
      build_barrier(cb);
    });
    bottoms_ = std::move(compacted);
  }

  // The top level, pointing at the compacted bottoms.
  for (VkAccelerationStructureInstanceKHR& in : placed)
    in.accelerationStructureReference = bottoms_[in.accelerationStructureReference]->address();
  instance_input->write(placed.data(), placed.size() * sizeof(placed[0]));
  top_ = std::make_unique<acceleration_structure>(ctx, VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR,
                                                  top.sizes.accelerationStructureSize);
  ctx.submit_and_wait([&](VkCommandBuffer cb) {
    auto info = top.info(VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR, top_flags);
    info.dstAccelerationStructure = top_->get();
    info.scratchData.deviceAddress = scratch_address;
    const VkAccelerationStructureBuildRangeInfoKHR* ranges = top.ranges.data();
    vkCmdBuildAccelerationStructuresKHR(cb, 1, &info, &ranges);
    // What the renders read next.
    VkMemoryBarrier b{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    b.srcAccessMask = VK_ACCESS_ACCELERATION_STRUCTURE_WRITE_BIT_KHR;
    b.dstAccessMask = VK_ACCESS_ACCELERATION_STRUCTURE_READ_BIT_KHR;
    const VkPipelineStageFlags readers =
        VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT |
        (ctx.ray_tracing_pipelines() ? VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR : 0);
    vkCmdPipelineBarrier(cb, VK_PIPELINE_STAGE_ACCELERATION_STRUCTURE_BUILD_BIT_KHR, readers, 0, 1,
                         &b, 0, nullptr, 0, nullptr);
  });
  build_seconds_ = seconds_since(start);
}

VkDeviceSize scene_accel::bytes() const {
  VkDeviceSize n = top_ ? top_->bytes() : 0;
  for (const auto& b : bottoms_)
    if (b) n += b->bytes();
  return n;
}

}  // namespace rtvk::gpu
