#include "colmap_model.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <map>
#include <optional>
#include <string_view>
#include <unordered_map>
#include <unordered_set>

#include "colmap_views.h"
#include "errors.h"
#include "format.h"
#include "image_size.h"
#include "input_file.h"

namespace rtvk {
namespace {

constexpr std::uint64_t max_cameras_bytes = std::uint64_t(16) << 20;
// images.txt holds every image's 2D points too: large models reach hundreds of MiB.
constexpr std::uint64_t max_images_bytes = std::uint64_t(256) << 20;

[[noreturn]] void fail(const std::string& file, int line, const std::string& what) {
  throw usage_error(file + ":" + std::to_string(line) + ": " + what);
}

// Values quoted in messages are cut short: a bad field may be a whole line of binary.
std::string quote(std::string_view s) {
  return "'" + std::string(s.substr(0, 40)) + (s.size() > 40 ? "...'" : "'");
}

bool space(char c) {
  return c == ' ' || c == '\t' || c == '\r';
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && space(s.front())) s.remove_prefix(1);
  while (!s.empty() && space(s.back())) s.remove_suffix(1);
  return s;
}

// The next whitespace-separated field of `rest` (removed from it); empty at the end.
std::string_view next_field(std::string_view& rest) {
  rest = trim(rest);
  std::size_t end = 0;
  while (end < rest.size() && !space(rest[end])) ++end;
  const std::string_view field = rest.substr(0, end);
  rest.remove_prefix(end);
  return field;
}

std::vector<std::string_view> fields(std::string_view line) {
  std::vector<std::string_view> out;
  for (std::string_view f = next_field(line); !f.empty(); f = next_field(line)) out.push_back(f);
  return out;
}

struct text_line {
  std::string_view text;  // without '\n'
  int number;             // 1-based
};

// The lines that are not comments ('#' first); blank lines are kept: in images.txt a blank
// line is an image without 2D points.
std::vector<text_line> data_lines(std::string_view text) {
  std::vector<text_line> out;
  int number = 0;
  for (std::size_t start = 0; start < text.size();) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view line = text.substr(start, end - start);
    ++number;
    start = end + 1;
    if (trim(line).substr(0, 1) != "#") out.push_back({line, number});
  }
  return out;
}

// A field that must be a finite number. from_chars: no locale, no hexadecimal.
double number(std::string_view field, const std::string& file, int line, const std::string& what) {
  double x = 0;
  const std::string_view f = field.substr(0, 1) == "+" ? field.substr(1) : field;
  const auto [end, ec] = std::from_chars(f.data(), f.data() + f.size(), x);
  if (ec != std::errc() || end != f.data() + f.size() || !std::isfinite(x))
    fail(file, line, what + " must be a finite number, got " + quote(field));
  return x;
}

std::uint64_t id(std::string_view field, const std::string& file, int line,
                 const std::string& what) {
  std::uint64_t x = 0;
  const auto [end, ec] = std::from_chars(field.data(), field.data() + field.size(), x);
  if (ec != std::errc() || end != field.data() + field.size())
    fail(file, line, what + " must be a whole number >= 0, got " + quote(field));
  return x;
}

int image_side(std::string_view field, const std::string& file, int line, const char* what) {
  const std::uint64_t x = id(field, file, line, what);
  if (x < 1 || x > std::uint64_t(max_image_side))
    fail(file, line,
         std::string(what) + " must be in [1, " + std::to_string(max_image_side) + "], got " +
             quote(field));
  return int(x);
}

struct colmap_camera {
  rtvk::projection model;  // opencv or opencv_fisheye
  lens_intrinsics lens;    // in rtvk's pixel convention
  int line;                // where cameras.txt defines it
};

// One line of cameras.txt: CAMERA_ID MODEL WIDTH HEIGHT PARAMS[].
std::pair<std::uint64_t, colmap_camera> read_camera(const text_line& l, const std::string& file) {
  const std::vector<std::string_view> f = fields(l.text);
  if (f.size() < 4)
    fail(file, l.number, "expected CAMERA_ID MODEL WIDTH HEIGHT PARAMS[], got " + quote(l.text));
  const std::uint64_t camera_id = id(f[0], file, l.number, "CAMERA_ID");
  const colmap_camera_model* spec = colmap_model_named(f[1]);
  if (!spec)
    fail(file, l.number,
         "camera model " + std::string(f[1].substr(0, 40)) +
             " is not supported; supported: " + colmap_supported_models());
  colmap_camera c{spec->model, {}, l.number};
  c.lens.width = image_side(f[2], file, l.number, "WIDTH");
  c.lens.height = image_side(f[3], file, l.number, "HEIGHT");
  if (int(f.size()) - 4 != spec->count)
    fail(file, l.number,
         "camera model " + std::string(spec->name) + " takes " + std::to_string(spec->count) +
             " parameters (" + std::string(spec->params) + "), got " +
             std::to_string(f.size() - 4));
  for (int i = 0; i < spec->count; ++i) {
    const double x = number(f[4 + i], file, l.number, "parameter " + std::to_string(i + 1));
    if (!put_colmap_param(*spec, i, x, c.lens))
      fail(file, l.number, "focal length must be > 0, got " + quote(f[4 + i]));
  }
  return {camera_id, c};
}

