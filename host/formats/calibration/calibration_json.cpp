// FileStorage's JSON, through nlohmann::json: the top-level values of a calibration file, as
// the YAML reader gives them. Only the top level and one level below are looked at, so nesting
// costs nothing here.
#include <algorithm>
#include <nlohmann/json.hpp>

#include "calibration_text.h"

namespace rtvk::calibration_text {
namespace {

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

}  // namespace

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

}  // namespace rtvk::calibration_text
