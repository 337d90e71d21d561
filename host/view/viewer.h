#pragma once
#include <functional>
#include <string>

#include "camera.h"
#include "context.h"
#include "image_rgb8.h"
#include "render_gpu.h"
#include "scene.h"

namespace rtvk::view {

struct viewer_options {
  gpu::gpu_options gpu;             // device, validation, timeout (surface filled in here)
  gpu::gpu_render_options render;   // BVH or not
  int target_spp = 0;               // stop accumulating at this many samples; 0: never
  bool exit_at_target = false;      // --screenshot: close once target_spp are in
  bool size_follows_window = true;  // false: --width/--aspect fix the render's size
  std::function<bool()> cancelled;  // Ctrl-C: close as if the window were closed
};

// What a viewing session ended with.
struct viewer_result {
  camera_pose pose;             // the camera when it closed
  int width = 0, height = 0;    // the render's size then
  double aspect = 0;            // and the aspect ratio its camera was made with
  int samples = 0;              // samples per pixel accumulated then
  image_rgb8 image;             // the accumulated image, encoded as rtvk render encodes it
  int frames = 0;               // frames shown in the session
  double seconds = 0;           // the session's length, window open to close
  long long pixel_samples = 0;  // samples traced in the session, all restarts included
};

// Opens a window and renders `s` from `pose` progressively on the chosen device: batches of
// samples drawn by the GPU engine add exactly to per-pixel sums it keeps on the device, and after
// each batch the running mean, encoded to 8 bits there as rtvk render encodes it, is shown. Throws
// usage_error when there is no window system. What the keys that hand the shot on do (K prints the
// camera, O writes a screenshot): given the session's state at that moment.
struct viewer_actions {
  std::function<void(const viewer_result&)> print;       // K, and once more on exit
  std::function<void(const viewer_result&)> screenshot;  // O
};

viewer_result run_viewer(const scene& s, const camera_pose& pose, const viewer_options& options,
                         const viewer_actions& actions = {});

}  // namespace rtvk::view
