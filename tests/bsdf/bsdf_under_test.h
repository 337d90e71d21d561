#pragma once
// pbr.h's BSDF as the statistical tests see it: sample, density and evaluation at one material,
// from either of its C++ compilations (double, the CPU reference's; float, the GPU's arithmetic
// on the host, tests/gpu/kernels_f32.h), and the parameter points the tests visit.
#include <memory>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "probe_types.h"

namespace rtvk::bsdf_test {

struct bsdf_sample {
  bool sampled = false;  // pbr_sample returned a direction
  glm::dvec3 wi{0.0};    // the direction
  glm::dvec3 weight{0.0};
  double pdf = 0;
  bool delta = false;
};

class bsdf_under_test {
 public:
  virtual ~bsdf_under_test() = default;
  virtual bsdf_sample sample(glm::dvec3 wo, glm::dvec3 u) const = 0;
  virtual double pdf(glm::dvec3 wo, glm::dvec3 wi) const = 0;
  virtual glm::dvec3 eval(glm::dvec3 wo, glm::dvec3 wi) const = 0;
};

enum class compilation { double_precision, single_precision };
const char* name_of(compilation c);

// The material of a probe entry (its inputs past wo and u), compiled one way or the other.
std::unique_ptr<bsdf_under_test> bsdf_of(compilation c, const gpu::pbr_probe_entry& material);

// A material with glTF's defaults for everything but these (pbr_surface_of's, in float).
gpu::pbr_probe_entry pbr_material(glm::vec3 base_color, float metallic, float roughness);

// One parameter point: a material and an outgoing direction.
struct bsdf_point {
  std::string name;  // for the failure messages, e.g. "metallic 0.5 roughness 0.3 theta 85"
  gpu::pbr_probe_entry material;
  glm::dvec3 wo;  // unit, wo.z > 0
};

// wo at theta degrees from the normal (an azimuth off the axes, so no symmetry hides an error).
glm::dvec3 wo_at(double theta_degrees);

// The points: metallic {0, 0.5, 1} x roughness {0.05, 0.3, 0.7, 1} x wo at {0, 30, 60, 85}
// degrees, then transmission (thin and not, eta 1.5 and 1 / 1.5), clearcoat, sheen and
// specular / specular_color points at 30 and 85 degrees.
const std::vector<bsdf_point>& statistics_points();

// Where the BSDF at a point may peak sharply: the mirror direction of wo about the normal and
// about the clearcoat's normal, the refracted direction (eta; none past the critical angle) and
// the straight-through one (-wo, thin).
std::vector<glm::dvec3> peaks_of(const bsdf_point& p);

}  // namespace rtvk::bsdf_test
