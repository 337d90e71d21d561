// COLMAP's binary models (cameras.bin, images.bin): the same views as the text model COLMAP 3.8
// converted them from (tests/data/colmap), and every cut, stray byte and bad field refused naming
// the file, the record and the field.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <functional>
#include <sstream>

#include "colmap_model.h"
#include "errors.h"
#include "temp_dir.h"

namespace rtvk {
namespace {

const std::filesystem::path data = std::filesystem::path(RTVK_TEST_DATA) / "colmap";

std::string file_bytes(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const usage_error& e) {
    return e.what();
  }
  return "(no usage_error)";
}

// Little-endian fields, as COLMAP writes them.
struct binary_writer {
  std::string bytes;
  template <class T>
  binary_writer& put(T x) {
    char b[sizeof x];
    std::memcpy(b, &x, sizeof x);
    bytes.append(b, sizeof x);
    return *this;
  }
  binary_writer& name(const std::string& s) {
    bytes.append(s.c_str(), s.size() + 1);
    return *this;
  }
};

// One PINHOLE camera 64x48, and one image of it at the identity pose, t = (0, 0, 5).
std::string one_camera_bin() {
  binary_writer w;
  w.put<std::uint64_t>(1).put<std::uint32_t>(1).put<std::int32_t>(1);
  w.put<std::uint64_t>(64).put<std::uint64_t>(48);
  for (double p : {50.0, 51.0, 32.0, 24.0}) w.put(p);
  return w.bytes;
}

std::string one_image_bin(double qw = 1) {
  binary_writer w;
  w.put<std::uint64_t>(1).put<std::uint32_t>(1);
  for (double x : {qw, 0.0, 0.0, 0.0, 0.0, 0.0, 5.0}) w.put(x);
  w.put<std::uint32_t>(1).name("a.jpg").put<std::uint64_t>(1);
  w.put(1.5).put(2.5).put<std::int64_t>(-1);
  return w.bytes;
}

TEST(ColmapBinary, GivesTheSameViewsAsTheTextModelItWasConvertedFrom) {
  std::vector<colmap_view> text = read_colmap_model(data / "text");
  std::vector<colmap_view> binary = read_colmap_model(data / "binary");
  ASSERT_EQ(text.size(), 7u);
  ASSERT_EQ(binary.size(), text.size());
  // COLMAP writes images.bin in its hash map's order, not the text file's: compared by name.
  const auto by_name = [](const colmap_view& a, const colmap_view& b) {
    return a.image_name < b.image_name;
  };
  std::sort(text.begin(), text.end(), by_name);
  std::sort(binary.begin(), binary.end(), by_name);
  for (std::size_t i = 0; i < text.size(); ++i) {
    EXPECT_EQ(binary[i].name, text[i].name) << i;
    EXPECT_EQ(binary[i].image_name, text[i].image_name) << i;
    EXPECT_EQ(binary[i].pose.projection, text[i].pose.projection) << i;
    EXPECT_EQ(binary[i].pose.intrinsics, text[i].pose.intrinsics) << i;
    EXPECT_EQ(binary[i].pose.lookfrom, text[i].pose.lookfrom) << i;
    EXPECT_EQ(binary[i].pose.lookat, text[i].pose.lookat) << i;
    EXPECT_EQ(binary[i].pose.vup, text[i].pose.vup) << i;
  }
  // Known answers, so that both cannot be wrong the same way.
  EXPECT_EQ(binary[0].name, "a");
  EXPECT_EQ(binary[3].name, "cam0_IMG_1");
  EXPECT_EQ(binary[0].pose.lookfrom, point3(0, 0, -5));
  EXPECT_EQ(binary[0].pose.intrinsics.fx, 50);
  EXPECT_EQ(binary[0].pose.intrinsics.cx, 31.5);
  EXPECT_EQ(binary[6].pose.projection, projection::opencv_fisheye);  // f.jpg
  EXPECT_EQ(binary[5].pose.intrinsics.k[7], 12);                     // e.jpg: FULL_OPENCV
}

// Every cut of either file ends in a message that names that file and says it ended.
TEST(ColmapBinary, EveryCutIsRefusedNamingTheFileAndField) {
  const std::string cameras = file_bytes(data / "binary/cameras.bin");
  const std::string images = file_bytes(data / "binary/images.bin");
  ASSERT_GT(cameras.size(), 100u);
  for (std::size_t n = 0; n < cameras.size(); ++n) {
    const std::string got =
        message_of([&] { parse_colmap_binary(cameras.substr(0, n), images, "m"); });
    EXPECT_EQ(got.find("m/cameras.bin: "), 0u) << n << ": " << got;
    EXPECT_NE(got.find("the file ends"), std::string::npos) << n << ": " << got;
  }
  for (std::size_t n = 0; n < images.size(); ++n) {
    const std::string got =
        message_of([&] { parse_colmap_binary(cameras, images.substr(0, n), "m"); });
    EXPECT_EQ(got.find("m/images.bin: "), 0u) << n << ": " << got;
  }
  // The first image's QW, cut after three of its eight bytes.
  EXPECT_EQ(message_of([&] { parse_colmap_binary(cameras, images.substr(0, 15), "m"); }),
            "m/images.bin: image 1 of 7, at byte 8: QW: the file ends (8 bytes needed, 3 left)");
}

TEST(ColmapBinary, RefusesBadFieldsByName) {
  const std::string camera = one_camera_bin(), image = one_image_bin();
  EXPECT_EQ(parse_colmap_binary(camera, image, "m").size(), 1u);
  struct bad_case {
    std::string cameras, images, expect;
  };
  std::string fov = camera, zero_focal = camera, huge = camera, nan_image = image, camera9 = image;
  fov[12] = 7;  // MODEL_ID
  std::memset(&zero_focal[32], 0, 8);
  huge[23] = 1;  // WIDTH 2^56 + 64
  const double nan = std::nan("");
  std::memcpy(&nan_image[12 + 8], &nan, 8);  // QX
  camera9[12 + 56] = 9;                      // CAMERA_ID
  const bad_case cases[] = {
      {fov, image,
       "m/cameras.bin: camera 1 of 1, at byte 8: MODEL_ID: camera model 7 (FOV) is "
       "not supported; supported: SIMPLE_PINHOLE"},
      {zero_focal, image, "camera 1 of 1, at byte 8: parameter 1: focal length must be > 0"},
      {huge, image, "WIDTH: must be in [1, 65536], got 72057594037928000"},
      {camera, nan_image, "m/images.bin: image 1 of 1, at byte 8: QX: must be a finite number"},
      {camera, camera9, "CAMERA_ID: camera 9 is not in m/cameras.bin"},
      {camera, one_image_bin(0), "image 1 of 1, at byte 8: the rotation quaternion is zero"},
      {camera + "x", image, "m/cameras.bin: end: 1 bytes after the last record (at byte 64)"},
      {camera, image.substr(0, 78) + "\x7f" + image.substr(79),
       "POINTS2D: 127 records of 24 bytes, but the file has 24 left"},
      {camera, std::string(8, '\0'), "m/images.bin: the number of images: no images"},
      {camera, std::string(8, '\xff') + std::string(64, 'g'), "image 1 of 18446744073709551615"},
  };
  for (const bad_case& c : cases)
    EXPECT_NE(message_of([&] { parse_colmap_binary(c.cameras, c.images, "m"); }).find(c.expect),
              std::string::npos)
        << c.expect
        << "\n got: " << message_of([&] { parse_colmap_binary(c.cameras, c.images, "m"); });
}

// A folder with cameras.txt is read as text, whatever .bin files lie beside it; without one, a
// cameras.bin makes it binary, and then images.bin is needed.
TEST(ColmapBinary, AFolderIsReadAsTextFirstThenBinary) {
  const test::temp_dir dir;
  std::ofstream(dir.path() / "cameras.bin", std::ios::binary) << one_camera_bin();
  EXPECT_NE(message_of([&] { read_colmap_model(dir.path()); }).find("images.bin"),
            std::string::npos);
  std::ofstream(dir.path() / "images.bin", std::ios::binary) << one_image_bin();
  const std::vector<colmap_view> views = read_colmap_model(dir.path());
  ASSERT_EQ(views.size(), 1u);
  EXPECT_EQ(views[0].pose.lookfrom, point3(0, 0, -5));
  EXPECT_EQ(views[0].pose.intrinsics.fy, 51);
  std::ofstream(dir.path() / "cameras.txt") << "1 PINHOLE 640 480 500 510 320 240\n";
  std::ofstream(dir.path() / "images.txt") << "1 1 0 0 0 0 0 5 1 x.jpg\n\n";
  EXPECT_EQ(read_colmap_model(dir.path()).at(0).pose.intrinsics.fy, 510);
}

}  // namespace
}  // namespace rtvk
