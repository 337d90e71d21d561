// The library's renderer: the scene set up once on its backend (`rtvk render`'s engine for a
// run), then any number of renders, each drawn as `rtvk render` draws it.
#include <algorithm>

#include "aov_output.h"
#include "aov_pass.h"
#include "api_impl.h"
#include "gpu_engine.h"
#include "gpu_flags.h"
#include "light_sources.h"
#include "precision_flag.h"
#include "render_cpu.h"
#include "vk_error.h"

namespace rtvk::api {

struct Renderer::impl {
  explicit impl(const Scene& sc) : scene(sc) {}
  Scene scene;          // the handle: edits show in its version
  std::string backend;  // "cpu" or "gpu"
  std::string device;   // --device's words
  cpu_precision precision = cpu_precision::reference;
  rtvk::scene s;  // the copy set up, with the motion span of the renders so far
  std::uint64_t version = ~std::uint64_t(0);  // of the scene `s` is a copy of
  std::uint64_t set_ups = 0;                  // times `s` was set up
  std::function<bool()> cancel;               // the render's poll, while one runs
  std::unique_ptr<gpu::gpu_context> ctx;
  std::unique_ptr<gpu::gpu_engine> engine;
  std::unique_ptr<cpu_scene> cpu;  // on the CPU: the world built once, as the engine is
  std::unique_ptr<gpu::aov_pass> aovs;

  engine_options options() {
    engine_options e;
    e.precision = precision;
    e.cancelled = [this] { return cancel && cancel(); };
    return e;
  }

  // Sets the scene up again when it changed, or when a camera's shutter reaches outside the
  // instants its trees bound moving spheres over.
  void prepare(const std::vector<camera>& views) {
    time_span span{views[0].time_open(), views[0].time_close()};
    for (const camera& c : views)
      span = {std::min(span.lo, c.time_open()), std::max(span.hi, c.time_close())};
    const bool moved = scene_moves(s) && (span.lo < s.motion.lo || span.hi > s.motion.hi);
    if (version == scene.impl_->version && !moved) return;
    version = ~std::uint64_t(0);  // set up again at the next render, unless this succeeds
    aovs.reset();
    cpu.reset();
    s = scene.impl_->s;
    s.motion = span;
    if (backend == "gpu") {
      if (!engine)
        engine = std::make_unique<gpu::gpu_engine>(
            *ctx, s,
            gpu::gpu_render_options{.engine = options(),
                                    .pipeline_cache_folder = gpu::default_cache_folder()});
      else
        try {
          engine->replace_scene(s);  // the pipelines kept
        } catch (...) {
          engine.reset();  // not to be used after a throw: made afresh next time
          throw;
        }
    } else {
      cpu = std::make_unique<cpu_scene>(s, options());
    }
    version = scene.impl_->version;
    ++set_ups;
  }

  std::vector<framebuffer> draw(const std::vector<camera>& views, const render_settings& rs,
                                const render_window& win,
                                const std::function<void(double)>& progress) {
    if (engine) {
      const auto samples = [&](int done) { progress(double(done) / win.samples()); };
      return engine->render_views(
          views, rs, win, progress ? gpu::sample_progress(samples) : gpu::sample_progress{});
    }
    std::vector<framebuffer> out;
    for (std::size_t k = 0; k < views.size(); ++k) {
      const auto rows = [&](int done) {
        progress((double(k) + double(done) / win.height) / double(views.size()));
      };
      out.push_back(cpu->render(views[k], rs, win,
                                progress ? progress_callback(rows) : progress_callback{}, options(),
                                nullptr));
    }
    return out;
  }

