// EXT_meshopt_compression: a buffer view whose bytes are meshoptimizer's vertex or index codec
// output in another buffer, decoded by Debian's libmeshoptimizer (and its filters) into a buffer
// of the view's own. The view's own buffer is then the extension's `fallback`: data for readers
// without the extension, or none at all (a buffer without uri, which gltfx_prepare stands in for).
#include <cstring>

#include <meshoptimizer.h>

#include "errors.h"
#include "gltf_ext.h"
#include "gltf_views.h"

namespace rtvk {
namespace {

constexpr const char* meshopt_ext = "EXT_meshopt_compression";

// No codec packs more than this many bytes of data into one byte of its stream (the vertex
// codec's densest is 64 to 1, a column of equal bytes); more is a file that asks for memory
// it cannot fill.
constexpr std::uint64_t max_ratio = 128;

std::uint64_t number(const tinygltf::Value& v, const char* key, std::uint64_t fallback) {
  if (!v.Has(key)) return fallback;
  const tinygltf::Value& x = v.Get(key);
  if (!x.IsNumber() || !(x.GetNumberAsDouble() >= 0) || x.GetNumberAsDouble() > 9e15)
    return ~std::uint64_t(0);  // refused by the checks that follow
  return std::uint64_t(x.GetNumberAsDouble());
}

std::string text(const tinygltf::Value& v, const char* key, const char* fallback) {
  return v.Has(key) && v.Get(key).IsString() ? v.Get(key).Get<std::string>() : fallback;
}

// Checks what the extension's spec requires of a view's mode, stride and filter; says why not.
std::string unfit(const std::string& mode, const std::string& filter, std::uint64_t stride,
                  std::uint64_t count) {
  if (mode == "ATTRIBUTES") {
    if (stride == 0 || stride % 4 != 0 || stride > 256)
      return "ATTRIBUTES byteStride " + std::to_string(stride) +
             " is not a multiple of 4 in [4, 256]";
    if (filter == "NONE") return "";
    if (filter == "OCTAHEDRAL" && stride != 4 && stride != 8)
      return "OCTAHEDRAL needs byteStride 4 or 8";
    if (filter == "QUATERNION" && stride != 8) return "QUATERNION needs byteStride 8";
    if (filter == "OCTAHEDRAL" || filter == "QUATERNION" || filter == "EXPONENTIAL") return "";
    return "filter \"" + filter + "\" is not NONE, OCTAHEDRAL, QUATERNION or EXPONENTIAL";
  }
  if (mode != "TRIANGLES" && mode != "INDICES")
    return "mode \"" + mode + "\" is not ATTRIBUTES, TRIANGLES or INDICES";
  if (stride != 2 && stride != 4)
    return mode + " byteStride " + std::to_string(stride) + " is not 2 or 4";
  if (filter != "NONE") return "filter " + filter + " is for ATTRIBUTES only";
  if (mode == "TRIANGLES" && count % 3 != 0)
    return "TRIANGLES count " + std::to_string(count) + " is not whole triangles";
  return "";
}

// Decodes view `index`'s stream into a new buffer that the view then points into.
void decode_view(tinygltf::Model& m, std::size_t index, const tinygltf::Value& ext,
                 const std::string& where) {
  const auto fail = [&](const std::string& why) { throw usage_error(where + ": " + why); };
  if (!ext.IsObject() || !ext.Has("buffer") || !ext.Get("buffer").IsInt()) fail("has no buffer");
  const int buffer = ext.Get("buffer").GetNumberAsInt();
  if (buffer < 0 || std::size_t(buffer) >= m.buffers.size())
    fail("buffer " + std::to_string(buffer) + " does not exist");
  const std::vector<unsigned char>& data = m.buffers[std::size_t(buffer)].data;
  const std::uint64_t offset = number(ext, "byteOffset", 0),
                      length = number(ext, "byteLength", ~0ull);
  const std::uint64_t stride = number(ext, "byteStride", 0), count = number(ext, "count", ~0ull);
  if (offset > data.size() || length > data.size() - offset)
    fail("byteOffset " + std::to_string(offset) + " and byteLength " + std::to_string(length) +
         " are not inside buffer " + std::to_string(buffer) + "'s " + std::to_string(data.size()) +
         " bytes");
  const std::string mode = text(ext, "mode", ""), filter = text(ext, "filter", "NONE");
  if (const std::string why = unfit(mode, filter, stride, count); !why.empty()) fail(why);
  tinygltf::BufferView& view = m.bufferViews[index];
  if (count > (1ull << 40) || count * stride != view.byteLength)
    fail("count " + std::to_string(count) + " x byteStride " + std::to_string(stride) +
         " is not the view's byteLength " + std::to_string(view.byteLength));
  if (view.byteLength > max_ratio * length + 65536)
    fail("decodes to " + std::to_string(view.byteLength) + " bytes from " + std::to_string(length) +
         " (more than the codec can pack)");
  std::vector<unsigned char> out(view.byteLength);
  const unsigned char* in = data.data() + offset;
  const int rc =
      mode == "ATTRIBUTES"  ? meshopt_decodeVertexBuffer(out.data(), count, stride, in, length)
      : mode == "TRIANGLES" ? meshopt_decodeIndexBuffer(out.data(), count, stride, in, length)
                            : meshopt_decodeIndexSequence(out.data(), count, stride, in, length);
  if (rc != 0)
    fail("the " + mode + " stream does not decode (meshopt error " + std::to_string(rc) + ")");
  if (filter == "OCTAHEDRAL") meshopt_decodeFilterOct(out.data(), count, stride);
  if (filter == "QUATERNION") meshopt_decodeFilterQuat(out.data(), count, stride);
  if (filter == "EXPONENTIAL") meshopt_decodeFilterExp(out.data(), count, stride);
  tinygltf::Buffer decoded;
  decoded.data = std::move(out);
  view.buffer = int(m.buffers.size());
  view.byteOffset = 0;
  m.buffers.push_back(std::move(decoded));
}

}  // namespace

void decode_meshopt_views(tinygltf::Model& m, const std::string& name) {
  for (std::size_t i = 0; i < m.bufferViews.size(); ++i) {
    const auto ext = m.bufferViews[i].extensions.find(meshopt_ext);
    if (ext == m.bufferViews[i].extensions.end()) continue;
    decode_view(m, i, ext->second,
                name + ": bufferViews " + std::to_string(i) + ": " + meshopt_ext);
  }
}

// The stand-in for a fallback buffer without data: tinygltf refuses a buffer without uri (a
// .gltf) or reads the .glb's own chunk into it; 4 zero bytes parse everywhere.
void stand_in_fallbacks(nlohmann::json& doc) {
  const auto buffers = doc.find("buffers");
  if (buffers == doc.end() || !buffers->is_array()) return;
  for (nlohmann::json& b : *buffers) {
    if (!b.is_object() || b.contains("uri")) continue;
    const nlohmann::json fallback = nlohmann::json::object({{meshopt_ext, {{"fallback", true}}}});
    const auto ext = b.find("extensions");
    if (ext == b.end() || !ext->is_object() || !ext->contains(meshopt_ext) ||
        (*ext)[meshopt_ext] != fallback[meshopt_ext])
      continue;
    b["uri"] = "data:application/octet-stream;base64,AAAAAA==";
    b["byteLength"] = 4;
  }
}

}  // namespace rtvk
