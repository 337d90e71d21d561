#include "image_io.h"

#include <stb_image.h>
#include <stb_image_write.h>

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>

#include "atomic_file.h"
#include "errors.h"
#include "format.h"
#include "image_size.h"
#include "input_file.h"

namespace rtvk {
namespace fs = std::filesystem;

file_format format_for_path(const fs::path& path, const std::string& flag) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  if (ext == ".ppm") return file_format::ppm;
  if (ext == ".png") return file_format::png;
  if (ext == ".exr") return file_format::exr;
  throw usage_error(flag + ": unknown image extension in '" + path.string() +
                    "' (expected .png, .ppm or .exr)");
}

void check_output_path(const fs::path& path, const std::string& flag, bool float_ok) {
  if (format_for_path(path, flag) == file_format::exr && !float_ok)
    throw usage_error(flag + ": '" + path.string() +
                      "': OpenEXR is for rtvk render and rtvk merge; use .png or .ppm");
  const fs::path dir = path.has_parent_path() ? path.parent_path() : fs::path(".");
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
    throw usage_error(flag + ": folder '" + dir.string() + "' of '" + path.string() +
                      "' does not exist");
  if (fs::is_directory(path, ec))
    throw usage_error(flag + ": '" + path.string() + "' is a folder, not a file name");
  // Try what the final write will do -- create a file in the folder -- before any work, so a
  // read-only folder or file system fails now (also as root, where permission bits do not).
  if (const int err = try_create_in(dir); err != 0)
    throw usage_error(flag + ": cannot write in folder '" + dir.string() + "' of '" +
                      path.string() + "': " + std::strerror(err));
}

namespace {

std::uint64_t png_row_bytes(int width, int height) {
  return (3 * std::uint64_t(width) + 1) * std::uint64_t(height);
}

}  // namespace

void check_output_size(const fs::path& path, int width, int height, const std::string& flag) {
  if (format_for_path(path, flag) != file_format::png) return;
  const std::uint64_t rows = png_row_bytes(width, height);
  if (rows > max_png_row_bytes)
    throw usage_error(flag + ": '" + path.string() + "': a " + std::to_string(width) + "x" +
                      std::to_string(height) + " PNG has " + format_bytes(rows) +
                      " of rows to compress, more than the PNG encoder handles (" +
                      format_bytes(max_png_row_bytes) + "); write .exr or .ppm");
}

std::string encode_ppm(const image_rgb8& img, ppm_encoding enc) {
  std::ostringstream out;
  if (enc == ppm_encoding::binary_p6) {
    out << "P6\n" << img.width << ' ' << img.height << "\n255\n";
    out.write(reinterpret_cast<const char*>(img.rgb.data()), std::streamsize(img.rgb.size()));
    return out.str();
  }
  // P3 exactly as the lesson prints it: one "r g b" line per pixel.
  out << "P3\n" << img.width << ' ' << img.height << "\n255\n";
  for (std::size_t i = 0; i < img.rgb.size(); i += 3)
    out << int(img.rgb[i]) << ' ' << int(img.rgb[i + 1]) << ' ' << int(img.rgb[i + 2]) << '\n';
  return out.str();
}

std::string encode_png(const image_rgb8& img) {
  if (png_row_bytes(img.width, img.height) > max_png_row_bytes)
    throw std::runtime_error("PNG encoding: a " + std::to_string(img.width) + "x" +
                             std::to_string(img.height) + " image is past the encoder's size");
  std::string out;
  auto append = [](void* ctx, void* data, int size) {
    static_cast<std::string*>(ctx)->append(static_cast<const char*>(data), std::size_t(size));
  };
  if (!stbi_write_png_to_func(append, &out, img.width, img.height, 3, img.rgb.data(),
                              img.width * 3))
    throw std::runtime_error("stbi_write_png_to_func: PNG encoding failed");
  return out;
}

void write_image(const image_rgb8& img, const fs::path& path, ppm_encoding enc) {
  const file_format fmt = format_for_path(path, "output");
  if (fmt == file_format::exr)
    throw std::logic_error("write_image: " + path.string() +
                           ": 8-bit images are not written as "
                           "OpenEXR; write a partial_image");
  write_file_atomically(path, fmt == file_format::png ? encode_png(img) : encode_ppm(img, enc));
}

