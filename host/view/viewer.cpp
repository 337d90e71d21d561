#include "viewer.h"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "bvh_world.h"
#include "byte_encoding.h"
#include "camera_controls.h"
#include "elapsed.h"
#include "gpu_engine.h"
#include "overlay.h"
#include "parallel.h"
#include "presenter.h"
#include "render_cpu.h"
#include "swapchain.h"
#include "vk_error.h"
#include "window.h"

namespace rtvk::view {
namespace {

// Exact per-pixel sums of every batch so far: integer additions, so the result does not depend
// on how the samples were batched (the same bits as one render of all of them). Batches cover
// bands of rows, so rows may briefly hold one pass more than others.
struct accumulation {
  int width = 0, height = 0;     // pixels
  int samples = 0;               // per pixel in every row: the passes completed
  std::vector<int> row_samples;  // per row, from the top
  std::vector<exact_sum> sums;   // 3 per pixel: r, g, b

  void reset(int w, int h) {
    width = w;
    height = h;
    samples = 0;
    row_samples.assign(std::size_t(h), 0);
    sums.assign(std::size_t(w) * std::size_t(h) * 3, 0);
  }
  // Adds `count` samples of rows [row, row + batch.height).
  void add(const gpu::sum_image& batch, int row, int count) {
    const std::size_t first = std::size_t(row) * std::size_t(width);
    parallel_for(batch.pixels.size(), 0, 4096, [&](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i) {
        sums[3 * (first + i)] += gpu::red_sum(batch.pixels[i]);
        sums[3 * (first + i) + 1] += gpu::green_sum(batch.pixels[i]);
        sums[3 * (first + i) + 2] += gpu::blue_sum(batch.pixels[i]);
      }
    });
    for (int y = row; y < row + batch.height; ++y) row_samples[std::size_t(y)] += count;
    samples = *std::min_element(row_samples.begin(), row_samples.end());
  }
};

// Rows [first, last) of the running mean as 8-bit RGB (for screenshots) and RGBA (for the
// window), by encode_sum: the device's tonemap.comp encodes rtvk render's images bit for bit the
// same way. Only rows that changed are encoded again.
void encode(const accumulation& acc, const byte_thresholds& t, int first, int last, image_rgb8& rgb,
            std::vector<std::uint32_t>& rgba) {
  const std::size_t pixels = std::size_t(acc.width) * std::size_t(acc.height);
  rgb.width = acc.width;
  rgb.height = acc.height;
  rgb.rgb.resize(pixels * 3);
  rgba.resize(pixels);
  const std::size_t w = std::size_t(acc.width);
  parallel_for((std::size_t(last) - std::size_t(first)) * w, 0, 4096,
               [&](std::size_t begin, std::size_t end) {
                 for (std::size_t k = begin; k < end; ++k) {
                   const std::size_t i = std::size_t(first) * w + k;
                   const auto n = std::uint32_t(acc.row_samples[i / w]);
                   std::uint32_t packed = 0xff000000u;
                   for (int c = 0; c < 3; ++c) {
                     const std::uint8_t byte = encode_sum(acc.sums[3 * i + c], n, t);
                     rgb.rgb[3 * i + c] = byte;
                     packed |= std::uint32_t(byte) << (8 * c);
                   }
                   rgba[i] = packed;
                 }
               });
}

// A batch is `count` samples of a band of rows. Both adapt so that a batch takes about 60 ms,
// keeping the window above 10 frames a second on slow devices (lavapipe: bands of the image)
// and busy on fast ones (many samples of the whole image): bands grow to the whole image before
// samples grow past one, and samples shrink back to one before bands shrink.
struct batch_shape {
  int rows = 16;  // band height, pixels
  int count = 1;  // samples per pixel

