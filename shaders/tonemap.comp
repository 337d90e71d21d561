#version 450
// One invocation per pixel turns the pixel's exact sums into 8-bit RGBA. For every view transform
// but AgX, bit for bit what encode_sum (host/base/byte_encoding.cpp) gives on the host: integer
// comparisons against the render's thresholds (made for its transform and exposure), no float
// rounding that could differ between devices. AgX mixes the channels, so no per-channel table
// holds it: the mean is computed in float and goes through the shared agx_display
// (shaders/shared/view_transform.h), within a level of the host's double (tests/gpu). A render
// then reads back 4 bytes a pixel instead of 48, and a window can show the same bytes.
#extension GL_GOOGLE_include_directive : require
#include "bindings.h"
#include "render_types.h"
#include "view_transform.h"

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
// product has up to 96 bits (thresholds below 2^63, samples at most 2^20): (low, middle, high)
// words, compared from the top.
bool at_least(uvec2 sum, uint top, uint k, uint samples) {
  uvec2 t = thresholds[k];
  uint h0, l0, h1, l1;
  umulExtended(t.x, samples, h0, l0);
  umulExtended(t.y, samples, h1, l1);
  uint carry;
  uint middle = uaddCarry(h0, l1, carry);
  uint high = h1 + carry;
  if (top != high) return top > high;
  if (sum.y != middle) return sum.y > middle;
  return sum.x >= l0;
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

// A channel's exposed scene-linear mean, in float.
float mean_of(uvec2 sum, uint top, uint samples) {
  float s = float(top) * 18446744073709551616.0 + float(sum.y) * 4294967296.0 + float(sum.x);
  return s / float(samples) * pc.mean_scale;
}

// to_byte (host/base/byte_encoding.h): int(255.999 * c) after clamping to [0, 1].
uint to_byte(float c) {
  if (!(c > 0.0)) return 0u;
  if (c >= 1.0) return 255u;
  return uint(255.999 * c);
}

void main() {
  // Rows of workgroups when one row would pass the device's workgroup count limit.
  uint k = gl_GlobalInvocationID.y * pc.row_invocations + gl_GlobalInvocationID.x;
  if (k >= pc.pixels) return;
  uint i = pc.first + k;  // a run of rows of a larger image (the viewer's), or all of it
  pixel_sum p = sums[i];
  uint r, g, b;
  if (pc.transform == RTVK_VIEW_AGX) {
    vec3 d = vec3(0.0);
    if (p.samples != 0u)
      d = agx_display(vec3(mean_of(p.r, p.r_top, p.samples), mean_of(p.g, p.g_top, p.samples),
                           mean_of(p.b, p.b_top, p.samples)));
    r = to_byte(srgb_encode(d.x));
    g = to_byte(srgb_encode(d.y));
    b = to_byte(srgb_encode(d.z));
  } else {
    r = encode_sum(p.r, p.r_top, p.samples);
    g = encode_sum(p.g, p.g_top, p.samples);
    b = encode_sum(p.b, p.b_top, p.samples);
  }
  rgba[i] = r | (g << 8) | (b << 16) | (255u << 24);
}
