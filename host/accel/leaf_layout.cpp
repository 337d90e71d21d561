#include "leaf_layout.h"

namespace rtvk {

leaf_layout make_leaf_layout(const bvh& tree, const primitive_spans& objects) {
  leaf_layout out;
  const std::size_t spheres = objects.spheres.size(), quads = objects.quads.size();
  out.spheres.reserve(spheres);
  out.quads.reserve(quads);
  out.triangles.reserve(objects.triangles.size());
  const auto place = [&](std::uint32_t object) -> std::uint32_t {
    if (object < spheres) {
      out.spheres.push_back(object);
      return RTVK_LEAF_SPHERE | std::uint32_t(out.spheres.size() - 1);
    }
    if (object < spheres + quads) {
      out.quads.push_back(std::uint32_t(object - spheres));
      return RTVK_LEAF_QUAD | std::uint32_t(out.quads.size() - 1);
    }
    if (object < spheres + quads + objects.triangles.size()) {
      out.triangles.push_back(std::uint32_t(object - spheres - quads));
      return RTVK_LEAF_TRIANGLE | std::uint32_t(out.triangles.size() - 1);
    }
    // A box (an instance): referred to by its own index, nothing to store in leaf order.
    return RTVK_LEAF_INSTANCE | std::uint32_t(object - spheres - quads - objects.triangles.size());
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
