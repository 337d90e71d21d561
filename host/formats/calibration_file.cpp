#include "calibration_file.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string_view>
#include <vector>

#include "errors.h"
#include "format.h"
#include "image_size.h"
#include "input_file.h"

namespace rtvk {
namespace {

constexpr std::uint64_t max_calibration_bytes = 1 << 20;  // a calibration is a few hundred bytes

// A scalar as written. It becomes a number only where a number is wanted, so an ignored key may
// hold any string.
struct scalar {
  std::string text;     // unquoted
  bool quoted = false;  // a quoted string is never a number
};

enum class value_kind { scalar, sequence, matrix, other };

// A top-level value, from YAML or JSON alike.
struct value {
  value_kind kind = value_kind::other;
  int line = 0;               // the key's line, 1-based; 0: not known (JSON)
  scalar single;              // scalar: the value
  std::vector<scalar> items;  // sequence: the items; matrix: the data, row by row
  int rows = 0;               // matrix: rows
  int cols = 0;               // matrix: columns
  std::string what;           // other: what it is, for messages ("an object")
};

using document = std::map<std::string, value>;

// "NAME:LINE: key: what", the line and key left out where not known.
[[noreturn]] void fail(const std::string& name, int line, const std::string& key,
                       const std::string& what) {
  std::string message = name + (line > 0 ? ":" + std::to_string(line) : "") + ": ";
  if (!key.empty()) message += key + ": ";
  throw usage_error(message + what);
}

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = char(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

std::string_view trim(std::string_view s) {
  const auto space = [](char c) { return c == ' ' || c == '\t' || c == '\r'; };
  while (!s.empty() && space(s.front())) s.remove_prefix(1);
  while (!s.empty() && space(s.back())) s.remove_suffix(1);
  return s;
}

// Values quoted in messages are cut short: a bad value may be a whole line of binary.
std::string quote(std::string_view s) {
  return "'" + std::string(s.substr(0, 40)) + (s.size() > 40 ? "...'" : "'");
}

// A number as FileStorage writes it: decimal (1.e+03, 0., -2.8e-01) or YAML's .Nan, .Inf and
// -.Inf. from_chars, not strtod: no locale, no hexadecimal.
std::optional<double> to_number(const scalar& s) {
  if (s.quoted) return std::nullopt;
  std::string_view t = s.text;
  const std::string l = lower(t);
  if (l == ".nan") return std::numeric_limits<double>::quiet_NaN();
  if (l == ".inf" || l == "+.inf") return std::numeric_limits<double>::infinity();
  if (l == "-.inf") return -std::numeric_limits<double>::infinity();
  if (t.size() > 1 && t[0] == '+' && t[1] != '-' && t[1] != '+') t.remove_prefix(1);
  double x = 0;
  const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), x);
  if (ec != std::errc() || end != t.data() + t.size()) return std::nullopt;
  return x;
}

void check_matrix_size(const std::string& name, const value& v, const std::string& key) {
  if (std::int64_t(v.rows) * v.cols != std::int64_t(v.items.size()))
    fail(name, v.line, key,
         "rows x cols = " + std::to_string(v.rows) + " x " + std::to_string(v.cols) +
             " does not match the " + std::to_string(v.items.size()) + " numbers of data");
}

std::string number_text(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", x);  // exact: read back, the same double
  return buf;
}

// ---------------------------------------------------------------------------------------------
// YAML: FileStorage's subset, line by line (see the header). Every loop moves forward through
// the lines, so the reader is linear in the text whatever it holds.

class yaml_reader {
 public:
  yaml_reader(std::string_view text, const std::string& name) : name_(name) {
    std::size_t start = 0;
    while (start <= text.size()) {
      std::size_t end = text.find('\n', start);
      if (end == std::string_view::npos) end = text.size();
      lines_.push_back(text.substr(start, end - start));
      start = end + 1;
    }
  }

  document read() {
    document doc;
    bool started = false;  // a key or "---" seen: no more directives
    bool document_start = false;
    for (at_ = 0; at_ < lines_.size();) {
      const int number = int(at_) + 1;
      const std::string_view content = content_of(at_);
      ++at_;
      if (trim(content).empty()) continue;
      if (content[0] == '%') {
        if (started || !is_yaml_directive(content))
          fail(number, "only a %YAML directive is read, before anything else");
        continue;
      }
      if (trim(content) == "---") {
        if (document_start || !doc.empty()) fail(number, "only one YAML document is read");
        started = document_start = true;
        continue;
      }
      started = true;
      if (content[0] == ' ' || content[0] == '\t')
        fail(number, "unexpected indented line (only a matrix's rows, cols, dt and data are)");
      const auto [key, rest] = split_key(content, number);
      if (doc.count(key)) fail(number, key + " is given twice");
      doc[key] = read_value(key, rest, number);
    }
    return doc;
  }

