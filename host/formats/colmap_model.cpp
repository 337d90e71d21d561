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

#include "errors.h"
#include "format.h"
#include "image_size.h"
#include "input_file.h"

namespace rtvk {
namespace {

constexpr std::uint64_t max_cameras_bytes = std::uint64_t(16) << 20;
// images.txt holds every image's 2D points too: large models reach hundreds of MiB.
constexpr std::uint64_t max_images_bytes = std::uint64_t(256) << 20;

// Where a parameter of a COLMAP camera model goes in lens_intrinsics: a slot below 0 is a focal
// length or the principal point, 0 and up the index in k (OpenCV's order).
enum param_slot : int { focal = -1, focal_x = -2, focal_y = -3, center_x = -4, center_y = -5 };

struct camera_model {
  std::string_view name;     // as cameras.txt writes it
  rtvk::projection model;    // what rtvk renders it with
  std::string_view params;   // the parameters' names, for messages
  std::array<int, 12> slot;  // where each parameter goes
  int count;                 // how many parameters
};

// COLMAP's SIMPLE_RADIAL and RADIAL are OpenCV's k1 (and k2) with p1 = p2 = 0; OPENCV and
// FULL_OPENCV are OpenCV's k1 k2 p1 p2 [k3 k4 k5 k6]; OPENCV_FISHEYE is OpenCV's fisheye.
constexpr camera_model camera_models[] = {
    {"SIMPLE_PINHOLE", projection::opencv, "f cx cy", {focal, center_x, center_y}, 3},
    {"PINHOLE", projection::opencv, "fx fy cx cy", {focal_x, focal_y, center_x, center_y}, 4},
    {"SIMPLE_RADIAL", projection::opencv, "f cx cy k", {focal, center_x, center_y, 0}, 4},
    {"RADIAL", projection::opencv, "f cx cy k1 k2", {focal, center_x, center_y, 0, 1}, 5},
    {"OPENCV",
     projection::opencv,
     "fx fy cx cy k1 k2 p1 p2",
     {focal_x, focal_y, center_x, center_y, 0, 1, 2, 3},
     8},
    {"FULL_OPENCV",
     projection::opencv,
     "fx fy cx cy k1 k2 p1 p2 k3 k4 k5 k6",
     {focal_x, focal_y, center_x, center_y, 0, 1, 2, 3, 4, 5, 6, 7},
     12},
    {"OPENCV_FISHEYE",
     projection::opencv_fisheye,
     "fx fy cx cy k1 k2 k3 k4",
     {focal_x, focal_y, center_x, center_y, 0, 1, 2, 3},
     8},
};

std::string supported_models() {
  std::string out;
  for (const camera_model& m : camera_models)
    out += (out.empty() ? "" : ", ") + std::string(m.name);
  return out;
}

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
  const auto spec = std::find_if(std::begin(camera_models), std::end(camera_models),
                                 [&](const camera_model& m) { return m.name == f[1]; });
  if (spec == std::end(camera_models))
    fail(file, l.number,
         "camera model " + std::string(f[1].substr(0, 40)) +
             " is not supported; supported: " + supported_models());
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
    const int s = spec->slot[i];
    if ((s == focal || s == focal_x || s == focal_y) && !(x > 0))
      fail(file, l.number, "focal length must be > 0, got " + quote(f[4 + i]));
    if (s == focal || s == focal_x) c.lens.fx = x;
    if (s == focal || s == focal_y) c.lens.fy = x;
    // COLMAP's (0, 0) is the image's top-left corner, rtvk's (and OpenCV's) the center of the
    // first pixel, half a pixel right of and below that corner.
    if (s == center_x) c.lens.cx = x - 0.5;
    if (s == center_y) c.lens.cy = x - 0.5;
    if (s >= 0) c.lens.k[std::size_t(s)] = x;
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

// The pose of a camera that maps world points p to R p + t (R from the unit quaternion q, as
// COLMAP's world-to-camera pose): its center is -R^T t and its axes in the world are R's rows,
// x right, y down, z forward (OpenCV's frame). rtvk's camera then gets u = x, v = -y, w = -z.
camera_pose pose_of(std::array<double, 4> q, const vec3& t, const std::string& file, int line) {
  // Scaled before it is squared, so that neither tiny nor huge numbers lose the rotation.
  const double largest = std::max({std::abs(q[0]), std::abs(q[1]), std::abs(q[2]), std::abs(q[3])});
  if (largest == 0) fail(file, line, "the rotation quaternion is zero");
  for (double& c : q) c /= largest;
  const double norm = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  const double w = q[0] / norm, x = q[1] / norm, y = q[2] / norm, z = q[3] / norm;
  const vec3 row_x(1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y));
  const vec3 row_y(2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x));
  const vec3 row_z(2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y));
  // -R^T t: the rows weighted by t's components.
  const point3 center = -(t.x * row_x + t.y * row_y + t.z * row_z);
  if (!std::isfinite(center.x) || !std::isfinite(center.y) || !std::isfinite(center.z))
    fail(file, line, "the camera's center -R^T t is not finite");
  camera_pose pose;
  pose.lookfrom = center;
  pose.lookat = center + row_z;
  pose.vup = -row_y;
  // So far from the origin that a unit step is rounded away, the view direction would be lost.
  if (glm::length((pose.lookat - pose.lookfrom) - row_z) > 1e-6)
    fail(file, line, "the camera's center is too far from the origin to keep its direction");
  return pose;
}

