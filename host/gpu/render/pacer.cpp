#include "pacer.h"

#include <algorithm>

namespace rtvk::gpu {

pacer::pacer(const pacing& targets, std::uint32_t fixed_per_dispatch,
             std::uint32_t fixed_per_submission, std::uint32_t fixed_loop_budget)
    : targets_(targets),
      fixed_(fixed_per_dispatch || fixed_per_submission),
      work_(std::clamp<std::uint64_t>(targets.first_work, 1, max_work)),
      lowest_budget_(fixed_loop_budget ? fixed_loop_budget : first_loop_budget),
      highest_budget_(fixed_loop_budget ? fixed_loop_budget : targets.highest_budget) {
  if (!fixed_) return;
  per_dispatch_ = std::max(1u, fixed_per_dispatch);
  per_submission_ = std::max(per_dispatch_, fixed_per_submission);
}

std::uint64_t pacer::pixel_allowance() const {
  return std::max<std::uint64_t>(1, work_ / lowest_budget_);
}

std::uint32_t pacer::loop_budget(std::uint64_t pixels) const {
  return std::uint32_t(std::clamp<std::uint64_t>(work_ / std::max<std::uint64_t>(pixels, 1),
                                                 lowest_budget_, highest_budget_));
}

bool pacer::starved(std::uint32_t budget) {
  if (budget >= highest_budget_) return false;
  lowest_budget_ = std::max(lowest_budget_,
                            std::uint32_t(std::min<std::uint64_t>(4ull * budget, highest_budget_)));
  return true;
}

bool pacer::loop_limit_found() {
  if (highest_budget_ <= loop_limited_budget) return false;
  highest_budget_ = loop_limited_budget;
  lowest_budget_ = std::min(lowest_budget_, highest_budget_);
  return true;
}

void pacer::measured(double seconds, std::uint32_t dispatches) {
  if (!(seconds == seconds) || dispatches == 0) return;
  const double per_dispatch = seconds / dispatches;
  // The work bounds every dispatch, fixed sample sizes or not. The first time (of the
  // calibration) scales it to the grow bound at once; later ones step it.
  if (!calibrated_ && per_dispatch > 0) {
    calibrated_ = true;
    const double scaled = double(work_) * targets_.dispatch_grow / per_dispatch;
    work_ = std::uint64_t(std::clamp(scaled, 1.0, double(max_work)));
  } else {
    if (per_dispatch < targets_.dispatch_grow && work_ < max_work) work_ *= 2;
    if (per_dispatch > targets_.dispatch_shrink && work_ > 1) work_ /= 2;
  }
  if (fixed_) return;
  if (per_dispatch < targets_.dispatch_grow && per_dispatch_ < max_samples) per_dispatch_ *= 2;
  if (per_dispatch > targets_.dispatch_shrink && per_dispatch_ > 1) per_dispatch_ /= 2;
  if (seconds < targets_.submission_grow && per_submission_ < max_samples) per_submission_ *= 2;
  if (seconds > targets_.submission_shrink && per_submission_ > 1) per_submission_ /= 2;
  per_submission_ = std::clamp(per_submission_, per_dispatch_, per_dispatch_ * max_dispatches);
}

}  // namespace rtvk::gpu
