// PBR materials (material_type::pbr) rendered on the CPU: the white furnace, Beer-Lambert
// absorption inside a volume, the albedo AOV, and the smooth metal that must look like the
// book's mirror. The GPU's side of each is tests/gpu/test_gpu_pbr.cpp.
#include <gtest/gtest.h>

#include "pbr_scenes.h"
#include "pbr_shading.h"  // pbr.h, its stand-in's unused parameter let through
#include "render_aov.h"
#include "render_helpers.h"
#include "shading.h"
#include "surface_scenes.h"

namespace rtvk {
namespace {

// Each map multiplies its factor by glTF's channel (pbr_surface_at, which both backends run): one
// image texel of bytes R 64, G 128, B 192, A 32 behind every map, factors of 1/2.
TEST(PbrRender, EachMapMultipliesItsFactorByItsChannel) {
  scene s;
  s.textures.push_back(test::row_texture({64u | (128u << 8) | (192u << 16) | (32u << 24)}));
  material m = test::pbr_of(color(1), 0.5, 0.5);
  pbr_material& q = m.pbr;
  q.specular = q.transmission = q.clearcoat = q.clearcoat_roughness = q.sheen_roughness = 0.5;
  q.thickness = 0.5;
  q.specular_color = q.sheen_color = color(0.5);
  for (int* t :
       {&q.metallic_roughness_texture, &q.specular_texture, &q.specular_color_texture,
        &q.transmission_texture, &q.thickness_texture, &q.clearcoat_texture,
        &q.clearcoat_roughness_texture, &q.sheen_color_texture, &q.sheen_roughness_texture})
    *t = 0;
  q.ior = 1.25;
  s.materials = {{"p", m}};
  const scene_shading shading(s);
  hit_record rec{};
  rec.uv = real2(0.5, 0.5);
  rec.front_face = true;
  const real r = 64 / 255.0, g = 128 / 255.0, b = 192 / 255.0, a = 32 / 255.0;
  const pbr_surface p = pbr_surface_at(shading.tables(), shading.pbr[0], real3(0.5), rec);
  EXPECT_DOUBLE_EQ(p.metallic, 0.5 * b);
  EXPECT_DOUBLE_EQ(p.roughness, 0.5 * g);
  EXPECT_DOUBLE_EQ(p.specular, 0.5 * a);
  EXPECT_DOUBLE_EQ(p.specular_color.y, 0.5 * g);
  EXPECT_DOUBLE_EQ(p.transmission, 0.5 * r);
  EXPECT_DOUBLE_EQ(p.clearcoat, 0.5 * r);
  EXPECT_DOUBLE_EQ(p.clearcoat_roughness, 0.5 * g);
  EXPECT_DOUBLE_EQ(p.sheen_color.z, 0.5 * b);
  EXPECT_DOUBLE_EQ(p.sheen_roughness, 0.5 * a);
  EXPECT_EQ(p.base_color, real3(0.5));
  EXPECT_FALSE(p.thin);  // thickness 0.5 G: a volume
  EXPECT_DOUBLE_EQ(p.eta, 1.25);
  rec.front_face = false;  // leaving: the ray sees 1 / ior
  EXPECT_DOUBLE_EQ(pbr_surface_at(shading.tables(), shading.pbr[0], real3(1), rec).eta, 0.8);
}

// An energy-conserving BSDF of white base color returns every path from the sphere with the sky's
// 1: a rough metal, and a rough dielectric (its diffuse base takes what its specular layer does
// not reflect).
TEST(PbrRender, AWhiteSphereInAWhiteFurnaceIsWhiteCpu) {
  for (const material& m : {test::pbr_of(color(1), 1, 1), test::pbr_of(color(1), 0, 0.5)}) {
    const scene s = test::pbr_furnace(m);
    const color mean = test::center_mean(render_cpu(test::scene_camera(s), s, s.render));
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(mean[c], 1.0, test::pbr_furnace_tolerance)
          << "metallic " << m.pbr.metallic << ", channel " << c;
  }
}

// Inside a volume the emission the camera sees has run `radius` through it: every pixel is
// attenuation^(radius / distance) (Beer-Lambert), to double's rounding.
TEST(PbrRender, AVolumeAttenuatesByBeerLambertCpu) {
  const color attenuation(0.5, 0.25, 0.8);
  const scene s = test::pbr_absorbing_sphere(attenuation, 2, 3);
  const color want = test::beer_lambert(attenuation, 2, 3);  // 0.354, 0.125, 0.716
  const framebuffer fb = render_cpu(test::scene_camera(s), s, s.render);
  for (int y = 0; y < fb.height(); ++y)
    for (int x = 0; x < fb.width(); ++x)
      for (int c = 0; c < 3; ++c) ASSERT_NEAR(fb.at(x, y)[c], want[c], 1e-9) << x << "," << y;
}

// A volume attenuates only what crossed it: from outside (front faces) nothing is absorbed,
// and a thin-walled material (thickness 0) has no inside.
TEST(PbrRender, OnlyAVolumesInsideAttenuatesCpu) {
  scene thin = test::pbr_absorbing_sphere(color(0.5), 1, 3);
  thin.materials[0].m.pbr.thickness = 0;
  const framebuffer fb = render_cpu(test::scene_camera(thin), thin, thin.render);
  EXPECT_EQ(fb.at(8, 8), color(1));
  scene outside = test::pbr_absorbing_sphere(color(0.5), 1, 3);
  main_camera(outside).pose.lookfrom = point3(0, 0, 6);
  outside.render.jitter = false;
  const framebuffer seen = render_cpu(test::scene_camera(outside), outside, outside.render);
  EXPECT_EQ(seen.at(8, 8), color(1));  // the sphere's front, emitting white
}

// The albedo AOV of a PBR material is its base color there, as for the other kinds.
TEST(PbrRender, TheAlbedoAovIsTheBaseColor) {
  const scene s = test::pbr_furnace(test::pbr_of(color(0.25, 0.5, 0.75), 1, 0.3));
  const camera cam = test::scene_camera(s);
  const std::vector<gpu::gpu_aov> aov = render_aov_cpu(cam, s, {0, 0, 24, 24, 0, 1});
  const gpu::gpu_aov& center = aov[12 * 24 + 12];
  ASSERT_EQ(center.hit, 1u);
  EXPECT_FLOAT_EQ(center.albedo.x, 0.25f);
  EXPECT_FLOAT_EQ(center.albedo.z, 0.75f);
}

// Whether pbr.h's model has landed: its stand-in (a Lambertian) never samples a delta lobe, the
// model's smooth metal always does.
bool smooth_metal_is_delta() {
  const pbr_surface m = pbr_surface_of(real3(1), 1, 0);
  real3 wi, weight;
  real pdf;
  bool delta = false;
  pbr_sample(m, real3(0.6, 0, 0.8), real3(0.5), wi, weight, pdf, delta);
  return delta;
}

// glTF's metal of roughness 0 is a mirror whose Fresnel is Schlick's from the base color: for a
// base color near 1 it is the book's metal of fuzz 0 (which reflects its albedo at every angle)
// within the Fresnel's rise at grazing angles, a thin rim. Seen through the same random numbers,
// the two images agree but at that rim. Written against the model (pbr.h's stand-in is a
// Lambertian: skipped until the model samples a delta lobe).
TEST(PbrRender, ASmoothPbrMetalIsTheBooksMirror) {
  if (!smooth_metal_is_delta()) GTEST_SKIP() << "pbr.h's model has not landed (its stand-in)";
  scene s = test::pbr_gallery();
  s.quads.clear();  // no lamp: the book's metal does not sample lights
  const material book{material_type::metal, color(0.95), 0, 1.5};
  s.materials[1].m = book;
  const framebuffer want = render_cpu(test::scene_camera(s), s, s.render);
  s.materials[1].m = test::pbr_of(color(0.95), 1, 0);
  const framebuffer got = render_cpu(test::scene_camera(s), s, s.render);
  int differ = 0;
  for (int y = 0; y < want.height(); ++y)
    for (int x = 0; x < want.width(); ++x)
      differ += std::abs(got.at(x, y).g - want.at(x, y).g) > 0.02;
  EXPECT_LE(differ, want.width() * want.height() / 50) << "pixels off by more than 2%";
}

// The lights' mixture (half toward the lamp, half by the BSDF, weighted by the mixture's
// density) estimates what plain sampling does: the gallery's mean color, each way, agrees within
// the noise. 32 x 21 pixels at 1,024 samples: the means differed by at most 0.54% over seeds 1
// to 4; tolerance 2%.
TEST(PbrRender, TheLightsMixtureEstimatesWhatPlainSamplingDoes) {
  scene s = test::pbr_gallery();
  s.render.width = 32;
  s.render.spp = 1024;
  const camera cam = test::scene_camera(s);
  s.render.sampling = sampling_mode::lights;
  const color lit = test::center_mean(render_cpu(cam, s, s.render));
  s.render.sampling = sampling_mode::plain;
  const color plain = test::center_mean(render_cpu(cam, s, s.render));
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(lit[c] / plain[c], 1.0, 0.02) << "channel " << c;
}

}  // namespace
}  // namespace rtvk