std::map<std::uint64_t, colmap_camera> read_cameras(std::string_view text,
                                                    const std::string& file) {
  std::map<std::uint64_t, colmap_camera> cameras;
  for (const text_line& l : data_lines(text)) {
    if (trim(l.text).empty()) continue;
    const auto [camera_id, c] = read_camera(l, file);
    const auto [it, added] = cameras.emplace(camera_id, c);
    if (!added)
      fail(file, l.number,
           "camera " + std::to_string(camera_id) + " is defined twice (first on line " +
               std::to_string(it->second.line) + ")");
  }
  return cameras;
}

// The second line of an image: X Y POINT3D_ID triples. Checked, so that a missing line (the
// next image's line read in its place) is caught rather than skipping every other image.
void check_points(const text_line& l, std::string_view image_id, const std::string& file) {
  std::string_view rest = l.text;
  std::size_t count = 0;
  for (std::string_view f = next_field(rest); !f.empty(); f = next_field(rest), ++count) {
    double x = 0;
    const auto [end, ec] = std::from_chars(f.data(), f.data() + f.size(), x);
    if (ec != std::errc() || end != f.data() + f.size())
      fail(file, l.number,
           "expected image " + std::string(image_id.substr(0, 20)) +
               "'s 2D points (X Y POINT3D_ID ...; every image has two lines), got " + quote(f));
  }
  if (count % 3 != 0)
    fail(file, l.number,
         "image " + std::string(image_id.substr(0, 20)) +
             "'s 2D points must be X Y POINT3D_ID triples, got " + std::to_string(count) +
             " numbers");
}

}  // namespace

std::vector<colmap_view> parse_colmap_model(const std::string& cameras_txt,
                                            const std::string& images_txt,
                                            const std::string& dir_name) {
  const std::string cameras_file = (std::filesystem::path(dir_name) / "cameras.txt").string();
  const std::string images_file = (std::filesystem::path(dir_name) / "images.txt").string();
  const std::map<std::uint64_t, colmap_camera> cameras = read_cameras(cameras_txt, cameras_file);

  std::vector<text_line> lines = data_lines(images_txt);
  while (!lines.empty() && trim(lines.back().text).empty()) lines.pop_back();  // the file's end
  std::vector<colmap_view> views;
  std::unordered_map<std::uint64_t, int> image_lines;  // image ID -> its line
  colmap_names names;
  // Strictly by pairs: the image's line, then its 2D points (blank when it has none; the last
  // image's may be missing).
  for (std::size_t i = 0; i < lines.size(); i += 2) {
    const text_line& l = lines[i];
    std::string_view rest = l.text;
    std::array<std::string_view, 9> f;
    for (std::string_view& field : f) field = next_field(rest);
    const std::string_view image_name = trim(rest);
    if (image_name.empty())
      fail(images_file, l.number,
           "expected IMAGE_ID QW QX QY QZ TX TY TZ CAMERA_ID NAME, got " + quote(l.text));
    const std::uint64_t image_id = id(f[0], images_file, l.number, "IMAGE_ID");
    const auto [seen, added] = image_lines.emplace(image_id, l.number);
    if (!added)
      fail(images_file, l.number,
           "image " + std::to_string(image_id) + " is given twice (first on line " +
               std::to_string(seen->second) + ")");
    const std::array<double, 4> q = {
        number(f[1], images_file, l.number, "QW"), number(f[2], images_file, l.number, "QX"),
        number(f[3], images_file, l.number, "QY"), number(f[4], images_file, l.number, "QZ")};
    const vec3 t(number(f[5], images_file, l.number, "TX"),
                 number(f[6], images_file, l.number, "TY"),
                 number(f[7], images_file, l.number, "TZ"));
    const std::uint64_t camera_id = id(f[8], images_file, l.number, "CAMERA_ID");
    const auto camera = cameras.find(camera_id);
    if (camera == cameras.end())
      fail(images_file, l.number,
           "camera " + std::to_string(camera_id) + " is not in " + cameras_file);
    if (i + 1 < lines.size()) check_points(lines[i + 1], f[0], images_file);

    colmap_view view;
    view.image_name = std::string(image_name);
    view.name = names.take(image_name);
    view.pose = colmap_pose(q, t, images_file + ":" + std::to_string(l.number));
    view.pose.projection = camera->second.model;
    view.pose.intrinsics = camera->second.lens;
    views.push_back(std::move(view));
  }
  if (views.empty()) throw usage_error(images_file + ": no images");
  return views;
}

std::vector<colmap_view> read_colmap_model(const std::filesystem::path& dir) {
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec))
    throw usage_error(dir.string() +
                      ": is not a folder (a COLMAP model is a folder holding "
                      "cameras.txt and images.txt, or cameras.bin and images.bin)");
  if (!std::filesystem::exists(dir / "cameras.txt", ec) &&
      std::filesystem::exists(dir / "cameras.bin", ec)) {
    const std::string cameras =
        read_regular_file(dir / "cameras.bin", max_cameras_bytes, "COLMAP cameras file");
    const std::string images =
        read_regular_file(dir / "images.bin", max_images_bytes, "COLMAP images file");
    return parse_colmap_binary(cameras, images, dir.string());
  }
  const std::string cameras =
      read_regular_file(dir / "cameras.txt", max_cameras_bytes, "COLMAP cameras file");
  const std::string images =
      read_regular_file(dir / "images.txt", max_images_bytes, "COLMAP images file");
  return parse_colmap_model(cameras, images, dir.string());
}

}  // namespace rtvk
