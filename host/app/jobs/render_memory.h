#pragma once
#include <cstddef>
#include <cstdint>

namespace rtvk {

// Host memory a render of width x height needs: the double framebuffer (24 bytes a pixel), the
// 8-bit image (3) and its encoded copy (up to 12 for P3's text, "255 255 255\n"; a PNG's
// filtered rows and deflate stream take about 6), times `renders`, plus the GPU's readback band.
std::uint64_t render_memory_bytes(int width, int height, int renders);

// Refuses, before any work, a render that cannot fit: throws usage_error naming the size and the
// memory it needs and the memory available.
void check_render_memory(int width, int height, int renders);

// Views a GPU run draws together: as many as the shader's camera array holds, within a quarter
// GiB of host framebuffers (24 bytes a pixel).
std::size_t gpu_group_size(int width, int height);

}  // namespace rtvk
