// The calibration reader's shared pieces: messages, and scalars as numbers.
#include <cctype>
#include <charconv>
#include <cstdio>
#include <limits>

#include "calibration_text.h"
#include "errors.h"

namespace rtvk::calibration_text {

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

}  // namespace rtvk::calibration_text
