// HDR environment maps' files (docs/lighting.md): Radiance .hdr through stb_image, after a walk
// of its scanlines (stb_image reads a truncated file as zeros), and OpenEXR .exr, told apart by
// content; both into RGBE texels (textures.h's environment_from_rgb).
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfInputFile.h>
#include <stb_image.h>

#include <algorithm>
#include <cstring>

#include "builtin_showcase.h"
#include "errors.h"
#include "input_file.h"
#include "scene_file.h"

namespace rtvk {
namespace {

// An OpenEXR file read from memory (the bytes read_regular_file read, under its limits).
class exr_bytes final : public Imf::IStream {
 public:
  exr_bytes(const std::string& bytes, const std::string& name)
      : Imf::IStream(name.c_str()), bytes_(bytes) {}
  bool read(char c[], int n) override {
    if (n < 0 || std::uint64_t(n) > bytes_.size() - at_)
      throw std::runtime_error("the file ends early (truncated)");
    std::memcpy(c, bytes_.data() + at_, std::size_t(n));
    at_ += std::uint64_t(n);
    return at_ < bytes_.size();
  }
  std::uint64_t tellg() override { return at_; }
  void seekg(std::uint64_t pos) override { at_ = std::min<std::uint64_t>(pos, bytes_.size()); }

 private:
  const std::string& bytes_;
  std::uint64_t at_ = 0;
};

bool is_exr(const std::string& bytes) {
  return bytes.size() >= 4 && std::uint8_t(bytes[0]) == 0x76 && std::uint8_t(bytes[1]) == 0x2f &&
         std::uint8_t(bytes[2]) == 0x31 && std::uint8_t(bytes[3]) == 0x01;
}

// An OpenEXR file's R, G and B as float RGB, then its width and height (two more floats).
std::vector<float> decode_exr(const std::string& bytes, const std::string& where) {
  exr_bytes stream(bytes, where);
  Imf::InputFile file(stream, 1);
  const Imath::Box2i window = file.header().dataWindow();
  const std::int64_t width = std::int64_t(window.max.x) - window.min.x + 1;
  const std::int64_t height = std::int64_t(window.max.y) - window.min.y + 1;
  check_environment_size(std::uint64_t(std::max<std::int64_t>(width, 0)),
                         std::uint64_t(std::max<std::int64_t>(height, 0)), where);
  const Imf::ChannelList& channels = file.header().channels();
  for (const char* c : {"R", "G", "B"})
    if (!channels.findChannel(c))
      throw usage_error(where + ": an OpenEXR file without an " + c +
                        " channel (expected R, G and B)");
  std::vector<float> rgb(std::size_t(width * height) * 3);
  // The frame buffer's base points at the data window's origin.
  char* base = reinterpret_cast<char*>(rgb.data()) -
               (std::ptrdiff_t(window.min.x) + std::ptrdiff_t(window.min.y) * width) * 12;
  Imf::FrameBuffer fb;
  fb.insert("R", Imf::Slice(Imf::FLOAT, base, 12, std::size_t(width) * 12));
  fb.insert("G", Imf::Slice(Imf::FLOAT, base + 4, 12, std::size_t(width) * 12));
  fb.insert("B", Imf::Slice(Imf::FLOAT, base + 8, 12, std::size_t(width) * 12));
  file.setFrameBuffer(fb);
  file.readPixels(window.min.y, window.max.y);
  rgb.push_back(float(width));
  rgb.push_back(float(height));
  return rgb;
}

// Whether a Radiance file's scanlines are all there: stb_image reads a truncated file without a
// complaint (past the end as zeros), so its data is walked first as stb_image decodes it -- a
// scanline run-length encoded where it starts 2, 2 and its width (and the width is 8 to 32767),
// else every remaining scanline flat, 4 bytes a texel.
bool hdr_complete(const std::string& bytes, std::uint64_t width, std::uint64_t height) {
  const std::size_t header_end = bytes.find("\n\n");
  if (header_end == std::string::npos) return false;
  std::size_t at = bytes.find('\n', header_end + 2);  // past the resolution line
  if (at == std::string::npos) return false;
  ++at;
  const auto byte = [&](std::size_t i) { return std::uint8_t(bytes[i]); };
  for (std::uint64_t row = 0; row < height; ++row) {
    const bool rle = width >= 8 && width < 32768 && at + 4 <= bytes.size() && byte(at) == 2 &&
                     byte(at + 1) == 2 && (byte(at + 2) & 0x80) == 0;
    if (!rle) return bytes.size() - at >= 4 * width * (height - row);
    at += 4;
    for (int channel = 0; channel < 4; ++channel) {
      for (std::uint64_t x = 0; x < width;) {
        if (at >= bytes.size()) return false;
        const std::uint32_t count = byte(at++);
        const bool run = count > 128;
        const std::uint32_t n = run ? count - 128 : count;
        if (n == 0 || x + n > width) return false;  // stb_image's "bad RLE data"
        at += run ? 1 : n;
        if (at > bytes.size()) return false;
        x += n;
      }
    }
  }
  return true;
}

std::vector<float> decode_hdr(const std::string& bytes, const std::string& where) {
  const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
  const int length = int(std::min<std::size_t>(bytes.size(), 0x7fffffff));
  int w = 0, h = 0, channels = 0;
  if (!stbi_is_hdr_from_memory(data, length) ||
      !stbi_info_from_memory(data, length, &w, &h, &channels))
    throw usage_error(where + ": not a Radiance .hdr or OpenEXR .exr image");
  check_environment_size(std::uint64_t(w), std::uint64_t(h), where);
  if (!hdr_complete(bytes, std::uint64_t(w), std::uint64_t(h)))
    throw usage_error(where + ": the file ends early (truncated) or its scanlines are damaged");
  float* pixels = stbi_loadf_from_memory(data, length, &w, &h, &channels, 3);
  if (!pixels)
    throw usage_error(where + ": cannot decode the image (" + stbi_failure_reason() + ")");
  std::vector<float> rgb(pixels, pixels + std::size_t(w) * std::size_t(h) * 3);
  stbi_image_free(pixels);
  rgb.push_back(float(w));
  rgb.push_back(float(h));
  return rgb;
}

}  // namespace

std::shared_ptr<const environment_image> load_environment_image(const std::filesystem::path& file,
                                                                const std::string& name) {
  if (file == builtin_sky_sun) return sky_sun_image();  // rtvk's own, drawn rather than read
  const std::string bytes = read_regular_file(file, max_environment_file_bytes, name);
  return decode_environment_image(bytes, name + " " + file.string());
}

std::shared_ptr<const environment_image> decode_environment_image(const std::string& bytes,
                                                                  const std::string& where) {
  std::vector<float> rgb;
  try {
    rgb = is_exr(bytes) ? decode_exr(bytes, where) : decode_hdr(bytes, where);
  } catch (const usage_error&) {
    throw;
  } catch (const std::exception& e) {  // OpenEXR's: a truncated or damaged file
    throw usage_error(where + ": cannot decode the image (" + e.what() + ")");
  }
  const int height = int(rgb.back());
  rgb.pop_back();
  const int width = int(rgb.back());
  rgb.pop_back();
  return environment_from_rgb(width, height, rgb, where);
}

}  // namespace rtvk
