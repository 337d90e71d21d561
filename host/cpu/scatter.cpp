#include "scatter.h"

#include <cmath>

namespace rtvk {

bool scatter_lambertian(const material& m, const hit_record& rec, const random_stream& rnd,
                        color& attenuation, ray& scattered) {
  vec3 direction = rec.normal + random_unit_vector(rnd(dim_direction_a), rnd(dim_direction_b));
  // A random vector opposite the normal would give a zero direction: keep the normal instead.
  const double s = 1e-8;
  if (std::abs(direction.x) < s && std::abs(direction.y) < s && std::abs(direction.z) < s)
    direction = rec.normal;
  scattered = ray(rec.scatter_origin(direction), direction);
  attenuation = m.albedo;
  return true;
}

bool scatter_metal(const material& m, const ray& r_in, const hit_record& rec,
                   const random_stream& rnd, color& attenuation, ray& scattered) {
  const vec3 reflected = reflect_dir(unit_vector(r_in.direction()), rec.normal);
  const vec3 fuzz =
      random_in_unit_sphere(rnd(dim_direction_a), rnd(dim_direction_b), rnd(dim_fuzz_radius));
  const vec3 direction = reflected + m.fuzz * fuzz;
  scattered = ray(rec.scatter_origin(direction), direction);
  attenuation = m.albedo;
  return glm::dot(scattered.direction(), rec.normal) > 0;
}

bool scatter_dielectric(const material& m, const ray& r_in, const hit_record& rec,
                        const random_stream& rnd, color& attenuation, ray& scattered) {
  attenuation = color(1.0, 1.0, 1.0);
  const double refraction_ratio = rec.front_face ? (1.0 / m.ir) : m.ir;
  const vec3 unit_direction = unit_vector(r_in.direction());
  const double cos_theta = std::min(glm::dot(-unit_direction, rec.normal), 1.0);
  const double sin_theta = std::sqrt(1.0 - cos_theta * cos_theta);
  const bool cannot_refract = refraction_ratio * sin_theta > 1.0;
  const vec3 direction =
      cannot_refract || schlick_reflectance(cos_theta, refraction_ratio) > rnd(dim_choice)
          ? reflect_dir(unit_direction, rec.normal)
          : refract_dir(unit_direction, rec.normal, refraction_ratio);
  scattered = ray(rec.scatter_origin(direction), direction);
  return true;
}

bool scatter(const material& m, const ray& r_in, const hit_record& rec, const random_stream& rnd,
             color& attenuation, ray& scattered) {
  switch (m.type) {
    case material_type::lambertian:
      return scatter_lambertian(m, rec, rnd, attenuation, scattered);
    case material_type::metal:
      return scatter_metal(m, r_in, rec, rnd, attenuation, scattered);
    case material_type::dielectric:
      return scatter_dielectric(m, r_in, rec, rnd, attenuation, scattered);
    case material_type::normal:
      break;
  }
  return false;
}

}  // namespace rtvk