  void adapt(double seconds, int height) {
    constexpr double target = 0.06;
    if (seconds < target / 2) {
      if (rows < height)
        rows = std::min(rows * 2, height);
      else
        count = std::min(count * 2, 1 << 16);
    } else if (seconds > target * 2) {
      if (count > 1)
        count /= 2;
      else
        rows = std::max(rows / 2, 1);
    }
  }
};

// Rays are counted for the overlay's Mrays/s (a counter beside the sums: the image is the same).
gpu::gpu_render_options counting(gpu::gpu_render_options o) {
  o.engine.count_rays = true;
  return o;
}

std::string xyz(const vec3& v) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "%.3g,%.3g,%.3g", v.x, v.y, v.z);
  return buf;
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
        engine_(ctx_, s, counting(options.render)),
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
  void apply_key(int key);
  void focus_at(double x, double y);
  void restart() { restart_ = true; }
  bool fit_to_window(int fb_w, int fb_h);
  void render_batch();
  void refresh_overlay();
  void show(int fb_w, int fb_h);
  std::vector<std::string> overlay_lines() const;

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
  batch_shape batch_;             // the next batch
  int pass_count_ = 0;            // samples per pixel of the pass under way
  int next_row_ = 0;              // where the pass's next band starts
  std::size_t named_ = 0;         // the named camera C last picked
  bool restart_ = true;           // accumulation starts again (size or camera changed)
  bool paused_ = false;           // Space
  bool overlay_ = true;           // H hides it
  bool overlay_changed_ = false;  // shown or hidden, or what it says changed, since last drawn
  int title_samples_ = -1;        // samples the title shows
  int overlay_rows_ = 0;          // rows the overlay was last drawn over
  int frames_ = 0;                // shown so far
  long long pixel_samples_ = 0;   // traced so far
  std::chrono::steady_clock::time_point started_ = std::chrono::steady_clock::now();
  double samples_per_second_ = 0;  // of the last batch: pixel samples
  double rays_per_second_ = 0;     // of the last batch
  double frame_seconds_ = 0;       // between the last two frames shown (smoothed)
  std::chrono::steady_clock::time_point last_frame_ = std::chrono::steady_clock::now();
};

std::vector<std::string> session::overlay_lines() const {
  char stats[160];
  std::snprintf(stats, sizeof stats, "%d spp   %.3g Msamples/s   %.3g Mrays/s   %.1f frames/s%s",
                acc_.samples, samples_per_second_ / 1e6, rays_per_second_ / 1e6,
                frame_seconds_ > 0 ? 1 / frame_seconds_ : 0.0, paused_ ? "   paused" : "");
  char lens[200];
  std::snprintf(lens, sizeof lens, "vfov %.3g   aperture %.3g   focus %.3g   %s", pose_.vfov,
                pose_.aperture, pose_.focus_dist,
                std::string(projection_name(pose_.projection)).c_str());
  return {
      stats,
      ctx_.device().name + "   " + std::to_string(acc_.width) + "x" + std::to_string(acc_.height),
      "from " + xyz(pose_.lookfrom) + "   at " + xyz(pose_.lookat),
      lens,
      "orbit: drag   pan: right-drag   dolly: wheel   fly: WASDQE",
      "fov: + -   aperture: [ ]   focus: F+click   P C Space R K O H"};
}

viewer_result session::state() const {
  viewer_result r;
  r.pose = pose_;
  r.width = acc_.width;
  r.height = acc_.height;
  r.aspect = rs_.aspect;
  r.samples = acc_.samples;
  r.image = rgb_;
  r.frames = frames_;
  r.seconds = seconds_since(started_);
  r.pixel_samples = pixel_samples_;
  return r;
}

// The keys that move the camera: each is one pure function of the pose (camera_controls.h).
camera_pose moved_by_key(const camera_pose& p, int key) {
  switch (key) {
    case GLFW_KEY_W:
      return fly(p, 1, 0, 0);
    case GLFW_KEY_S:
      return fly(p, -1, 0, 0);
    case GLFW_KEY_D:
      return fly(p, 0, 1, 0);
    case GLFW_KEY_A:
      return fly(p, 0, -1, 0);
    case GLFW_KEY_E:
      return fly(p, 0, 0, 1);
    case GLFW_KEY_Q:
      return fly(p, 0, 0, -1);
    case GLFW_KEY_EQUAL:
    case GLFW_KEY_KP_ADD:
      return zoom(p, 1);
    case GLFW_KEY_MINUS:
    case GLFW_KEY_KP_SUBTRACT:
      return zoom(p, -1);
    case GLFW_KEY_RIGHT_BRACKET:
      return stop(p, 1);
    case GLFW_KEY_LEFT_BRACKET:
      return stop(p, -1);
    case GLFW_KEY_P:
      return next_projection(p);
    default:
      return p;
  }
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
    pose_ = moved_by_key(pose_, key);
    apply_key(key);
  }
  if (in.focus_click) focus_at(in.click_x, in.click_y);
  if (!(pose_ == before)) restart();
}

