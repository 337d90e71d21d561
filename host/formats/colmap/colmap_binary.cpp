// COLMAP's binary model (cameras.bin and images.bin, what COLMAP writes by default), laid out as
// COLMAP 3.8's ReadCamerasBinary and ReadImagesBinary read it (src/base/reconstruction.cc), all
// little-endian:
//   cameras.bin: u64 count; each: u32 CAMERA_ID, i32 MODEL_ID, u64 WIDTH, u64 HEIGHT,
//                f64 PARAMS[the model's count]
//   images.bin:  u64 count; each: u32 IMAGE_ID, f64 QW QX QY QZ, f64 TX TY TZ, u32 CAMERA_ID,
//                NAME ending in '\0', u64 POINTS2D, then POINTS2D x (f64 X, f64 Y, i64 POINT3D_ID)
// Each field is checked as the text model's is; a file that ends early, or goes on after its
// last record, is refused naming the file, the record and the field.
#include <cmath>
#include <cstring>
#include <map>

#include "colmap_model.h"
#include "colmap_views.h"
#include "errors.h"
#include "format.h"
#include "image_size.h"

namespace rtvk {
namespace {

// Reads one file's fields in order; every message names the file, the record and the field.
class binary_fields {
 public:
  binary_fields(std::string_view bytes, std::string file) : bytes_(bytes), file_(std::move(file)) {}

  // Says which record the following fields belong to ("camera 2 of 3").
  void record(const std::string& what) { record_ = what + ", at byte " + std::to_string(at_); }

  [[noreturn]] void fail(const std::string& field, const std::string& what) const {
    throw usage_error(file_ + ": " + (record_.empty() ? "" : record_ + ": ") + field + ": " + what);
  }

  // An unsigned little-endian integer of `Size` bytes.
  template <int Size>
  std::uint64_t whole(const std::string& field) {
    need(Size, field);
    std::uint64_t x = 0;
    for (int i = Size - 1; i >= 0; --i) x = x << 8 | static_cast<unsigned char>(bytes_[at_ + i]);
    at_ += Size;
    return x;
  }

  // A little-endian IEEE double, which must be finite.
  double number(const std::string& field) {
    const std::uint64_t bits = whole<8>(field);
    double x = 0;
    std::memcpy(&x, &bits, sizeof x);
    if (!std::isfinite(x)) fail(field, "must be a finite number, got " + format_number(x));
    return x;
  }

  // Characters up to a '\0', which is passed.
  std::string text(const std::string& field) {
    const std::size_t end = bytes_.find('\0', at_);
    if (end == std::string_view::npos) fail(field, "the file ends before its closing '\\0'");
    const std::string out(bytes_.substr(at_, end - at_));
    at_ = end + 1;
    return out;
  }

  // `count` records of `size` bytes, passed over.
  void skip(std::uint64_t count, std::uint64_t size, const std::string& field) {
    if (count > (bytes_.size() - at_) / size)
      fail(field, std::to_string(count) + " records of " + std::to_string(size) +
                      " bytes, but the file has " + std::to_string(bytes_.size() - at_) + " left");
    at_ += std::size_t(count * size);
  }

  // The file and the record, to begin a message.
  std::string where() const { return file_ + (record_.empty() ? "" : ": " + record_); }

  // The file must end after its last record.
  void end() {
    record_.clear();
    if (at_ != bytes_.size())
      fail("end", std::to_string(bytes_.size() - at_) + " bytes after the last record (at byte " +
                      std::to_string(at_) + ")");
  }

 private:
  void need(std::size_t n, const std::string& field) const {
    if (bytes_.size() - at_ < n)
      fail(field, "the file ends (" + std::to_string(n) + " bytes needed, " +
                      std::to_string(bytes_.size() - at_) + " left)");
  }

