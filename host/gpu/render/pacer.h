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
// tenth of a second or more (submissions a quarter to a second: well inside a 2-second watchdog,
// which tests/view/layers plays on lavapipe) and, from 8 samples a pixel on, bands are kept small
// enough that one dispatch can take all of a band's samples: about 2^18 pixel samples a band (2^15
// pixels at least). With fewer samples there is little to gain, and many views in one dispatch (an
// animation's frames) do better: one band, one wait and one readback for all of them. Before
// anything was measured, a dispatch may run at most `first_work` loop iterations in all (its pixels
// times its loop budget): a short calibration, tens of milliseconds on two cores of lavapipe, far
// inside Windows' 2-second watchdog (TDR), Linux's GPU job timeouts and --gpu-timeout on any
// device; its measured time sizes the work of the dispatches after it.
struct pacing {
  double dispatch_grow, dispatch_shrink;      // seconds of device time per dispatch
  double submission_grow, submission_shrink;  // seconds per submission
  bool small_bands;                           // bands sized to the sample count, as above
  std::uint64_t first_work;                   // loop iterations a first dispatch may run
  std::uint32_t highest_budget;               // loop iterations one invocation may run
};

// The most loop iterations one invocation may run. lavapipe silently stops an invocation's loops
// after 65,535 trips in all (Mesa 22.3; a cut is found by the probe at the end of every
// invocation, render_body.glsl), so there rtvk stops first, at 60,000 (the rest is for loops it
// does not count, such as rejection sampling). A device with no loop limit is bounded by time
// instead: a budget grows only as far as some sample needs (fourfold at a time), and a dispatch
// is given fewer pixels as it grows, so that its pixels times its budget stay within the work its
// measured times allow; the fence timeout (--gpu-timeout) catches one sample longer than that on
// its own. Its highest budget, 2^30, only keeps the shader's 32-bit count from wrapping.
inline constexpr std::uint32_t loop_limited_budget = 60'000;
inline constexpr std::uint32_t unlimited_budget = 1u << 30;

// The targets for a CPU device (lavapipe) or for any other. lavapipe runs about 3e8 iterations a
// second on two cores (a third of that when the cores are shared), so the calibration's 2^22 is
// 15 to 45 ms there, and far less on a GPU. At the first loop budget that is 2^14 pixels: enough
// invocations to keep a GPU busy while it is timed. (It was 2^26 before it was measured, over a
// second on a loaded lavapipe: with the fourfold budgets of starved samples, past 4 s.)
// `loop_limited`: the driver stops loops (lavapipe, known by its driver ID: loop_limited in
// render_plan.h).
constexpr pacing pacing_for(bool cpu_device, bool loop_limited) {
  const std::uint32_t highest = loop_limited ? loop_limited_budget : unlimited_budget;
  return cpu_device ? pacing{0.1, 0.4, 0.25, 1.0, true, 1ull << 22, highest}
                    : pacing{0.004, 0.016, 0.1, 0.4, false, 1ull << 22, highest};
}

// Samples per dispatch and per submission, and how much work one dispatch may do. The samples
// per dispatch and per submission start at one and double while the measured times
// are below the targets' grow bounds, halve while above their shrink bounds (a grow bound at most
// half its shrink bound keeps a steady device steady), and carry over from one render to the
// next. A submission holds at least one dispatch's samples and at most max_dispatches
// dispatches. Fixed sizes (--samples-per-dispatch and per submission, for tests) are never
// changed.
// The work is what bounds a dispatch's time before it runs, whatever the scene: an invocation
// stops after its loop budget (render.comp) and the next dispatch goes on from there, so a
// dispatch of P pixels runs at most P x budget iterations. The work starts at the pacing's
// first_work, a calibration: the first time measured scales it at once to what the dispatch
// grow bound allows at the rate it showed (iterations a second, counting every one the bound
// allowed: a dispatch whose invocations used a quarter of their budgets still ends inside the
// shrink bound). After that it doubles or halves with the dispatch times as the samples do; a
// dispatch is given as many pixels as the work allows at the lowest budget (a GPU wants many
// invocations), and the budget grows only once a dispatch's pixels are all it was asked for. The
// lowest budget starts at first_loop_budget and grows fourfold whenever some sample needed more
// (`starved`), up to the pacing's highest budget, where a sample that does not fit fails the
// render. A device that turns out to cut loops all the same (`loop_limit_found`) is held to
// loop_limited_budget from then on.
class pacer {
 public:
  static constexpr std::uint32_t max_samples = 1u << 20;  // either size
  static constexpr std::uint32_t max_dispatches = 256;    // dispatches in one submission
  static constexpr std::uint32_t first_loop_budget = 256;
  static constexpr std::uint64_t max_work = 1ull << 40;  // loop iterations per dispatch

  // Paced toward `targets`; or, when either fixed size is not 0, fixed: per dispatch
  // max(1, fixed_per_dispatch), per submission at least that and fixed_per_submission. A fixed
  // loop budget (not 0) is the lowest and the highest budget.
  explicit pacer(const pacing& targets, std::uint32_t fixed_per_dispatch = 0,
                 std::uint32_t fixed_per_submission = 0, std::uint32_t fixed_loop_budget = 0);

  std::uint32_t samples_per_dispatch() const { return per_dispatch_; }
  std::uint32_t samples_per_submission() const { return per_submission_; }
  std::uint64_t work() const { return work_; }  // loop iterations one dispatch may run
  // Pixels one dispatch may draw: the work at the lowest budget (at least one).
  std::uint64_t pixel_allowance() const;
  // The loop budget for a dispatch of `pixels`: the work shared among them, within the lowest
  // and the highest budget.
  std::uint32_t loop_budget(std::uint64_t pixels) const;
  std::uint32_t highest_loop_budget() const { return highest_budget_; }
  // Some sample needed more than `budget` iterations: the lowest budget becomes four times
  // that, up to the highest. False when `budget` was already the highest: the sample cannot be
  // drawn on any device.
  bool starved(std::uint32_t budget);
  // The device cut an invocation's loops short (its probe saw it, render_body.glsl) though its
  // driver was not known to: the highest budget becomes loop_limited_budget, as on lavapipe.
  // False when it was that already (or lower): nothing to change.
  bool loop_limit_found();

  // A submission of `dispatches` dispatches took `seconds` (device time where the device has a
  // timer: wall time includes the wait behind the other submission in flight). A time that is not
  // a number changes nothing.
  void measured(double seconds, std::uint32_t dispatches);

 private:
  pacing targets_;
  bool fixed_;                        // sizes given, not paced
  std::uint32_t per_dispatch_ = 1;    // samples per dispatch
  std::uint32_t per_submission_ = 1;  // samples per submission
  std::uint64_t work_;                // loop iterations per dispatch
  bool calibrated_ = false;           // the work was scaled by a measured time
  std::uint32_t lowest_budget_;       // loop iterations per invocation and dispatch, at least
  std::uint32_t highest_budget_;      // and at most
};

}  // namespace rtvk::gpu
