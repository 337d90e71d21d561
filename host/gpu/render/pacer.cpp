#include "pacer.h"

#include <algorithm>

namespace rtvk::gpu {

pacer::pacer(const pacing& targets, std::uint32_t fixed_per_dispatch,
             std::uint32_t fixed_per_submission)
    : targets_(targets), fixed_(fixed_per_dispatch || fixed_per_submission) {
  if (!fixed_) return;
  per_dispatch_ = std::max(1u, fixed_per_dispatch);
  per_submission_ = std::max(per_dispatch_, fixed_per_submission);
}

void pacer::measured(double seconds, std::uint32_t dispatches) {
  if (fixed_ || !(seconds == seconds) || dispatches == 0) return;
  const double per_dispatch = seconds / dispatches;
  if (per_dispatch < targets_.dispatch_grow && per_dispatch_ < max_samples) per_dispatch_ *= 2;
  if (per_dispatch > targets_.dispatch_shrink && per_dispatch_ > 1) per_dispatch_ /= 2;
  if (seconds < targets_.submission_grow && per_submission_ < max_samples) per_submission_ *= 2;
  if (seconds > targets_.submission_shrink && per_submission_ > 1) per_submission_ /= 2;
  per_submission_ = std::clamp(per_submission_, per_dispatch_, per_dispatch_ * max_dispatches);
}

}  // namespace rtvk::gpu