  std::string_view bytes_;
  std::string file_;    // as messages name it
  std::string record_;  // the record being read, for messages
  std::size_t at_ = 0;  // the next field's first byte
};

struct binary_camera {
  rtvk::projection model;  // opencv or opencv_fisheye
  lens_intrinsics lens;    // in rtvk's pixel convention
};

const char* const unrendered_models[] = {"FOV", "SIMPLE_RADIAL_FISHEYE", "RADIAL_FISHEYE",
                                         "THIN_PRISM_FISHEYE"};

int image_side(binary_fields& in, const char* field) {
  const std::uint64_t x = in.whole<8>(field);
  if (x < 1 || x > std::uint64_t(max_image_side))
    in.fail(field,
            "must be in [1, " + std::to_string(max_image_side) + "], got " + std::to_string(x));
  return int(x);
}

std::pair<std::uint64_t, binary_camera> read_camera(binary_fields& in) {
  const std::uint64_t camera_id = in.whole<4>("CAMERA_ID");
  const std::int64_t model_id = std::int32_t(std::uint32_t(in.whole<4>("MODEL_ID")));
  int count = 0;
  const colmap_camera_model* spec = colmap_model_numbered(model_id, count);
  if (!spec)
    in.fail("MODEL_ID", "camera model " + std::to_string(model_id) +
                            (model_id >= 7 && model_id <= 10
                                 ? std::string(" (") + unrendered_models[model_id - 7] + ")"
                                 : std::string()) +
                            " is not supported; supported: " + colmap_supported_models());
  binary_camera c{spec->model, {}};
  c.lens.width = image_side(in, "WIDTH");
  c.lens.height = image_side(in, "HEIGHT");
  for (int i = 0; i < count; ++i) {
    const std::string field = "parameter " + std::to_string(i + 1);
    if (!put_colmap_param(*spec, i, in.number(field), c.lens))
      in.fail(field, "focal length must be > 0");
  }
  return {camera_id, c};
}

std::map<std::uint64_t, binary_camera> read_cameras(std::string_view bytes,
                                                    const std::string& file) {
  binary_fields in(bytes, file);
  const std::uint64_t count = in.whole<8>("the number of cameras");
  std::map<std::uint64_t, binary_camera> cameras;
  for (std::uint64_t k = 0; k < count; ++k) {
    in.record("camera " + std::to_string(k + 1) + " of " + std::to_string(count));
    const auto [camera_id, c] = read_camera(in);
    if (!cameras.emplace(camera_id, c).second)
      in.fail("CAMERA_ID", "camera " + std::to_string(camera_id) + " is defined twice");
  }
  in.end();
  return cameras;
}

}  // namespace

std::vector<colmap_view> parse_colmap_binary(const std::string& cameras_bin,
                                             const std::string& images_bin,
                                             const std::string& dir_name) {
  const std::string cameras_file = (std::filesystem::path(dir_name) / "cameras.bin").string();
  const std::map<std::uint64_t, binary_camera> cameras = read_cameras(cameras_bin, cameras_file);
  binary_fields in(images_bin, (std::filesystem::path(dir_name) / "images.bin").string());
  const std::uint64_t count = in.whole<8>("the number of images");
  std::vector<colmap_view> views;
  std::map<std::uint64_t, std::uint64_t> seen;  // image ID -> its record
  colmap_names names;
  for (std::uint64_t k = 0; k < count; ++k) {
    in.record("image " + std::to_string(k + 1) + " of " + std::to_string(count));
    const std::uint64_t image_id = in.whole<4>("IMAGE_ID");
    if (!seen.emplace(image_id, k).second)
      in.fail("IMAGE_ID", "image " + std::to_string(image_id) + " is given twice");
    std::array<double, 4> q;
    for (int i = 0; i < 4; ++i) q[std::size_t(i)] = in.number(std::string("Q") + "WXYZ"[i]);
    vec3 t;
    for (int i = 0; i < 3; ++i) t[i] = in.number(std::string("T") + "XYZ"[i]);
    const std::uint64_t camera_id = in.whole<4>("CAMERA_ID");
    const auto camera = cameras.find(camera_id);
    if (camera == cameras.end())
      in.fail("CAMERA_ID", "camera " + std::to_string(camera_id) + " is not in " + cameras_file);
    colmap_view view;
    view.image_name = in.text("NAME");
    if (view.image_name.empty()) in.fail("NAME", "is empty");
    in.skip(in.whole<8>("POINTS2D"), 24, "POINTS2D");
    view.name = names.take(view.image_name);
    view.pose = colmap_pose(q, t, in.where());
    view.pose.projection = camera->second.model;
    view.pose.intrinsics = camera->second.lens;
    views.push_back(std::move(view));
  }
  in.end();
  if (views.empty()) in.fail("the number of images", "no images");
  return views;
}

}  // namespace rtvk
