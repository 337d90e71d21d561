// The shared kernels with float as `real` (kernels_f32.h). Built with -Wdouble-promotion as an
// error (tests/CMakeLists.txt): a literal that would silently widen the kernel's arithmetic to
// double, where the GPU computes in float, fails the build.
#define RTVK_REAL float
#define RTVK_KERNEL_NAMESPACE rtvk::f32::k
#include "kernels_f32.h"

#include "camera_rays.h"
#include "environment_probe.h"
#include "hit_sphere.h"
#include "kernel_probe.h"
#include "light_probe.h"
#include "light_tree_probe.h"
#include "pbr_probe.h"
#include "punctual_probe.h"
#include "random.h"

namespace rtvk::f32 {

glm::vec2 turn_cos_sin(float b) {
  return k::turn_cos_sin(b);
}

ray_f get_ray(const gpu::camera_ubo& cam, float s, float t, glm::vec2 lens) {
  k::camera_frame f{};  // in float, every field is the GPU's own value
#define RTVK_UNPACK_CAMERA_FIELD(type, name) f.name = cam.name;
  RTVK_CAMERA_FIELDS(RTVK_UNPACK_CAMERA_FIELD)
#undef RTVK_UNPACK_CAMERA_FIELD
  const k::ray r = k::get_ray(f, s, t, lens);
  return {r.origin, r.direction};
}

glm::vec2 opencv_distort(glm::vec4 ka, glm::vec4 kb, glm::vec2 p) {
  glm::vec2 d_dx, d_dy;
  return k::opencv_distort(ka, kb, p, d_dx, d_dy);
}

bool opencv_undistort(glm::vec4 ka, glm::vec4 kb, glm::vec2 target, float limit2, glm::vec2& p) {
  return k::opencv_undistort(ka, kb, target, limit2, p);
}

bool hit_sphere(glm::vec3 center, float radius, ray_f r, float t_min, float t_max, float& t) {
  return k::hit_sphere(center, radius, k::ray(r.origin, r.direction), t_min, t_max, t);
}

glm::vec3 scatter_origin(glm::vec3 center, float radius, ray_f r, float t, glm::vec3 leaving) {
  k::hit_record rec;
  k::record_hit(center, radius, 0u, k::ray(r.origin, r.direction), t, false, rec);
  return k::scatter_origin(rec, leaving);
}

void run_kernel_probe(gpu::kernel_probe_entry& e) {
  k::run_kernel_probe(e);
}

void run_light_probe(gpu::light_probe_entry& e) {
  k::run_light_probe(e);
}

void run_pbr_probe(gpu::pbr_probe_entry& e) {
  k::run_pbr_probe(e);
}

void run_punctual_probe(const std::vector<gpu::gpu_punctual>& lights,
                        gpu::punctual_probe_entry& e) {
  std::vector<k::punctual_record> records;
  for (const gpu::gpu_punctual& g : lights)
    records.push_back(
        {g.position, g.kind, g.direction, g.angle_scale, g.intensity, g.angle_offset, g.cone_gap});
  // The shader reads the count from the first element (0 in an unused one).
  const k::punctual_table t{records.data(), lights.empty() ? 0u : lights[0].count};
  k::run_punctual_probe(t, e);
}

void run_light_tree_probe(const std::vector<gpu::gpu_light>& lamps,
                          const std::vector<gpu::gpu_light_node>& nodes,
                          gpu::light_tree_probe_entry& e) {
  std::vector<k::light_record> records;
  for (const gpu::gpu_light& g : lamps) {
    k::light_record r;
    r.a = g.a;
    r.kind = g.kind;
    r.u = g.u;
    r.radius = g.radius;
    r.v = g.v;
    r.area = g.area;
    r.normal = g.normal;
    r.flags = g.flags;
    r.emission = g.emission;
    records.push_back(r);
  }
  const k::light_table t{records.data(), uint(records.size()), nodes.data()};
  k::run_light_tree_probe(t, e);
}

void run_environment_probe(const std::uint32_t* texels, const float* table,
                           gpu::environment_probe_entry& e) {
  k::run_environment_probe(k::environment_table{texels, table}, e);
}

bool pbr_sample(const gpu::pbr_probe_entry& e, glm::vec3 wo, glm::vec3 u, glm::vec3& wi,
                glm::vec3& weight, float& pdf, bool& delta) {
  return k::pbr_sample(k::pbr_probe_surface(e), wo, u, wi, weight, pdf, delta);
}

float pbr_pdf(const gpu::pbr_probe_entry& e, glm::vec3 wo, glm::vec3 wi) {
  return k::pbr_pdf(k::pbr_probe_surface(e), wo, wi);
}

glm::vec3 pbr_eval(const gpu::pbr_probe_entry& e, glm::vec3 wo, glm::vec3 wi) {
  return k::pbr_eval(k::pbr_probe_surface(e), wo, wi);
}

}  // namespace rtvk::f32
