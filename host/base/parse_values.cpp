#include "parse_values.h"

#include <charconv>
#include <cmath>
#include <optional>

#include "errors.h"

namespace rtvk {
namespace {

// The whole of `s` as a finite number > 0, or nothing.
std::optional<double> positive_number(std::string_view s) {
  double v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size() || !std::isfinite(v) || v <= 0)
    return std::nullopt;
  return v;
}

std::optional<double> finite_number(std::string_view s) {
  double v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

}  // namespace

vec3 parse_vec3(const std::string& text, const std::string& flag) {
  vec3 v;
  std::string_view rest(text);
  for (int k = 0; k < 3; ++k) {
    const auto comma = rest.find(',');
    const auto part = finite_number(rest.substr(0, comma));
    if (!part || (k < 2) == (comma == std::string_view::npos))
      throw usage_error(flag + ": invalid vector '" + text +
                        "' (expected x,y,z: three finite numbers)");
    v[k] = *part;
    rest = comma == std::string_view::npos ? std::string_view() : rest.substr(comma + 1);
  }
  return v;
}

std::vector<double> parse_numbers(const std::string& text, const std::string& flag,
                                  std::size_t least, std::size_t most, const std::string& what) {
  std::vector<double> out;
  std::string_view rest(text);
  bool more = true;
  while (more) {
    const auto comma = rest.find(',');
    const auto part = finite_number(rest.substr(0, comma));
    if (!part || out.size() == most)
      throw usage_error(flag + ": invalid list '" + text + "' (expected " + what + ")");
    out.push_back(*part);
    more = comma != std::string_view::npos;
    if (more) rest = rest.substr(comma + 1);
  }
  if (out.size() < least)
    throw usage_error(flag + ": invalid list '" + text + "' (expected " + what + ")");
  return out;
}

double parse_aspect(const std::string& text, const std::string& flag) {
  const auto colon = text.find(':');
  std::optional<double> ratio;
  if (colon == std::string::npos) {
    ratio = positive_number(text);
  } else {
    const auto w = positive_number(std::string_view(text).substr(0, colon));
    const auto h = positive_number(std::string_view(text).substr(colon + 1));
    if (w && h) ratio = *w / *h;
  }
  if (!ratio || !std::isfinite(*ratio) || *ratio <= 0)
    throw usage_error(flag + ": invalid aspect ratio '" + text +
                      "' (expected W:H with both > 0, such as 16:9, or a decimal > 0)");
  return *ratio;
}

}  // namespace rtvk
