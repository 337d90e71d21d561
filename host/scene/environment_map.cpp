#include "environment_map.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfInputFile.h>
#include <stb_image.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "errors.h"
#include "input_file.h"
#include "vec3.h"

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

// The limit's test, before any texel is decoded.
void check_size(std::uint64_t width, std::uint64_t height, const std::string& where) {
  const std::uint64_t texel_bytes = 4 * width * height;
  const std::uint64_t table_bytes = 4 * ((width + 2) * height + RTVK_ENV_HEADER + 1);
  if (width == 0 || height == 0 || width > (1u << 24) || height > (1u << 24) ||
      texel_bytes > max_environment_buffer_bytes || table_bytes > max_environment_buffer_bytes)
    throw usage_error(where + ": " + std::to_string(width) + "x" + std::to_string(height) +
                      " texels is past the limit (texels and sampling table each within 128 MiB, "
                      "lavapipe's storage-buffer range: 6144x3072 fits, 8192x4096 does not)");
}

std::vector<float> decode_exr(const std::string& bytes, const std::string& where) {
  exr_bytes stream(bytes, where);
  Imf::InputFile file(stream, 1);
  const Imath::Box2i window = file.header().dataWindow();
  const std::int64_t width = std::int64_t(window.max.x) - window.min.x + 1;
  const std::int64_t height = std::int64_t(window.max.y) - window.min.y + 1;
  check_size(std::uint64_t(std::max<std::int64_t>(width, 0)),
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
  check_size(std::uint64_t(w), std::uint64_t(h), where);
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

// Rec. 709 luminance.
double luminance(const color& c) {
  return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z;
}

color decode(std::uint32_t w) {
  const std::uint32_t e = w >> 24;
  if (e == 0) return color(0);
  const double s = std::ldexp(1.0, int(e) - 136);
  return color((w & 255) * s, ((w >> 8) & 255) * s, ((w >> 16) & 255) * s);
}

// Writes a CDF of the weights (n + 1 entries from `out`): 0, the running sums over their total,
// 1; a uniform one where the total is 0. Returns the total.
double write_cdf(const std::vector<double>& weights, float* out) {
  double total = 0;
  for (double w : weights) total += w;
  const std::size_t n = weights.size();
  double sum = 0;
  out[0] = 0.0f;
  for (std::size_t i = 1; i < n; ++i) {
    sum += weights[i - 1];
    out[i] = total > 0 ? float(sum / total) : float(double(i) / double(n));
  }
  out[n] = 1.0f;
  return total;
}

// ceil(log2(n)): the trips of environment_search over n steps.
std::uint32_t search_trips(std::uint64_t n) {
  std::uint32_t trips = 0;
  while ((std::uint64_t(1) << trips) < n) ++trips;
  return trips;
}

}  // namespace

std::uint32_t encode_rgbe(float r, float g, float b) {
  const float largest = std::max({r, g, b});
  if (!(largest >= 0x1p-118f)) return 0;  // below what the GPU's decode builds (e >= 10)
  int e = 0;
  std::frexp(largest, &e);  // largest = f 2^e, f in [0.5, 1)
  const double scale = std::ldexp(1.0, 8 - e);
  auto mantissa = [&](float c) { return std::uint32_t(std::min(255.0, std::floor(c * scale))); };
  return mantissa(r) | mantissa(g) << 8 | mantissa(b) << 16 | std::uint32_t(e + 128) << 24;
}

std::shared_ptr<const environment_image> environment_from_rgb(int width, int height,
                                                              const std::vector<float>& rgb,
                                                              const std::string& where) {
  check_size(std::uint64_t(std::max(width, 0)), std::uint64_t(std::max(height, 0)), where);
  auto image = std::make_shared<environment_image>();
  image->width = width;
  image->height = height;
  const std::size_t n = std::size_t(width) * std::size_t(height);
  image->texels.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const float* t = &rgb[3 * i];
    for (int c = 0; c < 3; ++c)
      if (!(t[c] >= 0 && t[c] < 0x1p127f))  // NaN fails too; RGBE's exponent ends at 2^127
        throw usage_error(where + ": texel " + std::to_string(i % std::size_t(width)) + "," +
                          std::to_string(i / std::size_t(width)) + " is " + std::to_string(t[c]) +
                          " (expected finite radiance, 0 to 1.7e38)");
    image->texels[i] = encode_rgbe(t[0], t[1], t[2]);
  }
  return image;
}

std::shared_ptr<const environment_image> load_environment_image(const std::filesystem::path& file,
                                                                const std::string& name) {
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

std::vector<float> environment_table_of(const environment_map& e) {
  const environment_image& image = *e.image;
  const std::size_t w = std::size_t(image.width), h = std::size_t(image.height);
  std::vector<float> table(RTVK_ENV_HEADER + (h + 1) + h * (w + 1), 0.0f);
  const double radians = e.rotation * 3.14159265358979323846 / 180.0;
  table[RTVK_ENV_WIDTH] = float(w);
  table[RTVK_ENV_HEIGHT] = float(h);
  table[RTVK_ENV_STRENGTH] = float(e.strength);
  table[RTVK_ENV_COS] = float(std::cos(radians));
  table[RTVK_ENV_SIN] = float(std::sin(radians));
  table[RTVK_ENV_VISIBLE] = e.visible ? 1.0f : 0.0f;
  table[RTVK_ENV_TRIPS] = float(search_trips(w) + search_trips(h));
  // Each texel weighs its luminance times sin(theta) at its row's center: the solid angle a row
  // spans shrinks toward the poles.
  std::vector<double> rows(h), texels(w);
  for (std::size_t y = 0; y < h; ++y) {
    const double sin_theta = std::sin(3.14159265358979323846 * (double(y) + 0.5) / double(h));
    for (std::size_t x = 0; x < w; ++x)
      texels[x] = luminance(decode(image.texels[y * w + x])) * sin_theta;
    rows[y] = write_cdf(texels, &table[RTVK_ENV_HEADER + h + 1 + y * (w + 1)]);
  }
  write_cdf(rows, &table[RTVK_ENV_HEADER]);
  return table;
}

}  // namespace rtvk
