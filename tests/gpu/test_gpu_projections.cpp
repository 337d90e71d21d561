// Every camera model on the GPU draws the CPU's picture: the lesson's scene (one sample, normal
// shading: deterministic), a posed Monte Carlo view of book-final, and a keyframed fisheye path.
#include <gtest/gtest.h>

#include <limits>
#include <map>

#include <cmath>

#include "camera_path.h"
#include "gpu_fixture.h"
#include "image_compare.h"
#include "image_io.h"
#include "process.h"
#include "quantize.h"
#include "render_gpu.h"
#include "render_helpers.h"
#include "temp_dir.h"

namespace rtvk {
namespace {

class GpuProjections : public test::GpuTest {};

const projection all_models[] = {projection::perspective, projection::orthographic,
                                 projection::equirectangular, projection::fisheye_equidistant,
                                 projection::fisheye_equisolid};

TEST_F(GpuProjections, TheLessonsSceneMatchesTheCpuUnderEveryModel) {
  const scene s = builtin_scene("seed");
  for (projection p : all_models) {
    SCOPED_TRACE(std::string(projection_name(p)));
    camera_pose pose;
    pose.projection = p;
    pose.fisheye_fov = 200;
    const camera c(pose, 2, 240);
    const image_rgb8 on_gpu = test::gpu_image(gpu(), s, c), on_cpu = test::cpu_image(s, c);
    const image_difference d = compare_images(on_gpu, on_cpu, 1);
    EXPECT_TRUE(agrees(d, agreement{})) << d.share_over * 100 << "% of pixels over 1 level";
    if (p == projection::fisheye_equidistant || p == projection::fisheye_equisolid) {
      // Outside the circle: exactly black on both, no ray traced.
      for (const image_rgb8* img : {&on_gpu, &on_cpu})
        for (int k = 0; k < 3; ++k) EXPECT_EQ(img->pixel(0, 0)[k], 0);
    }
  }
}

TEST_F(GpuProjections, APosedMonteCarloViewMatchesTheCpuUnderEveryModel) {
  scene s = test::small_scene("book-final", 96, 8);
  s.render.max_depth = 10;
  camera_pose pose = main_camera(s).pose;
  pose.aperture = 0;  // the panoramic models have no lens
  // Measured on lavapipe, per model (PSNR dB, share over 2 levels): the rule is
  // measured_agreement of these.
  const std::map<projection, std::pair<double, double>> measured{
      {projection::perspective, {59.1, 0.0030}},
      {projection::orthographic, {59.6, 0.0017}},
      {projection::equirectangular, {std::numeric_limits<double>::infinity(), 0}},
      {projection::fisheye_equidistant, {84.8, 0}},
      {projection::fisheye_equisolid, {59.0, 0.0011}}};
  for (projection p : all_models) {
    SCOPED_TRACE(std::string(projection_name(p)));
    pose.projection = p;
    const camera c(pose, 2, 96);
    const image_difference d = compare_images(test::gpu_image(gpu(), s, c), test::cpu_image(s, c),
                                              monte_carlo_agreement.tolerance);
    const auto [psnr, share] = measured.at(p);
    EXPECT_TRUE(
        agrees(d, test::measured_agreement(psnr, share, c.image_width() * c.image_height())))
        << "PSNR " << d.psnr_db << ", " << d.share_over * 100 << "% over 2 levels";
  }
}

TEST_F(GpuProjections, AKeyframedFisheyePathRendersAlikeOnBothBackends) {
  scene s = builtin_scene("seed");
  camera_path path;
  path.motion = camera_motion::keyframes;
  camera_pose a, b;
  a.projection = b.projection = projection::fisheye_equisolid;
  a.fisheye_fov = 150;
  b.fisheye_fov = 300;
  b.lookfrom = point3(0.3, 0.4, 0.2);
  path.keyframes = {{0.0, a}, {1.0, b}};
  std::vector<camera> views;
  for (double time : {0.0, 0.4, 1.0}) views.emplace_back(path.at(time), 16.0 / 9.0, 160);
  const render_window all = whole_render(160, views[0].image_height(), 1);
  const std::vector<framebuffer> fbs = gpu::render_gpu_views(gpu(), views, s, s.render, all);
  for (std::size_t k = 0; k < views.size(); ++k) {
    const image_difference d =
        compare_images(quantize(fbs[k], s.render.gamma), test::cpu_image(s, views[k]), 1);
    EXPECT_TRUE(agrees(d, agreement{})) << "view " << k;
  }
  // The field of view is interpolated, the model held.
  EXPECT_EQ(path.at(0.5).projection, projection::fisheye_equisolid);
  EXPECT_DOUBLE_EQ(path.at(0.5).fisheye_fov, 225);
}

// An independent tracer of the lesson's scene, written from the models' definitions
// (docs/camera.md), sharing no code with rtvk's camera or renderers: the default camera at the
// origin looking down -z (u = +x, v = +y, w = +z), 90-degree vertical field of view, focus 1;
// two spheres with normal shading under the lesson's sky; gamma 1.
struct reference_ray {
  glm::dvec3 origin, direction;  // direction zero: no ray, black
};

reference_ray reference_camera(const std::string& model, double s, double t, double aspect) {
  const double pi = 3.14159265358979323846, fov = pi;  // fisheye field of view 180 degrees
  if (model == "perspective")
    return {{0, 0, 0}, {(2 * s - 1) * aspect, 2 * t - 1, -1}};  // viewport 2 high at z = -1
  if (model == "orthographic") return {{(2 * s - 1) * aspect, 2 * t - 1, 0}, {0, 0, -1}};
  if (model == "equirectangular") {
    const double phi = (s - 0.5) * 2 * pi, theta = (t - 0.5) * pi;
    return {{0, 0, 0},
            {std::cos(theta) * std::sin(phi), std::sin(theta), -std::cos(theta) * std::cos(phi)}};
  }
  const double x = (2 * s - 1) * aspect, y = 2 * t - 1, r = std::hypot(x, y);
  if (r > 1) return {{0, 0, 0}, {0, 0, 0}};
  if (r == 0) return {{0, 0, 0}, {0, 0, -1}};
  const double theta =
      model == "fisheye-equidistant" ? r * fov / 2 : 2 * std::asin(r * std::sin(fov / 4));
  return {{0, 0, 0}, {std::sin(theta) * x / r, std::sin(theta) * y / r, -std::cos(theta)}};
}

glm::dvec3 reference_color(const reference_ray& ray) {
  if (ray.direction == glm::dvec3(0)) return glm::dvec3(0);
  const glm::dvec3 centers[2] = {{0, 0, -1}, {0, -100.5, -1}};
  const double radii[2] = {0.5, 100};
  double nearest = INFINITY;
  glm::dvec3 normal{};
  for (int k = 0; k < 2; ++k) {
    const glm::dvec3 oc = ray.origin - centers[k];
    const double a = glm::dot(ray.direction, ray.direction), b = glm::dot(oc, ray.direction);
    const double disc = b * b - a * (glm::dot(oc, oc) - radii[k] * radii[k]);
    if (disc < 0) continue;
    for (double root : {(-b - std::sqrt(disc)) / a, (-b + std::sqrt(disc)) / a})
      if (root > 0.001 && root < nearest) {
        nearest = root;
        normal = (ray.origin + root * ray.direction - centers[k]) / radii[k];
        if (glm::dot(ray.direction, normal) > 0) normal = -normal;  // facing the ray, as the book
        break;
      }
  }
  if (nearest < INFINITY) return 0.5 * (normal + glm::dvec3(1));
  const double t = 0.5 * (glm::normalize(ray.direction).y + 1);
  return (1 - t) * glm::dvec3(1) + t * glm::dvec3(0.5, 0.7, 1.0);
}

image_rgb8 reference_image(const std::string& model, int width, int height) {
  image_rgb8 img{width, height, {}};
  const double aspect = double(width) / height;
  for (int row = 0; row < height; ++row)
    for (int i = 0; i < width; ++i) {
      const double s = double(i) / (width - 1), t = double(height - 1 - row) / (height - 1);
      const glm::dvec3 c = reference_color(reference_camera(model, s, t, aspect));
      for (int k = 0; k < 3; ++k) img.rgb.push_back(to_byte(c[k]));
    }
  return img;
}

TEST_F(GpuProjections, TheCliDrawsEveryModelAsAnIndependentTracerDoes) {
  test::temp_dir dir;
  for (const std::string model : {"perspective", "orthographic", "equirectangular",
                                  "fisheye-equidistant", "fisheye-equisolid"}) {
    const image_rgb8 want = reference_image(model, 240, 120);
    for (const std::string backend : {"cpu", "gpu"}) {
      SCOPED_TRACE(model + " on the " + backend);
      const std::string out = (dir.path() / (model + "-" + backend + ".png")).string();
      std::vector<std::string> args{
          "render",       "--scene", "seed",      "--width", "240", "--aspect", "2",
          "--projection", model,     "--backend", backend,   "-o",  out,        "-q"};
      if (backend == "gpu" && !test::test_device().empty())
        args.insert(args.end(), {"--device", test::test_device()});
      const auto r = test::run_rtvk(args);
      ASSERT_EQ(r.status, 0) << r.err;
      const image_difference d = compare_images(read_image(out), want, 1);
      EXPECT_TRUE(agrees(d, agreement{}))
          << d.share_over * 100 << "% of pixels over 1 level, max " << d.max_abs;
    }
  }
}

}  // namespace
}  // namespace rtvk
