#pragma once
#include <string>
#include <vector>

#include "camera.h"
#include "output_pattern.h"
#include "render_settings.h"
#include "scene.h"
#include "scene_overrides.h"

namespace rtvk {

// A half-open range of integers written "A:B" (A up to, not including, B, like a Python slice),
// or a single number "N" (N:N+1).
struct int_range {
  int begin = 0;  // first
  int end = 0;    // one past the last
};

// Parses "A:B" or "N" with lo <= A < B <= hi. Throws usage_error naming the flag and the text.
// `hi_note` follows hi in the message, saying where the limit comes from.
int_range parse_range(const std::string& text, const std::string& flag, int lo, int hi,
                      const std::string& hi_note = "");

// Parses "x,y,w,h" (four integers). Throws usage_error naming the flag and the text.
render_window parse_region(const std::string& text, const std::string& flag);

// What `rtvk render` was asked to draw, besides the scene.
struct job_request {
  std::vector<std::string> cameras;  // --camera values; "all", or empty for the first camera
  std::string frames;                // --frames A:B or N; empty: frame 0 only
  double fps = 24;                   // --fps: frame f shows time f / fps
  std::string region;                // --region x,y,w,h; empty: the whole image
  std::string samples;               // --samples A:B; empty: 0:spp
  std::string output;                // -o, with {camera}, {frame} or {frame:0N} placeholders
};

// One image a run produces: a camera at a frame.
struct render_job {
  std::string camera_name;  // the scene's name for the camera
  int frame = 0;            // animation frame number
  camera cam;               // posed for the frame's time
  std::string output;       // the -o path with placeholders filled in
  std::string fingerprint;  // the scene, settings and pose, hashed (partial_image.h); .exr only
};

// The selected cameras (s.cameras narrowed to them, in the scene's order), the overrides applied,
// and one job per camera and frame, every output path checked. Throws usage_error naming the
// flag and the value for an unknown camera, a range or region outside the image or its samples,
// a -o that would make two images share a file, or an unwritable folder.
// `output` is req.output, parsed (before the scene was loaded).
std::vector<render_job> plan_jobs(scene& s, const job_request& req, const output_pattern& output,
                                  const scene_overrides& overrides, render_window& window);

}  // namespace rtvk
