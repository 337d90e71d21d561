#pragma once
// Internal to formats/: a glTF accessor read as doubles, every byte it names checked against its
// buffer first (mesh_gltf.cpp).
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <string>

#include <tiny_gltf.h>

#include "mesh_builder.h"

namespace rtvk {

// Reads an accessor's elements as doubles, after checking that every byte it names lies in its
// buffer.
class accessor_reader {
 public:
  accessor_reader(const tinygltf::Model& m, int index, const mesh_builder& b, std::string where)
      : b_(b), where_(std::move(where)) {
    if (index < 0 || std::size_t(index) >= m.accessors.size())
      b_.fail(where_, "accessor " + std::to_string(index) + " does not exist");
    a_ = &m.accessors[std::size_t(index)];
    where_ += " (accessor " + std::to_string(index) + ")";
    if (a_->sparse.isSparse) b_.fail(where_, "sparse accessors are not supported");
    if (a_->bufferView < 0 || std::size_t(a_->bufferView) >= m.bufferViews.size())
      b_.fail(where_, "has no buffer view");
    const tinygltf::BufferView& view = m.bufferViews[std::size_t(a_->bufferView)];
    if (view.buffer < 0 || std::size_t(view.buffer) >= m.buffers.size())
      b_.fail(where_, "its buffer view names no buffer");
    const std::vector<unsigned char>& data = m.buffers[std::size_t(view.buffer)].data;
    components_ = tinygltf::GetNumComponentsInType(std::uint32_t(a_->type));
    component_bytes_ = tinygltf::GetComponentSizeInBytes(std::uint32_t(a_->componentType));
    if (components_ <= 0 || component_bytes_ <= 0) b_.fail(where_, "has an unknown type");
    const std::size_t element = std::size_t(components_) * std::size_t(component_bytes_);
    stride_ = view.byteStride ? view.byteStride : element;
    if (stride_ < element || stride_ > 252)  // glTF's own bounds on a stride
      b_.fail(where_, "its stride " + std::to_string(stride_) + " is not in [" +
                          std::to_string(element) + ", 252]");
    // The view within the buffer, then every byte of the accessor within the view. Each term is
    // bounded before the sum (offsets by the buffer's size, the stride by 252, the count by
    // 2^40), so nothing wraps.
    const auto outside = [&] {
      b_.fail(where_, "points outside its buffer's " + std::to_string(data.size()) + " bytes");
    };
    if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset) outside();
    if (a_->byteOffset > view.byteLength || a_->count > (std::uint64_t(1) << 40)) outside();
    const std::uint64_t end =
        a_->count == 0
            ? 0
            : std::uint64_t(a_->byteOffset) + std::uint64_t(stride_) * (a_->count - 1) + element;
    if (end > view.byteLength) outside();
    base_ = data.data() + view.byteOffset + a_->byteOffset;
  }

  std::size_t count() const { return a_->count; }
  int components() const { return components_; }
  int type() const { return a_->type; }

  // Component c of element i, as a double (normalized integers are scaled to [0, 1]).
  double get(std::size_t i, int c) const {
    const unsigned char* p = base_ + i * stride_ + std::size_t(c) * std::size_t(component_bytes_);
    switch (a_->componentType) {
      case TINYGLTF_COMPONENT_TYPE_FLOAT:
        return load<float>(p);
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        return scaled(load<std::uint32_t>(p), 4294967295.0);
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        return scaled(load<std::uint16_t>(p), 65535.0);
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return scaled(load<std::uint8_t>(p), 255.0);
      case TINYGLTF_COMPONENT_TYPE_SHORT:
        return scaled(load<std::int16_t>(p), 32767.0);
      case TINYGLTF_COMPONENT_TYPE_BYTE:
        return scaled(load<std::int8_t>(p), 127.0);
      case TINYGLTF_COMPONENT_TYPE_DOUBLE:
        return load<double>(p);
      default:
        b_.fail(where_, "has an unknown component type");
    }
  }
  // Element i as an index (integer components only).
  std::uint64_t index(std::size_t i) const {
    const unsigned char* p = base_ + i * stride_;
    switch (a_->componentType) {
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        return load<std::uint32_t>(p);
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        return load<std::uint16_t>(p);
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return load<std::uint8_t>(p);
      default:
        b_.fail(where_, "indices must be unsigned integers");
    }
  }
  vec3 vec(std::size_t i) const { return vec3(get(i, 0), get(i, 1), get(i, 2)); }

 private:
  template <typename T>
  static T load(const unsigned char* p) {
    T v;
    std::memcpy(&v, p, sizeof v);
    return v;
  }
  double scaled(double v, double max) const { return a_->normalized ? std::max(v / max, -1.0) : v; }

  const mesh_builder& b_;
  std::string where_;
  const tinygltf::Accessor* a_ = nullptr;
  const unsigned char* base_ = nullptr;
  std::size_t stride_ = 0;
  int components_ = 0, component_bytes_ = 0;
};

}  // namespace rtvk
