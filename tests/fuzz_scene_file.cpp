// libFuzzer target for the scene-file parser. Any input may be rejected, but only with
// usage_error (a clear message, exit 2 in the CLI); anything else -- a crash, another exception,
// undefined behaviour, a leak -- is a bug. An accepted scene must survive a dump and a re-read
// unchanged.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "errors.h"
#include "scene_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  rtvk::scene parsed;
  try {
    parsed = rtvk::parse_scene_json(text, "fuzz.json");
  } catch (const rtvk::usage_error&) {
    return 0;  // rejected with a message: fine
  }
  const std::string dumped = rtvk::dump_scene_json(parsed);
  if (rtvk::dump_scene_json(rtvk::parse_scene_json(dumped, "dumped.json")) != dumped) std::abort();
  return 0;
}
