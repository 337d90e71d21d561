// OpenCV calibration files (cv::FileStorage's YAML and JSON) and COLMAP text models: known
// answers worked by hand, the model rule, the half-pixel shift between COLMAP and OpenCV, poses
// checked against the camera's basis, and a table of bad inputs with the message each gets.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <fstream>
#include <functional>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>
#include <set>

#include "calibration_file.h"
#include "camera_path.h"
#include "colmap_model.h"
#include "errors.h"
#include "temp_dir.h"

namespace rtvk {
namespace {

// cv::FileStorage's YAML, as OpenCV's calibration sample writes it.
const std::string opencv_yaml = R"(%YAML:1.0
---
image_width: 640
image_height: 480
camera_matrix: !!opencv-matrix
   rows: 3
   cols: 3
   dt: d
   data: [ 5.0e+02, 0., 3.195e+02, 0., 5.1e+02, 2.395e+02, 0., 0., 1. ]
distortion_coefficients: !!opencv-matrix
   rows: 1
   cols: 5
   dt: d
   data: [ -2.8e-01, 7.e-02, 1.e-03, -2.e-04, 0. ]
)";

void expect_sample(const calibration& c) {
  EXPECT_EQ(c.model, projection::opencv);
  EXPECT_EQ(c.lens.width, 640);
  EXPECT_EQ(c.lens.height, 480);
  EXPECT_EQ(c.lens.fx, 500);
  EXPECT_EQ(c.lens.fy, 510);
  EXPECT_EQ(c.lens.cx, 319.5);
  EXPECT_EQ(c.lens.cy, 239.5);
  EXPECT_EQ(c.lens.k, (std::array<double, 8>{-0.28, 0.07, 0.001, -0.0002, 0, 0, 0, 0}));
  EXPECT_EQ(c.lens.radius, 0);
}

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const usage_error& e) {
    return e.what();
  }
  return "(no usage_error)";
}

TEST(OpenCVCalibration, ReadsFileStorageYaml) {
  expect_sample(parse_opencv_calibration(opencv_yaml, "cal.yml"));
  // The same from a file.
  const test::temp_dir dir;
  std::ofstream(dir.path() / "cal.yml") << opencv_yaml;
  expect_sample(read_opencv_calibration(dir.path() / "cal.yml"));
}

// FileStorage's other spellings: no header, "%YAML 1.0", CRLF line ends, comments, data over
// several lines in %.16e, other keys of every kind ignored, fields in another order.
TEST(OpenCVCalibration, ReadsYamlVariants) {
  const std::string text =
      "%YAML 1.0\r\n"
      "# written by hand\r\n"
      "calibration_time: \"Wed 08 Jun 2011 # not a comment\"\r\n"
      "nframes: 10\r\n"
      "avg_reprojection_error: 2.9e-01  # pixels\r\n"
      "per_view: [ 'a', \"b\" ]\r\n"
      "empty: []\r\n"
      "nothing:\r\n"
      "extrinsic_parameters: !!opencv-matrix\r\n"
      "   rows: 1\r\n"
      "   cols: 6\r\n"
      "   dt: d\r\n"
      "   data: [ .Nan, .Inf, -.Inf, 1, 2, 3 ]\r\n"
      "camera_matrix: !!opencv-matrix  # K\r\n"
      "   rows: 3\r\n"
      "   data: [ 5.0000000000000000e+02, 0., 3.1950000000000000e+02, 0.,\r\n"
      "\r\n"
      "       # a comment inside the data\r\n"
      "       5.1000000000000000e+02, 2.3950000000000000e+02, 0., 0., 1. ]\r\n"
      "   cols: 3\r\n"
      "   dt: d\r\n"
      "image_height: 480\r\n"
      "distortion_coefficients: !!opencv-matrix\r\n"
      "   rows: 5\r\n"
      "   cols: 1\r\n"
      "   dt: d\r\n"
      "   data: [ -2.8e-01, +7.e-02, 1.e-03, -2.e-04, 0. ]\r\n"
      "image_width: 640.\r\n";
  expect_sample(parse_opencv_calibration(text, "variants.yml"));
  // No header at all, a document start, and a UTF-8 byte order mark.
  expect_sample(parse_opencv_calibration("\xEF\xBB\xBF---\n" + opencv_yaml.substr(14), "bom.yml"));
}

