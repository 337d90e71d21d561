// The viewer's passes near max_spp: a session with no target ("forever") started a few samples
// short of the bound must end its passes exactly there, each pass a window check_window accepts
// (before, the pass past the bound threw invalid_argument and the viewer exited 2, "bad input").
#include <gtest/gtest.h>

#include "render_settings.h"
#include "sample_target.h"

namespace rtvk::view {
namespace {

// The viewer's passes from `done` samples in batches of `batch`, as session::render_batch asks
// for them, each checked as the engine checks it; returns the samples reached.
int run_passes(int target_spp, int done, int batch) {
  for (int passes = 0; passes < 100; ++passes) {
    const int count = next_pass_samples(target_spp, done, batch);
    if (count == 0) break;
    check_window({0, 0, 4, 2, done, done + count}, 4, 2);  // throws past max_spp
    done += count;
  }
  return done;
}

TEST(SampleTarget, ForeverStopsAtTheBoundAndKeepsTheImage) {
  EXPECT_EQ(run_passes(0, max_spp - 5, 4), max_spp);
  EXPECT_EQ(run_passes(0, max_spp - 5, 1 << 16), max_spp);
  EXPECT_EQ(next_pass_samples(0, max_spp, 8), 0) << "nothing more once there";
}

TEST(SampleTarget, ATargetIsReachedExactly) {
  EXPECT_EQ(run_passes(100, 90, 8), 100);
  EXPECT_EQ(next_pass_samples(100, 100, 8), 0);
  EXPECT_EQ(next_pass_samples(0, 0, 8), 8) << "forever far from the bound: the whole batch";
}

}  // namespace
}  // namespace rtvk::view
