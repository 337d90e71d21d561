#include "pipeline_cache.h"

#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <system_error>
#include <vector>

#include "vk_error.h"

namespace rtvk::gpu {
namespace {

// The device's pipelineCacheUUID in hex: a file made by another device or driver has another
// name, so it is never offered to this one.
std::string uuid_hex(const device_info& d) {
  VkPhysicalDeviceProperties props{};
  vkGetPhysicalDeviceProperties(d.handle, &props);
  static const char digits[] = "0123456789abcdef";
  std::string out;
  for (std::uint8_t b : props.pipelineCacheUUID) {
    out += digits[b >> 4];
    out += digits[b & 15];
  }
  return out;
}

// The file's bytes when its header (VkPipelineCacheHeaderVersionOne) names this device;
// otherwise none. Drivers check too, but not every driver checks everything.
std::vector<char> read_matching(const std::filesystem::path& file, const device_info& d) {
  std::ifstream in(file, std::ios::binary);
  std::vector<char> data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  VkPhysicalDeviceProperties props{};
  vkGetPhysicalDeviceProperties(d.handle, &props);
  std::uint32_t header[4] = {};
  if (data.size() < 32) return {};
  std::memcpy(header, data.data(), sizeof header);
  if (header[0] < 32 || header[1] != VK_PIPELINE_CACHE_HEADER_VERSION_ONE ||
      header[2] != props.vendorID || header[3] != props.deviceID ||
      std::memcmp(data.data() + 16, props.pipelineCacheUUID, VK_UUID_SIZE) != 0)
    return {};
  return data;
}

}  // namespace

std::filesystem::path default_cache_folder() {
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg)
    return std::filesystem::path(xdg) / "rtvk";
  if (const char* home = std::getenv("HOME"); home && *home)
    return std::filesystem::path(home) / ".cache" / "rtvk";
  return {};
}

pipeline_cache::pipeline_cache(const gpu_context& ctx, std::filesystem::path folder) : ctx_(ctx) {
  std::vector<char> initial;
  if (!folder.empty()) {
    file_ = folder / ("pipelines-" + uuid_hex(ctx.device()) + ".bin");
    initial = read_matching(file_, ctx.device());
  }
  VkPipelineCacheCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_CACHE_CREATE_INFO};
  info.initialDataSize = initial.size();
  info.pInitialData = initial.empty() ? nullptr : initial.data();
  VkPipelineCache cache = VK_NULL_HANDLE;
  vk_check(vkCreatePipelineCache(ctx.vk(), &info, nullptr, &cache), "vkCreatePipelineCache");
  cache_ = unique_pipeline_cache(ctx.vk(), cache);
  loaded_ = initial.size();
}

pipeline_cache::~pipeline_cache() {
  if (ctx_.lost()) cache_.release();  // a hung device may still be compiling into it
}

bool pipeline_cache::save() const {
  if (file_.empty()) return false;
  std::size_t size = 0;
  if (vkGetPipelineCacheData(ctx_.vk(), cache_.get(), &size, nullptr) != VK_SUCCESS) return false;
  std::vector<char> data(size);
  if (vkGetPipelineCacheData(ctx_.vk(), cache_.get(), &size, data.data()) != VK_SUCCESS)
    return false;
  data.resize(size);
  std::error_code ec;
  std::filesystem::create_directories(file_.parent_path(), ec);
  if (ec) return false;
  // Another run may be writing the same file: each writes its own temporary, the rename is atomic.
  const std::filesystem::path tmp =
      file_.string() + ".tmp-" + std::to_string(static_cast<long>(::getpid()));
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out.write(data.data(), std::streamsize(data.size()));
    if (!out.flush()) {
      std::filesystem::remove(tmp, ec);
      return false;
    }
  }
  std::filesystem::rename(tmp, file_, ec);
  if (!ec) return true;
  std::filesystem::remove(tmp, ec);
  return false;
}

}  // namespace rtvk::gpu
