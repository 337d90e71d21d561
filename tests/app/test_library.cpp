// rtvk.h, the library's C++ API, on the CPU: what the Python module and librtvk.so are made of,
// run here under the sanitizers too (the module is not built there). Its images are
// render_cpu's, its errors the CLI's.
#include <gtest/gtest.h>

#include <cstring>

#include "render_helpers.h"
#include "rtvk.h"

namespace rtvk {
namespace {

TEST(Library, TheLessonsSceneIsRenderCpusImage) {
  const api::Scene scene("seed");
  api::Renderer renderer(scene, "cpu");
  const api::Image image = renderer.render(api::Camera::from_scene(scene));
  const rtvk::scene s = builtin_scene("seed");
  const framebuffer fb = render_cpu(test::scene_camera(s), s, s.render);
  ASSERT_EQ(image.width, fb.width());
  ASSERT_EQ(image.height, fb.height());
  for (int y = 0; y < fb.height(); ++y)
    for (int x = 0; x < fb.width(); ++x)
      for (int c = 0; c < 3; ++c)
        ASSERT_EQ(image.rgb[(std::size_t(y) * fb.width() + x) * 3 + c], float(fb.at(x, y)[c]));
  EXPECT_EQ(renderer.description(), "cpu (reference)");
}

TEST(Library, BadInputIsBadInputWithTheClisMessage) {
  try {
    api::Scene("no-such-scene");
    FAIL() << "no exception";
  } catch (const api::bad_input& e) {
    EXPECT_NE(std::strstr(e.what(), "--scene: unknown scene 'no-such-scene'"), nullptr) << e.what();
  }
  EXPECT_THROW(api::Renderer(api::Scene("seed"), "tpu"), api::bad_input);
  EXPECT_THROW(api::Camera::look_at({0, 0, 0}, {0, 0, 0}, 8, 8), api::bad_input);
  api::Renderer r(api::Scene("seed"), "cpu");
  api::RenderOptions o;
  o.spp = -1;
  EXPECT_THROW(r.render(api::Camera::from_scene(api::Scene("seed")), o), api::bad_input);
}

TEST(Library, ACancelledRenderThrowsCancelled) {
  const api::Scene scene("book-final");
  api::Renderer r(scene, "cpu");
  api::RenderOptions o;
  o.cancelled = [] { return true; };
  EXPECT_THROW(r.render(api::Camera::from_scene(scene), o), api::cancelled);
}

}  // namespace
}  // namespace rtvk
