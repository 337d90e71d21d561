#include "calibration_file.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "calibration_text.h"
#include "errors.h"
#include "format.h"
#include "image_size.h"
#include "input_file.h"

namespace rtvk {
namespace {

using namespace calibration_text;

constexpr std::uint64_t max_calibration_bytes = 1 << 20;  // a calibration is a few hundred bytes

// What the values mean, the same for YAML and JSON.
class interpreter {
 public:
  interpreter(const document& doc, const std::string& name) : doc_(doc), name_(name) {}

  // The value under the first of `names` the file has, or null; two of them is ambiguous.
  const value* find(std::initializer_list<const char*> names, std::string& key) const {
    const value* found = nullptr;
    for (const char* n : names) {
      const auto it = doc_.find(n);
      if (it == doc_.end()) continue;
      if (found)
        fail(name_, it->second.line, n, "given together with " + key + "; give one of them");
      found = &it->second;
      key = n;
    }
    return found;
  }

  std::vector<double> numbers(const std::string& key, const value& v) const {
    std::vector<double> out;
    for (const scalar& s : v.items) out.push_back(number(key, v, s));
    return out;
  }

  double number(const std::string& key, const value& v, const scalar& s) const {
    const std::optional<double> x = to_number(s);
    if (!x || !std::isfinite(*x))
      fail(name_, v.line, key, "expected a finite number, got " + quote(s.text));
    return *x;
  }

  int side(const std::string& key, const value& v, const scalar& s) const {
    const double x = number(key, v, s);
    if (x != std::floor(x) || x < 1 || x > max_image_side)
      fail(name_, v.line, key,
           "image size must be a whole number in [1, " + std::to_string(max_image_side) +
               "], got " + quote(s.text));
    return int(x);
  }

  const scalar& single(const std::string& key, const value& v, const char* what) const {
    if (v.kind != value_kind::scalar) fail(name_, v.line, key, std::string("expected ") + what);
    return v.single;
  }

  void camera_matrix(lens_intrinsics& lens) const {
    std::string key;
    const value* v = find({"camera_matrix", "K", "cameraMatrix"}, key);
    if (!v) fail(name_, 0, "", "no camera matrix (camera_matrix, K or cameraMatrix)");
    const bool square = (v->kind == value_kind::matrix && v->rows == 3 && v->cols == 3) ||
                        (v->kind == value_kind::sequence && v->items.size() == 9);
    if (!square)
      fail(name_, v->line, key,
           "the camera matrix must be 3x3, got " +
               (v->kind == value_kind::matrix
                    ? std::to_string(v->rows) + "x" + std::to_string(v->cols)
                : v->kind == value_kind::sequence ? std::to_string(v->items.size()) + " numbers"
                : v->kind == value_kind::scalar   ? quote(v->single.text)
                                                  : v->what));
    const std::vector<double> m = numbers(key, *v);
    if (m[1] != 0)
      fail(name_, v->line, key,
           "a skewed camera matrix (K[0][1] = " + format_number(m[1]) + ") is not supported");
    if (m[3] != 0 || m[6] != 0 || m[7] != 0 || m[8] != 1)
      fail(name_, v->line, key,
           "the camera matrix must be fx 0 cx / 0 fy cy / 0 0 1, got rows 2 and 3 " +
               format_number(m[3]) + " " + format_number(m[4]) + " " + format_number(m[5]) + " / " +
               format_number(m[6]) + " " + format_number(m[7]) + " " + format_number(m[8]));
    if (!(m[0] > 0) || !(m[4] > 0))
      fail(name_, v->line, key,
           "focal lengths must be > 0, got fx " + format_number(m[0]) + ", fy " +
               format_number(m[4]));
    lens.fx = m[0];
    lens.cx = m[2];
    lens.fy = m[4];
    lens.cy = m[5];
  }

  void image_size(lens_intrinsics& lens) const {
    std::string wkey, hkey, skey;
    const value* w = find({"image_width"}, wkey);
    const value* h = find({"image_height"}, hkey);
    const value* s = find({"image_size", "imageSize"}, skey);
    if (w && h) {
      lens.width = side(wkey, *w, single(wkey, *w, "a number"));
      lens.height = side(hkey, *h, single(hkey, *h, "a number"));
    } else if (w || h) {
      fail(name_, (w ? w : h)->line, w ? wkey : hkey, "image_width and image_height go together");
    }
    if (!s) {
      if (!w) fail(name_, 0, "", "no image size (image_width and image_height, or image_size)");
      return;
    }
    const bool pair =
        (s->kind == value_kind::sequence && s->items.size() == 2) ||
        (s->kind == value_kind::matrix && s->items.size() == 2 && (s->rows == 1 || s->cols == 1));
    if (!pair) fail(name_, s->line, skey, "expected [width, height]");
    const int width = side(skey, *s, s->items[0]), height = side(skey, *s, s->items[1]);
    if (w && (width != lens.width || height != lens.height))
      fail(name_, s->line, skey,
           std::to_string(width) + "x" + std::to_string(height) +
               " differs from image_width and image_height (" + std::to_string(lens.width) + "x" +
               std::to_string(lens.height) + ")");
    lens.width = width;
    lens.height = height;
  }