TEST(OpenCVCalibration, ReadsFileStorageJson) {
  const std::string text = R"({
    "image_width": 640,
    "image_height": 480,
    "calibration_time": "today",
    "camera_matrix": {"type_id": "opencv-matrix", "rows": 3, "cols": 3, "dt": "d",
                      "data": [5.0000000000000000e+02, 0.0, 3.1950000000000000e+02, 0.0,
                               5.1e+02, 2.395e+02, 0.0, 0.0, 1.0]},
    "distortion_coefficients": {"type_id": "opencv-matrix", "rows": 1, "cols": 5, "dt": "d",
                                "data": [-2.8e-01, 7e-02, 1e-03, -2e-04, 0]},
    "extrinsics": {"anything": [[1, 2], {"x": 3}]}
  })";
  expect_sample(parse_opencv_calibration(text, "cal.json"));
  // A plain JSON file: the camera matrix as rows, the distortion as an array, imageSize.
  const calibration plain = parse_opencv_calibration(
      R"({"K": [[500, 0, 319.5], [0, 510, 239.5], [0, 0, 1]], "D": [-0.28, 0.07, 0.001, -0.0002],
          "imageSize": [640, 480]})",
      "plain.json");
  EXPECT_EQ(plain.model, projection::opencv);  // 4 coefficients without a fisheye flag
  EXPECT_EQ(plain.lens.fx, 500);
  EXPECT_EQ(plain.lens.cy, 239.5);
  EXPECT_EQ(plain.lens.width, 640);
  EXPECT_EQ(plain.lens.k, (std::array<double, 8>{-0.28, 0.07, 0.001, -0.0002}));
}

const std::string fisheye_matrix =
    "K: [ 300, 0, 320, 0, 300, 240, 0, 0, 1 ]\n"
    "image_size: [ 640, 480 ]\n"
    "D: [ 0.1, -0.02, 0.003, -0.0004 ]\n";

TEST(OpenCVCalibration, ModelKeyOrFisheyeFlagPicksFisheye) {
  for (const char* model :
       {"model: fisheye\n", "model: \"opencv-fisheye\"\n", "distortion_model: equidistant\n",
        "distortion_model: Kannala-Brandt\n", "fisheye: 1\n", "fisheye: true\n",
        "model: fisheye\nfisheye: 1\n", "model: fisheye\ndistortion_model: equidistant\n"}) {
    const calibration c = parse_opencv_calibration(fisheye_matrix + model, "fe.yml");
    EXPECT_EQ(c.model, projection::opencv_fisheye) << model;
    EXPECT_EQ(c.lens.k, (std::array<double, 8>{0.1, -0.02, 0.003, -0.0004})) << model;
    EXPECT_EQ(c.lens.fx, 300) << model;
  }
  for (const char* model : {"", "model: pinhole\n", "distortion_model: plumb_bob\n", "fisheye: 0\n",
                            "distortion_model: radtan\nfisheye: false\n"})
    EXPECT_EQ(parse_opencv_calibration(fisheye_matrix + model, "cv.yml").model, projection::opencv)
        << model;
}

// A ROS camera_info file: untagged matrices, distortion_model, ignored rectification and
// projection matrices, rational_polynomial's 8 coefficients.
TEST(OpenCVCalibration, ReadsRosCameraInfo) {
  const std::string text =
      "image_width: 1280\n"
      "image_height: 720\n"
      "camera_name: narrow_stereo/left\n"
      "camera_matrix:\n"
      "  rows: 3\n"
      "  cols: 3\n"
      "  data: [700.5, 0, 640.25, 0, 701.5, 360.75, 0, 0, 1]\n"
      "distortion_model: rational_polynomial\n"
      "distortion_coefficients:\n"
      "  rows: 1\n"
      "  cols: 8\n"
      "  data: [0.1, 0.2, 0.003, 0.004, 0.5, 0.6, 0.7, 0.8]\n"
      "rectification_matrix:\n"
      "  rows: 3\n"
      "  cols: 3\n"
      "  data: [1, 0, 0, 0, 1, 0, 0, 0, 1]\n";
  const calibration c = parse_opencv_calibration(text, "left.yaml");
  EXPECT_EQ(c.model, projection::opencv);
  EXPECT_EQ(c.lens.width, 1280);
  EXPECT_EQ(c.lens.height, 720);
  EXPECT_EQ(c.lens.fx, 700.5);
  EXPECT_EQ(c.lens.fy, 701.5);
  EXPECT_EQ(c.lens.cx, 640.25);
  EXPECT_EQ(c.lens.cy, 360.75);
  EXPECT_EQ(c.lens.k, (std::array<double, 8>{0.1, 0.2, 0.003, 0.004, 0.5, 0.6, 0.7, 0.8}));
  // Without distortion at all: no distortion.
  const calibration bare = parse_opencv_calibration(
      "image_width: 10\nimage_height: 20\nK: [ 1, 0, 2, 0, 3, 4, 0, 0, 1 ]\n", "bare.yml");
  EXPECT_EQ(bare.lens.k, (std::array<double, 8>{}));
  EXPECT_EQ(bare.lens.height, 20);
}

