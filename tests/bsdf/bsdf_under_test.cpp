#include "bsdf_under_test.h"

#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "gpu/kernels_f32.h"
#include "pbr.h"  // the double compilation, in namespace rtvk

namespace rtvk::bsdf_test {
namespace {

class double_bsdf final : public bsdf_under_test {
 public:
  explicit double_bsdf(const gpu::pbr_probe_entry& e)
      : m_(pbr_surface_of(e.base_color, e.metallic, e.roughness)) {
    m_.eta = e.eta;
    m_.specular = e.specular;
    m_.specular_color = e.specular_color;
    m_.transmission = e.transmission;
    m_.thin = e.thin != 0;
    m_.clearcoat = e.clearcoat;
    m_.clearcoat_roughness = e.clearcoat_roughness;
    m_.clearcoat_normal = e.clearcoat_normal;
    m_.sheen_color = e.sheen_color;
    m_.sheen_roughness = e.sheen_roughness;
  }
  bsdf_sample sample(glm::dvec3 wo, glm::dvec3 u) const override {
    bsdf_sample s;
    s.sampled = pbr_sample(m_, wo, u, s.wi, s.weight, s.pdf, s.delta);
    return s;
  }
  double pdf(glm::dvec3 wo, glm::dvec3 wi) const override { return pbr_pdf(m_, wo, wi); }
  glm::dvec3 eval(glm::dvec3 wo, glm::dvec3 wi) const override { return pbr_eval(m_, wo, wi); }

 private:
  pbr_surface m_;
};

// The float compilation: directions and random numbers rounded to float on the way in (u kept
// below 1), as the GPU receives them.
class float_bsdf final : public bsdf_under_test {
 public:
  explicit float_bsdf(const gpu::pbr_probe_entry& e) : e_(e) {}
  bsdf_sample sample(glm::dvec3 wo, glm::dvec3 u) const override {
    const float below_one = std::nextafter(1.0f, 0.0f);
    glm::vec3 wi, weight;
    float pdf;
    bsdf_sample s;
    s.sampled = f32::pbr_sample(e_, glm::vec3(wo), glm::min(glm::vec3(u), glm::vec3(below_one)), wi,
                                weight, pdf, s.delta);
    s.wi = wi;
    s.weight = weight;
    s.pdf = pdf;
    return s;
  }
  double pdf(glm::dvec3 wo, glm::dvec3 wi) const override {
    return f32::pbr_pdf(e_, glm::vec3(wo), glm::vec3(wi));
  }
  glm::dvec3 eval(glm::dvec3 wo, glm::dvec3 wi) const override {
    return glm::dvec3(f32::pbr_eval(e_, glm::vec3(wo), glm::vec3(wi)));
  }