 private:
  [[noreturn]] void fail(int line, const std::string& what) const {
    rtvk::fail(name_, line, "", what);
  }

  // Line i without its comment: a '#' at the start or after a space, outside quotes.
  std::string_view content_of(std::size_t i) const {
    const std::string_view s = lines_[i];
    char in_quote = 0;
    for (std::size_t j = 0; j < s.size(); ++j) {
      const char c = s[j];
      if (in_quote) {
        if (c == '\\' && in_quote == '"')
          ++j;  // an escaped character never ends the string
        else if (c == in_quote)
          in_quote = 0;
      } else if (c == '"' || c == '\'') {
        in_quote = c;
      } else if (c == '#' && (j == 0 || s[j - 1] == ' ' || s[j - 1] == '\t')) {
        return s.substr(0, j);
      }
    }
    if (!s.empty() && s.back() == '\r') return s.substr(0, s.size() - 1);
    return s;
  }

  static bool is_yaml_directive(std::string_view line) {
    line = trim(line);
    return line.size() >= 8 && (line.substr(0, 6) == "%YAML:" || line.substr(0, 6) == "%YAML ") &&
           trim(line.substr(6)).substr(0, 2) == "1.";
  }

  static bool key_char(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.';
  }

  // "key: rest" -> {key, rest trimmed}.
  std::pair<std::string, std::string_view> split_key(std::string_view content, int number) const {
    const std::string_view body = trim(content);
    const std::size_t colon = body.find(':');
    const bool ok = colon != std::string_view::npos && colon > 0 &&
                    std::all_of(body.begin(), body.begin() + colon, key_char) &&
                    (colon + 1 == body.size() || body[colon + 1] == ' ' || body[colon + 1] == '\t');
    if (!ok) fail(number, "expected `key: value`, got " + quote(body));
    return {std::string(body.substr(0, colon)), trim(body.substr(colon + 1))};
  }

  value read_value(const std::string& key, std::string_view rest, int number) {
    value v;
    v.line = number;
    if (rest.empty() || rest == "!!opencv-matrix") {
      read_block(key, rest.empty(), v);
      return v;
    }
    const char c = rest[0];
    if (c == '!')
      fail(number, key + ": tag " + quote(rest) + " is not read (only !!opencv-matrix)");
    if (c == '[') {
      v.kind = value_kind::sequence;
      v.items = read_flow(key, rest.substr(1), number);
      return v;
    }
    v.kind = value_kind::scalar;
    v.single = read_scalar(key, rest, number);
    return v;
  }

  // A whole scalar after "key:": quoted, or plain up to the comment.
  scalar read_scalar(const std::string& key, std::string_view rest, int number) const {
    const char c = rest[0];
    if (c == '"' || c == '\'') {
      std::size_t end = 0;
      scalar s = read_quoted(key, rest, end, number);
      if (!trim(rest.substr(end)).empty())
        fail(number, key + ": unexpected " + quote(trim(rest.substr(end))) + " after the string");
      return s;
    }
    // Flow mappings, anchors, aliases, block scalars and block sequences are not FileStorage's.
    if (std::string_view("{}]&*|>@`?%,").find(c) != std::string_view::npos ||
        (c == '-' && (rest.size() == 1 || rest[1] == ' ')))
      fail(number, key + ": " + quote(rest) + " is not read (not OpenCV's YAML)");
    return {std::string(rest), false};
  }

  // A quoted string at the start of s; `end` is set just past its closing quote.
  scalar read_quoted(const std::string& key, std::string_view s, std::size_t& end,
                     int number) const {
    const char q = s[0];
    scalar out{"", true};
    for (std::size_t i = 1; i < s.size(); ++i) {
      const char c = s[i];
      if (q == '\'' && c == '\'' && i + 1 < s.size() && s[i + 1] == '\'') {
        out.text += '\'';  // '' is a quote inside a single-quoted string
        ++i;
      } else if (c == q) {
        end = i + 1;
        return out;
      } else if (q == '"' && c == '\\' && i + 1 < s.size()) {
        const char e = s[++i];
        if (e == 'n')
          out.text += '\n';
        else if (e == 't')
          out.text += '\t';
        else if (e == '"' || e == '\\' || e == '/')
          out.text += e;
        else
          fail(number, key + ": escape \\" + std::string(1, e) + " is not read");
      } else {
        out.text += c;
      }
    }
    fail(number, key + ": unterminated string " + quote(s));
  }

