// KHR_draco_mesh_compression: a primitive's attributes and indices in one Draco stream (a buffer
// view), decoded by Debian's libdraco into new float accessors and 32-bit indices of the model,
// which the primitive then names instead of its own. The loader reads them as any others.
#include <cmath>
#include <cstring>

#include <draco/compression/decode.h>

#include "errors.h"
#include "gltf_ext.h"
#include "gltf_views.h"

namespace rtvk {
namespace {

constexpr const char* draco_ext = "KHR_draco_mesh_compression";

// The decoded data goes into a buffer of its own, one view per attribute.
int add_view(tinygltf::Model& m, std::vector<unsigned char> bytes) {
  tinygltf::Buffer buf;
  buf.data = std::move(bytes);
  tinygltf::BufferView view;
  view.buffer = int(m.buffers.size());
  view.byteLength = buf.data.size();
  m.buffers.push_back(std::move(buf));
  m.bufferViews.push_back(view);
  return int(m.bufferViews.size() - 1);
}

// A new accessor of `count` elements of `type` in a new view of `bytes`.
int add_accessor(tinygltf::Model& m, std::vector<unsigned char> bytes, int component_type, int type,
                 std::size_t count) {
  tinygltf::Accessor a;
  a.bufferView = add_view(m, std::move(bytes));
  a.componentType = component_type;
  a.type = type;
  a.count = count;
  m.accessors.push_back(a);
  return int(m.accessors.size() - 1);
}

class draco_primitive {
 public:
  draco_primitive(tinygltf::Model& m, std::string where) : m_(m), where_(std::move(where)) {}
  [[noreturn]] void fail(const std::string& what) const { throw usage_error(where_ + ": " + what); }

  void decode(tinygltf::Primitive& prim, const tinygltf::Value& ext) {
    if (!ext.IsObject() || !ext.Has("bufferView") || !ext.Get("bufferView").IsInt())
      fail("has no bufferView");
    const view_span bytes = view_bytes(m_, ext.Get("bufferView").GetNumberAsInt(),
                                       [&](const std::string& why) { fail(why); });
    draco::DecoderBuffer in;
    in.Init(reinterpret_cast<const char*>(bytes.data), bytes.size);
    draco::Decoder decoder;
    auto decoded = decoder.DecodeMeshFromBuffer(&in);
    if (!decoded.ok())
      fail("the Draco stream does not decode: " + decoded.status().error_msg_string());
    mesh_ = std::move(decoded).value();
    if (!mesh_ || mesh_->num_points() == 0) fail("the Draco stream holds no points");
    if (mesh_->num_faces() > max_faces) fail("the Draco stream holds too many faces");
    const tinygltf::Value& ids = ext.Get("attributes");
    if (!ids.IsObject()) fail("has no attributes");
    for (const std::string& key : ids.Keys()) {
      const auto it = prim.attributes.find(key);
      if (it == prim.attributes.end()) fail("attribute " + key + " is not one of the primitive's");
      if (!ids.Get(key).IsInt()) fail("attribute " + key + " has no Draco id");
      it->second = attribute(key, ids.Get(key).GetNumberAsInt(), it->second);
    }
    prim.indices = indices();
  }

 private:
  static constexpr std::uint32_t max_faces = 1u << 28;  // max_scene_objects

  // The Draco attribute `id` as float elements of the glTF accessor's type.
  int attribute(const std::string& key, int id, int accessor) {
    if (accessor < 0 || std::size_t(accessor) >= m_.accessors.size())
      fail("attribute " + key + ": accessor " + std::to_string(accessor) + " does not exist");
    const int type = m_.accessors[std::size_t(accessor)].type;
    const int n = tinygltf::GetNumComponentsInType(std::uint32_t(type));
    if (n <= 0 || n > 4) fail("attribute " + key + " has an unknown type");
    const draco::PointAttribute* att =
        id < 0 ? nullptr : mesh_->GetAttributeByUniqueId(std::uint32_t(id));
    if (!att)
      fail("attribute " + key + ": the Draco stream has no attribute " + std::to_string(id));
    const std::size_t points = mesh_->num_points();
    std::vector<unsigned char> out(points * std::size_t(n) * sizeof(float));
    float value[4];
    for (std::uint32_t p = 0; p < points; ++p) {
      const draco::AttributeValueIndex v = att->mapped_index(draco::PointIndex(p));
      if (v.value() >= att->size() || !att->ConvertValue<float>(v, std::int8_t(n), value))
        fail("attribute " + key + " point " + std::to_string(p) + " does not decode");
      std::memcpy(out.data() + std::size_t(p) * std::size_t(n) * sizeof(float), value,
                  std::size_t(n) * sizeof(float));
    }
    return add_accessor(m_, std::move(out), TINYGLTF_COMPONENT_TYPE_FLOAT, type, points);
  }

  // The faces as a list of 32-bit indices.
  int indices() {
    const std::size_t faces = mesh_->num_faces();
    std::vector<std::uint32_t> corners(3 * faces);
    for (std::uint32_t f = 0; f < faces; ++f) {
      const draco::Mesh::Face& face = mesh_->face(draco::FaceIndex(f));
      for (int k = 0; k < 3; ++k) corners[3 * f + std::size_t(k)] = face[k].value();
    }
    std::vector<unsigned char> out(corners.size() * sizeof(std::uint32_t));
    if (!out.empty()) std::memcpy(out.data(), corners.data(), out.size());
    return add_accessor(m_, std::move(out), TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT,
                        TINYGLTF_TYPE_SCALAR, corners.size());
  }

  tinygltf::Model& m_;
  std::string where_;                  // "<file>: mesh M primitive P: KHR_draco_mesh_compression"
  std::unique_ptr<draco::Mesh> mesh_;  // the decoded stream
};

}  // namespace

void gltfx_decompress(tinygltf::Model& m, const std::string& name) {
  decode_meshopt_views(m, name);
  for (std::size_t i = 0; i < m.meshes.size(); ++i)
    for (std::size_t p = 0; p < m.meshes[i].primitives.size(); ++p) {
      tinygltf::Primitive& prim = m.meshes[i].primitives[p];
      const auto ext = prim.extensions.find(draco_ext);
      if (ext == prim.extensions.end()) continue;
      draco_primitive(m, name + ": mesh " + std::to_string(i) + " primitive " + std::to_string(p) +
                             ": " + draco_ext)
          .decode(prim, ext->second);
    }
}

bool gltfx_honours(const std::string& ext) {
  return ext == draco_ext || ext == "EXT_meshopt_compression";
}

}  // namespace rtvk