struct bad_input {
  std::string text;      // the file
  std::string fragment;  // what its message must contain
};

const std::string good_k = "K: [ 500, 0, 320, 0, 500, 240, 0, 0, 1 ]\n";
const std::string good_size = "image_width: 640\nimage_height: 480\n";

TEST(OpenCVCalibration, RefusesBadFilesNamingWhereAndWhat) {
  const bad_input cases[] = {
      // YAML's structure, with the line.
      {"%YAML:1.0\n---\nimage_width 640\n",
       "bad.yml:3: expected `key: value`, got 'image_width 640'"},
      {good_size + "K: [ 1, 2,\n  3\n", "bad.yml:3: K: the sequence's [ is never closed"},
      {good_size + "K: [ 1, [2] ]\n", "bad.yml:3: K: nested sequences"},
      {good_size + "K: { a: 1 }\n", "bad.yml:3: K: '{ a: 1 }' is not read"},
      {good_size + "K: &anchor 1\n", "bad.yml:3: K: '&anchor 1' is not read"},
      {good_size + "  K: 1\n", "bad.yml:3: unexpected indented line"},
      {good_size + "K: !!opencv-nd-matrix\n", "bad.yml:3: K: tag '!!opencv-nd-matrix' is not read"},
      {good_size + "K: !!opencv-matrix\n  rows: 3\n  cols: 3\n  stride: 4\n",
       "bad.yml:6: K: stride is not read"},
      {good_size + "K: !!opencv-matrix\n  rows: 3\n   cols: 3\n", "bad.yml:5: K: inconsistent"},
      {good_size + "K: !!opencv-matrix\n  rows: 3\n  cols: 3\n",
       "bad.yml:3: K: a matrix needs rows, cols and data"},
      {good_size + "K: !!opencv-matrix\n  rows: 3\n  cols: 3\n  data: [ 1, 2 ]\n",
       "bad.yml:3: K: rows x cols = 3 x 3 does not match the 2 numbers of data"},
      {good_size + "K: !!opencv-matrix\n  rows: 3\n  rows: 3\n",
       "bad.yml:5: K: rows is given twice"},
      {good_size + "K: !!opencv-matrix\n  rows: -3\n  cols: 3\n  data: []\n",
       "bad.yml:3: K: a matrix's rows and cols must be whole numbers >= 0, got '-3'"},
      {good_size + "K: \"open\n", "bad.yml:3: K: unterminated string"},
      {good_size + good_k + "K: 1\n", "bad.yml:4: K is given twice"},
      {"%TAG ! x\n" + good_size, "bad.yml:1: only a %YAML directive"},
      {good_size + "---\n" + good_k, "bad.yml:3: only one YAML document"},
      {good_size + "- 1\n", "bad.yml:3: expected `key: value`"},
      // What the values mean: the file, the line and the key, the bad value.
      {good_size, "bad.yml: no camera matrix"},
      {good_k + "image_width: 640\n", "bad.yml:2: image_width: image_width and image_height"},
      {good_k, "bad.yml: no image size"},
      {good_k + "image_width: 0\nimage_height: 480\n",
       "bad.yml:2: image_width: image size must be a whole number in [1, 65536], got '0'"},
      {good_k + "image_width: 640.5\nimage_height: 480\n", "got '640.5'"},
      {good_k + "image_width: 640\nimage_height: 70000\n", "bad.yml:3: image_height:"},
      {good_k + "image_size: [ 640 ]\n", "bad.yml:2: image_size: expected [width, height]"},
      {good_k + good_size + "image_size: [ 640, 481 ]\n", "640x481 differs"},
      {good_size + "K: [ 500, 1, 320, 0, 500, 240, 0, 0, 1 ]\n",
       "bad.yml:3: K: a skewed camera matrix (K[0][1] = 1) is not supported"},
      {good_size + "K: [ -500, 0, 320, 0, 500, 240, 0, 0, 1 ]\n",
       "bad.yml:3: K: focal lengths must be > 0, got fx -500, fy 500"},
      {good_size + "K: [ 500, 0, 320, 0, 500, 240, 0, 0, 2 ]\n",
       "bad.yml:3: K: the camera matrix must be fx 0 cx / 0 fy cy / 0 0 1"},
      {good_size + "K: [ 500, 0, .Nan, 0, 500, 240, 0, 0, 1 ]\n",
       "bad.yml:3: K: expected a finite number, got '.Nan'"},
      {good_size + "K: [ 500, 0, 1e999, 0, 500, 240, 0, 0, 1 ]\n", "got '1e999'"},
      {good_size + "K: [ 500, 0, 0x10, 0, 500, 240, 0, 0, 1 ]\n", "got '0x10'"},
      {good_size + "K: [ 500, 0, '320', 0, 500, 240, 0, 0, 1 ]\n", "got '320'"},
      {good_size + "K: [ 1, 2, 3, 4 ]\n",
       "bad.yml:3: K: the camera matrix must be 3x3, got 4 numbers"},
      {good_size + "K: !!opencv-matrix\n  rows: 2\n  cols: 2\n  data: [1, 0, 0, 1]\n",
       "must be 3x3, got 2x2"},
      {good_size + good_k + "camera_matrix: [ 1 ]\n",
       "bad.yml:3: K: given together with camera_matrix"},
      {good_size + good_k + "D: [ 0.1, 0.2, 0.3 ]\n",
       "bad.yml:4: D: opencv takes 4, 5 or 8 coefficients (k1 k2 p1 p2 [k3 [k4 k5 k6]]), got 3"},
      {good_size + good_k + "D: [ 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0 ]\n",
       "bad.yml:4: D: 12 coefficients (thin prism / tilted sensor) are not supported"},
      {good_size + good_k + "D: [ 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0 ]\n",
       "D: 14 coefficients"},
      {good_size + good_k + "D: [ 0.1, -.Inf, 0, 0 ]\n",
       "bad.yml:4: D: expected a finite number, got '-.Inf'"},
      {good_size + good_k + "D: !!opencv-matrix\n  rows: 2\n  cols: 2\n  data: [0, 0, 0, 0]\n",
       "bad.yml:4: D: expected a 1xN or Nx1 matrix or a sequence, got 2x2"},
      {good_size + good_k + "model: fisheye\nD: [ 0, 0, 0, 0, 0 ]\n",
       "bad.yml:5: D: opencv-fisheye takes exactly 4 coefficients (k1 k2 k3 k4), got 5"},
      {good_size + good_k + "model: kb8\n", "bad.yml:4: model: unknown model 'kb8'"},
      {good_size + good_k + "model: fisheye\ndistortion_model: plumb_bob\n",
       "bad.yml:5: distortion_model: contradicts model"},
      {good_size + good_k + "model: pinhole\nfisheye: 1\n",
       "bad.yml:5: fisheye: contradicts the model"},
      {good_size + good_k + "fisheye: yes\n",
       "bad.yml:4: fisheye: expected 1, 0, true or false, got 'yes'"},
      {good_size + good_k + "model: [ a ]\n", "bad.yml:4: model: expected a string"},
  };
  for (const bad_input& c : cases)
    EXPECT_NE(message_of([&] { parse_opencv_calibration(c.text, "bad.yml"); }).find(c.fragment),
              std::string::npos)
        << c.text << "\n got: " << message_of([&] { parse_opencv_calibration(c.text, "bad.yml"); });

  const bad_input json_cases[] = {
      {"{\"K\": [1, 2", "bad.json: [json.exception.parse_error"},
      {"{\"K\": .Nan}", "bad.json: [json.exception.parse_error"},
      {R"({"image_size": [640, 480], "K": {"type_id": "opencv-matrix", "rows": 3, "cols": 3,
          "data": [1, 0, 0, 0, 1, 0, 0, 0]}})",
       "bad.json: K: rows x cols = 3 x 3 does not match the 8 numbers of data"},
      {R"({"image_size": [640, 480], "K": {"type_id": "opencv-matrix", "rows": "3", "cols": 3,
          "data": []}})",
       "bad.json: K: a matrix's rows must be a whole number"},
      {R"({"image_size": [640, 480], "K": [[1, 0, 2], [0, 1, 2], [0, 0, 1]], "D": "none"})",
       "bad.json: D: expected a 1xN or Nx1 matrix or a sequence"},
      {R"({"image_size": [640, 480], "K": {"rows": 3}})",
       "bad.json: K: the camera matrix must be 3x3, got an object"},
      {R"({"image_size": [640, "480"], "K": [[1, 0, 2], [0, 1, 2], [0, 0, 1]]})",
       "bad.json: image_size: expected a finite number, got '480'"},
  };
  for (const bad_input& c : json_cases)
    EXPECT_NE(message_of([&] { parse_opencv_calibration(c.text, "bad.json"); }).find(c.fragment),
              std::string::npos)
        << c.text
        << "\n got: " << message_of([&] { parse_opencv_calibration(c.text, "bad.json"); });
  // Files: one that is missing, one that is a folder.
  const test::temp_dir dir;
  EXPECT_NE(message_of([&] { read_opencv_calibration(dir.path() / "none.yml"); }).find("none.yml"),
            std::string::npos);
  EXPECT_NE(message_of([&] { read_opencv_calibration(dir.path()); }).find("a folder"),
            std::string::npos);
}

