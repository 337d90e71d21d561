// The pacer on synthetic devices: no Vulkan, just the times a device of a given speed would
// report, so that devices nobody here has (a fast discrete GPU, a slow integrated one, a device
// that slows down when it heats up) are tried too.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "pacer.h"

namespace rtvk::gpu {
namespace {

// A device on which a dispatch costs `per_sample` seconds per sample it asks of each pixel, plus
// `overhead` per dispatch.
struct synthetic_device {
  double per_sample;    // seconds
  double overhead = 0;  // seconds per dispatch
};

// One submission as the engine makes it: dispatches of samples_per_dispatch until the
// submission's samples are done. Returns its seconds, after telling the pacer.
double submit(pacer& p, const synthetic_device& d) {
  const std::uint32_t step = p.samples_per_dispatch();
  const std::uint32_t dispatches = (p.samples_per_submission() + step - 1) / step;
  const double seconds = dispatches * (d.overhead + step * d.per_sample);
  p.measured(seconds, dispatches);
  return seconds;
}

void expect_sane(const pacer& p) {
  EXPECT_GE(p.samples_per_dispatch(), 1u);
  EXPECT_LE(p.samples_per_dispatch(), pacer::max_samples);
  EXPECT_GE(p.samples_per_submission(), p.samples_per_dispatch());
  EXPECT_LE(p.samples_per_submission(), p.samples_per_dispatch() * pacer::max_dispatches);
}

TEST(Pacer, StartsAtOneSample) {
  const pacer p(pacing_for(false, false));
  EXPECT_EQ(p.samples_per_dispatch(), 1u);
  EXPECT_EQ(p.samples_per_submission(), 1u);
}

// On any steady device the sizes settle with dispatches and submissions inside their targets,
// within a few dozen submissions, and stay there.
TEST(Pacer, SettlesInsideTheTargetsOnSteadyDevices) {
  for (const bool cpu : {false, true}) {
    const pacing t = pacing_for(cpu, cpu);
    for (const double per_sample : {1e-7, 3e-6, 1e-4, 2e-3}) {
      SCOPED_TRACE(std::string(cpu ? "cpu" : "gpu") + " pacing, " + std::to_string(per_sample) +
                   " s a sample");
      pacer p(t);
      const synthetic_device d{per_sample};
      for (int k = 0; k < 60; ++k) submit(p, d);
      const std::uint32_t settled_dispatch = p.samples_per_dispatch();
      const std::uint32_t settled_submission = p.samples_per_submission();
      for (int k = 0; k < 20; ++k) {
        const double seconds = submit(p, d);
        const double dispatch = p.samples_per_dispatch() * per_sample;
        // Shorter than the aims only at a cap: the most samples, or the most dispatches in one
        // submission.
        if (p.samples_per_dispatch() < pacer::max_samples) {
          EXPECT_GE(dispatch, t.dispatch_grow);
        }
        EXPECT_LE(dispatch, t.dispatch_shrink);
        EXPECT_LE(seconds, t.submission_shrink);
        if (seconds < t.submission_grow) {
          EXPECT_TRUE(p.samples_per_submission() == pacer::max_samples ||
                      p.samples_per_submission() ==
                          p.samples_per_dispatch() * pacer::max_dispatches)
              << p.samples_per_submission() << " samples in " << seconds << " s";
        }
        expect_sane(p);
      }
      EXPECT_EQ(p.samples_per_dispatch(), settled_dispatch) << "a steady device, steady sizes";
      EXPECT_EQ(p.samples_per_submission(), settled_submission);
    }
  }
}

// A device too slow for even one sample a dispatch stays at one, never zero.
TEST(Pacer, ASlowDeviceStaysAtOneSample) {
  pacer p(pacing_for(false, false));
  for (int k = 0; k < 10; ++k) submit(p, {5.0});
  EXPECT_EQ(p.samples_per_dispatch(), 1u);
  EXPECT_EQ(p.samples_per_submission(), 1u);
}

// A device so fast that no size reaches the targets stops at the caps.
TEST(Pacer, AnInstantDeviceStopsAtTheCaps) {
  pacer p(pacing_for(false, false));
  for (int k = 0; k < 100; ++k) submit(p, {0.0});
  EXPECT_EQ(p.samples_per_dispatch(), pacer::max_samples);
  EXPECT_EQ(p.samples_per_submission(), pacer::max_samples);
  expect_sane(p);
}

// A device that becomes ten times slower (a laptop's GPU when it heats up, another program on a
// shared GPU) is back inside the dispatch target within a few submissions.
TEST(Pacer, ADeviceThatSlowsDownIsFollowed) {
  const pacing t = pacing_for(false, false);
  pacer p(t);
  for (int k = 0; k < 60; ++k) submit(p, {1e-5});
  int submissions = 0;
  while (p.samples_per_dispatch() * 1e-4 > t.dispatch_shrink) {
    submit(p, {1e-4});
    ASSERT_LT(++submissions, 8) << "still " << p.samples_per_dispatch() << " samples a dispatch";
  }
  expect_sane(p);
}

// Whatever times a device reports, even contradictory ones (dispatches quick but submissions slow:
// a device shared with a display), a submission holds at least one dispatch and at most the most
// dispatches.
TEST(Pacer, TheSizesStayConsistentWhateverTheTimes) {
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> log_seconds(-7, 1);
  std::uniform_int_distribution<std::uint32_t> dispatches(1, 2000);
  for (const bool cpu : {false, true}) {
    pacer p(pacing_for(cpu, cpu));
    for (int k = 0; k < 5000; ++k) {
      p.measured(std::pow(10.0, log_seconds(gen)), dispatches(gen));
      expect_sane(p);
      if (::testing::Test::HasFailure()) return;
    }
  }
}

// Fixed sizes are what the tests asked for, whatever the times say.
TEST(Pacer, FixedSizesAreKept) {
  pacer p(pacing_for(false, false), 3, 7);
  EXPECT_EQ(p.samples_per_dispatch(), 3u);
  EXPECT_EQ(p.samples_per_submission(), 7u);
  for (double seconds : {0.0, 1e-9, 100.0}) p.measured(seconds, 3);
  EXPECT_EQ(p.samples_per_dispatch(), 3u);
  EXPECT_EQ(p.samples_per_submission(), 7u);
  const pacer at_least_one_dispatch(pacing_for(false, false), 5, 2);
  EXPECT_EQ(at_least_one_dispatch.samples_per_submission(), 5u);
  const pacer submission_only(pacing_for(false, false), 0, 4);
  EXPECT_EQ(submission_only.samples_per_dispatch(), 1u);
  EXPECT_EQ(submission_only.samples_per_submission(), 4u);
}

// A time that is not a number (a broken timer) changes nothing; an infinite one shrinks.
TEST(Pacer, TimesThatAreNotNumbersChangeNothing) {
  pacer p(pacing_for(false, false));
  for (int k = 0; k < 10; ++k) submit(p, {1e-6});
  const std::uint32_t d = p.samples_per_dispatch(), s = p.samples_per_submission();
  p.measured(std::numeric_limits<double>::quiet_NaN(), 4);
  p.measured(1.0, 0);
  EXPECT_EQ(p.samples_per_dispatch(), d);
  EXPECT_EQ(p.samples_per_submission(), s);
  p.measured(std::numeric_limits<double>::infinity(), 1);
  EXPECT_EQ(p.samples_per_dispatch(), d / 2);
  expect_sane(p);
}

// Before anything is measured, a dispatch of as many pixels as the pacer allows runs at most the
// pacing's first work (pixels times loop budget), on any device kind and any band: a GPU's first
// dispatch over a 4K image cannot run into a watchdog.
TEST(Pacer, EveryFirstDispatchIsBoundedBeforeAnythingIsMeasured) {
  for (const bool cpu : {false, true}) {
    const pacing t = pacing_for(cpu, cpu);
    const pacer p(t);
    for (const std::uint64_t band : {1ull, 1200ull, 1200ull * 675, 3840ull * 2160, 1ull << 30}) {
      const std::uint64_t pixels = std::min(band, p.pixel_allowance());
      EXPECT_LE(pixels * p.loop_budget(pixels), t.first_work) << band << " pixels wanted";
      EXPECT_GE(p.loop_budget(pixels), pacer::first_loop_budget);
    }
    EXPECT_GE(p.pixel_allowance(), 1u << 14) << "a GPU wants many invocations a dispatch";
  }
}

// The first dispatch is a calibration of first_work iterations, a fraction of a second even on a
// device 30 times slower than two cores of lavapipe; its time scales the work at once to the
// dispatch grow bound at the rate it showed, on fast and slow devices alike: the next dispatch,
// every iteration of its bound used, takes the grow bound's time, within the shrink bound even
// when the calibration used only a quarter of its bound. Later times step it as before.
TEST(Pacer, TheCalibrationsTimeSizesTheWorkAtOnce) {
  for (const bool cpu : {false, true}) {
    const pacing t = pacing_for(cpu, cpu);
    EXPECT_LE(double(t.first_work) * 1e-7, 0.5);
    for (const double per_iteration : {1e-13, 1e-11, 1e-9, 1e-7}) {
      SCOPED_TRACE(std::string(cpu ? "cpu" : "gpu") + " pacing, " + std::to_string(per_iteration) +
                   " s an iteration");
      pacer p(t);
      EXPECT_EQ(p.work(), t.first_work);
      p.measured(double(p.work()) * per_iteration, 1);
      const double next = double(p.work()) * per_iteration;
      if (p.work() < pacer::max_work) {
        EXPECT_NEAR(next, t.dispatch_grow, t.dispatch_grow * 1e-6);
      }
      EXPECT_LE(4 * next, t.dispatch_shrink * (1 + 1e-6));
      const std::uint64_t sized = p.work();
      p.measured(next * 1.01, 1);  // just past the grow bound, far inside the shrink bound
      EXPECT_EQ(p.work(), sized);
    }
  }
}

// The work grows on a fast device and shrinks on a slow one, so that a dispatch of the allowed
// pixels at their budget stays inside the targets even when every invocation uses its whole
// budget.
TEST(Pacer, TheWorkFollowsTheDispatchTimes) {
  const pacing t = pacing_for(false, false);
  pacer p(t);
  const auto worst_case = [&](double per_iteration) {  // seconds of one dispatch
    const std::uint64_t pixels = p.pixel_allowance();
    return double(pixels) * p.loop_budget(pixels) * per_iteration;
  };
  for (int k = 0; k < 60; ++k) p.measured(worst_case(1e-12), 1);
  EXPECT_GT(p.work(), t.first_work);
  EXPECT_LE(worst_case(1e-12), t.dispatch_shrink);
  int submissions = 0;
  while (worst_case(1e-10) > t.dispatch_shrink) {  // a hundred times slower
    p.measured(worst_case(1e-10), 1);
    ASSERT_LT(++submissions, 10) << p.work() << " iterations a dispatch";
  }
}

// A sample that needs more than its budget raises the lowest budget fourfold, up to the highest;
// one that needs more than the highest cannot be drawn (the engine fails the render).
TEST(Pacer, StarvedSamplesRaiseTheBudgetUpToTheHighest) {
  pacer p(pacing_for(false, true));
  const std::uint64_t many = 1ull << 40;  // pixels: the budget is the lowest
  EXPECT_EQ(p.loop_budget(many), pacer::first_loop_budget);
  std::uint32_t budget = p.loop_budget(many);
  int raises = 0;
  while (p.starved(budget)) {
    EXPECT_EQ(p.loop_budget(many), std::min(4 * budget, loop_limited_budget));
    budget = p.loop_budget(many);
    ASSERT_LT(++raises, 5);
  }
  EXPECT_EQ(budget, loop_limited_budget);
  EXPECT_EQ(p.highest_loop_budget(), loop_limited_budget);
  EXPECT_LE(p.pixel_allowance() * loop_limited_budget, p.work());
  // A starvation reported late, under a budget lower than the lowest now, lowers nothing.
  EXPECT_TRUE(p.starved(pacer::first_loop_budget));
  EXPECT_EQ(p.loop_budget(many), loop_limited_budget);
}

// On a device with no loop limit (any but lavapipe) a budget grows past lavapipe's, as far as a
// sample needs, and a dispatch's pixels shrink as it grows: what bounds a dispatch there is the
// work its measured times allow, not a count of iterations.
TEST(Pacer, WithoutALoopLimitTheBudgetGrowsAsFarAsASampleNeeds) {
  pacer p(pacing_for(false, false));
  const std::uint64_t many = 1ull << 40;
  std::uint32_t budget = p.loop_budget(many);
  int raises = 0;
  while (p.starved(budget)) {
    budget = p.loop_budget(many);
    const std::uint64_t pixels = p.pixel_allowance();
    if (budget <= p.work()) {
      EXPECT_LE(pixels * p.loop_budget(pixels), p.work()) << budget;
    }
    ASSERT_LT(++raises, 20);
  }
  EXPECT_EQ(budget, unlimited_budget);
  EXPECT_EQ(p.highest_loop_budget(), unlimited_budget);
  EXPECT_EQ(p.pixel_allowance(), 1u);
}

// A device not known to cut loops whose invocations were cut all the same (their probes saw it):
// held to lavapipe's budget from then on, the lowest budget too; once.
TEST(Pacer, ALoopLimitFoundHoldsTheBudgetToLavapipes) {
  pacer p(pacing_for(false, false));
  const std::uint64_t many = 1ull << 40;
  for (std::uint32_t budget = p.loop_budget(many); budget <= loop_limited_budget;
       budget = p.loop_budget(many))
    ASSERT_TRUE(p.starved(budget));
  EXPECT_GT(p.loop_budget(many), loop_limited_budget);
  EXPECT_TRUE(p.loop_limit_found());
  EXPECT_EQ(p.highest_loop_budget(), loop_limited_budget);
  EXPECT_EQ(p.loop_budget(many), loop_limited_budget);
  EXPECT_EQ(p.loop_budget(1), loop_limited_budget);
  EXPECT_FALSE(p.starved(loop_limited_budget));
  EXPECT_FALSE(p.loop_limit_found());
  pacer lavapipe(pacing_for(true, true));
  EXPECT_FALSE(lavapipe.loop_limit_found());
  EXPECT_EQ(lavapipe.highest_loop_budget(), loop_limited_budget);
}

// A fixed budget (tests) is the only budget: a starved sample under it fails.
TEST(Pacer, AFixedBudgetIsTheOnlyOne) {
  pacer p(pacing_for(true, true), 0, 0, 400);
  EXPECT_EQ(p.loop_budget(1), 400u);
  EXPECT_EQ(p.loop_budget(1ull << 40), 400u);
  EXPECT_FALSE(p.starved(400));
}

}  // namespace
}  // namespace rtvk::gpu
