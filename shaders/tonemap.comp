#version 450
// One invocation per pixel turns the pixel's exact sums into 8-bit RGBA, bit for bit what
// encode_sum (host/base/byte_encoding.cpp) gives on the host: integer comparisons against the
// render's thresholds, no float rounding that could differ between devices. A render then reads
// back 4 bytes a pixel instead of 48, and a window can show the same bytes.
#extension GL_GOOGLE_include_directive : require
#include "bindings.h"
#include "render_types.h"

layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;

layout(std430, set = 0, binding = RTVK_TONEMAP_SUMS) readonly buffer image_block {
  pixel_sum sums[];
};
layout(std430, set = 0, binding = RTVK_TONEMAP_BYTES) writeonly buffer byte_block { uint rgba[]; };
layout(std430, set = 0, binding = RTVK_TONEMAP_THRESHOLDS) readonly buffer threshold_block {
  uvec2 thresholds[256];  // (low word, high word) of byte_thresholds
};
layout(push_constant) uniform push_block { tonemap_push pc; };

// sum >= thresholds[k] * samples, for a 96-bit sum of (low, high) words and a top word. The
// product fits 64 bits: thresholds are at most 2^42 and samples at most 2^20; a sum with a top
// word is larger.
bool at_least(uvec2 sum, uint top, uint k, uint samples) {
  if (top != 0u) return true;
  uvec2 t = thresholds[k];
  uint high, low;
  umulExtended(t.x, samples, high, low);
  high += t.y * samples;
  return sum.y > high || (sum.y == high && sum.x >= low);
}

// Mirrors encode_sum: the largest k with sum >= thresholds[k] * samples.
uint encode_sum(uvec2 sum, uint top, uint samples) {
  if (samples == 0u) return 0u;
  uint lo = 0u;
  uint hi = 255u;
  while (lo < hi) {
    uint mid = (lo + hi + 1u) / 2u;
    if (at_least(sum, top, mid, samples))
      lo = mid;
    else
      hi = mid - 1u;
  }
  return lo;
}

void main() {
  // Rows of workgroups when one row would pass the device's workgroup count limit.
  uint k = gl_GlobalInvocationID.y * pc.row_invocations + gl_GlobalInvocationID.x;
  if (k >= pc.pixels) return;
  uint i = pc.first + k;  // a run of rows of a larger image (the viewer's), or all of it
  pixel_sum p = sums[i];
  uint r = encode_sum(p.r, p.r_top, p.samples);
  uint g = encode_sum(p.g, p.g_top, p.samples);
  uint b = encode_sum(p.b, p.b_top, p.samples);
  rgba[i] = r | (g << 8) | (b << 16) | (255u << 24);
}
