#include "leaf_layout.h"

namespace rtvk {

leaf_layout make_leaf_layout(const bvh& tree, const primitive_spans& objects) {
  leaf_layout out;
  const std::array<std::size_t, shape_kinds> counts = objects.counts();
  for (std::size_t k = 0; k < shape_kinds; ++k) out.kinds[k].reserve(counts[k]);
  const auto place = [&](std::uint32_t object) -> std::uint32_t {
    std::size_t i = object;
    for (std::size_t k = 0; k < shape_kinds; ++k) {
      if (i < counts[k]) {
        out.kinds[k].push_back(std::uint32_t(i));
        return leaf_code(k) | std::uint32_t(out.kinds[k].size() - 1);
      }
      i -= counts[k];
    }
    // A box (an instance): referred to by its own index, nothing to store in leaf order.
    return RTVK_LEAF_INSTANCE | std::uint32_t(i);
  };
  if (tree.nodes().empty()) {
    for (std::size_t i = 0; i < objects.size(); ++i) place(std::uint32_t(i));
    return out;
  }
  out.refs.reserve(tree.order().size());
  for (const std::uint32_t object : tree.order()) out.refs.push_back(place(object));
  return out;
}

}  // namespace rtvk