// ---------------------------------------------------------------------------------------------
// COLMAP

const std::string one_camera = "1 PINHOLE 640 480 500 510 320 240\n";

std::string image_line(const std::string& qt, const std::string& name, int id = 1, int cam = 1) {
  return std::to_string(id) + " " + qt + " " + std::to_string(cam) + " " + name + "\n\n";
}

// Each COLMAP model's parameters land where OpenCV has them, cx and cy half a pixel lower.
TEST(ColmapModel, MapsEachCameraModelToOpenCV) {
  const std::string cameras =
      "# Camera list with one line of data per camera:\n"
      "#   CAMERA_ID, MODEL, WIDTH, HEIGHT, PARAMS[]\n"
      "1 SIMPLE_PINHOLE 640 480 500 320 240\n"
      "2 PINHOLE 640 480 500 510 320 240\n"
      "\n"
      "3 SIMPLE_RADIAL 800 600 400 400.5 300.25 0.01\n"
      "4 RADIAL 800 600 400 400 300 0.01 -0.02\n"
      "5 OPENCV 1920 1080 1000 1001 960 540 0.1 0.2 0.003 0.004\n"
      "6 FULL_OPENCV 10 20 1 2 3 4 5 6 7 8 9 10 11 12\n"
      "7 OPENCV_FISHEYE 1000 1000 300 301 500 500 0.1 0.2 0.3 0.4\n";
  std::string images;
  for (int i = 1; i <= 7; ++i) images += image_line("1 0 0 0 0 0 0", "img.png", i, i);
  const std::vector<colmap_view> views = parse_colmap_model(cameras, images, "model");
  ASSERT_EQ(views.size(), 7u);
  using k8 = std::array<double, 8>;
  const lens_intrinsics expected[] = {
      {640, 480, 500, 500, 319.5, 239.5, k8{}, 0},
      {640, 480, 500, 510, 319.5, 239.5, k8{}, 0},
      {800, 600, 400, 400, 400, 299.75, k8{0.01}, 0},
      {800, 600, 400, 400, 399.5, 299.5, k8{0.01, -0.02}, 0},
      {1920, 1080, 1000, 1001, 959.5, 539.5, k8{0.1, 0.2, 0.003, 0.004}, 0},
      {10, 20, 1, 2, 2.5, 3.5, k8{5, 6, 7, 8, 9, 10, 11, 12}, 0},
      {1000, 1000, 300, 301, 499.5, 499.5, k8{0.1, 0.2, 0.3, 0.4}, 0},
  };
  for (int i = 0; i < 7; ++i) {
    EXPECT_EQ(views[i].pose.intrinsics, expected[i]) << i;
    EXPECT_EQ(views[i].pose.projection, i == 6 ? projection::opencv_fisheye : projection::opencv)
        << i;
  }
}

