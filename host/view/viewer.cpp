#include "viewer.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "accumulation.h"
#include "bvh_world.h"
#include "camera_controls.h"
#include "elapsed.h"
#include "errors.h"
#include "format.h"
#include "gpu_engine.h"
#include "key_bindings.h"
#include "overlay.h"
#include "presenter.h"
#include "render_cpu.h"
#include "sample_target.h"
#include "swapchain.h"
#include "vk_error.h"
#include "window.h"

namespace rtvk::view {
namespace {

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

// The largest image of the window's aspect (at most its size) whose sums fit one of the
// device's storage buffers: the accumulation keeps the whole image's on the device.
void fit_accumulation(const gpu::gpu_engine& engine, int& width, int& height) {
  const double aspect = double(width) / double(height);
  while (width > 1 && !engine.accumulation_fits(width, height)) {
    width = std::max(1, width * 9 / 10);
    height = std::max(1, int(width / aspect));
  }
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
        chain_(ctx_, start_width(), start_height()),
        frames_in_flight_{frame_slot{make_semaphore(ctx_.vk())},
                          frame_slot{make_semaphore(ctx_.vk())}},
        rs_(s.render),
        pose_(pose) {
    // A size fixed by the flags must let the whole image's sums stay on the device (one that
    // follows the window is scaled down to fit: fit_accumulation).
    const camera sized(pose_, rs_.aspect, rs_.width);
    if (!options_.size_follows_window &&
        !engine_.accumulation_fits(sized.image_width(), sized.image_height()))
      throw usage_error("--width " + std::to_string(rs_.width) + ": rtvk view keeps the whole " +
                        std::to_string(sized.image_width()) + "x" +
                        std::to_string(sized.image_height()) +
                        " image's sums on the device, 48 bytes a pixel in one storage buffer, "
                        "more than device '" +
                        ctx_.device().name + "' allows (" +
                        format_bytes(ctx_.device().limits.maxStorageBufferRange) +
                        "): a smaller --width, or rtvk render");
  }

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
  viewer_result state();
  void apply(const window_input& in);
  void apply_key(int key);
  void focus_at(double x, double y);
  void restart() { restart_ = true; }
  bool fit_to_window(int fb_w, int fb_h);
  void render_batch();
  void show(int fb_w, int fb_h);
  std::vector<std::string> overlay_lines() const;

  const scene& s_;
  const viewer_options& options_;
  const viewer_actions& actions_;
  window_system windowing_;  // GLFW, for the session
  window win_;
  gpu::gpu_context ctx_;  // with the window's surface
  gpu::gpu_engine engine_;
  swapchain chain_;
  // Two frames in flight: each has the semaphore its swapchain image's acquisition signals, and
  // the submission that waited on it (done before the semaphore is used again).
  struct frame_slot {
    gpu::unique_semaphore acquired;  // signalled when a swapchain image may be written
    std::uint64_t ticket = 0;        // the submission that waits on it; 0: none yet
  };
  std::array<frame_slot, 2> frames_in_flight_;
  std::uint64_t last_shown_ = 0;      // the presenting queue's last frame submission
  std::unique_ptr<presenter> shown_;  // the render's size
  std::unique_ptr<bvh_world> world_;  // on the CPU, made at the first focus click
  render_settings rs_;                // size and aspect as rendered now
  camera_pose pose_;                  // as moved by the controls
  accumulation acc_;
  batch_shape batch_;             // the next batch
  int pass_count_ = 0;            // samples per pixel of the pass under way
  int next_row_ = 0;              // where the pass's next band starts
  std::size_t named_ = 0;         // the named camera C last picked
  bool restart_ = true;           // accumulation starts again (size or camera changed)
  bool paused_ = false;           // Space
  bool overlay_ = true;           // H hides it
  bool overlay_changed_ = false;  // shown or hidden, or what it says changed, since last drawn
  int title_samples_ = -1;        // samples the title shows
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

viewer_result session::state() {
  viewer_result r;
  r.pose = pose_;
  r.width = acc_.width;
  r.height = acc_.height;
  r.aspect = rs_.aspect;
  r.samples = acc_.samples;
  if (acc_.samples > 0) r.image = engine_.read_accumulation(acc_.width, acc_.height);
  r.frames = frames_;
  r.seconds = seconds_since(started_);
  r.pixel_samples = pixel_samples_;
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
  if (!world_) world_ = std::make_unique<bvh_world>(s_);
  const camera cam(pose_, rs_.aspect, rs_.width);
  // Pixel (px, py) from the top is the render's (i, j) = (px, height - 1 - py) from the bottom.
  const double u = pixel_coordinate(px, acc_.width);
  const double v = pixel_coordinate(acc_.height - 1 - py, acc_.height);
  // At the middle of the shutter: where a moving sphere is seen, blurred either side of it.
  ray r = cam.get_ray(u, v);
  r.time = (cam.time_open() + cam.time_close()) / 2;
  hit_record rec{};
  if (!world_->hit(r, 1e-3, std::numeric_limits<double>::infinity(), rec)) return;
  const double along = glm::dot(rec.p - cam.origin(), -cam.axis_w());
  if (along > 0) pose_.focus_dist = along;
}

// Follows the window's size when the render does; true when the render's size changed.
bool session::fit_to_window(int fb_w, int fb_h) {
  if (!options_.size_follows_window) return false;
  int w = fb_w, h = fb_h;
  fit_accumulation(engine_, w, h);
  if (w == rs_.width && std::abs(rs_.aspect - double(fb_w) / fb_h) < 1e-12 && acc_.width > 0)
    return false;
  rs_.width = w;
  rs_.aspect = double(fb_w) / double(fb_h);
  return true;
}

void session::render_batch() {
  if (next_row_ == 0)  // a new pass: every row gets the same samples
    pass_count_ = next_pass_samples(options_.target_spp, acc_.samples, batch_.count);
  const camera cam(pose_, rs_.aspect, rs_.width);
  const int rows = std::min(batch_.rows, acc_.height - next_row_);
  const render_window window{0,    next_row_,    acc_.width,
                             rows, acc_.samples, acc_.samples + pass_count_};
  const auto start = std::chrono::steady_clock::now();
  // On two queues, nothing orders the frames' reads of the bytes (presenting queue) before the
  // batch's tonemap writes them (compute queue): the host waits for the last frame, a copy and a
  // blit. The other way round the host already waits: the batch reads its status block back.
  // On one queue, submission order and the engine's barriers do both.
  if (ctx_.split_queues()) ctx_.wait(last_shown_, gpu::queue_role::presenting);
  render_stats stats;
  engine_.accumulate(cam, rs_, window, &stats);
  const double seconds = std::max(seconds_since(start), 1e-9);
  acc_.add(next_row_, rows, pass_count_);
  next_row_ = next_row_ + rows >= acc_.height ? 0 : next_row_ + rows;
  const double traced = double(acc_.width) * rows * pass_count_;
  pixel_samples_ += (long long)traced;
  samples_per_second_ = traced / seconds;
  rays_per_second_ = double(stats.rays) / seconds;
  batch_.adapt(seconds, acc_.height);
}

// The accumulated image, with the overlay over it unless H hid it, into the next swapchain
// image. The frame is not waited for: the host goes on to the next batch while it is drawn and
// presented, and waits only before its acquisition semaphore is used again, two frames later.
void session::show(int fb_w, int fb_h) {
  frame_slot& slot = frames_in_flight_[std::size_t(frames_) % frames_in_flight_.size()];
  if (slot.ticket != 0) ctx_.wait(slot.ticket, gpu::queue_role::presenting);
  std::uint32_t index = 0;
  if (!chain_.acquire(slot.acquired.get(), index)) {
    chain_.recreate(fb_w, fb_h);
    return;
  }
  shown_->show_from(engine_.accumulated_bytes());
  const overlay_mask overlay =
      overlay_ ? draw_overlay(acc_.width, acc_.height, overlay_lines()) : overlay_mask{};
  overlay_changed_ = false;
  slot.ticket = ctx_.submit([&](VkCommandBuffer cb) { shown_->record(cb, overlay, chain_, index); },
                            gpu::submit_sync{slot.acquired.get(), VK_PIPELINE_STAGE_TRANSFER_BIT,
                                             chain_.ready_to_present(index)},
                            gpu::queue_role::presenting);
  last_shown_ = slot.ticket;
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
        ctx_.wait_all();  // the frames in flight show the old bytes
        // Black until the first pass reaches each row.
        engine_.reset_accumulation(sized.image_width(), sized.image_height());
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
    // Past max_spp samples the image stays as it is, shown (sample_target.h).
    const bool want_more = next_pass_samples(options_.target_spp, acc_.samples, 1) > 0;
    if (want_more && !paused_) render_batch();

    if (acc_.samples != title_samples_) {  // how far it is, shown or not (the tests read it)
      title_samples_ = acc_.samples;
      win_.set_title("rtvk view: " + s_.name + " - " + std::to_string(acc_.samples) + " spp");
    }
    if (shown_) show(fb_w, fb_h);
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
