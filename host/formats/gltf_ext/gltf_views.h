#pragma once
// Internal to formats/gltf_ext/: a buffer view's bytes, checked inside its buffer, and the meshopt
// pass that gltfx_decompress runs first.
#include <cstddef>
#include <string>

#include <tiny_gltf.h>
#include <nlohmann/json.hpp>

namespace rtvk {

struct view_span {
  const unsigned char* data = nullptr;  // the view's first byte
  std::size_t size = 0;                 // bytes
};

// The bytes of buffer view `index`; calls `fail` (which throws) with why when it has none.
template <typename Fail>
view_span view_bytes(const tinygltf::Model& m, int index, Fail fail) {
  if (index < 0 || std::size_t(index) >= m.bufferViews.size())
    fail("buffer view " + std::to_string(index) + " does not exist");
  const tinygltf::BufferView& v = m.bufferViews[std::size_t(index)];
  if (v.buffer < 0 || std::size_t(v.buffer) >= m.buffers.size())
    fail("buffer view " + std::to_string(index) + " names no buffer");
  const std::vector<unsigned char>& data = m.buffers[std::size_t(v.buffer)].data;
  if (v.byteOffset > data.size() || v.byteLength > data.size() - v.byteOffset)
    fail("buffer view " + std::to_string(index) + " points outside its buffer's " +
         std::to_string(data.size()) + " bytes");
  return {data.data() + v.byteOffset, v.byteLength};
}

// Decodes each EXT_meshopt_compression view of `m` into a buffer of its own (gltf_meshopt.cpp).
void decode_meshopt_views(tinygltf::Model& m, const std::string& name);

// Gives each EXT_meshopt_compression fallback buffer without uri 4 bytes of data URI, so that
// tinygltf parses the file (gltf_meshopt.cpp; gltfx_prepare calls it).
void stand_in_fallbacks(nlohmann::json& doc);

}  // namespace rtvk
