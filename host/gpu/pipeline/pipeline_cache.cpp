#include "pipeline_cache.h"

#include <cstdint>
#include <cstdio>
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
// name, so it is rarely offered to this one.
std::string uuid_hex(const std::uint8_t (&uuid)[VK_UUID_SIZE]) {
  static const char digits[] = "0123456789abcdef";
  std::string out;
  for (std::uint8_t b : uuid) {
    out += digits[b >> 4];
    out += digits[b & 15];
  }
  return out;
}

// FNV-1a, 64 bits: finds a flipped or lost byte, which is all it is for.
std::uint64_t fnv1a(const char* data, std::size_t n) {
  std::uint64_t h = 0xcbf29ce484222325ull;
  for (std::size_t i = 0; i < n; ++i) h = (h ^ std::uint8_t(data[i])) * 0x100000001b3ull;
  return h;
}

// rtvk's own header in front of the driver's data. Drivers have crashed on stale or truncated
// cache data, and not every driver checks everything of the Vulkan header it starts with, so
// the payload goes to the driver only when all of this matches.
struct file_header {
  char magic[8];                           // "rtvkpc1\0"
  std::uint64_t payload_bytes;             // the driver's data after this header
  std::uint64_t payload_hash;              // fnv1a of it
  std::uint32_t vendor_id, device_id;      // the device's
  std::uint32_t driver_version, reserved;  // vendor-encoded; 0
  std::uint8_t driver_uuid[VK_UUID_SIZE];  // VkPhysicalDeviceIDProperties'
  std::uint8_t cache_uuid[VK_UUID_SIZE];   // pipelineCacheUUID
};
static_assert(sizeof(file_header) == pipeline_cache::header_bytes);
constexpr char file_magic[8] = {'r', 't', 'v', 'k', 'p', 'c', '1', 0};

file_header header_for(const device_info& d, const char* payload, std::size_t bytes) {
  file_header h{};
  std::memcpy(h.magic, file_magic, sizeof h.magic);
  h.payload_bytes = bytes;
  h.payload_hash = fnv1a(payload, bytes);
  h.vendor_id = d.vendor_id;
  h.device_id = d.device_id;
  h.driver_version = d.driver_version;
  std::memcpy(h.driver_uuid, d.driver_uuid, VK_UUID_SIZE);
  std::memcpy(h.cache_uuid, d.pipeline_cache_uuid, VK_UUID_SIZE);
  return h;
}

// Why the file's payload cannot go to this device's driver, or empty when it can.
std::string check(const std::vector<char>& data, const device_info& d) {
  if (data.size() < sizeof(file_header)) return "shorter than its header";
  file_header h;
  std::memcpy(&h, data.data(), sizeof h);
  if (std::memcmp(h.magic, file_magic, sizeof h.magic) != 0) return "not an rtvk pipeline cache";
  const char* payload = data.data() + sizeof h;
  const std::size_t bytes = data.size() - sizeof h;
  if (h.payload_bytes != bytes)
    return "truncated or extended: " + std::to_string(bytes) + " bytes of data where its header " +
           "says " + std::to_string(h.payload_bytes);
  if (h.payload_hash != fnv1a(payload, bytes)) return "corrupted: its data does not match its hash";
  const file_header want = header_for(d, payload, bytes);
  if (h.vendor_id != want.vendor_id || h.device_id != want.device_id ||
      h.driver_version != want.driver_version ||
      std::memcmp(h.driver_uuid, want.driver_uuid, VK_UUID_SIZE) != 0 ||
      std::memcmp(h.cache_uuid, want.cache_uuid, VK_UUID_SIZE) != 0)
    return "made by another device or driver";
  // The driver's own header (VkPipelineCacheHeaderVersionOne), checked once more.
  std::uint32_t vk_header[4] = {};
  if (bytes < 32) return "its driver data is shorter than Vulkan's cache header";
  std::memcpy(vk_header, payload, sizeof vk_header);
  if (vk_header[0] < 32 || vk_header[1] != VK_PIPELINE_CACHE_HEADER_VERSION_ONE ||
      vk_header[2] != d.vendor_id || vk_header[3] != d.device_id ||
      std::memcmp(payload + 16, d.pipeline_cache_uuid, VK_UUID_SIZE) != 0)
    return "its driver data names another device";
  return {};
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
  std::vector<char> data;
  if (!folder.empty()) {
    file_ = folder / ("pipelines-" + uuid_hex(ctx.device().pipeline_cache_uuid) + ".bin");
    std::ifstream in(file_, std::ios::binary);
    if (in) {
      data.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
      ignored_ = check(data, ctx.device());
      if (!ignored_.empty()) {
        std::fprintf(stderr,
                     "rtvk: warning: ignoring the pipeline cache %s: %s (it is written anew)\n",
                     file_.c_str(), ignored_.c_str());
        data.clear();
      } else {
        data.erase(data.begin(), data.begin() + sizeof(file_header));
      }
    }
  }
  VkPipelineCacheCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_CACHE_CREATE_INFO};
  info.initialDataSize = data.size();
  info.pInitialData = data.empty() ? nullptr : data.data();
  VkPipelineCache cache = VK_NULL_HANDLE;
  vk_check(vkCreatePipelineCache(ctx.vk(), &info, nullptr, &cache), "vkCreatePipelineCache");
  cache_ = unique_pipeline_cache(ctx.vk(), cache);
  loaded_ = data.size();
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
  const file_header h = header_for(ctx_.device(), data.data(), data.size());
  data.insert(data.begin(), reinterpret_cast<const char*>(&h),
              reinterpret_cast<const char*>(&h) + sizeof h);
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
