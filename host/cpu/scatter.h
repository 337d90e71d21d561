#pragma once
#include <algorithm>
#include <cmath>

#include "hittable.h"
#include "material.h"
#include "random.h"

namespace rtvk {

// Mirror reflection of v about the unit normal n.
inline vec3 reflect_dir(const vec3& v, const vec3& n) {
  return v - 2 * glm::dot(v, n) * n;
}

// Snell's law for a unit direction uv entering a surface with unit normal n (facing against uv),
// etai_over_etat = n1 / n2.
inline vec3 refract_dir(const vec3& uv, const vec3& n, double etai_over_etat) {
  const double cos_theta = std::min(glm::dot(-uv, n), 1.0);
  const vec3 r_out_perp = etai_over_etat * (uv + cos_theta * n);
  const vec3 r_out_parallel = -std::sqrt(std::abs(1.0 - glm::dot(r_out_perp, r_out_perp))) * n;
  return r_out_perp + r_out_parallel;
}

// Schlick's approximation of the reflected fraction.
inline double schlick_reflectance(double cosine, double ref_idx) {
  double r0 = (1 - ref_idx) / (1 + ref_idx);
  r0 = r0 * r0;
  const double x = 1 - cosine, x2 = x * x;
  return r0 + (1 - r0) * (x2 * x2 * x);  // (1 - cosine)^5 without libm's pow
}

// Each returns false when the ray is absorbed; `rnd` is the stream of this bounce.
bool scatter_lambertian(const material& m, const hit_record& rec, const random_stream& rnd,
                        color& attenuation, ray& scattered);
bool scatter_metal(const material& m, const ray& r_in, const hit_record& rec,
                   const random_stream& rnd, color& attenuation, ray& scattered);
bool scatter_dielectric(const material& m, const ray& r_in, const hit_record& rec,
                        const random_stream& rnd, color& attenuation, ray& scattered);
bool scatter(const material& m, const ray& r_in, const hit_record& rec, const random_stream& rnd,
             color& attenuation, ray& scattered);

}  // namespace rtvk
