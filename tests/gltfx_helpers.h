#pragma once
// glTF files in the compressed forms formats/gltf_ext/ decodes, made by the tests with the encoders
// of the same libraries: Draco (libdraco's encoder) and meshopt (meshoptimizer's), so that no
// such file need be shipped; and a .glb packer for any JSON and binary chunk.
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include <draco/attributes/attribute_quantization_transform.h>
#include <draco/compression/decode.h>
#include <draco/compression/encode.h>
#include <draco/mesh/triangle_soup_mesh_builder.h>
#include <meshoptimizer.h>
#include <nlohmann/json.hpp>

#include "mesh_helpers.h"

namespace rtvk::test {

// The Draco stream of a mesh's positions (quantized to `bits`), and the Draco id of POSITION.
inline std::string draco_stream(const indexed_mesh& m, int bits, int& position_id) {
  draco::TriangleSoupMeshBuilder builder;
  builder.Start(int(m.faces.size()));
  const int att = builder.AddAttribute(draco::GeometryAttribute::POSITION, 3, draco::DT_FLOAT32);
  for (std::size_t f = 0; f < m.faces.size(); ++f) {
    float p[3][3];
    for (int k = 0; k < 3; ++k)
      for (int c = 0; c < 3; ++c) p[k][c] = float(m.positions[m.faces[f][std::size_t(k)]][c]);
    builder.SetAttributeValuesForFace(att, draco::FaceIndex(std::uint32_t(f)), p[0], p[1], p[2]);
  }
  const std::unique_ptr<draco::Mesh> mesh = builder.Finalize();
  position_id = int(mesh->attribute(att)->unique_id());
  draco::Encoder encoder;
  encoder.SetAttributeQuantization(draco::GeometryAttribute::POSITION, bits);
  draco::EncoderBuffer out;
  if (!encoder.EncodeMeshToBuffer(*mesh, &out).ok()) return "";
  return std::string(out.data(), out.size());
}

// A .glb of a mesh whose one primitive is Draco-compressed (the stream its BIN chunk).
inline std::string draco_glb(const indexed_mesh& m, int bits = 14) {
  int id = 0;
  const std::string stream = draco_stream(m, bits, id);
  nlohmann::json doc = {
      {"asset", {{"version", "2.0"}}},
      {"extensionsUsed", {"KHR_draco_mesh_compression"}},
      {"extensionsRequired", {"KHR_draco_mesh_compression"}},
      {"scene", 0},
      {"scenes", {{{"nodes", {0}}}}},
      {"nodes", {{{"mesh", 0}}}},
      {"meshes",
       {{{"primitives",
          {{{"attributes", {{"POSITION", 0}}},
            {"indices", 1},
            {"extensions",
             {{"KHR_draco_mesh_compression",
               {{"bufferView", 0}, {"attributes", {{"POSITION", id}}}}}}}}}}}}},
      {"buffers", {{{"byteLength", stream.size()}}}},
      {"bufferViews", {{{"buffer", 0}, {"byteLength", stream.size()}}}},
      {"accessors",
       {{{"componentType", 5126}, {"count", m.positions.size()}, {"type", "VEC3"}},
        {{"componentType", 5125}, {"count", 3 * m.faces.size()}, {"type", "SCALAR"}}}}};
  return glb_of(doc.dump(), stream);
}

// One EXT_meshopt_compression view: `raw` (count elements of `stride` bytes) encoded in `mode`
// into `bin` (buffer 1), the view itself in buffer 0 (the fallback) at `fallback_offset`.
inline nlohmann::json meshopt_view(const std::string& raw, std::size_t count, std::size_t stride,
                                   const std::string& mode, const std::string& filter,
                                   std::string& bin, std::size_t& fallback_offset) {
  std::vector<unsigned char> out;
  if (mode == "ATTRIBUTES") {
    out.resize(meshopt_encodeVertexBufferBound(count, stride));
    out.resize(meshopt_encodeVertexBuffer(out.data(), out.size(), raw.data(), count, stride));
  } else {  // TRIANGLES of 32-bit indices
    std::vector<unsigned> idx(count);
    std::memcpy(idx.data(), raw.data(), count * 4);
    out.resize(meshopt_encodeIndexBufferBound(count, count));
    out.resize(meshopt_encodeIndexBuffer(out.data(), out.size(), idx.data(), count));
  }
  nlohmann::json ext = {
      {"buffer", 1},          {"byteOffset", bin.size()}, {"byteLength", out.size()},
      {"byteStride", stride}, {"count", count},           {"mode", mode}};
  if (!filter.empty()) ext["filter"] = filter;
  bin.append(reinterpret_cast<const char*>(out.data()), out.size());
  while (bin.size() % 4) bin += '\0';
  nlohmann::json view = {{"buffer", 0},
                         {"byteOffset", fallback_offset},
                         {"byteLength", raw.size()},
                         {"extensions", {{"EXT_meshopt_compression", ext}}}};
  if (mode == "ATTRIBUTES") view["byteStride"] = stride;
  fallback_offset += raw.size();
  return view;
}

}  // namespace rtvk::test