// The identity rotation with t = (0, 0, 5): the world's origin is 5 in front of the camera, so
// the camera stands at (0, 0, -5) looking down +z, its x right and y down as the world's.
TEST(ColmapModel, IdentityPoseLooksDownPlusZ) {
  const std::vector<colmap_view> views =
      parse_colmap_model(one_camera, image_line("1 0 0 0 0 0 5", "a.jpg"), "m");
  ASSERT_EQ(views.size(), 1u);
  const camera_pose& p = views[0].pose;
  EXPECT_EQ(p.lookfrom, point3(0, 0, -5));
  EXPECT_EQ(p.lookat, point3(0, 0, -4));
  EXPECT_EQ(p.vup, vec3(0, -1, 0));
  EXPECT_EQ(p.projection, projection::opencv);
  const camera cam(p, 640.0 / 480.0, 640);
  EXPECT_EQ(cam.lens_u(), vec3(1, 0, 0));   // image x: the world's +x
  EXPECT_EQ(cam.lens_v(), vec3(0, -1, 0));  // image up: the world's -y (OpenCV's y is down)
  EXPECT_EQ(cam.axis_w(), vec3(0, 0, -1));  // w points backwards
}

void expect_close(const vec3& got, const vec3& want) {
  EXPECT_NEAR(got.x, want.x, 1e-12);
  EXPECT_NEAR(got.y, want.y, 1e-12);
  EXPECT_NEAR(got.z, want.z, 1e-12);
}

