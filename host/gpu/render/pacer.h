#pragma once
// How much work one dispatch and one submission get, from how long the last ones took. Kept apart
// from the engine that records and submits the commands, and pure (it is told the seconds), so
// that tests can drive it with any device's timings: it is the part of the engine most likely to
// misbehave on a device nobody here has measured.
#include <cstdint>

namespace rtvk::gpu {

// How long dispatches and submissions should take, by kind of device. A GPU wants dispatches of a
// few milliseconds (a display may be waiting, and long shaders risk a driver's watchdog) and
// submissions short enough for progress and Ctrl-C. On a CPU device (lavapipe) nothing waits on
// a dispatch, and an invocation tracing more of its samples keeps its SIMD lanes busier (a lane
// whose path ends starts its next sample while the others bounce), so dispatches may take a
// quarter second and, from 8 samples a pixel on, bands are kept small enough that one dispatch
// can take all of a band's samples: about 2^18 pixel samples a band (2^15 pixels at least).
// With fewer samples there is little to gain, and many views in one dispatch (an animation's
// frames) do better: one band, one wait and one readback for all of them.
struct pacing {
  double dispatch_grow, dispatch_shrink;      // seconds of device time per dispatch
  double submission_grow, submission_shrink;  // seconds per submission
  bool small_bands;                           // bands sized to the sample count, as above
};

// The targets for a CPU device (lavapipe) or for any other.
constexpr pacing pacing_for(bool cpu_device) {
  return cpu_device ? pacing{0.25, 1.0, 0.5, 2.0, true} : pacing{0.004, 0.016, 0.1, 0.4, false};
}

// Samples per dispatch and per submission. Both start at one and double while the measured times
// are below the targets' grow bounds, halve while above their shrink bounds (a grow bound at most
// half its shrink bound keeps a steady device steady), and carry over from one render to the
// next. A submission holds at least one dispatch's samples and at most max_dispatches
// dispatches. Fixed sizes (--samples-per-dispatch and per submission, for tests) are never
// changed.
class pacer {
 public:
  static constexpr std::uint32_t max_samples = 1u << 20;  // either size
  static constexpr std::uint32_t max_dispatches = 256;    // dispatches in one submission

  // Paced toward `targets`; or, when either fixed size is not 0, fixed: per dispatch
  // max(1, fixed_per_dispatch), per submission at least that and fixed_per_submission.
  explicit pacer(const pacing& targets, std::uint32_t fixed_per_dispatch = 0,
                 std::uint32_t fixed_per_submission = 0);

  std::uint32_t samples_per_dispatch() const { return per_dispatch_; }
  std::uint32_t samples_per_submission() const { return per_submission_; }

  // A submission of `dispatches` dispatches took `seconds` (device time where the device has a
  // timer: wall time includes the wait behind the other submission in flight). A time that is not
  // a number changes nothing.
  void measured(double seconds, std::uint32_t dispatches);

 private:
  pacing targets_;
  bool fixed_;                        // sizes given, not paced
  std::uint32_t per_dispatch_ = 1;    // samples per dispatch
  std::uint32_t per_submission_ = 1;  // samples per submission
};

}  // namespace rtvk::gpu