  // The model the file names, if it names one (see the header's rule).
  std::optional<projection> named_model() const {
    std::optional<projection> model;
    std::string first;
    for (const char* key : {"model", "distortion_model"}) {
      const auto it = doc_.find(key);
      if (it == doc_.end()) continue;
      const std::string text = lower(single(key, it->second, "a string").text);
      std::optional<projection> m;
      for (const char* n : {"fisheye", "opencv-fisheye", "equidistant", "kannala-brandt"})
        if (text == n) m = projection::opencv_fisheye;
      for (const char* n : {"pinhole", "opencv", "plumb_bob", "rational_polynomial", "radtan"})
        if (text == n) m = projection::opencv;
      if (!m)
        fail(name_, it->second.line, key,
             "unknown model " + quote(it->second.single.text) +
                 "; known: fisheye, opencv-fisheye, equidistant, kannala-brandt (opencv-fisheye), "
                 "pinhole, opencv, plumb_bob, rational_polynomial, radtan (opencv)");
      if (model && *model != *m) fail(name_, it->second.line, key, "contradicts " + first);
      model = m;
      first = key;
    }
    return model;
  }

  projection model() const {
    const std::optional<projection> named = named_model();
    const auto it = doc_.find("fisheye");
    if (it == doc_.end()) return named.value_or(projection::opencv);
    const std::string flag = lower(single("fisheye", it->second, "1, 0, true or false").text);
    const bool on = flag == "1" || flag == "true";
    if (!on && flag != "0" && flag != "false")
      fail(name_, it->second.line, "fisheye",
           "expected 1, 0, true or false, got " + quote(it->second.single.text));
    const projection flagged = on ? projection::opencv_fisheye : projection::opencv;
    if (named && *named != flagged)
      fail(name_, it->second.line, "fisheye", "contradicts the model the file names");
    return flagged;
  }

  void distortion(projection model, lens_intrinsics& lens) const {
    std::string key;
    const value* v = find({"distortion_coefficients", "dist_coeffs", "D", "distCoeffs"}, key);
    if (!v) return;  // no distortion
    const bool vector = v->kind == value_kind::sequence ||
                        (v->kind == value_kind::matrix && (v->rows == 1 || v->cols == 1)) ||
                        (v->kind == value_kind::matrix && v->items.empty());
    if (!vector)
      fail(name_, v->line, key,
           "expected a 1xN or Nx1 matrix or a sequence" +
               (v->kind == value_kind::matrix
                    ? ", got " + std::to_string(v->rows) + "x" + std::to_string(v->cols)
                    : std::string()));
    const std::vector<double> k = numbers(key, *v);
    const std::size_t n = k.size();
    if (model == projection::opencv_fisheye && n != 4)
      fail(name_, v->line, key,
           "opencv-fisheye takes exactly 4 coefficients (k1 k2 k3 k4), got " + std::to_string(n));
    if (n == 12 || n == 14)
      fail(name_, v->line, key,
           std::to_string(n) +
               " coefficients (thin prism / tilted sensor) are not supported; opencv takes 4, "
               "5 or 8");
    if (n != 0 && n != 4 && n != 5 && n != 8)
      fail(name_, v->line, key,
           "opencv takes 4, 5 or 8 coefficients (k1 k2 p1 p2 [k3 [k4 k5 k6]]), got " +
               std::to_string(n));
    std::copy(k.begin(), k.end(), lens.k.begin());
  }

 private:
  const document& doc_;      // the file's top-level values
  const std::string& name_;  // the file's, for messages
};

bool looks_like_json(std::string_view text) {
  const std::size_t first = text.find_first_not_of(" \t\r\n");
  return first != std::string_view::npos && text[first] == '{';
}

}  // namespace

calibration parse_opencv_calibration(const std::string& text, const std::string& name) {
  std::string_view t = text;
  if (t.substr(0, 3) == "\xEF\xBB\xBF") t.remove_prefix(3);  // a UTF-8 byte order mark
  const document doc = looks_like_json(t) ? read_json(t, name) : read_yaml(t, name);
  const interpreter in(doc, name);
  calibration c;
  in.camera_matrix(c.lens);
  in.image_size(c.lens);
  c.model = in.model();
  in.distortion(c.model, c.lens);
  return c;
}

calibration read_opencv_calibration(const std::filesystem::path& file) {
  return parse_opencv_calibration(
      read_regular_file(file, max_calibration_bytes, "calibration file"), file.string());
}

}  // namespace rtvk
