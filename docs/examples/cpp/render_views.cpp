// rtvk from C++: a scene set up once, three views of it rendered, each image's mean color and the
// share of its pixels that see an object printed. Build it with CMakeLists.txt beside it.
#include <rtvk/rtvk.h>

#include <cstdio>
#include <string>

int main(int argc, char** argv) {
  try {
    const rtvk::api::Scene scene(argc > 1 ? argv[1] : "cornell-box");
    rtvk::api::Renderer renderer(scene, argc > 2 ? argv[2] : "auto");  // the GPU where there is one
    std::printf("%s on %s\n", scene.name().c_str(), renderer.description().c_str());
    for (int k = 0; k < 3; ++k) {
      const double x = 278 + 150.0 * (k - 1);
      const rtvk::api::Camera camera =
          rtvk::api::Camera::look_at({x, 278, -800}, {278, 278, 0}, 64, 48, 40);
      rtvk::api::RenderOptions options;
      options.spp = 4;
      options.aovs = rtvk::api::aov_object_id;
      const rtvk::api::Image image = renderer.render(camera, options);
      double mean = 0;
      for (const float c : image.rgb) mean += c;
      mean /= double(image.rgb.size());
      std::size_t seen = 0;
      for (const auto id : image.object_id) seen += id != 0;
      std::printf("view %d: %dx%d, mean %.4f, objects at %.1f%% of pixels\n", k, image.width,
                  image.height, mean, 100.0 * double(seen) / double(image.object_id.size()));
    }
    return 0;
  } catch (const rtvk::api::bad_input& e) {
    std::fprintf(stderr, "render_views: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "render_views: error: %s\n", e.what());
    return 1;
  }
}
