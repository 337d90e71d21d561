#pragma once
// Internal to the glTF reader: an accessor read as the spec defines it, every byte it names
// checked against its buffer first (gltf_accessor.cpp).
#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include <tiny_gltf.h>

#include "mesh_builder.h"

namespace rtvk {

// The component types by their C names, for accessor_reader::require.
namespace tinygltf_types {
inline constexpr int i8 = TINYGLTF_COMPONENT_TYPE_BYTE, u8 = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                     i16 = TINYGLTF_COMPONENT_TYPE_SHORT,
                     u16 = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                     u32 = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
}  // namespace tinygltf_types

// Reads an accessor's elements as doubles: floats as they are, normalized integers scaled by the
// spec's formulas (signed ones to [-1, 1], unsigned ones to [0, 1]), other integers as their
// values (KHR_mesh_quantization's positions and texture coordinates, which the node's transform
// or the texture transform scales). A sparse accessor's substitutions are applied once, when it
// is made (their indices kept in order, each looked up); an accessor without a buffer view reads
// zeros, as the spec says.
class accessor_reader {
 public:
  accessor_reader(const tinygltf::Model& m, int index, const mesh_builder& b, std::string where);

  std::size_t count() const { return a_->count; }
  int components() const { return components_; }
  int type() const { return a_->type; }
  int component_type() const { return a_->componentType; }
  bool normalized() const { return a_->normalized; }
  const std::string& where() const { return where_; }

  // Component c (< components()) of element i (< count()).
  double get(std::size_t i, int c) const {
    const std::size_t at = std::size_t(c) * std::size_t(component_bytes_);
    if (!substituted_.empty()) {
      const auto k = std::lower_bound(substituted_.begin(), substituted_.end(), i);
      if (k != substituted_.end() && *k == i)
        return read(values_ + std::size_t(k - substituted_.begin()) * element_ + at);
    }
    return base_ ? read(base_ + i * stride_ + at) : 0;
  }
  // Element i as an index (unsigned integer components only, checked when made).
  std::uint64_t index(std::size_t i) const { return std::uint64_t(get(i, 0)); }
  vec3 vec(std::size_t i) const { return vec3(get(i, 0), get(i, 1), get(i, 2)); }
  // Fails unless the accessor is one of `types` (TINYGLTF_TYPE_*) of the component types
  // `components` (TINYGLTF_COMPONENT_TYPE_*; float always allowed) with `count` elements (0: any).
  void require(std::initializer_list<int> types, std::initializer_list<int> components,
               std::size_t count, const std::string& what) const;

 private:
  double read(const unsigned char* p) const;
  void apply_sparse(const tinygltf::Model& m);

  const mesh_builder* b_;  // names the file in messages
  std::string where_;
  const tinygltf::Accessor* a_ = nullptr;
  const unsigned char* base_ = nullptr;  // element 0's bytes; null: no buffer view (zeros)
  std::size_t stride_ = 0;               // bytes from one element to the next
  std::size_t element_ = 0;              // bytes of one element, packed
  int components_ = 0, component_bytes_ = 0;
  std::vector<std::size_t> substituted_;   // sparse: the elements replaced, increasing
  const unsigned char* values_ = nullptr;  // sparse: their values, packed in that order
};

}  // namespace rtvk
