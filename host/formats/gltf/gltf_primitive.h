#pragma once
// Internal to the glTF reader: one primitive's vertex attributes, each checked when made, read per
// vertex with its morph targets applied at their default weights (gltf_primitive.cpp).
#include <array>
#include <optional>
#include <string>
#include <vector>

#include <tiny_gltf.h>

#include "gltf_accessor.h"
#include "gltf_reader.h"

namespace rtvk {

class primitive_vertices {
 public:
  // `weights`: the morph targets' weights (the node's, else the mesh's; missing ones 0).
  primitive_vertices(const tinygltf::Model& m, const tinygltf::Primitive& prim,
                     const uv_mapping& mapping, const std::optional<uv_mapping>& second,
                     const std::vector<double>& weights, const mesh_builder& b,
                     const std::string& where);

  std::size_t count() const { return pos_->count(); }
  bool has_normals() const { return nrm_.has_value(); }
  bool has_uv() const { return tex_.has_value(); }
  bool has_uv1() const { return tex1_.has_value(); }
  bool has_color() const { return col_.has_value(); }
  bool has_tangent() const { return tan_.has_value(); }
  // The attribute set k's texture coordinates come from (0: uv, 1: uv1).
  const std::string& texcoord(int k) const { return texcoord_[std::size_t(k)]; }

  vec3 position(std::size_t i) const;  // the file's, morphed
  vec3 normal(std::size_t i) const;    // the file's, morphed (not normalized)
  // Texture coordinates mapped by the material's transform, v flipped to rtvk's; uv1: the second
  // set's, by the emissive texture's transform.
  glm::dvec2 uv(std::size_t i) const { return mapped(*tex_, mapping_, i); }
  glm::dvec2 uv1(std::size_t i) const { return mapped(*tex1_, *second_, i); }
  glm::vec4 color(std::size_t i) const;  // linear RGBA (alpha 1 for VEC3)
  // The file's TANGENT: xyz along +u (not normalized), w the handedness (+1 or -1).
  glm::vec4 tangent(std::size_t i) const;
  // Vertex i's joint matrices blended by its weights (`joints`: the skin's); fails naming
  // `where` for a joint the skin does not have or a weight that is not finite.
  glm::dmat4 skin(std::size_t i, const std::vector<glm::dmat4>& joints,
                  const std::string& where) const;
  // The accessor a JOINTS_0 / WEIGHTS_0 names, when the primitive has it.
  const std::optional<accessor_reader>& joints() const { return joints_; }
  const std::optional<accessor_reader>& weights() const { return weights_; }

 private:
  static glm::dvec2 mapped(const accessor_reader& tex, const uv_mapping& mapping, std::size_t i);
  std::optional<accessor_reader> attribute(const std::map<std::string, int>& attributes,
                                           const std::string& name) const;

  const tinygltf::Model& m_;
  const mesh_builder& b_;
  std::string where_;
  uv_mapping mapping_;
  std::optional<uv_mapping> second_;     // the second set's, when the material reads one
  std::array<std::string, 2> texcoord_;  // the attributes the two sets come from
  std::optional<accessor_reader> pos_, nrm_, tex_, tex1_, col_, tan_, joints_, weights_;
  // Morph targets with a weight that is not 0: the weight and the target's displacements.
  struct target {
    double weight;
    std::optional<accessor_reader> pos, nrm;
  };
  std::vector<target> targets_;
};

}  // namespace rtvk
