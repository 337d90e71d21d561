// libFuzzer target for the environment-map reader (host/formats/environment_file.cpp): Radiance
// .hdr through stb_image after rtvk's own walk of its scanlines, OpenEXR .exr through OpenEXR, told
// apart by content. Any input may be rejected, but only with usage_error; anything else -- a
// crash, another exception, undefined behaviour, a read past a buffer -- is a bug. Every map
// accepted has its size's texels within the limit, and a sampling table whose CDFs run from 0 to
// 1 without stepping back.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "errors.h"
#include "light_sources.h"
#include "scene_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  rtvk::environment_map e;
  try {
    e.image = rtvk::decode_environment_image(bytes, "fuzz");
  } catch (const rtvk::usage_error&) {
    return 0;
  }
  const rtvk::environment_image& image = *e.image;
  if (image.width <= 0 || image.height <= 0 ||
      image.texels.size() != std::size_t(image.width) * std::size_t(image.height))
    std::abort();
  const std::vector<float> table = rtvk::environment_table_of(e);
  for (std::size_t i = RTVK_ENV_HEADER + 1; i < table.size(); ++i)
    if (!(table[i] >= 0 && table[i] <= 1)) std::abort();
  return 0;
}