// 90 degrees about +y: q = (cos 45, 0, sin 45, 0), R = [0 0 1; 0 1 0; -1 0 0]. The camera's
// axes are R's rows: x = +z, y = +y, z = -x. With t = (0, 0, 5) its center is -R^T t = (5, 0, 0):
// it looks from +x back at the origin. The world point (0, 0, 1) maps to R p + t = (1, 0, 5),
// right of the image's center; (0, -1, 0) maps to (0, -1, 5), above it.
TEST(ColmapModel, QuarterTurnWorkedByHand) {
  const std::vector<colmap_view> views = parse_colmap_model(
      one_camera, image_line("0.70710678118654757 0 0.70710678118654757 0 0 0 5", "a.jpg"), "m");
  const camera_pose& p = views[0].pose;
  expect_close(p.lookfrom, point3(5, 0, 0));
  expect_close(p.lookat - p.lookfrom, vec3(-1, 0, 0));
  const camera cam(p, 640.0 / 480.0, 640);
  expect_close(cam.lens_u(), vec3(0, 0, 1));
  expect_close(cam.lens_v(), vec3(0, -1, 0));
  expect_close(cam.axis_w(), vec3(1, 0, 0));
  EXPECT_NEAR(dot(point3(0, 0, 1) - p.lookfrom, cam.lens_u()), 1, 1e-12);   // right by 1
  EXPECT_NEAR(dot(point3(0, -1, 0) - p.lookfrom, cam.lens_v()), 1, 1e-12);  // up by 1
  EXPECT_NEAR(dot(point3(0, 0, 0) - p.lookfrom, -cam.axis_w()), 5, 1e-12);  // 5 in front
}

// Any pose: a world point's camera coordinates R p + t (R from glm's quaternion, independently
// of the reader) are its offsets from lookfrom along u, -v and -w. The quaternion is COLMAP's
// documentation's and not of unit length, as files written by hand may have it.
TEST(ColmapModel, PoseAgreesWithWorldToCameraTransform) {
  const double qw = 0.851773, qx = 0.0165051, qy = 0.503764, qz = -0.142941;
  const vec3 t(-0.737434, 1.02973, 3.74354);
  const std::vector<colmap_view> views = parse_colmap_model(
      one_camera,
      image_line("0.851773 0.0165051 0.503764 -0.142941 -0.737434 1.02973 3.74354", "P1180141.JPG"),
      "m");
  const glm::dmat3 R = glm::mat3_cast(glm::normalize(glm::dquat(qw, qx, qy, qz)));
  const camera_pose& p = views[0].pose;
  const camera cam(p, 640.0 / 480.0, 640);
  for (const point3& world : {point3(0, 0, 0), point3(1, 2, 3), point3(-4, 0.5, 7)}) {
    const vec3 c = R * world + t;
    const vec3 offset = world - p.lookfrom;
    EXPECT_NEAR(dot(offset, cam.lens_u()), c.x, 1e-12);
    EXPECT_NEAR(dot(offset, -cam.lens_v()), c.y, 1e-12);
    EXPECT_NEAR(dot(offset, -cam.axis_w()), c.z, 1e-12);
  }
  EXPECT_GT(dot(vec3(0, 0, 0) - p.lookfrom, -cam.axis_w()), 0);  // the origin is in front
  EXPECT_EQ(views[0].name, "P1180141");
  EXPECT_EQ(views[0].image_name, "P1180141.JPG");
}

