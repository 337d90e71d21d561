#pragma once
#include <cstdint>
#include <filesystem>
#include <string>

#include "image_rgb8.h"

namespace rtvk {

enum class file_format { ppm, png, exr };
enum class ppm_encoding { ascii_p3, binary_p6 };

// The format for an output path, from its extension (.ppm, .png or .exr, any case).
// Throws usage_error naming the flag and the path for anything else.
file_format format_for_path(const std::filesystem::path& path, const std::string& flag);

// Checks, before any work is done, that `path` can be written: known extension, existing folder.
// Throws usage_error naming the flag and the value.
// .exr only where `float_ok` (linear float output: rtvk render and rtvk merge).
void check_output_path(const std::filesystem::path& path, const std::string& flag,
                       bool float_ok = false);

// The largest PNG rtvk writes, in bytes of filtered rows ((3 x width + 1) x height): libstb's
// PNG encoder keeps those rows and its deflate stream in buffers sized with int and grows the
// stream by doubling, so past about 1 GiB it overflows (a 65536x65536 PNG crashed rtvk with
// SIGSEGV). 900 MiB is 17,700 pixels square; larger images go to .exr or .ppm.
inline constexpr std::uint64_t max_png_row_bytes = std::uint64_t(900) << 20;

// Checks, before any work, that an image of width x height can be written to `path` in its
// format. Throws usage_error naming the flag, the size and the limit.
void check_output_size(const std::filesystem::path& path, int width, int height,
                       const std::string& flag);

std::string encode_ppm(const image_rgb8& img, ppm_encoding enc);
std::string encode_png(const image_rgb8& img);

// Encodes by the path's extension and writes atomically (never a partial file at `path`).
void write_image(const image_rgb8& img, const std::filesystem::path& path,
                 ppm_encoding enc = ppm_encoding::ascii_p3);

// Thrown when a file cannot be read or is not a valid image.
class image_read_error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The largest image file `rtvk compare` reads (a P3 file of the largest image is far larger, but
// anything above this would not fit the memory of the machines rtvk runs on anyway).
inline constexpr std::uint64_t max_image_file_bytes = std::uint64_t(4) << 30;

// Reads PNG or PPM (P3 or P6, any maxval up to 255), told apart by content, not name.
image_rgb8 read_image(const std::filesystem::path& path);
image_rgb8 decode_ppm(const std::string& bytes, const std::string& name);

}  // namespace rtvk
