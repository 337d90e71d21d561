#pragma once
#include <cstdint>
#include <functional>

namespace rtvk {

// How the GPU finds each ray's nearest hit (--accel): its own four-wide BVH in the compute
// shader (bvh; none when use_bvh is false), or the driver's acceleration structures through
// ray queries from that compute shader (rt-query) or a ray-tracing pipeline (rt-pipeline).
enum class gpu_traversal { compute, ray_query, ray_pipeline };

// The CPU's two modes (--backend cpu and --backend reference): the double-precision reference,
// the lesson's exact image and what the GPU is compared against; or the fast mode, the shared
// kernels in float over the GPU's arrays, packet_bvh and Embree finding the hits (host/fast), whose
// images are the GPU's within the GPU's tolerances.
enum class cpu_precision { reference, fast };

// How a backend does the work, as opposed to what it draws: none of this changes the image, but
// for the CPU's precision, which changes it by float's rounding.
struct engine_options {
  bool use_bvh = true;  // false: test every sphere for every ray (--accel none)
  gpu_traversal traversal = gpu_traversal::compute;    // the GPU's; the CPU always walks its BVH
  int threads = 0;                                     // CPU worker threads; 0: one per core
  cpu_precision precision = cpu_precision::reference;  // the CPU's mode
  bool count_rays = false;  // fill render_stats::rays (costs a little on the GPU)
  // Polled between passes (a CPU row, a GPU submission); when it returns true the render stops
  // and throws render_cancelled. Empty: never cancelled.
  std::function<bool()> cancelled = {};
};

// Whether a CPU render runs the fast mode: asked for, and not --accel none (the lesson's list of
// every object, which only the reference has).
inline bool runs_fast(const engine_options& e) {
  return e.precision == cpu_precision::fast && e.use_bvh;
}

// What finds the hits, in --accel's words: "bvh", "none", "rt-query" or "rt-pipeline".
inline const char* accel_word(const engine_options& e) {
  switch (e.traversal) {
    case gpu_traversal::ray_query:
      return "rt-query";
    case gpu_traversal::ray_pipeline:
      return "rt-pipeline";
    case gpu_traversal::compute:
      break;
  }
  return e.use_bvh ? "bvh" : "none";
}

// What a render did, for `rtvk bench`.
struct render_stats {
  std::uint64_t rays = 0;             // rays traced: camera rays plus scattered rays
  std::uint64_t dropped_samples = 0;  // samples with a NaN or infinite channel: added as black
  std::uint64_t stack_overflows = 0;  // GPU: of those, samples whose BVH walk overflowed its stack
  double build_seconds = 0;           // of the render's time, building the BVH
  int submissions = 0;     // GPU: command buffers submitted (all views of a group share each)
  double gpu_seconds = 0;  // GPU: device time of those submissions (timestamp queries); 0 when
                           // the device's queue has no timestamps
  std::uint64_t cut_traversals = 0;  // GPU: invocations a driver's loop limit cut short,
                                     // redrawn (render_status::cut_traversals)
};

}  // namespace rtvk