  // The items of a flow sequence, from just after its '['; it may go on over the next lines
  // (at_ is moved past them). Nested sequences and mappings are refused.
  std::vector<scalar> read_flow(const std::string& key, std::string_view rest, int number) {
    std::vector<scalar> items;
    std::string item;          // the plain item being read
    bool item_quoted = false;  // it was a quoted string
    bool after_quote = false;  // its closing quote was read: only ',' or ']' may follow
    bool any = false;          // something was read (so "[]" is empty, "[ , ]" is not)
    auto finish = [&](int line) {
      const std::string_view t = trim(item);
      if (t.empty() && !item_quoted) fail(line, key + ": empty item in the sequence");
      items.push_back({std::string(item_quoted ? std::string_view(item) : t), item_quoted});
      item.clear();
      item_quoted = after_quote = false;
    };
    for (int line = number;;) {
      for (std::size_t i = 0; i < rest.size(); ++i) {
        const char c = rest[i];
        if (c == ']' || c == ',') {
          if (c == ']' && !any && trim(item).empty()) return items;
          finish(line);
          if (c == ']') {
            if (!trim(rest.substr(i + 1)).empty())
              fail(line, key + ": unexpected " + quote(trim(rest.substr(i + 1))) + " after ]");
            return items;
          }
          any = true;
        } else if (c == ' ' || c == '\t' || c == '\r') {
          if (!after_quote) item += c;  // trimmed when the item ends
        } else if (after_quote) {
          fail(line, key + ": unexpected " + quote(rest.substr(i)) + " after a string");
        } else if ((c == '"' || c == '\'') && trim(item).empty()) {
          std::size_t end = 0;
          item = read_quoted(key, rest.substr(i), end, line).text;
          item_quoted = after_quote = any = true;
          i += end - 1;
        } else if (c == '[' || c == '{') {
          fail(line, key + ": nested sequences and mappings are not read");
        } else {
          item += c;
          any = true;
        }
      }
      if (at_ >= lines_.size()) fail(number, key + ": the sequence's [ is never closed");
      line = int(at_) + 1;
      rest = content_of(at_++);
      if (!after_quote) item += ' ';  // a line break separates like a space
    }
  }

  // The indented lines after "key:" or "key: !!opencv-matrix": rows, cols, dt and data.
  void read_block(const std::string& key, bool untagged, value& v) {
    scalar rows, cols;
    bool has_rows = false, has_cols = false, has_dt = false, has_data = false;
    std::size_t indent = 0;  // of the block's first line; the others must match it
    while (at_ < lines_.size()) {
      const std::string_view content = content_of(at_);
      const int number = int(at_) + 1;
      if (trim(content).empty()) {
        ++at_;
        continue;
      }
      const std::size_t spaces = content.find_first_not_of(' ');
      if (spaces == 0) break;  // the next top-level key
      if (content[spaces] == '\t') fail(number, "tabs are not allowed in YAML's indentation");
      if (indent == 0) indent = spaces;
      if (spaces != indent) fail(number, key + ": inconsistent indentation");
      ++at_;
      const auto [sub, rest] = split_key(content, number);
      bool* seen = sub == "rows"   ? &has_rows
                   : sub == "cols" ? &has_cols
                   : sub == "dt"   ? &has_dt
                   : sub == "data" ? &has_data
                                   : nullptr;
      if (!seen)
        fail(number, key + ": " + sub + " is not read (a matrix has rows, cols, dt, data)");
      if (*seen) fail(number, key + ": " + sub + " is given twice");
      *seen = true;
      if (sub == "data") {
        if (rest.empty() || rest[0] != '[') fail(number, key + ": data must be a [ ... ] sequence");
        v.items = read_flow(key, rest.substr(1), number);
      } else if (rest.empty()) {
        fail(number, key + ": " + sub + " has no value");
      } else {
        const scalar s = read_scalar(key, rest, number);
        if (sub == "rows") rows = s;
        if (sub == "cols") cols = s;
      }
    }
    if (untagged && !has_rows && !has_cols && !has_dt && !has_data) {
      v.kind = value_kind::scalar;  // "key:" and nothing: YAML's null
      return;
    }
    if (!has_rows || !has_cols || !has_data)
      fail(v.line, key + ": a matrix needs rows, cols and data");
    v.kind = value_kind::matrix;
    v.rows = matrix_side(key, rows, v.line);
    v.cols = matrix_side(key, cols, v.line);
    check_matrix_size(name_, v, key);
  }

