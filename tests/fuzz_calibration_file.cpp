// libFuzzer target for the camera calibration readers: OpenCV's FileStorage YAML and JSON, and
// COLMAP's text and binary models. The first byte picks the reader ('y' or 'j': an OpenCV file,
// the reader picking YAML or JSON by content as it does for files; 'c': COLMAP's text model, the
// rest split at its first '\0' into cameras.txt and images.txt; 'b': COLMAP's binary model, a
// 4-byte little-endian length of cameras.bin, its bytes, then images.bin's; anything else:
// nothing). Any input may be
// rejected, but only with usage_error; anything else -- a crash, another exception, undefined
// behaviour, a read past a buffer -- is a bug. What is accepted must make a camera: sizes in
// range, finite focal lengths > 0, finite coefficients, valid and unique names, and poses whose
// geometry the camera class takes.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <set>
#include <string>

#include "calibration_file.h"
#include "camera_path.h"
#include "colmap_model.h"
#include "errors.h"

namespace {

void check_lens(rtvk::projection model, const rtvk::lens_intrinsics& lens) {
  if (model != rtvk::projection::opencv && model != rtvk::projection::opencv_fisheye) std::abort();
  if (lens.width < 1 || lens.width > rtvk::max_image_side) std::abort();
  if (lens.height < 1 || lens.height > rtvk::max_image_side) std::abort();
  if (!(lens.fx > 0) || !(lens.fy > 0) || !std::isfinite(lens.fx) || !std::isfinite(lens.fy))
    std::abort();
  if (!std::isfinite(lens.cx) || !std::isfinite(lens.cy)) std::abort();
  for (double k : lens.k)
    if (!std::isfinite(k)) std::abort();
}

void check_colmap(const std::vector<rtvk::colmap_view>& views) {
  if (views.empty()) std::abort();
  std::set<std::string> names;
  for (const rtvk::colmap_view& v : views) {
    if (!rtvk::valid_camera_name(v.name) || !names.insert(v.name).second) std::abort();
    const rtvk::lens_intrinsics& lens = v.pose.intrinsics;
    check_lens(v.pose.projection, lens);
    // The reader's geometry must make a view: the camera throws std::invalid_argument (a bug
    // here: it escapes) for a pose it cannot view from. The lens is left out: whether a
    // distortion can be inverted over the image is the camera's check, which whoever builds
    // cameras from these views turns into a usage_error.
    rtvk::camera_pose geometry = v.pose;
    geometry.projection = rtvk::projection::perspective;
    geometry.intrinsics = {};
    const rtvk::camera cam(geometry, double(lens.width) / lens.height, lens.width);
    (void)cam;
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const char kind = char(data[0]);
  const std::string bytes(reinterpret_cast<const char*>(data) + 1, size - 1);
  try {
    if (kind == 'y' || kind == 'j') {
      const rtvk::calibration c =
          rtvk::parse_opencv_calibration(bytes, kind == 'y' ? "fuzz.yml" : "fuzz.json");
      check_lens(c.model, c.lens);
      if (c.model == rtvk::projection::opencv_fisheye)
        for (std::size_t i = 4; i < c.lens.k.size(); ++i)
          if (c.lens.k[i] != 0) std::abort();
    } else if (kind == 'c') {
      const std::size_t split = bytes.find('\0');
      check_colmap(rtvk::parse_colmap_model(
          bytes.substr(0, split),
          split == std::string::npos ? std::string() : bytes.substr(split + 1), "fuzz"));
    } else if (kind == 'b' && bytes.size() >= 4) {
      std::size_t length = 0;
      for (int i = 3; i >= 0; --i) length = length << 8 | static_cast<unsigned char>(bytes[i]);
      const std::string rest = bytes.substr(4);
      const std::size_t split = std::min(length, rest.size());
      check_colmap(rtvk::parse_colmap_binary(rest.substr(0, split), rest.substr(split), "fuzz"));
    }
  } catch (const rtvk::usage_error&) {
    return 0;
  }
  return 0;
}
