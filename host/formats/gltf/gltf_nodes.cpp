// The glTF reader's walk: the default scene's node tree with each node's transform, and each
// mesh's triangle primitives with their positions, normals, texture coordinates and materials.
#include "gltf_primitive.h"
#include "gltf_reader.h"

namespace rtvk {

gltf_walker::gltf_walker(const tinygltf::Model& m, mesh_builder& b, const mesh_placement& how)
    : m_(m), b_(b), how_(how) {
  if (how.material < 0) materials_.emplace(m, b);
}

void gltf_walker::walk_scene() {
  std::vector<int> roots;
  const int scene = m_.defaultScene >= 0 ? m_.defaultScene : 0;
  if (std::size_t(scene) < m_.scenes.size()) {
    roots = m_.scenes[std::size_t(scene)].nodes;
  } else {  // no scenes: every node that is nobody's child
    std::vector<bool> child(m_.nodes.size());
    for (const tinygltf::Node& n : m_.nodes)
      for (int c : n.children)
        if (c >= 0 && std::size_t(c) < child.size()) child[std::size_t(c)] = true;
    for (std::size_t i = 0; i < child.size(); ++i)
      if (!child[i]) roots.push_back(int(i));
  }
  for (int n : roots) walk(n, transform{}, 0);
}

void gltf_walker::walk(int index, const transform& parent, int depth) {
  const std::string where = "node " + std::to_string(index);
  if (index < 0 || std::size_t(index) >= m_.nodes.size()) b_.fail(where, "does not exist");
  if (depth > 64) b_.fail(where, "the node tree is deeper than 64 levels (or has a cycle)");
  // glTF's nodes form trees: a node reached twice (a shared child, a cycle) would be walked
  // once per path, exponentially many times.
  if (walked_.empty()) walked_.resize(m_.nodes.size());
  if (walked_[std::size_t(index)]) b_.fail(where, "is reached twice (glTF nodes form trees)");
  walked_[std::size_t(index)] = true;
  const tinygltf::Node& n = m_.nodes[std::size_t(index)];
  const transform t = compose(parent, node_transform(n));
  if (n.mesh >= 0) {
    if (const std::optional<std::string> why = degenerate(t))
      b_.fail(where, "its transform cannot place a mesh: " + *why);
    add_mesh(n, t, where);
  }
  for (int c : n.children) walk(c, t, depth + 1);
}

void gltf_walker::add_mesh(const tinygltf::Node& n, const transform& t, const std::string& node) {
  const int index = n.mesh;
  if (std::size_t(index) >= m_.meshes.size())
    b_.fail(node, "mesh " + std::to_string(index) + " does not exist");
  const tinygltf::Mesh& mesh = m_.meshes[std::size_t(index)];
  // Morph targets at their default weights: the node's, else the mesh's.
  const std::vector<double>& weights = n.weights.empty() ? mesh.weights : n.weights;
  // A skinned mesh is placed by its joints alone (the spec ignores its node's transform).
  const std::vector<glm::dmat4>* joints = n.skin >= 0 ? &joint_matrices(n.skin, node) : nullptr;
  for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
    const std::string where = "mesh " + std::to_string(index) + " primitive " + std::to_string(p);
    add_primitive(mesh.primitives[p], weights, joints, t, where);
  }
}