TEST(ColmapModel, NamesAreValidAndUnique) {
  const std::string long_name(80, 'x');
  const std::vector<std::string> names = {
      "images/IMG 1.JPG", "a.jpg",          "a.png", "A.jpg", "a-2.jpg",  "all.png",
      ".hidden.png",      "cam0\\0001.png", "é.jpg", "noext", "x.tar.gz", long_name + ".jpg",
      long_name + ".png", "dir.d/file"};
  std::string images;
  for (std::size_t i = 0; i < names.size(); ++i)
    images += image_line("1 0 0 0 0 0 0", names[i], int(i) + 1);
  const std::vector<colmap_view> views = parse_colmap_model(one_camera, images, "m");
  ASSERT_EQ(views.size(), names.size());
  const std::vector<std::string> expected = {"images_IMG_1",
                                             "a",
                                             "a-2",
                                             "A-3",
                                             "a-2-2",
                                             "all_",
                                             "_hidden",
                                             "cam0_0001",
                                             "__",
                                             "noext",
                                             "x.tar",
                                             std::string(64, 'x'),
                                             std::string(62, 'x') + "-2",
                                             "dir.d_file"};
  std::set<std::string> seen;
  for (std::size_t i = 0; i < views.size(); ++i) {
    EXPECT_EQ(views[i].name, expected[i]) << names[i];
    EXPECT_EQ(views[i].image_name, names[i]);
    EXPECT_TRUE(valid_camera_name(views[i].name)) << views[i].name;
    EXPECT_TRUE(seen.insert(views[i].name).second) << views[i].name;
  }
}

// Comments anywhere, an image without points (a blank second line), points, the last image's
// second line missing, blank lines after it, CRLF line ends.
TEST(ColmapModel, ReadsImagesStrictlyByPairs) {
  const std::string images =
      "# Image list with two lines of data per image:\r\n"
      "1 1 0 0 0 0 0 0 1 a.jpg\r\n"
      "\r\n"
      "# a comment between images\r\n"
      "2 1 0 0 0 1 0 0 1 b.jpg\r\n"
      "2362.39 248.498 58396 1784.7 268.254 -1\r\n"
      "3 1 0 0 0 2 0 0 1 c c.jpg\r\n"
      "\r\n"
      "\r\n";
  const std::vector<colmap_view> views = parse_colmap_model(one_camera, images, "m");
  ASSERT_EQ(views.size(), 3u);
  EXPECT_EQ(views[1].pose.lookfrom, point3(-1, 0, 0));
  EXPECT_EQ(views[2].image_name, "c c.jpg");
  EXPECT_EQ(views[2].name, "c_c");
  EXPECT_EQ(views[2].pose.lookfrom, point3(-2, 0, 0));
}

