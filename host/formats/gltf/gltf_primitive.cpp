// A glTF primitive's vertex attributes: POSITION, NORMAL, TANGENT, TEXCOORD_n, COLOR_0 (and
// JOINTS_0 / WEIGHTS_0 for skins), each of the types the spec and KHR_mesh_quantization allow.
#include "gltf_primitive.h"

#include <cmath>

namespace rtvk {

using namespace tinygltf_types;

primitive_vertices::primitive_vertices(const tinygltf::Model& m, const tinygltf::Primitive& prim,
                                       const uv_mapping& mapping,
                                       const std::optional<uv_mapping>& second,
                                       const std::vector<double>& weights, const mesh_builder& b,
                                       const std::string& where)
    : m_(m), b_(b), where_(where), mapping_(mapping), second_(second) {
  pos_ = attribute(prim.attributes, "POSITION");
  if (!pos_) b_.fail(where, "has no POSITION");
  pos_->require({TINYGLTF_TYPE_VEC3}, {i8, u8, i16, u16}, 0, "is not VEC3 of floats or integers");
  const std::size_t n = pos_->count();
  nrm_ = attribute(prim.attributes, "NORMAL");
  if (nrm_) nrm_->require({TINYGLTF_TYPE_VEC3}, {i8, i16}, n, "is not one VEC3 per position");
  texcoord_[0] = "TEXCOORD_" + std::to_string(mapping.set);
  tex_ = attribute(prim.attributes, texcoord_[0]);
  if (tex_)
    tex_->require({TINYGLTF_TYPE_VEC2}, {i8, u8, i16, u16}, n, "is not one VEC2 per position");
  if (second) {
    texcoord_[1] = "TEXCOORD_" + std::to_string(second->set);
    tex1_ = attribute(prim.attributes, texcoord_[1]);
    if (tex1_)
      tex1_->require({TINYGLTF_TYPE_VEC2}, {i8, u8, i16, u16}, n, "is not one VEC2 per position");
  }
  col_ = attribute(prim.attributes, "COLOR_0");
  if (col_)
    col_->require({TINYGLTF_TYPE_VEC3, TINYGLTF_TYPE_VEC4}, {u8, u16}, n,
                  "is not one VEC3 or VEC4 per position of floats or normalized integers");
  if (col_ && col_->component_type() != TINYGLTF_COMPONENT_TYPE_FLOAT && !col_->normalized())
    b_.fail(col_->where(), "integer colors must be normalized");
  tan_ = attribute(prim.attributes, "TANGENT");
  if (tan_) tan_->require({TINYGLTF_TYPE_VEC4}, {i8, i16}, n, "is not one VEC4 per position");
  joints_ = attribute(prim.attributes, "JOINTS_0");
  if (joints_) joints_->require({TINYGLTF_TYPE_VEC4}, {u8, u16}, n, "is not one VEC4 per position");
  if (joints_ && joints_->component_type() == TINYGLTF_COMPONENT_TYPE_FLOAT)
    b_.fail(joints_->where(), "joints must be unsigned integers");
  weights_ = attribute(prim.attributes, "WEIGHTS_0");
  if (weights_)
    weights_->require({TINYGLTF_TYPE_VEC4}, {u8, u16}, n, "is not one VEC4 per position");
  for (std::size_t k = 0; k < prim.targets.size(); ++k) {
    const double w = k < weights.size() && std::isfinite(weights[k]) ? weights[k] : 0;
    if (w == 0) continue;
    const std::string at = "target " + std::to_string(k) + " ";
    target t{w, attribute(prim.targets[k], at + "POSITION"),
             attribute(prim.targets[k], at + "NORMAL")};
    if (t.pos) t.pos->require({TINYGLTF_TYPE_VEC3}, {i8, i16}, n, "is not one VEC3 per position");
    if (t.nrm) t.nrm->require({TINYGLTF_TYPE_VEC3}, {i8, i16}, n, "is not one VEC3 per position");
    targets_.push_back(std::move(t));
  }
}

// An attribute by name ("target k NAME" for a morph target's, named by its last word).
std::optional<accessor_reader> primitive_vertices::attribute(
    const std::map<std::string, int>& attributes, const std::string& name) const {
  const auto it = attributes.find(name.substr(name.rfind(' ') + 1));
  if (it == attributes.end()) return std::nullopt;
  return accessor_reader(m_, it->second, b_, where_ + " " + name);
}

vec3 primitive_vertices::position(std::size_t i) const {
  vec3 p = pos_->vec(i);
  for (const target& t : targets_)
    if (t.pos) p += t.weight * t.pos->vec(i);
  return p;
}

vec3 primitive_vertices::normal(std::size_t i) const {
  vec3 n = nrm_->vec(i);
  for (const target& t : targets_)
    if (t.nrm) n += t.weight * t.nrm->vec(i);
  return n;
}

// Mapped by the texture transform in glTF's uv, whose v runs down the image from its top; then
// flipped to rtvk's (the book's, OBJ's) v, up from its bottom.
glm::dvec2 primitive_vertices::mapped(const accessor_reader& tex, const uv_mapping& mapping,
                                      std::size_t i) {
  const glm::dvec3 t = mapping.matrix * glm::dvec3(tex.get(i, 0), tex.get(i, 1), 1);
  return glm::dvec2(t.x, 1 - t.y);
}

glm::vec4 primitive_vertices::color(std::size_t i) const {
  glm::vec4 c(1);
  for (int k = 0; k < col_->components(); ++k) {
    const double v = col_->get(i, k);
    c[k] = float(std::isfinite(v) ? std::clamp(v, 0.0, 1.0) : 0.0);
  }
  return c;
}

glm::vec4 primitive_vertices::tangent(std::size_t i) const {
  glm::vec4 t(0);
  for (int k = 0; k < 4; ++k) {
    const double v = tan_->get(i, k);
    t[k] = float(std::isfinite(v) && std::abs(v) <= 1e6 ? v : 0.0);
  }
  return t;
}

glm::dmat4 primitive_vertices::skin(std::size_t i, const std::vector<glm::dmat4>& joints,
                                    const std::string& where) const {
  glm::dmat4 m(0.0);
  for (int k = 0; k < 4; ++k) {
    const double w = weights_->get(i, k);
    if (!std::isfinite(w) || std::abs(w) > 1e6) b_.fail(where, "a skin weight is not finite");
    if (w == 0) continue;
    const double j = joints_->get(i, k);
    if (!(j >= 0 && j < double(joints.size())))
      b_.fail(where, "joint " + std::to_string(std::uint64_t(j)) + " is not one of the skin's " +
                         std::to_string(joints.size()));
    m += w * joints[std::size_t(j)];
  }
  return m;
}

}  // namespace rtvk
