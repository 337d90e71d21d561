#include "viewer.h"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "bvh_world.h"
#include "byte_encoding.h"
#include "camera_controls.h"
#include "elapsed.h"
#include "gpu_engine.h"
#include "parallel.h"
#include "presenter.h"
#include "swapchain.h"
#include "vk_error.h"
#include "window.h"

namespace rtvk::view {
namespace {

// Exact per-pixel sums of every batch so far: integer additions, so the result does not depend
// on how the samples were batched (the same bits as one render of all of them).
struct accumulation {
  int width = 0, height = 0;        // pixels
  int samples = 0;                  // per pixel, all pixels alike
  std::vector<std::uint64_t> sums;  // 3 per pixel: r, g, b

  void reset(int w, int h) {
    width = w;
    height = h;
    samples = 0;
    sums.assign(std::size_t(w) * std::size_t(h) * 3, 0);
  }
  void add(const gpu::sum_image& batch, int batch_samples) {
    const auto word = [](gpu::uvec2 v) { return std::uint64_t(v.y) << 32 | v.x; };
    parallel_for(batch.pixels.size(), 0, 4096, [&](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i) {
        sums[3 * i] += word(batch.pixels[i].r);
        sums[3 * i + 1] += word(batch.pixels[i].g);
        sums[3 * i + 2] += word(batch.pixels[i].b);
      }
    });
    samples += batch_samples;
  }
};

// The running mean as 8-bit RGB (for screenshots) and RGBA (for the window), by encode_sum: the
// device's tonemap.comp encodes rtvk render's images bit for bit the same way.
void encode(const accumulation& acc, const byte_thresholds& t, image_rgb8& rgb,
            std::vector<std::uint32_t>& rgba) {
  const std::size_t pixels = std::size_t(acc.width) * std::size_t(acc.height);
  rgb.width = acc.width;
  rgb.height = acc.height;
  rgb.rgb.resize(pixels * 3);
  rgba.resize(pixels);
  parallel_for(pixels, 0, 4096, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      std::uint32_t packed = 0xff000000u;
      for (int c = 0; c < 3; ++c) {
        const std::uint8_t byte = encode_sum(acc.sums[3 * i + c], std::uint32_t(acc.samples), t);
        rgb.rgb[3 * i + c] = byte;
        packed |= std::uint32_t(byte) << (8 * c);
      }
      rgba[i] = packed;
    }
  });
}

// Samples per batch: grown or shrunk so a batch takes about a tenth of a second, which keeps
// the window responsive (about 10 frames a second) on slow devices and busy on fast ones.
int next_batch(int batch, double seconds) {
  constexpr double target = 0.1;
  if (seconds < target / 2) return std::min(batch * 2, 1 << 16);
  if (seconds > target * 2) return std::max(batch / 2, 1);
  return batch;
}

