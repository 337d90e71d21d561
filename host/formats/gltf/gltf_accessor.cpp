// glTF accessors (the spec's section 3.6), read with every byte they name checked first.
#include "gltf_accessor.h"

#include <algorithm>
#include <cstring>

namespace rtvk {
namespace {

template <typename T>
T load(const unsigned char* p) {
  T v;
  std::memcpy(&v, p, sizeof v);
  return v;
}

// The bytes of `count` elements of `element` bytes, `stride` apart, from `offset` into buffer
// view `view`, after checking that every one lies in the view and the view in its buffer. Each
// term is bounded before the sum (offsets by the buffer's size, the stride by 252, the count by
// 2^40), so nothing wraps.
const unsigned char* view_bytes(const tinygltf::Model& m, int view, std::size_t offset,
                                std::uint64_t count, std::size_t element, std::size_t stride,
                                const mesh_builder& b, const std::string& where) {
  if (view < 0 || std::size_t(view) >= m.bufferViews.size())
    b.fail(where, "buffer view " + std::to_string(view) + " does not exist");
  const tinygltf::BufferView& v = m.bufferViews[std::size_t(view)];
  if (v.buffer < 0 || std::size_t(v.buffer) >= m.buffers.size())
    b.fail(where, "its buffer view names no buffer");
  const std::vector<unsigned char>& data = m.buffers[std::size_t(v.buffer)].data;
  const auto outside = [&] {
    b.fail(where, "points outside its buffer's " + std::to_string(data.size()) + " bytes");
  };
  if (v.byteOffset > data.size() || v.byteLength > data.size() - v.byteOffset) outside();
  if (offset > v.byteLength || count > (std::uint64_t(1) << 40)) outside();
  const std::uint64_t end =
      count == 0 ? 0 : std::uint64_t(offset) + std::uint64_t(stride) * (count - 1) + element;
  if (end > v.byteLength) outside();
  return data.data() + v.byteOffset + offset;
}

// An index component type's bytes, or 0 for one that is not an unsigned integer.
int index_bytes(int component_type) {
  switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return 1;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
      return 4;
    default:
      return 0;
  }
}

std::uint64_t load_index(const unsigned char* p, int bytes) {
  return bytes == 1   ? load<std::uint8_t>(p)
         : bytes == 2 ? load<std::uint16_t>(p)
                      : load<std::uint32_t>(p);
}

}  // namespace

accessor_reader::accessor_reader(const tinygltf::Model& m, int index, const mesh_builder& b,
                                 std::string where)
    : b_(&b), where_(std::move(where)) {
  if (index < 0 || std::size_t(index) >= m.accessors.size())
    b_->fail(where_, "accessor " + std::to_string(index) + " does not exist");
  a_ = &m.accessors[std::size_t(index)];
  where_ += " (accessor " + std::to_string(index) + ")";
  components_ = tinygltf::GetNumComponentsInType(std::uint32_t(a_->type));
  component_bytes_ = tinygltf::GetComponentSizeInBytes(std::uint32_t(a_->componentType));
  if (components_ <= 0 || component_bytes_ <= 0) b_->fail(where_, "has an unknown type");
  if (a_->count > (std::uint64_t(1) << 40)) b_->fail(where_, "has too many elements");
  element_ = std::size_t(components_) * std::size_t(component_bytes_);
  const std::size_t element = element_;
  if (a_->bufferView >= 0) {
    stride_ = element;
    if (std::size_t(a_->bufferView) < m.bufferViews.size() &&
        m.bufferViews[std::size_t(a_->bufferView)].byteStride)
      stride_ = m.bufferViews[std::size_t(a_->bufferView)].byteStride;
    if (stride_ < element || stride_ > 252)  // glTF's own bounds on a stride
      b_->fail(where_, "its stride " + std::to_string(stride_) + " is not in [" +
                           std::to_string(element) + ", 252]");
    base_ = view_bytes(m, a_->bufferView, a_->byteOffset, a_->count, element, stride_, *b_, where_);
  }
  if (a_->sparse.isSparse) apply_sparse(m);
}

// The spec's sparse storage: `count` strictly increasing indices, each naming the element that
// the matching value replaces.
void accessor_reader::apply_sparse(const tinygltf::Model& m) {
  const auto& sp = a_->sparse;
  const std::string where = where_ + " sparse";
  if (sp.count < 1 || std::size_t(sp.count) > a_->count)
    b_->fail(where, "count " + std::to_string(sp.count) + " is not in [1, " +
                        std::to_string(a_->count) + "]");
  const int ib = index_bytes(sp.indices.componentType);
  if (ib == 0) b_->fail(where, "indices are not unsigned integers");
  if (sp.indices.byteOffset < 0 || sp.values.byteOffset < 0)
    b_->fail(where, "has a negative byteOffset");
  const unsigned char* indices = view_bytes(
      m, sp.indices.bufferView, std::size_t(sp.indices.byteOffset), std::uint64_t(sp.count),
      std::size_t(ib), std::size_t(ib), *b_, where + " indices");
  values_ = view_bytes(m, sp.values.bufferView, std::size_t(sp.values.byteOffset),
                       std::uint64_t(sp.count), element_, element_, *b_, where + " values");
  substituted_.reserve(std::size_t(sp.count));
  for (std::size_t k = 0; k < std::size_t(sp.count); ++k) {
    const std::uint64_t i = load_index(indices + k * std::size_t(ib), ib);
    if (i >= a_->count || (k > 0 && i <= substituted_.back()))
      b_->fail(where, "index " + std::to_string(i) + " is out of range or out of order");
    substituted_.push_back(std::size_t(i));
  }
}

double accessor_reader::read(const unsigned char* p) const {
  const bool norm = a_->normalized;
  switch (a_->componentType) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
      return load<float>(p);
    case TINYGLTF_COMPONENT_TYPE_DOUBLE:
      return load<double>(p);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
      return norm ? load<std::uint32_t>(p) / 4294967295.0 : load<std::uint32_t>(p);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return norm ? load<std::uint16_t>(p) / 65535.0 : load<std::uint16_t>(p);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return norm ? load<std::uint8_t>(p) / 255.0 : load<std::uint8_t>(p);
    case TINYGLTF_COMPONENT_TYPE_SHORT:
      return norm ? std::max(load<std::int16_t>(p) / 32767.0, -1.0) : load<std::int16_t>(p);
    case TINYGLTF_COMPONENT_TYPE_BYTE:
      return norm ? std::max(load<std::int8_t>(p) / 127.0, -1.0) : load<std::int8_t>(p);
    default:
      b_->fail(where_, "has an unknown component type");
  }
}

void accessor_reader::require(std::initializer_list<int> types,
                              std::initializer_list<int> component_types, std::size_t count,
                              const std::string& what) const {
  const bool type_ok = std::find(types.begin(), types.end(), a_->type) != types.end();
  const bool component_ok = a_->componentType == TINYGLTF_COMPONENT_TYPE_FLOAT ||
                            std::find(component_types.begin(), component_types.end(),
                                      a_->componentType) != component_types.end();
  if (!type_ok || !component_ok || (count && a_->count != count)) b_->fail(where_, what);
}

}  // namespace rtvk