// "cam0/IMG 1.jpg" -> "cam0_IMG_1" (see the header), before it is made unique.
std::string base_name(std::string_view image_name) {
  const std::size_t folder = image_name.find_last_of("/\\");
  const std::size_t file_start = folder == std::string_view::npos ? 0 : folder + 1;
  const std::size_t dot = image_name.rfind('.');
  if (dot != std::string_view::npos && dot > file_start) image_name = image_name.substr(0, dot);
  std::string out;
  for (char c : image_name.substr(0, 64)) {
    const bool keep =
        std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '_';
    out += keep ? c : '_';
  }
  if (!out.empty() && out[0] == '.') out[0] = '_';
  if (out.empty()) return "image";
  if (out == "all") return "all_";
  return out;
}

std::string lower(std::string s) {
  for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// Hands out names no other view has, ignoring case.
class name_pool {
 public:
  std::string take(const std::string& base) {
    if (used_.insert(lower(base)).second) return base;
    int& n = next_[lower(base)];  // each base's counter only moves forward: linear overall
    for (n = std::max(n, 2);; ++n) {
      const std::string suffix = "-" + std::to_string(n);
      const std::string name = base.substr(0, 64 - suffix.size()) + suffix;
      if (used_.insert(lower(name)).second) return name;
    }
  }

 private:
  std::unordered_set<std::string> used_;       // the names handed out, lower case
  std::unordered_map<std::string, int> next_;  // a base's next suffix to try
};

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
  name_pool names;
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
    view.name = names.take(base_name(image_name));
    view.pose = pose_of(q, t, images_file, l.number);
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
                      "cameras.txt and images.txt)");
  for (const char* part : {"cameras", "images"}) {
    const std::string txt = std::string(part) + ".txt", bin = std::string(part) + ".bin";
    if (!std::filesystem::exists(dir / txt, ec) && std::filesystem::exists(dir / bin, ec))
      throw usage_error(dir.string() + ": holds COLMAP's binary model (" + bin + ") but no " + txt +
                        "; convert it with `colmap model_converter --input_path " + dir.string() +
                        " --output_path " + dir.string() + " --output_type TXT`");
  }
  const std::string cameras =
      read_regular_file(dir / "cameras.txt", max_cameras_bytes, "COLMAP cameras file");
  const std::string images =
      read_regular_file(dir / "images.txt", max_images_bytes, "COLMAP images file");
  return parse_colmap_model(cameras, images, dir.string());
}

}  // namespace rtvk