gpu::unique_semaphore make_semaphore(VkDevice device) {
  VkSemaphoreCreateInfo info{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
  VkSemaphore sem = VK_NULL_HANDLE;
  gpu::vk_check(vkCreateSemaphore(device, &info, nullptr, &sem), "vkCreateSemaphore");
  return gpu::unique_semaphore(device, sem);
}

// One viewing session: the window, the device objects, the camera and what has accumulated.
class session {
 public:
  session(const scene& s, const camera_pose& pose, const viewer_options& options,
          const viewer_actions& actions)
      : s_(s),
        options_(options),
        actions_(actions),
        win_(windowing_, start_width(), start_height(), "rtvk view: " + s.name),
        ctx_(gpu_options()),
        engine_(ctx_, s, options.render),
        thresholds_(make_byte_thresholds(s.render.gamma, engine_.sum_exponent())),
        chain_(ctx_, start_width(), start_height()),
        acquired_(make_semaphore(ctx_.vk())),
        rs_(s.render),
        pose_(pose) {}

  ~session() {
    ctx_.wait_all();
    if (!ctx_.lost()) vkDeviceWaitIdle(ctx_.vk());
  }

  viewer_result run();

 private:
  int start_width() const { return options_.size_follows_window ? 960 : s_.render.width; }
  int start_height() const {
    return options_.size_follows_window ? 540
                                        : std::max(1, int(s_.render.width / s_.render.aspect));
  }
  gpu::gpu_options gpu_options() {
    gpu::gpu_options g = options_.gpu;
    g.instance_extensions = windowing_.instance_extensions();
    g.make_surface = [this](VkInstance instance) { return win_.create_surface(instance); };
    return g;
  }
  viewer_result state() const;
  void apply(const window_input& in);
  void focus_at(double x, double y);
  void restart() { restart_ = true; }
  bool fit_to_window(int fb_w, int fb_h);
  void render_batch();
  void show(int fb_w, int fb_h);

  const scene& s_;
  const viewer_options& options_;
  const viewer_actions& actions_;
  window_system windowing_;  // GLFW, for the session
  window win_;
  gpu::gpu_context ctx_;  // with the window's surface
  gpu::gpu_engine engine_;
  byte_thresholds thresholds_;
  swapchain chain_;
  gpu::unique_semaphore acquired_;    // signalled when a swapchain image may be written
  std::unique_ptr<presenter> shown_;  // the render's size
  std::unique_ptr<bvh_world> world_;  // on the CPU, made at the first focus click
  render_settings rs_;                // size and aspect as rendered now
  camera_pose pose_;                  // as moved by the controls
  accumulation acc_;
  image_rgb8 rgb_;
  std::vector<std::uint32_t> rgba_;
  int batch_ = 1;          // samples in the next batch
  std::size_t named_ = 0;  // the named camera C last picked
  bool restart_ = true;    // accumulation starts again (size or camera changed)
  bool paused_ = false;    // Space
};

viewer_result session::state() const {
  viewer_result r;
  r.pose = pose_;
  r.width = acc_.width;
  r.height = acc_.height;
  r.aspect = rs_.aspect;
  r.samples = acc_.samples;
  r.image = rgb_;
  return r;
}

// The controls of docs/viewer.md: every move goes through the camera pose and restarts the
// accumulation.
void session::apply(const window_input& in) {
  const camera_pose before = pose_;
  if (in.drag[0][0] != 0 || in.drag[0][1] != 0) pose_ = orbit(pose_, in.drag[0][0], -in.drag[0][1]);
  const double pan_x = in.drag[1][0] + in.drag[2][0], pan_y = in.drag[1][1] + in.drag[2][1];
  if (pan_x != 0 || pan_y != 0) {
    int w = 0, h = 0;
    win_.window_size(w, h);
    pose_ = pan(pose_, pan_x, -pan_y, h);
  }
  if (in.scroll != 0) pose_ = dolly(pose_, in.scroll);
  for (const int key : in.keys) {
    switch (key) {
      case GLFW_KEY_W:
        pose_ = fly(pose_, 1, 0, 0);
        break;
      case GLFW_KEY_S:
        pose_ = fly(pose_, -1, 0, 0);
        break;
      case GLFW_KEY_D:
        pose_ = fly(pose_, 0, 1, 0);
        break;
      case GLFW_KEY_A:
        pose_ = fly(pose_, 0, -1, 0);
        break;
      case GLFW_KEY_E:
        pose_ = fly(pose_, 0, 0, 1);
        break;
      case GLFW_KEY_Q:
        pose_ = fly(pose_, 0, 0, -1);
        break;
      case GLFW_KEY_EQUAL:
      case GLFW_KEY_KP_ADD:
        pose_ = zoom(pose_, 1);
        break;
      case GLFW_KEY_MINUS:
      case GLFW_KEY_KP_SUBTRACT:
        pose_ = zoom(pose_, -1);
        break;
      case GLFW_KEY_RIGHT_BRACKET:
        pose_ = stop(pose_, 1);
        break;
      case GLFW_KEY_LEFT_BRACKET:
        pose_ = stop(pose_, -1);
        break;
      case GLFW_KEY_P:
        pose_ = next_projection(pose_);
        break;
      case GLFW_KEY_C:
        if (!s_.cameras.empty()) {
          named_ = (named_ + 1) % s_.cameras.size();
          pose_ = s_.cameras[named_].path.at(0);
        }
        break;
      case GLFW_KEY_SPACE:
        paused_ = !paused_;
        break;
      case GLFW_KEY_R:
        restart();
        break;
      case GLFW_KEY_ESCAPE:
        win_.request_close();
        break;
      case GLFW_KEY_K:
        if (actions_.print) actions_.print(state());
        break;
      case GLFW_KEY_O:
        if (actions_.screenshot && acc_.samples > 0) actions_.screenshot(state());
        break;
      default:
        break;
    }
  }
  if (in.focus_click) focus_at(in.click_x, in.click_y);
  if (!(pose_ == before)) restart();
}

// F + click: the distance in focus becomes that of the surface under the cursor, along the
// view axis, hit on the CPU by the ray get_ray casts through that pixel (no lens offset).
void session::focus_at(double x, double y) {
  int w = 0, h = 0;
  win_.window_size(w, h);
  if (w <= 0 || h <= 0 || acc_.width == 0) return;
  // The render is shown scaled to fit, centred: undo that.
  const double scale = std::min(double(w) / acc_.width, double(h) / acc_.height);
  const double px = (x - (w - acc_.width * scale) / 2) / scale;
  const double py = (y - (h - acc_.height * scale) / 2) / scale;
  if (px < 0 || py < 0 || px >= acc_.width || py >= acc_.height) return;
  if (!world_) world_ = std::make_unique<bvh_world>(s_.spheres);
  const camera cam(pose_, rs_.aspect, rs_.width);
  const double u = px / (acc_.width - 1 > 0 ? acc_.width - 1 : 1);
  const double v = (acc_.height - 1 - py) / (acc_.height - 1 > 0 ? acc_.height - 1 : 1);
  const ray r = cam.get_ray(u, v);
  hit_record rec;
  if (!world_->hit(r, 1e-3, std::numeric_limits<double>::infinity(), rec)) return;
  const double along = glm::dot(rec.p - cam.origin(), -cam.axis_w());
  if (along > 0) pose_.focus_dist = along;
}

// Follows the window's size when the render does; true when the render's size changed.
bool session::fit_to_window(int fb_w, int fb_h) {
  if (!options_.size_follows_window) return false;
  if (fb_w == rs_.width && std::abs(rs_.aspect - double(fb_w) / fb_h) < 1e-12 && acc_.width > 0)
    return false;
  rs_.width = fb_w;
  rs_.aspect = double(fb_w) / double(fb_h);
  return true;
}

void session::render_batch() {
  const camera cam(pose_, rs_.aspect, rs_.width);
  const int count =
      options_.target_spp == 0 ? batch_ : std::min(batch_, options_.target_spp - acc_.samples);
  const render_window window{0, 0, acc_.width, acc_.height, acc_.samples, acc_.samples + count};
  const auto start = std::chrono::steady_clock::now();
  const std::vector<gpu::sum_image> sums = engine_.render_sums({cam}, rs_, window);
  acc_.add(sums.front(), count);
  batch_ = next_batch(batch_, seconds_since(start));
  encode(acc_, thresholds_, rgb_, rgba_);
  shown_->write(rgba_.data());
}

void session::show(int fb_w, int fb_h) {
  std::uint32_t index = 0;
  if (!chain_.acquire(acquired_.get(), index)) {
    chain_.recreate(fb_w, fb_h);
    return;
  }
  const std::uint64_t ticket =
      ctx_.submit([&](VkCommandBuffer cb) { shown_->record(cb, chain_, index); },
                  gpu::submit_sync{acquired_.get(), VK_PIPELINE_STAGE_TRANSFER_BIT,
                                   chain_.ready_to_present(index)});
  ctx_.wait(ticket);
  if (!chain_.present(index)) chain_.recreate(fb_w, fb_h);
}

viewer_result session::run() {
  while (!win_.should_close() && !(options_.cancelled && options_.cancelled())) {
    win_.poll();
    apply(win_.take_input());
    int fb_w = 0, fb_h = 0;
    win_.framebuffer_size(fb_w, fb_h);
    if (fb_w == 0 || fb_h == 0) {  // minimized: nothing to show, nothing to render
      win_.wait();
      continue;
    }
    if (fit_to_window(fb_w, fb_h)) restart();
    if (restart_) {
      const camera sized(pose_, rs_.aspect, rs_.width);
      acc_.reset(sized.image_width(), sized.image_height());
      if (!shown_ || shown_->width() != acc_.width || shown_->height() != acc_.height)
        shown_ = std::make_unique<presenter>(ctx_, acc_.width, acc_.height);
      if (chain_.extent().width != std::uint32_t(fb_w) ||
          chain_.extent().height != std::uint32_t(fb_h))
        chain_.recreate(fb_w, fb_h);
      batch_ = 1;
      restart_ = false;
    }
    const bool want_more = options_.target_spp == 0 || acc_.samples < options_.target_spp;
    if (want_more && !paused_) render_batch();
    if (acc_.samples > 0) show(fb_w, fb_h);
    if (!want_more && options_.exit_at_target) break;
    if (!want_more || paused_) win_.wait();  // idle until something happens
  }
  ctx_.wait_all();
  if (ctx_.validation_messages() > 0)
    throw std::runtime_error("the Vulkan validation layer reported " +
                             std::to_string(ctx_.validation_messages()) + " problem(s) (above)");
  return state();
}

}  // namespace

viewer_result run_viewer(const scene& s, const camera_pose& pose, const viewer_options& options,
                         const viewer_actions& actions) {
  session viewing(s, pose, options, actions);
  return viewing.run();
}

}  // namespace rtvk::view