TEST(ColmapModel, RefusesBadModelsNamingFileAndLine) {
  const std::string image = image_line("1 0 0 0 0 0 0", "a.jpg");
  struct bad_model {
    std::string cameras, images, fragment;
  };
  const bad_model cases[] = {
      {"# c\n1 SIMPLE_RADIAL_FISHEYE 640 480 1 2 3 4\n", image,
       "m/cameras.txt:2: camera model SIMPLE_RADIAL_FISHEYE is not supported; supported: "
       "SIMPLE_PINHOLE, PINHOLE, SIMPLE_RADIAL, RADIAL, OPENCV, FULL_OPENCV, OPENCV_FISHEYE"},
      {"1 FOV 640 480 1 2 3 4 5\n", image, "camera model FOV is not supported"},
      {"1 PINHOLE 640 480 500 500 320\n", image,
       "m/cameras.txt:1: camera model PINHOLE takes 4 parameters (fx fy cx cy), got 3"},
      {"1 PINHOLE 640 480 500 500 320 abc\n", image,
       "m/cameras.txt:1: parameter 4 must be a finite number, got 'abc'"},
      {"1 PINHOLE 640 480 500 nan 320 240\n", image, "parameter 2 must be a finite number"},
      {"1 PINHOLE 640 480 500 inf 320 240\n", image, "got 'inf'"},
      {"1 SIMPLE_PINHOLE 640 480 0 320 240\n", image,
       "m/cameras.txt:1: focal length must be > 0, got '0'"},
      {"1 PINHOLE 640 480 500 -1 320 240\n", image, "focal length must be > 0, got '-1'"},
      {"1 PINHOLE 0 480 500 500 320 240\n", image, "m/cameras.txt:1: WIDTH must be in [1, 65536]"},
      {"1 PINHOLE 640 65537 500 500 320 240\n", image, "HEIGHT must be in [1, 65536], got '65537'"},
      {"1 PINHOLE 640.0 480 500 500 320 240\n", image, "WIDTH must be a whole number"},
      {"-1 PINHOLE 640 480 500 500 320 240\n", image, "CAMERA_ID must be a whole number"},
      {"1 PINHOLE 640\n", image, "m/cameras.txt:1: expected CAMERA_ID MODEL WIDTH HEIGHT"},
      {one_camera + "\n1 PINHOLE 64 48 50 50 32 24\n", image,
       "m/cameras.txt:3: camera 1 is defined twice (first on line 1)"},
      {one_camera, "# x\n" + image_line("1 0 0 0 0 0 0", "a.jpg", 1, 2),
       "m/images.txt:2: camera 2 is not in m/cameras.txt"},
      {one_camera, image + image_line("1 0 0 0 0 0 0", "b.jpg", 1),
       "m/images.txt:3: image 1 is given twice (first on line 1)"},
      {one_camera, "# nothing\n\n", "m/images.txt: no images"},
      {one_camera, "", "m/images.txt: no images"},
      {one_camera, image_line("0 0 0 0 0 0 0", "a.jpg"),
       "m/images.txt:1: the rotation quaternion is zero"},
      {one_camera, image_line("1 0 0 0 0 0 1e309", "a.jpg"),
       "m/images.txt:1: TZ must be a finite number"},
      {one_camera, image_line("1 0 0 x 0 0 0", "a.jpg"),
       "m/images.txt:1: QZ must be a finite number, got 'x'"},
      {one_camera, image_line("0.7071 0 0.7071 0 0 0 1e300", "a.jpg"),
       "m/images.txt:1: the camera's center is too far"},
      {one_camera, "1 1 0 0 0 0 0 0 1\n\n",
       "m/images.txt:1: expected IMAGE_ID QW QX QY QZ TX TY TZ CAMERA_ID NAME"},
      {one_camera, "\n1 1 0 0 0 0 0 0 1 a.jpg\n", "m/images.txt:1: expected IMAGE_ID"},
      // The points line left out: the next image's line is read as points and refused.
      {one_camera, "1 1 0 0 0 0 0 0 1 a.jpg\n2 1 0 0 0 0 0 0 1 b.jpg\n3 1 0 0 0 0 0 0 1 c.jpg\n",
       "m/images.txt:2: expected image 1's 2D points"},
      {one_camera, "1 1 0 0 0 0 0 0 1 a.jpg\n1 2 3 4\n",
       "m/images.txt:2: image 1's 2D points must be X Y POINT3D_ID triples, got 4 numbers"},
  };
  for (const bad_model& c : cases) {
    const std::string got = message_of([&] { parse_colmap_model(c.cameras, c.images, "m"); });
    EXPECT_NE(got.find(c.fragment), std::string::npos)
        << c.cameras << c.images << "\n got: " << got;
  }
}

TEST(ColmapModel, ReadsAFolderAndItsBinaryModel) {
  const test::temp_dir dir;
  // A cameras.bin without cameras.txt is read as the binary model (test_colmap_binary.cpp).
  std::ofstream(dir.path() / "cameras.bin") << "binary";
  std::ofstream(dir.path() / "images.bin") << "x";
  const std::string got = message_of([&] { read_colmap_model(dir.path()); });
  EXPECT_NE(got.find("cameras.bin: the number of cameras: the file ends"), std::string::npos)
      << got;
  std::ofstream(dir.path() / "cameras.txt") << one_camera;
  EXPECT_NE(message_of([&] { read_colmap_model(dir.path()); }).find("images.txt"),
            std::string::npos);
  std::ofstream(dir.path() / "images.txt") << image_line("1 0 0 0 0 0 5", "x.jpg");
  const std::vector<colmap_view> views = read_colmap_model(dir.path());
  ASSERT_EQ(views.size(), 1u);
  EXPECT_EQ(views[0].pose.lookfrom, point3(0, 0, -5));
  EXPECT_EQ(views[0].pose.intrinsics.cx, 319.5);
  EXPECT_NE(message_of([&] { read_colmap_model(dir.path() / "images.txt"); }).find("not a folder"),
            std::string::npos);
}

}  // namespace
}  // namespace rtvk
