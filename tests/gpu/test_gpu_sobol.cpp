// sobol.h's low-discrepancy numbers on the device (tests/gpu/probes/sobol_probe.comp): 32-bit
// integer arithmetic and one exact conversion, so the GPU's bits and floats are the C++'s, bit
// for bit, for every counter.
#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "gpu_fixture.h"
#include "probe.h"
#include "random.h"
#include "random.h"

namespace rtvk {
namespace {

class GpuSobol : public test::GpuTest {};

bool same_float_bits(float a, float b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

TEST_F(GpuSobol, TheDeviceDrawsTheHostsBits) {
  // Whole nets of a few pixels (consecutive samples) and scattered counters up to the top bits.
  std::vector<gpu::sobol_probe_entry> entries;
  for (std::uint32_t pixel : {0u, 1u, 4097u})
    for (std::uint32_t sample = 0; sample < 256; ++sample)
      for (std::uint32_t bounce : {0u, 3u})
        for (std::uint32_t dim : {dim_jitter_u, dim_lens_a, dim_light_a, dim_alpha})
          entries.push_back({pixel, sample, bounce, dim, 0, 0, 0, 0, 0, 0});
  for (std::uint32_t k = 0; k < 4096; ++k)
    entries.push_back(
        {hash32(k), hash32(k + 1) >> (k % 32), hash32(k + 2) >> 26, k % 16, 0, 0, 0, 0, 0, 0});
  const auto out = gpu::run_sobol_probe(gpu(), entries);
  ASSERT_EQ(out.size(), entries.size());
  int differ = 0;
  for (const auto& e : out) {
    const random_stream s =
        at_bounce(pixel_sample_stream(0x5eedu, e.pixel, e.sample_index), e.bounce);
    const uvec2 b = sobol_bits2(s, e.dim);
    const real2 v = sobol_rnd2(s, e.dim);
    const bool same = e.bits == sobol_bits(s, e.dim) && e.bits_x == b.x && e.bits_y == b.y &&
                      same_float_bits(e.value, float(sobol_rnd(s, e.dim))) &&
                      same_float_bits(e.value_x, float(v.x)) &&
                      same_float_bits(e.value_y, float(v.y));
    if (!same && ++differ <= 5)
      ADD_FAILURE() << "pixel " << e.pixel << " sample " << e.sample_index << " bounce " << e.bounce
                    << " dim " << e.dim << ": device " << std::hex << e.bits << " " << e.bits_x
                    << " " << e.bits_y << ", host " << sobol_bits(s, e.dim) << " " << b.x << " "
                    << b.y;
  }
  EXPECT_EQ(differ, 0) << "of " << out.size();
}

}  // namespace
}  // namespace rtvk
