#pragma once
#include <string>
#include <vector>

namespace rtvk {

// An output path with placeholders, as `-o` takes it: `{camera}` (the camera's name), `{frame}`
// (the frame number) and `{frame:0N}` (zero-padded to N digits, N from 1 to 9). Parsed once, up
// front, so that a malformed pattern is refused before any work and expanding cannot fail.
class output_pattern {
 public:
  // Throws usage_error naming `flag`, the pattern and what is wrong with it: an unclosed `{`, a
  // stray `}`, an empty `{}`, a `{` inside a placeholder, or an unknown placeholder.
  output_pattern(const std::string& text, const std::string& flag);

  std::string expand(const std::string& camera_name, int frame) const;

  bool has_camera() const;  // holds {camera}
  bool has_frame() const;   // holds {frame} or {frame:0N}
  const std::string& text() const { return text_; }

 private:
  struct piece {
    enum class kind { literal, camera, frame } what;  // what this piece turns into
    std::string literal;                              // kind::literal: the text itself
    int digits = 0;                                   // kind::frame: zero-padded width, or 0
  };
  std::string text_;           // the pattern as given
  std::vector<piece> pieces_;  // literal text and placeholders, in order
};

}  // namespace rtvk
