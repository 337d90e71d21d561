// Mirrors host/cpu/scatter.cpp. Expects `materials` (gpu_material[]) declared by the including
// shader.
#ifndef RTVK_MATERIAL_GLSL
#define RTVK_MATERIAL_GLSL
#include "random.glsl"
#include "ray.glsl"

precise vec3 reflect_dir(vec3 v, vec3 n) { return v - 2.0 * dot3(v, n) * n; }

precise vec3 refract_dir(vec3 uv, vec3 n, float etai_over_etat) {
  precise float cos_theta = min(dot3(-uv, n), 1.0);
  precise vec3 r_out_perp = etai_over_etat * (uv + cos_theta * n);
  precise vec3 r_out_parallel = -sqrt(abs(1.0 - dot3(r_out_perp, r_out_perp))) * n;
  return r_out_perp + r_out_parallel;
}

precise float schlick_reflectance(float cosine, float ref_idx) {
  precise float r0 = (1.0 - ref_idx) / (1.0 + ref_idx);
  r0 = r0 * r0;
  precise float x = 1.0 - cosine;
  precise float x2 = x * x;
  return r0 + (1.0 - r0) * (x2 * x2 * x);
}

bool scatter_lambertian(gpu_material m, hit_record rec, random_stream s,
                        precise out vec3 attenuation, precise out ray scattered) {
  precise vec3 direction =
      rec.normal + random_unit_vector(rnd(s, dim_direction_a), rnd(s, dim_direction_b));
  const float e = 1e-8;
  if (abs(direction.x) < e && abs(direction.y) < e && abs(direction.z) < e) direction = rec.normal;
  scattered = ray(scatter_origin(rec, direction), direction);
  attenuation = m.albedo;
  return true;
}

bool scatter_metal(gpu_material m, ray r_in, hit_record rec, random_stream s,
                   precise out vec3 attenuation, precise out ray scattered) {
  precise vec3 reflected = reflect_dir(unit_vector(r_in.direction), rec.normal);
  precise vec3 fuzz = random_in_unit_sphere(rnd(s, dim_direction_a), rnd(s, dim_direction_b),
                                    rnd(s, dim_fuzz_radius));
  precise vec3 direction = reflected + m.fuzz * fuzz;
  scattered = ray(scatter_origin(rec, direction), direction);
  attenuation = m.albedo;
  precise float facing = dot3(scattered.direction, rec.normal);
  return facing > 0.0;
}

bool scatter_dielectric(gpu_material m, ray r_in, hit_record rec, random_stream s,
                        precise out vec3 attenuation, precise out ray scattered) {
  attenuation = vec3(1.0, 1.0, 1.0);
  precise float refraction_ratio = rec.front_face ? (1.0 / m.ir) : m.ir;
  precise vec3 unit_direction = unit_vector(r_in.direction);
  precise float cos_theta = min(dot3(-unit_direction, rec.normal), 1.0);
  precise float sin_theta = sqrt(1.0 - cos_theta * cos_theta);
  bool cannot_refract = refraction_ratio * sin_theta > 1.0;
  precise vec3 direction =
      cannot_refract || schlick_reflectance(cos_theta, refraction_ratio) > rnd(s, dim_choice)
          ? reflect_dir(unit_direction, rec.normal)
          : refract_dir(unit_direction, rec.normal, refraction_ratio);
  scattered = ray(scatter_origin(rec, direction), direction);
  return true;
}

bool scatter(gpu_material m, ray r_in, hit_record rec, random_stream s,
             precise out vec3 attenuation, precise out ray scattered) {
  attenuation = vec3(0.0);
  scattered = r_in;
  if (m.type == RTVK_MATERIAL_LAMBERTIAN)
    return scatter_lambertian(m, rec, s, attenuation, scattered);
  if (m.type == RTVK_MATERIAL_METAL) return scatter_metal(m, r_in, rec, s, attenuation, scattered);
  if (m.type == RTVK_MATERIAL_DIELECTRIC)
    return scatter_dielectric(m, r_in, rec, s, attenuation, scattered);
  return false;
}

#endif