 private:
  gpu::pbr_probe_entry e_;
};

}  // namespace

const char* name_of(compilation c) {
  return c == compilation::double_precision ? "double" : "float";
}

std::unique_ptr<bsdf_under_test> bsdf_of(compilation c, const gpu::pbr_probe_entry& material) {
  if (c == compilation::double_precision) return std::make_unique<double_bsdf>(material);
  return std::make_unique<float_bsdf>(material);
}

gpu::pbr_probe_entry pbr_material(glm::vec3 base_color, float metallic, float roughness) {
  gpu::pbr_probe_entry e{};
  e.base_color = base_color;
  e.metallic = metallic;
  e.roughness = roughness;
  e.eta = 1.5f;
  e.specular = 1.0f;
  e.specular_color = glm::vec3(1.0f);
  e.transmission = 0.0f;
  e.thin = 1u;
  e.clearcoat = 0.0f;
  e.clearcoat_roughness = 0.0f;
  e.clearcoat_normal = glm::vec3(0.0f, 0.0f, 1.0f);
  e.sheen_color = glm::vec3(0.0f);
  e.sheen_roughness = 0.0f;
  return e;
}

glm::dvec3 wo_at(double theta_degrees) {
  const double theta = theta_degrees * std::numbers::pi / 180, phi = 0.7;
  return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

const std::vector<bsdf_point>& statistics_points() {
  static const std::vector<bsdf_point> points = [] {
    std::vector<bsdf_point> v;
    const glm::vec3 base(0.8f, 0.5f, 0.3f);
    for (float metallic : {0.0f, 0.5f, 1.0f})
      for (float roughness : {0.05f, 0.3f, 0.7f, 1.0f})
        for (double theta : {0.0, 30.0, 60.0, 85.0})
          v.push_back({"metallic " + std::to_string(metallic).substr(0, 3) + " roughness " +
                           std::to_string(roughness).substr(0, 4) + " theta " +
                           std::to_string(int(theta)),
                       pbr_material(base, metallic, roughness), wo_at(theta)});
    struct extra {
      std::string name;
      gpu::pbr_probe_entry m;
    };
    std::vector<extra> extras;
    for (float eta : {1.5f, 1.0f / 1.5f})
      for (unsigned thin : {1u, 0u}) {
        gpu::pbr_probe_entry m = pbr_material(base, 0.0f, 0.3f);
        m.transmission = 1.0f;
        m.eta = eta;
        m.thin = thin;
        extras.push_back({std::string("transmission 1 roughness 0.3 ") + (thin ? "thin" : "solid") +
                              " eta " + (eta > 1 ? "1.5" : "1/1.5"),
                          m});
      }
    {
      gpu::pbr_probe_entry m = pbr_material(base, 0.0f, 0.7f);
      m.transmission = 0.5f;
      m.thin = 0u;
      extras.push_back({"transmission 0.5 roughness 0.7 solid eta 1.5", m});
    }
    {
      gpu::pbr_probe_entry m = pbr_material(base, 0.0f, 0.5f);
      m.clearcoat = 1.0f;
      m.clearcoat_roughness = 0.1f;
      extras.push_back({"clearcoat 1 roughness 0.1 over roughness 0.5", m});
      m = pbr_material(base, 1.0f, 0.6f);
      m.clearcoat = 0.5f;
      m.clearcoat_roughness = 0.3f;
      m.clearcoat_normal = glm::normalize(glm::vec3(0.2f, -0.1f, 1.0f));
      extras.push_back({"clearcoat 0.5 roughness 0.3 tilted normal over metal 0.6", m});
    }
    {
      gpu::pbr_probe_entry m = pbr_material(base, 0.0f, 0.6f);
      m.sheen_color = glm::vec3(1.0f, 0.5f, 0.2f);
      m.sheen_roughness = 0.5f;
      extras.push_back({"sheen (1, 0.5, 0.2) roughness 0.5 over roughness 0.6", m});
      m = pbr_material(base, 0.0f, 0.4f);
      m.specular = 0.5f;
      m.specular_color = glm::vec3(1.0f, 0.5f, 0.2f);
      extras.push_back({"specular 0.5 color (1, 0.5, 0.2) roughness 0.4", m});
      m.specular = 0.0f;
      extras.push_back({"specular 0 roughness 0.4", m});
    }
    for (const extra& x : extras)
      for (double theta : {30.0, 85.0})
        v.push_back({x.name + " theta " + std::to_string(int(theta)), x.m, wo_at(theta)});
    return v;
  }();
  return points;
}

std::vector<glm::dvec3> peaks_of(const bsdf_point& p) {
  const glm::dvec3 wo = p.wo, n(0, 0, 1);
  const glm::dvec3 cn = glm::normalize(glm::dvec3(p.material.clearcoat_normal));
  std::vector<glm::dvec3> v = {glm::reflect(-wo, n), glm::reflect(-wo, cn), -wo};
  const glm::dvec3 t = glm::refract(-wo, n, 1.0 / double(p.material.eta));
  if (glm::dot(t, t) > 0) v.push_back(glm::normalize(t));
  return v;
}

}  // namespace rtvk::bsdf_test