  int matrix_side(const std::string& key, const scalar& s, int line) const {
    const std::optional<double> x = to_number(s);
    if (!x || !(*x >= 0 && *x <= 1 << 20) || *x != std::floor(*x))
      fail(line,
           key + ": a matrix's rows and cols must be whole numbers >= 0, got " + quote(s.text));
    return int(*x);
  }

  const std::string& name_;              // the file's, for messages
  std::vector<std::string_view> lines_;  // the text's lines, without their '\n'
  std::size_t at_ = 0;                   // the next line to read
};

// ---------------------------------------------------------------------------------------------
// JSON: FileStorage's, through nlohmann::json. Only the top level and one level below are
// looked at, so nesting costs nothing here.

using json = nlohmann::json;

scalar json_scalar(const json& j) {
  if (j.is_string()) return {j.get<std::string>(), true};
  if (j.is_number_integer()) return {std::to_string(j.get<std::int64_t>()), false};
  if (j.is_number_unsigned()) return {std::to_string(j.get<std::uint64_t>()), false};
  if (j.is_number()) return {number_text(j.get<double>()), false};
  return {j.dump(), false};  // true, false, null
}

bool json_primitive(const json& j) {
  return !j.is_array() && !j.is_object();
}

bool all_primitive(const json& array) {
  return std::all_of(array.begin(), array.end(), json_primitive);
}

value json_value(const std::string& name, const std::string& key, const json& j) {
  value v;
  if (json_primitive(j)) {
    v.kind = value_kind::scalar;
    v.single = json_scalar(j);
  } else if (j.is_array() && all_primitive(j)) {
    v.kind = value_kind::sequence;
    for (const json& item : j) v.items.push_back(json_scalar(item));
  } else if (j.is_array() && !j.empty() && j[0].is_array() && !j[0].empty() &&
             std::all_of(j.begin(), j.end(), [&](const json& row) {
               return row.is_array() && row.size() == j[0].size() && all_primitive(row);
             })) {
    // [[fx, 0, cx], [0, fy, cy], [0, 0, 1]]: a matrix row by row.
    v.kind = value_kind::matrix;
    v.rows = int(std::min<std::size_t>(j.size(), 1 << 20));
    v.cols = int(std::min<std::size_t>(j[0].size(), 1 << 20));
    for (const json& row : j)
      for (const json& item : row) v.items.push_back(json_scalar(item));
  } else if (j.is_object() && j.contains("type_id") && j["type_id"] == "opencv-matrix") {
    v.kind = value_kind::matrix;
    for (const char* side : {"rows", "cols"}) {
      const auto it = j.find(side);
      if (it == j.end() || !it->is_number_integer() || *it < 0 || *it > 1 << 20)
        fail(name, 0, key, std::string("a matrix's ") + side + " must be a whole number >= 0");
      (side[0] == 'r' ? v.rows : v.cols) = it->get<int>();
    }
    const auto data = j.find("data");
    if (data == j.end() || !data->is_array() || !all_primitive(*data))
      fail(name, 0, key, "a matrix's data must be an array of numbers");
    for (const json& item : *data) v.items.push_back(json_scalar(item));
    check_matrix_size(name, v, key);
  } else {
    v.what = j.is_array() ? "an array of arrays or objects" : "an object";
  }
  return v;
}

document read_json(std::string_view text, const std::string& name) {
  json j;
  try {
    j = json::parse(text);
  } catch (const json::exception& e) {
    fail(name, 0, "", e.what());
  }
  if (!j.is_object()) fail(name, 0, "", "the top level must be a JSON object");
  document doc;
  for (const auto& [key, item] : j.items()) doc[key] = json_value(name, key, item);
  return doc;
}

// ---------------------------------------------------------------------------------------------
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
  const document doc = looks_like_json(t) ? read_json(t, name) : yaml_reader(t, name).read();
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