  aov_image ground_truth(const camera& c, unsigned which, const render_window& win) {
    if (!engine) return aov_from(cpu->aovs(c, win, 0), object_ids(s), which, win);
    if (!aovs)
      aovs = std::make_unique<gpu::aov_pass>(*ctx, engine->device_scene(), engine->scene_has_bvh());
    return aov_from(aovs->run(c, win), object_ids(s), which, win);
  }
};

namespace {

Image image_of(const framebuffer& fb, const aov_image* a) {
  Image im;
  im.width = fb.width();
  im.height = fb.height();
  im.rgb.reserve(std::size_t(im.width) * std::size_t(im.height) * 3);
  for (int y = 0; y < im.height; ++y)
    for (int x = 0; x < im.width; ++x)
      for (int c = 0; c < 3; ++c) im.rgb.push_back(float(fb.at(x, y)[c]));  // as the EXR holds
  if (a) {
    im.depth = a->depth;
    im.distance = a->distance;
    im.normal = a->normal;
    im.albedo = a->albedo;
    im.object_id = a->object_id;
    im.material_id = a->material_id;
  }
  return im;
}

}  // namespace

Renderer::Renderer(const Scene& scene, const std::string& backend, const std::string& device,
                   const std::string& precision)
    : impl_(std::make_unique<impl>(scene)) {
  translate([&] {
    if (backend != "cpu" && backend != "gpu" && backend != "auto")
      throw bad_input("backend " + backend + ": expected cpu, gpu or auto");
    if (precision != "auto" && precision != "fast" && precision != "reference")
      throw bad_input("precision " + precision + ": expected auto, fast or reference");
    if (!device.empty() && backend == "cpu")
      throw bad_input("device " + device + ": needs backend gpu or auto");
    impl_->backend = backend == "auto" ? "gpu" : backend;
    impl_->device = device;
    impl_->precision = precision != "auto"    ? precision_for(precision, "")
                       : scene.impl_->builtin ? cpu_precision::reference
                                              : cpu_precision::fast;
    if (backend != "cpu") {
      gpu_flags flags;
      flags.device = device;
      try {
        impl_->ctx = std::make_unique<gpu::gpu_context>(flags.options());
      } catch (const rtvk::gpu::no_device_error&) {
        if (backend != "auto") throw;
        impl_->backend = "cpu";  // auto: the CPU where there is no device, as `rtvk render`
      }
    }
    return 0;
  });
}

Renderer::~Renderer() = default;
Renderer::Renderer(Renderer&&) noexcept = default;
Renderer& Renderer::operator=(Renderer&&) noexcept = default;

Image Renderer::render(const Camera& camera, const RenderOptions& options) {
  return render(std::vector<Camera>{camera}, options).front();
}

std::vector<Image> Renderer::render(const std::vector<Camera>& cameras,
                                    const RenderOptions& options) {
  return translate([&] {
    if (cameras.empty()) throw bad_input("cameras: expected at least one");
    std::vector<camera> views;
    for (const Camera& c : cameras) {
      views.push_back(c.impl_->cam);
      if (c.width() != cameras[0].width() || c.height() != cameras[0].height())
        throw bad_input("cameras: every view of one render must have the same size");
    }
    impl_->prepare(views);
    render_settings rs = impl_->s.render;
    if (options.spp != 0) rs.spp = options.spp;
    if (options.max_depth != 0) rs.max_depth = options.max_depth;
    if (options.seed >= 0) rs.seed = std::uint32_t(options.seed);
    if (rs.spp < 1 || options.spp < 0)
      throw bad_input("spp " + std::to_string(options.spp) + ": expected at least 1");
    if (options.max_depth < 0 || rs.max_depth > max_depth_limit)
      throw bad_input("max_depth " + std::to_string(options.max_depth) + ": expected 1 to " +
                      std::to_string(max_depth_limit));
    if (options.seed > 0xffffffffll)
      throw bad_input("seed " + std::to_string(options.seed) + ": expected 0 to 4294967295");
    const render_window win = whole_render(views[0].image_width(), views[0].image_height(), rs.spp);
    impl_->cancel = options.cancelled;
    const std::vector<framebuffer> drawn = impl_->draw(views, rs, win, options.progress);
    std::vector<Image> out;
    for (std::size_t k = 0; k < views.size(); ++k) {
      if (options.aovs == 0) {
        out.push_back(image_of(drawn[k], nullptr));
        continue;
      }
      const aov_image a = impl_->ground_truth(views[k], options.aovs & 31u, win);
      out.push_back(image_of(drawn[k], &a));
    }
    impl_->cancel = {};
    return out;
  });
}

std::uint64_t Renderer::set_ups() const {
  return impl_->set_ups;
}

std::string Renderer::description() const {
  if (impl_->backend == "cpu")
    return impl_->precision == cpu_precision::fast ? "cpu (fast)" : "cpu (reference)";
  return "gpu (" + impl_->ctx->device().name + ")";
}

}  // namespace rtvk::api
