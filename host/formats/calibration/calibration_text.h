#pragma once
// Internal to formats/: a calibration file as read, before anything is made of it -- the
// top-level values of FileStorage's YAML or JSON alike (calibration_yaml.cpp,
// calibration_json.cpp), which calibration_file.cpp's interpreter reads the meaning of.
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rtvk::calibration_text {

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
                       const std::string& what);

std::string lower(std::string_view s);
std::string_view trim(std::string_view s);
// Values quoted in messages are cut short: a bad value may be a whole line of binary.
std::string quote(std::string_view s);
// A number as FileStorage writes it: decimal (1.e+03, 0., -2.8e-01) or YAML's .Nan, .Inf and
// -.Inf; none for anything else (a quoted string is never a number).
std::optional<double> to_number(const scalar& s);
// Refuses a matrix whose rows x cols is not its count of data.
void check_matrix_size(const std::string& name, const value& v, const std::string& key);
// A double exactly, so that read back it is the same double.
std::string number_text(double x);

// The top-level values of the YAML subset and of the JSON FileStorage writes; `name` is the
// file's, for messages. Throw usage_error.
document read_yaml(std::string_view text, const std::string& name);
document read_json(std::string_view text, const std::string& name);

}  // namespace rtvk::calibration_text
