#pragma once
// COLMAP's models, text (cameras.txt and images.txt, as `colmap model_converter --output_type TXT`
// writes them) or binary (cameras.bin and images.bin, what COLMAP writes by default): one rtvk
// camera per registered image, placed and calibrated as COLMAP solved it.
//
// Camera models: SIMPLE_PINHOLE, PINHOLE, SIMPLE_RADIAL, RADIAL, OPENCV and FULL_OPENCV become
// opencv (coefficients in OpenCV's order k1 k2 p1 p2 k3 k4 k5 k6, the missing ones 0);
// OPENCV_FISHEYE becomes opencv-fisheye (k1 k2 k3 k4). The others are refused.
// COLMAP puts the image's top-left corner at (0, 0); rtvk (as OpenCV) puts the first pixel's
// center there, so the principal point moves by half a pixel: cx = cx_colmap - 0.5.
//
// Camera names: the image's NAME without its extension, folder separators and every character
// outside [A-Za-z0-9._-] replaced by '_' ("cam0/IMG 1.jpg" -> "cam0_IMG_1"), a leading '.' too,
// cut to 64 characters; "all" becomes "all_", nothing becomes "image". Names that repeat one
// before them -- ignoring case, so that they stay distinct files on any file system -- get
// "-2", "-3", ... in images.txt's order (cut shorter where the suffix would pass 64).
#include <filesystem>
#include <string>
#include <vector>

#include "camera.h"

namespace rtvk {

// One registered image of the model, as an rtvk camera.
struct colmap_view {
  std::string name;        // rtvk's camera name, unique, valid_camera_name (see above)
  std::string image_name;  // NAME as images.txt writes it
  camera_pose pose;        // where COLMAP put the camera: lookfrom its center, looking along its
                           // +z, vup its -y; projection opencv or opencv_fisheye, intrinsics
};

// Reads DIR/cameras.txt and DIR/images.txt, or where there is no cameras.txt but a cameras.bin,
// DIR/cameras.bin and DIR/images.bin: one view per image, in the images file's order. Throws
// usage_error.
std::vector<colmap_view> read_colmap_model(const std::filesystem::path& dir);

// The same from the two files' text; `dir_name` is the folder, for messages, which read
// "DIR/cameras.txt:LINE: what". Throws usage_error; at least one image is returned.
std::vector<colmap_view> parse_colmap_model(const std::string& cameras_txt,
                                            const std::string& images_txt,
                                            const std::string& dir_name);

// The same from the binary files' bytes (colmap_binary.cpp says their layout); messages read
// "DIR/images.bin: image 2 of 5, at byte 130: QW: what". Throws usage_error; at least one image
// is returned.
std::vector<colmap_view> parse_colmap_binary(const std::string& cameras_bin,
                                             const std::string& images_bin,
                                             const std::string& dir_name);

}  // namespace rtvk