// The keys that do something other than move the camera.
void session::apply_key(int key) {
  switch (key) {
    case GLFW_KEY_C:
      if (!s_.cameras.empty()) {
        named_ = (named_ + 1) % s_.cameras.size();
        pose_ = s_.cameras[named_].path.at(0);
      }
      break;
    case GLFW_KEY_SPACE:
      paused_ = !paused_;
      overlay_changed_ = true;  // it says "paused"
      break;
    case GLFW_KEY_R:
      restart();
      break;
    case GLFW_KEY_H:
      overlay_ = !overlay_;
      overlay_changed_ = true;
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
  // Pixel (px, py) from the top is the render's (i, j) = (px, height - 1 - py) from the bottom.
  const double u = pixel_coordinate(px, acc_.width);
  const double v = pixel_coordinate(acc_.height - 1 - py, acc_.height);
  const ray r = cam.get_ray(u, v);
  hit_record rec{};
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
  if (next_row_ == 0)  // a new pass: every row gets the same samples
    pass_count_ = options_.target_spp == 0
                      ? batch_.count
                      : std::min(batch_.count, options_.target_spp - acc_.samples);
  const camera cam(pose_, rs_.aspect, rs_.width);
  const int rows = std::min(batch_.rows, acc_.height - next_row_);
  const render_window window{0,    next_row_,    acc_.width,
                             rows, acc_.samples, acc_.samples + pass_count_};
  const auto start = std::chrono::steady_clock::now();
  const std::vector<gpu::sum_image> sums = engine_.render_sums({cam}, rs_, window);
  const double seconds = std::max(seconds_since(start), 1e-9);
  const int row = next_row_;
  acc_.add(sums.front(), row, pass_count_);
  next_row_ = next_row_ + rows >= acc_.height ? 0 : next_row_ + rows;
  const double traced = double(acc_.width) * rows * pass_count_;
  pixel_samples_ += (long long)traced;
  std::uint64_t rays = 0;
  for (const gpu::pixel_sum& p : sums.front().pixels) rays += p.rays;
  samples_per_second_ = traced / seconds;
  rays_per_second_ = double(rays) / seconds;
  batch_.adapt(seconds, acc_.height);
  encode(acc_, thresholds_, row, row + rows, rgb_, rgba_);
  refresh_overlay();
}

// The rows the last overlay covered are encoded again from the sums, and the overlay drawn over
// them (or not, when H hid it); then the image goes to the presenter.
void session::refresh_overlay() {
  encode(acc_, thresholds_, 0, std::min(overlay_rows_, acc_.height), rgb_, rgba_);
  overlay_rows_ = overlay_ ? draw_overlay(rgba_, acc_.width, acc_.height, overlay_lines()) : 0;
  shown_->write(rgba_.data());
  overlay_changed_ = false;
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
  ++frames_;
  const double since = seconds_since(last_frame_);
  last_frame_ = std::chrono::steady_clock::now();
  frame_seconds_ = frame_seconds_ == 0 ? since : 0.8 * frame_seconds_ + 0.2 * since;
}

viewer_result session::run() {
  while (!win_.should_close() && !(options_.cancelled && options_.cancelled())) {
    win_.poll();
    apply(win_.take_input());
    if (win_.minimized()) {  // nothing to show, nothing to render (X11 keeps the size)
      win_.wait();
      continue;
    }
    int fb_w = 0, fb_h = 0;
    win_.framebuffer_size(fb_w, fb_h);
    if (fit_to_window(fb_w, fb_h)) restart();
    if (restart_) {
      const camera sized(pose_, rs_.aspect, rs_.width);
      if (sized.image_width() != acc_.width || sized.image_height() != acc_.height) {
        rgba_.assign(std::size_t(sized.image_width()) * std::size_t(sized.image_height()),
                     0xff000000u);  // black until the first pass reaches each row
        rgb_ = image_rgb8{};
      }  // else the last view stays until the new one's rows replace it
      acc_.reset(sized.image_width(), sized.image_height());
      if (!shown_ || shown_->width() != acc_.width || shown_->height() != acc_.height)
        shown_ = std::make_unique<presenter>(ctx_, acc_.width, acc_.height);
      if (chain_.extent().width != std::uint32_t(fb_w) ||
          chain_.extent().height != std::uint32_t(fb_h))
        chain_.recreate(fb_w, fb_h);
      batch_ = batch_shape{};
      next_row_ = 0;
      restart_ = false;
    }
    const bool want_more = options_.target_spp == 0 || acc_.samples < options_.target_spp;
    if (want_more && !paused_)
      render_batch();
    else if (overlay_changed_ && acc_.samples > 0)  // idle: nothing else would draw it
      refresh_overlay();
    if (acc_.samples != title_samples_) {  // how far it is, shown or not (the tests read it)
      title_samples_ = acc_.samples;
      win_.set_title("rtvk view: " + s_.name + " - " + std::to_string(acc_.samples) + " spp");
    }
    if (!rgba_.empty()) show(fb_w, fb_h);
    if (!want_more && options_.exit_at_target) break;
    if (!want_more || paused_) win_.wait();  // idle until something happens
  }
  ctx_.wait_all();
  ctx_.check_validation();
  return state();
}

}  // namespace

viewer_result run_viewer(const scene& s, const camera_pose& pose, const viewer_options& options,
                         const viewer_actions& actions) {
  session viewing(s, pose, options, actions);
  return viewing.run();
}

}  // namespace rtvk::view
