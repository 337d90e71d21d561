#include "object_ids.h"

#include <algorithm>

namespace rtvk {

object_ids::object_ids(const scene& s) {
  const std::size_t quads0 = s.spheres.size(), triangles0 = quads0 + s.quads.size();
  own_.assign(shape_count(s), 0);
  // Where a compound starts, and how long it runs, by scene index.
  std::vector<std::uint32_t> run(own_.size(), 0);
  for (const primitive_run& c : s.compounds) {
    const std::size_t start = (c.triangles ? triangles0 : quads0) + c.first;
    const std::size_t end = std::min(own_.size(), start + c.count);
    if (start < end && run[start] == 0) run[start] = std::uint32_t(end - start);
  }
  std::uint32_t next = 1;
  for (std::size_t k = 0; k < own_.size();) {
    if (run[k] > 1) {  // every primitive of the compound gets its first one's id
      for (std::size_t n = 0; n < run[k]; ++n) own_[k + n] = next;
      k += run[k];
    } else {
      own_[k++] = next;
    }
    ++next;
  }
  first_instance_ = next;
  instances_ = std::uint32_t(s.instances.size());
  count_ = next - 1 + instances_;
}

std::uint32_t object_ids::of(std::uint32_t object, std::uint32_t instance) const {
  if (instance > 0) return instance <= instances_ ? first_instance_ + instance - 1 : 0;
  return object < own_.size() ? own_[object] : 0;
}

}  // namespace rtvk
