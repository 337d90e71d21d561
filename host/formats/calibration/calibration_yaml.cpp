// FileStorage's YAML subset, line by line (calibration_file.h says which): the top-level values
// of a calibration file. Every loop moves forward through the lines, so the reader is linear in
// the text whatever it holds.
#include <algorithm>
#include <cmath>

#include "calibration_text.h"

namespace rtvk::calibration_text {
namespace {

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
    calibration_text::fail(name_, line, "", what);
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

}  // namespace

document read_yaml(std::string_view text, const std::string& name) {
  return yaml_reader(text, name).read();
}

}  // namespace rtvk::calibration_text
