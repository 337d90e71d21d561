// glTF skins at rest: each joint's matrix is its node's global transform (the nodes' own
// transforms, no animation) times its inverse bind matrix; a vertex is moved by its joints'
// matrices blended by its weights (linear blend skinning, the spec's).
#include <glm/gtc/type_ptr.hpp>

#include "gltf_accessor.h"
#include "gltf_reader.h"

namespace rtvk {
namespace {

glm::dmat4 as_matrix(const transform& t) {
  glm::dmat4 m(t.linear);
  m[3] = glm::dvec4(t.offset, 1);
  return m;
}

}  // namespace

// Node k's global transform: its parents' down to it (a node's parent is the node whose children
// name it; checked for cycles by depth).
glm::dmat4 gltf_walker::global_matrix(int node, const std::string& where) {
  if (parents_.empty()) {
    parents_.assign(m_.nodes.size(), -1);
    for (std::size_t p = 0; p < m_.nodes.size(); ++p)
      for (int c : m_.nodes[p].children)
        if (c >= 0 && std::size_t(c) < parents_.size()) parents_[std::size_t(c)] = int(p);
  }
  glm::dmat4 m(1.0);
  for (int n = node, depth = 0; n >= 0; n = parents_[std::size_t(n)], ++depth) {
    if (std::size_t(n) >= m_.nodes.size())
      b_.fail(where, "joint " + std::to_string(n) + " does not exist");
    if (depth > 64)
      b_.fail(where, "joint " + std::to_string(node) + " is deeper than 64 levels (or in a cycle)");
    m = as_matrix(node_transform(m_.nodes[std::size_t(n)])) * m;
  }
  return m;
}

// Skin k's joint matrices, made once per skin.
const std::vector<glm::dmat4>& gltf_walker::joint_matrices(int k, const std::string& node) {
  const auto cached = skins_.find(k);
  if (cached != skins_.end()) return cached->second;
  const std::string where = node + " skin " + std::to_string(k);
  if (k < 0 || std::size_t(k) >= m_.skins.size()) b_.fail(where, "does not exist");
  const tinygltf::Skin& skin = m_.skins[std::size_t(k)];
  std::optional<accessor_reader> ibm;
  if (skin.inverseBindMatrices >= 0) {
    ibm.emplace(m_, skin.inverseBindMatrices, b_, where + " inverseBindMatrices");
    ibm->require({TINYGLTF_TYPE_MAT4}, {}, 0, "is not MAT4 of floats");
    if (ibm->count() < skin.joints.size())
      b_.fail(ibm->where(), "has fewer matrices than the skin has joints");
  }
  std::vector<glm::dmat4> out;
  for (std::size_t j = 0; j < skin.joints.size(); ++j) {
    glm::dmat4 inverse_bind(1.0);
    if (ibm)
      for (int e = 0; e < 16; ++e) glm::value_ptr(inverse_bind)[e] = ibm->get(j, e);
    out.push_back(global_matrix(skin.joints[j], where) * inverse_bind);
  }
  return skins_[k] = std::move(out);
}

}  // namespace rtvk
