#include "pipeline_cache.h"

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "atomic_file.h"
#include "vk_error.h"

namespace rtvk::gpu {
namespace {

// The device's pipelineCacheUUID in hex: a file made by another device or driver has another
// name, so it is never offered to this one.
std::string uuid_hex(const VkPhysicalDeviceProperties& props) {
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
std::vector<char> read_matching(const std::filesystem::path& file,
                                const VkPhysicalDeviceProperties& props) {
  std::ifstream in(file, std::ios::binary);
  std::vector<char> data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
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
    VkPhysicalDeviceProperties props{};
    vkGetPhysicalDeviceProperties(ctx.device().handle, &props);
    file_ = folder / ("pipelines-" + uuid_hex(props) + ".bin");
    initial = read_matching(file_, props);
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
  try {  // another run may write the same file: each write is whole, the last one stays
    write_file_atomically(file_, std::string_view(data.data(), data.size()));
  } catch (const std::runtime_error&) {
    return false;
  }
  return true;
}

}  // namespace rtvk::gpu
