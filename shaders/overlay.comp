#version 450
// The viewer's overlay, composed on the device: a band at the top left of the image, the render
// darkened to a quarter under it (it stays faintly visible), and white text where the mask's
// bit is set. The host rasterizes the text into the mask (stb_easy_font's quads, a bit a pixel:
// a few KiB), so the image itself never leaves the device. The band is written to its own buffer
// and copied over the image that is shown; the encoded image (the screenshots') is untouched.
#extension GL_GOOGLE_include_directive : require
#include "overlay_push.h"

layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;

layout(std430, set = 0, binding = RTVK_OVERLAY_BYTES) readonly buffer byte_block { uint rgba[]; };
layout(std430, set = 0, binding = RTVK_OVERLAY_MASK) readonly buffer mask_block {
  uint mask[];
};
layout(std430, set = 0, binding = RTVK_OVERLAY_BAND) writeonly buffer overlay_block {
  uint band[];
};
layout(push_constant) uniform push_block { overlay_push pc; };

void main() {
  uint x = gl_GlobalInvocationID.x, y = gl_GlobalInvocationID.y;
  if (x >= pc.width || y >= pc.height) return;
  uint under = rgba[y * pc.image_width + x];
  bool text = (mask[y * pc.mask_words + x / 32u] & (1u << (x % 32u))) != 0u;
  band[y * pc.width + x] = text ? 0xffffffffu : 0xff000000u | ((under >> 2) & 0x003f3f3fu);
}
