#include "render_settings.h"

#include <stdexcept>
#include <string>

namespace rtvk {

void check_window(const render_window& w, int width, int height) {
  auto fail = [&](const std::string& what) {
    throw std::invalid_argument("region " + std::to_string(w.x) + "," + std::to_string(w.y) + "," +
                                std::to_string(w.width) + "," + std::to_string(w.height) + " " +
                                what + " of the " + std::to_string(width) + "x" +
                                std::to_string(height) + " image");
  };
  if (w.width < 1 || w.height < 1) fail("is empty: it needs a width and height >= 1");
  if (w.x < 0 || w.y < 0 || w.x > width - w.width || w.y > height - w.height)
    fail("reaches outside");
  if (w.sample_begin < 0 || w.sample_end <= w.sample_begin || w.sample_end > max_spp)
    throw std::invalid_argument("sample range " + std::to_string(w.sample_begin) + ":" +
                                std::to_string(w.sample_end) + " is empty or outside [0, " +
                                std::to_string(max_spp) + "]");
}

}  // namespace rtvk