void gltf_walker::add_primitive(const tinygltf::Primitive& prim, const std::vector<double>& weights,
                                const std::vector<glm::dmat4>* joints, const transform& node,
                                const std::string& where) {
  if (prim.mode != TINYGLTF_MODE_TRIANGLES && prim.mode != -1)
    b_.fail(where, "mode " + std::to_string(prim.mode) + " is not triangles (4)");
  const primitive_vertices v(m_, prim, mapping_of(prim), second_mapping_of(prim), weights, b_,
                             where);
  std::optional<accessor_reader> idx;
  if (prim.indices >= 0) {
    idx.emplace(m_, prim.indices, b_, where + " indices");
    if (idx->component_type() == TINYGLTF_COMPONENT_TYPE_FLOAT)
      b_.fail(idx->where(), "indices must be unsigned integers");
    using namespace tinygltf_types;
    idx->require({TINYGLTF_TYPE_SCALAR}, {u8, u16, u32}, 0, "indices must be unsigned integers");
  }
  const std::size_t corners = idx ? idx->count() : v.count();
  if (corners % 3 != 0)
    b_.fail(where, std::to_string(corners) + " vertices are not whole triangles");
  const int material = material_of(prim, where);
  const bool skinned = joints && v.joints() && v.weights();
  const transform t = skinned ? transform{} : node;
  for (std::size_t f = 0; f < corners / 3; ++f) {
    const std::string face = where + " triangle " + std::to_string(f);
    std::array<point3, 3> p;
    std::array<vec3, 3> n;
    std::array<glm::dvec2, 3> uv{}, uv1{};
    std::array<glm::vec4, 3> color{}, tangent{};
    for (std::size_t k = 0; k < 3; ++k) {
      const std::uint64_t i = idx ? idx->index(3 * f + k) : 3 * f + k;
      if (i >= v.count())
        b_.fail(face, "index " + std::to_string(i) + " is not one of the " +
                          std::to_string(v.count()) + " vertices");
      vec3 q = v.position(std::size_t(i));
      if (v.has_normals()) n[k] = v.normal(std::size_t(i));
      if (v.has_tangent()) tangent[k] = v.tangent(std::size_t(i));
      if (skinned) {
        const glm::dmat4 m = v.skin(std::size_t(i), *joints, face);
        q = vec3(m * glm::dvec4(q, 1));
        if (v.has_normals()) n[k] = glm::inverse(glm::transpose(glm::dmat3(m))) * n[k];
        if (v.has_tangent()) {  // a direction in the surface: by the linear part, as positions
          const float side = glm::determinant(glm::dmat3(m)) < 0 ? -1.0f : 1.0f;
          tangent[k] = glm::vec4(glm::vec3(glm::dmat3(m) * vec3(tangent[k])), side * tangent[k].w);
        }
      }
      p[k] = b_.position(q, t, face);
      if (v.has_color()) color[k] = v.color(std::size_t(i));
      if (v.has_uv()) uv[k] = checked_uv(v.uv(std::size_t(i)), face + " " + v.texcoord(0));
      if (v.has_uv1()) uv1[k] = checked_uv(v.uv1(std::size_t(i)), face + " " + v.texcoord(1));
    }
    b_.add(p, material, v.has_normals() ? std::optional(n) : std::nullopt, uv, v.has_uv(), t,
           v.has_color() ? std::optional(color) : std::nullopt,
           v.has_uv1() ? std::optional(uv1) : std::nullopt,
           v.has_tangent() ? std::optional(tangent) : std::nullopt);
  }
}

uv_mapping gltf_walker::mapping_of(const tinygltf::Primitive& prim) const {
  if (how_.material >= 0 || prim.material < 0 || !materials_ ||
      std::size_t(prim.material) >= m_.materials.size())
    return {};
  return materials_->mapping(prim.material);
}

std::optional<uv_mapping> gltf_walker::second_mapping_of(const tinygltf::Primitive& prim) const {
  if (how_.material >= 0 || prim.material < 0 || !materials_ ||
      std::size_t(prim.material) >= m_.materials.size())
    return std::nullopt;
  return materials_->second_mapping(prim.material);
}

glm::dvec2 gltf_walker::checked_uv(glm::dvec2 uv, const std::string& where) const {
  if (!(std::abs(uv.x) <= 1e6 && std::abs(uv.y) <= 1e6))
    b_.fail(where, "is not finite or beyond +-1e6");
  return uv;
}

int gltf_walker::material_of(const tinygltf::Primitive& prim, const std::string& where) {
  if (how_.material >= 0) return how_.material;
  if (prim.material >= 0) return materials_->scene_material(prim.material, where);
  if (fallback_ < 0)
    fallback_ =
        b_.add_material(b_.name() + ":default", {material_type::lambertian, color(0.7), 0, 1.5});
  return fallback_;
}

}  // namespace rtvk
