// What overlay.comp (shaders/overlay.comp, compiled into this library) reads, for both
// languages: its bindings, in binding order, and its push constants. The presenter fills them.
#ifndef RTVK_OVERLAY_PUSH_H
#define RTVK_OVERLAY_PUSH_H

#include "glsl_types.h"

// overlay.comp's set 0: the encoded image in, the text's mask in, the composed band out.
#define RTVK_OVERLAY_BYTES 9  // storage buffer: uint[], the image's RGBA8 (tonemap.comp's bytes)
#define RTVK_OVERLAY_MASK 11  // storage buffer: uint[], the text, a bit a pixel (overlay_mask)
#define RTVK_OVERLAY_BAND 12  // storage buffer: uint[], the band's RGBA8, copied over the image

RTVK_GPU_TYPES_BEGIN

// Push constants of overlay.comp (std430): the viewer's overlay, a band at the top left of the
// image darkened, with white text where the mask's bits are set.
struct overlay_push {
  uint width;        // band's columns
  uint height;       // band's rows
  uint image_width;  // columns of the RGBA8 image under it
  uint mask_words;   // 32-bit words of the mask per band row
};
#ifdef __cplusplus
static_assert(offsetof(overlay_push, mask_words) == 12);
static_assert(sizeof(overlay_push) == 16);
#endif

RTVK_GPU_TYPES_END

#endif  // RTVK_OVERLAY_PUSH_H
