#pragma once
#include <cstddef>
#include <filesystem>
#include <string>

#include "context.h"
#include "vk_handle.h"

namespace rtvk::gpu {

// The device's compiled pipelines, kept in a file between runs so that a second run skips the
// shader compiler. One file per device and driver (named after the device's pipelineCacheUUID),
// the driver's data behind rtvk's own header: magic, size, hash, and the device's vendor and
// device IDs, driver version, driver UUID and pipelineCacheUUID. A file that is missing is
// ignored; one that is truncated, corrupted or made for another device or driver is ignored with
// a warning on stderr (drivers have crashed on such data), and written anew; a cache that cannot
// be written is only slower: none of it ever fails a render.
class pipeline_cache {
 public:
  // `folder` empty: an in-memory cache only.
  pipeline_cache(const gpu_context& ctx, std::filesystem::path folder);
  ~pipeline_cache();
  pipeline_cache(const pipeline_cache&) = delete;
  pipeline_cache& operator=(const pipeline_cache&) = delete;

  VkPipelineCache get() const { return cache_.get(); }
  // Writes the cache's data to its file (write_file_atomically: never a partial file). Returns
  // whether it did.
  bool save() const;

  const std::filesystem::path& file() const { return file_; }  // empty without a folder
  std::size_t loaded_bytes() const { return loaded_; }  // driver data the file gave, 0 if none
  // Why the file was ignored ("corrupted: ..."), or empty.
  const std::string& ignored_because() const { return ignored_; }
  static constexpr std::size_t header_bytes = 72;  // rtvk's header in front of the driver's data

 private:
  const gpu_context& ctx_;       // tells whether the device may still be using the cache
  std::filesystem::path file_;   // where the data lives between runs
  std::size_t loaded_ = 0;       // bytes of initial data accepted from file_
  std::string ignored_;          // why file_ was not used, or empty
  unique_pipeline_cache cache_;  // the Vulkan object
};

// Where rtvk keeps its caches: $XDG_CACHE_HOME/rtvk, else $HOME/.cache/rtvk, else nothing.
std::filesystem::path default_cache_folder();

}  // namespace rtvk::gpu