namespace {

// Reads the whitespace- and comment-separated header tokens of a PPM.
class ppm_reader {
 public:
  ppm_reader(const std::string& bytes, const std::string& name) : b_(bytes), name_(name) {}

  [[noreturn]] void fail(const std::string& what) const {
    throw image_read_error(name_ + ": " + what);
  }

  void skip_space_and_comments() {
    while (pos_ < b_.size()) {
      if (std::isspace(static_cast<unsigned char>(b_[pos_]))) {
        ++pos_;
      } else if (b_[pos_] == '#') {
        while (pos_ < b_.size() && b_[pos_] != '\n') ++pos_;
      } else {
        break;
      }
    }
  }

  // A decimal number in [lo, hi]; `what` names it in the error message.
  int number(const char* what, int lo, int hi) {
    skip_space_and_comments();
    if (pos_ >= b_.size()) fail(std::string("truncated: missing ") + what);
    long long v = 0;
    std::size_t digits = 0;
    while (pos_ < b_.size() && std::isdigit(static_cast<unsigned char>(b_[pos_])) && digits < 12) {
      v = v * 10 + (b_[pos_++] - '0');
      ++digits;
    }
    if (digits == 0) fail(std::string("expected a number for ") + what);
    if (v < lo || v > hi)
      fail(std::string(what) + " " + std::to_string(v) + " is outside [" + std::to_string(lo) +
           ", " + std::to_string(hi) + "]");
    return int(v);
  }

  std::size_t pos_ = 0;  // read position in b_

 private:
  const std::string& b_;     // the whole file
  const std::string& name_;  // for messages
};

std::uint8_t rescale(int v, int maxval) {
  return static_cast<std::uint8_t>((v * 255 + maxval / 2) / maxval);
}

}  // namespace

image_rgb8 decode_ppm(const std::string& bytes, const std::string& name) {
  ppm_reader r(bytes, name);
  if (bytes.size() < 2 || bytes[0] != 'P' || (bytes[1] != '3' && bytes[1] != '6'))
    r.fail("not a P3 or P6 PPM file");
  const bool binary = bytes[1] == '6';
  r.pos_ = 2;
  image_rgb8 img;
  img.width = r.number("width", 1, max_image_side);
  img.height = r.number("height", 1, max_image_side);
  const int maxval = r.number("maxval", 1, 255);
  if (binary) ++r.pos_;  // exactly one whitespace byte separates the header from the raster
  // Checked before allocating, so a forged header cannot ask for gigabytes.
  const std::size_t have = r.pos_ <= bytes.size() ? bytes.size() - r.pos_ : 0;
  const std::size_t need = binary ? img.size_bytes() : 2 * img.size_bytes() - 1;
  if (have < need)
    r.fail("truncated: expected at least " + std::to_string(need) + " bytes of pixel data, found " +
           std::to_string(have));
  img.rgb.resize(img.size_bytes());
  if (binary) {
    for (std::size_t i = 0; i < img.rgb.size(); ++i) {
      const int v = static_cast<unsigned char>(bytes[r.pos_ + i]);
      if (v > maxval) r.fail("sample " + std::to_string(v) + " exceeds maxval");
      img.rgb[i] = rescale(v, maxval);
    }
  } else {
    for (auto& c : img.rgb) c = rescale(r.number("pixel sample", 0, maxval), maxval);
  }
  return img;
}

image_rgb8 read_image(const fs::path& path) {
  std::string bytes;
  try {
    bytes = read_regular_file(path, max_image_file_bytes, "image file");
  } catch (const usage_error& e) {
    throw image_read_error(e.what());
  }

  static constexpr char png_magic[] = "\x89PNG\r\n\x1a\n";
  if (bytes.compare(0, 8, png_magic, 8) == 0) {
    int w = 0, h = 0, n = 0;
    stbi_uc* data = stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()),
                                          int(bytes.size()), &w, &h, &n, 3);
    if (!data)
      throw image_read_error(path.string() + ": invalid PNG (" + stbi_failure_reason() + ")");
    image_rgb8 img{w, h, {}};
    img.rgb.assign(data, data + img.size_bytes());
    stbi_image_free(data);
    return img;
  }
  if (bytes.size() >= 2 && bytes[0] == 'P' && (bytes[1] == '3' || bytes[1] == '6'))
    return decode_ppm(bytes, path.string());
  throw image_read_error(path.string() + ": not a PNG or PPM (P3/P6) image");
}

}  // namespace rtvk
