#pragma once
// Internal to the glTF reader: one primitive's vertex attributes, each checked when made, read per
// vertex with its morph targets applied at their default weights (gltf_primitive.cpp).
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
                     const uv_mapping& mapping, const std::vector<double>& weights,
                     const mesh_builder& b, const std::string& where);

  std::size_t count() const { return pos_->count(); }
  bool has_normals() const { return nrm_.has_value(); }
  bool has_uv() const { return tex_.has_value(); }
  bool has_color() const { return col_.has_value(); }
  const std::string& texcoord() const { return texcoord_; }

  vec3 position(std::size_t i) const;  // the file's, morphed
  vec3 normal(std::size_t i) const;    // the file's, morphed (not normalized)
  // Texture coordinates mapped by the material's transform, v flipped to rtvk's.
  glm::dvec2 uv(std::size_t i) const;
  glm::vec4 color(std::size_t i) const;  // linear RGBA (alpha 1 for VEC3)
  // Vertex i's joint matrices blended by its weights (`joints`: the skin's); fails naming
  // `where` for a joint the skin does not have or a weight that is not finite.
  glm::dmat4 skin(std::size_t i, const std::vector<glm::dmat4>& joints,
                  const std::string& where) const;
  // The accessor a JOINTS_0 / WEIGHTS_0 names, when the primitive has it.
  const std::optional<accessor_reader>& joints() const { return joints_; }
  const std::optional<accessor_reader>& weights() const { return weights_; }

 private:
  std::optional<accessor_reader> attribute(const std::map<std::string, int>& attributes,
                                           const std::string& name) const;

  const tinygltf::Model& m_;
  const mesh_builder& b_;
  std::string where_;
  uv_mapping mapping_;
  std::string texcoord_;  // the attribute the texture coordinates come from
  std::optional<accessor_reader> pos_, nrm_, tex_, col_, joints_, weights_;
  // Morph targets with a weight that is not 0: the weight and the target's displacements.
  struct target {
    double weight;
    std::optional<accessor_reader> pos, nrm;
  };
  std::vector<target> targets_;
};

}  // namespace rtvk
