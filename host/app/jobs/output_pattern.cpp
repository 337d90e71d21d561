#include "output_pattern.h"

#include <algorithm>

#include "errors.h"

namespace rtvk {
namespace {

constexpr const char* expected = "(expected {camera}, {frame} or {frame:0N}, N from 1 to 9)";

}  // namespace

output_pattern::output_pattern(const std::string& text, const std::string& flag) : text_(text) {
  auto fail = [&](const std::string& what) {
    throw usage_error(flag + " '" + text + "': " + what + " " + expected);
  };
  std::string literal;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '}') fail("'}' at character " + std::to_string(i + 1) + " closes no '{'");
    if (text[i] != '{') {
      literal += text[i];
      continue;
    }
    const std::size_t close = text.find_first_of("{}", i + 1);
    if (close == std::string::npos)
      fail("'{' at character " + std::to_string(i + 1) + " is not closed by '}'");
    if (text[close] == '{')
      fail("'{' at character " + std::to_string(close + 1) + " is inside another placeholder");
    const std::string field = text.substr(i + 1, close - i - 1);
    piece p{piece::kind::literal, {}, 0};
    if (field == "camera") {
      p.what = piece::kind::camera;
    } else if (field == "frame") {
      p.what = piece::kind::frame;
    } else if (field.size() == 8 && field.compare(0, 7, "frame:0") == 0 && field[7] >= '1' &&
               field[7] <= '9') {
      p.what = piece::kind::frame;
      p.digits = field[7] - '0';
    } else {
      fail(field.empty() ? std::string("empty placeholder {}")
                         : "unknown placeholder {" + field + "}");
    }
    if (!literal.empty()) pieces_.push_back({piece::kind::literal, std::move(literal), 0});
    literal.clear();
    pieces_.push_back(p);
    i = close;
  }
  if (!literal.empty()) pieces_.push_back({piece::kind::literal, std::move(literal), 0});
}

std::string output_pattern::expand(const std::string& camera_name, int frame) const {
  std::string out;
  for (const piece& p : pieces_) {
    if (p.what == piece::kind::literal) {
      out += p.literal;
    } else if (p.what == piece::kind::camera) {
      out += camera_name;
    } else {
      const std::string n = std::to_string(frame);
      out += std::string(std::size_t(std::max(0, p.digits - int(n.size()))), '0') + n;
    }
  }
  return out;
}

bool output_pattern::has_camera() const {
  return std::any_of(pieces_.begin(), pieces_.end(),
                     [](const piece& p) { return p.what == piece::kind::camera; });
}

bool output_pattern::has_frame() const {
  return std::any_of(pieces_.begin(), pieces_.end(),
                     [](const piece& p) { return p.what == piece::kind::frame; });
}

}  // namespace rtvk
