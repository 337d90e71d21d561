#pragma once
#include "camera.h"
#include "context.h"
#include "framebuffer.h"
#include "scene.h"

namespace rtvk::gpu {

// The lesson's image on the GPU: one compute invocation per pixel, float precision. The result
// comes back widened to the same framebuffer type the CPU renderer fills.
framebuffer render_gpu(gpu_context& ctx, const camera& cam, const scene& s);

}  // namespace rtvk::gpu
