#include "aov_image.h"

#include <array>
#include <sstream>

namespace rtvk {
namespace {

constexpr std::array<const char*, 5> names = {"depth", "normal", "albedo", "object-id",
                                              "material-id"};

}  // namespace

std::string aov_names() {
  std::string out;
  for (const char* n : names) out += (out.empty() ? "" : ",") + std::string(n);
  return out;
}

std::string aov_name(aov_bit b) {
  for (std::size_t k = 0; k < names.size(); ++k)
    if (unsigned(b) == 1u << k) return names[k];
  return "aov";
}

std::optional<unsigned> parse_aov_list(const std::string& text) {
  unsigned bits = 0;
  std::stringstream in(text);
  std::string item;
  int items = 0;
  while (std::getline(in, item, ',')) {
    ++items;
    unsigned bit = 0;
    for (std::size_t k = 0; k < names.size(); ++k)
      if (item == names[k]) bit = 1u << k;
    if (bit == 0) return std::nullopt;
    bits |= bit;
  }
  if (items == 0 || text.back() == ',') return std::nullopt;
  return bits;
}

}  // namespace rtvk
