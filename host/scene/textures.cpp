#include "textures.h"

#include <stb_image.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <tuple>

#include "environment.h"
#include "errors.h"
#include "input_file.h"
#include "texture.h"

namespace rtvk {
namespace {

// splitmix64: a small, portable generator (the standard library's distributions differ between
// implementations; the noise must be the same everywhere).
struct splitmix {
  std::uint64_t state;
  std::uint64_t next() {
    std::uint64_t z = (state += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }
  double unit() { return double(next() >> 11) * 0x1.0p-53; }  // [0, 1)
};

}  // namespace

// The planet's texels, drawn (planet_image keeps them).
std::shared_ptr<const texel_image> draw_planet(int width, int height, std::uint32_t seed);

std::uint8_t linear_to_byte(float v) {
  if (!(v > 0)) return 0;
  if (v >= 1) return 255;
  return std::uint8_t(256.0f * v);
}

std::shared_ptr<const texel_image> load_texel_image(const std::filesystem::path& file,
                                                    const std::string& name,
                                                    texel_encoding encoding) {
  const std::string what = "image texture (" + name + ")";
  const std::string bytes = read_regular_file(file, max_texture_file_bytes, what);
  return decode_texel_image(bytes, name + ": " + file.string(), encoding);
}

std::shared_ptr<const texel_image> decode_texel_image(const std::string& bytes,
                                                      const std::string& where,
                                                      texel_encoding encoding) {
  const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
  const int length = int(std::min<std::size_t>(bytes.size(), 0x7fffffff));
  int w = 0, h = 0, channels = 0;
  if (!stbi_info_from_memory(data, length, &w, &h, &channels))
    throw usage_error(where + ": not an image stb_image reads (" + stbi_failure_reason() + ")");
  if (w > max_texture_side || h > max_texture_side ||
      std::uint64_t(w) * std::uint64_t(h) > max_texture_texels)
    throw usage_error(where + ": " + std::to_string(w) + "x" + std::to_string(h) +
                      " texels is past the limit (" + std::to_string(max_texture_side) +
                      " a side, " + std::to_string(max_texture_texels) + " in all)");
  stbi_uc* pixels = stbi_load_from_memory(data, length, &w, &h, &channels, 4);
  if (!pixels)
    throw usage_error(where + ": cannot decode the image (" + stbi_failure_reason() + ")");
  // The book's: stb_image's own LDR-to-linear rule (stbi_loadf: (byte / 255)^2.2 in float); sRGB:
  // IEC 61966-2-1's curve; then the book's byte per channel.
  std::array<std::uint8_t, 256> to_linear{};
  for (int b = 0; b < 256; ++b) {
    const float v = float(b) / 255.0f;
    const float linear = encoding == texel_encoding::book ? std::pow(v, 2.2f)
                         : encoding == texel_encoding::srgb
                             ? (v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f))
                             : v;
    to_linear[std::size_t(b)] = linear_to_byte(linear);
  }
  auto image = std::make_shared<texel_image>();
  image->width = w;
  image->height = h;
  image->texels.resize(std::size_t(w) * std::size_t(h));
  for (std::size_t i = 0; i < image->texels.size(); ++i) {
    const stbi_uc* p = pixels + 4 * i;
    image->texels[i] = std::uint32_t(to_linear[p[0]]) | std::uint32_t(to_linear[p[1]]) << 8 |
                       std::uint32_t(to_linear[p[2]]) << 16 | std::uint32_t(p[3]) << 24;
  }
  stbi_image_free(pixels);
  return image;
}

void check_environment_size(std::uint64_t width, std::uint64_t height, const std::string& where) {
  const std::uint64_t texel_bytes = 4 * width * height;
  const std::uint64_t table_bytes = 4 * ((width + 2) * height + RTVK_ENV_HEADER + 1);
  if (width == 0 || height == 0 || width > (1u << 24) || height > (1u << 24) ||
      texel_bytes > max_environment_buffer_bytes || table_bytes > max_environment_buffer_bytes)
    throw usage_error(where + ": " + std::to_string(width) + "x" + std::to_string(height) +
                      " texels is past the limit (texels and sampling table each within 128 MiB, "
                      "lavapipe's storage-buffer range: 6144x3072 fits, 8192x4096 does not)");
}

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
  check_environment_size(std::uint64_t(std::max(width, 0)), std::uint64_t(std::max(height, 0)),
                         where);
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

perlin_tables make_perlin(std::uint32_t seed) {
  splitmix rng{0x7065726c696eull ^ (std::uint64_t(seed) << 17)};
  perlin_tables t;
  for (vec3& v : t.vectors) {
    // The book's unit_vector(vec3::random(-1, 1)); a vector too short to normalize is drawn again.
    do {
      v = vec3(2 * rng.unit() - 1, 2 * rng.unit() - 1, 2 * rng.unit() - 1);
    } while (glm::dot(v, v) < 1e-6);
    v = v / std::sqrt(glm::dot(v, v));
  }
  for (std::size_t axis = 0; axis < 3; ++axis) {
    std::uint32_t* p = t.perm.data() + axis * RTVK_PERLIN_POINTS;
    for (std::uint32_t i = 0; i < RTVK_PERLIN_POINTS; ++i) p[i] = i;
    for (std::uint32_t i = RTVK_PERLIN_POINTS - 1; i > 0; --i)  // the book's shuffle
      std::swap(p[i], p[std::uint32_t(rng.next() % (i + 1))]);
  }
  return t;
}

std::shared_ptr<const texel_image> planet_image(int width, int height, std::uint32_t seed) {
  // Drawn once per size and seed: every scene and texture naming it shares the texels.
  static std::mutex lock;
  static std::map<std::tuple<int, int, std::uint32_t>, std::shared_ptr<const texel_image>> made;
  const std::lock_guard<std::mutex> hold(lock);
  std::shared_ptr<const texel_image>& cached = made[{width, height, seed}];
  if (!cached) cached = draw_planet(width, height, seed);
  return cached;
}

std::shared_ptr<const texel_image> draw_planet(int width, int height, std::uint32_t seed) {
  const perlin_tables noise = make_perlin(seed);
  const texture_tables tables{nullptr, nullptr, noise.vectors.data(), noise.perm.data()};
  auto image = std::make_shared<texel_image>();
  image->width = width;
  image->height = height;
  image->texels.resize(std::size_t(width) * std::size_t(height));
  const auto pack = [](color c) {
    return std::uint32_t(linear_to_byte(float(c.x))) |
           std::uint32_t(linear_to_byte(float(c.y))) << 8 |
           std::uint32_t(linear_to_byte(float(c.z))) << 16 | 0xff000000u;
  };
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i) {
      // The texel's direction, as sphere_uv maps a sphere onto (u, v) (row 0 is v = 1: the top).
      const double u = (i + 0.5) / width, v = 1 - (j + 0.5) / height;
      const double theta = v * pi, phi = u * 2 * pi - pi;
      const vec3 n(-std::sin(theta) * std::cos(phi), -std::cos(theta),
                   std::sin(theta) * std::sin(phi));
      const double height_at = perlin_noise(tables, 1.6 * n) + 0.5 * perlin_noise(tables, 3.2 * n) +
                               0.25 * perlin_noise(tables, 6.4 * n);
      const double latitude = std::abs(0.5 - v) * 2;  // 0 at the equator, 1 at the poles
      color c;
      if (latitude + 0.1 * height_at > 0.86)
        c = color(0.85, 0.88, 0.9);  // ice
      else if (height_at < 0.05)
        c = glm::mix(color(0.01, 0.03, 0.12), color(0.03, 0.12, 0.3),
                     std::clamp(height_at + 0.6, 0.0, 1.0));
      else
        c = glm::mix(color(0.08, 0.22, 0.04), color(0.3, 0.22, 0.1),
                     std::clamp(height_at * 2, 0.0, 1.0));
      image->texels[std::size_t(j) * std::size_t(width) + std::size_t(i)] = pack(c);
    }
  return image;
}

packed_textures pack_textures(const std::vector<texture>& textures) {
  packed_textures out;
  std::map<const texel_image*, std::uint32_t> first_of;  // images packed so far
  for (const texture& t : textures) {
    texture_record r;
    r.type = std::uint32_t(t.type);
    r.even = t.even;
    r.odd = t.odd;
    r.scale = t.scale;
    r.style = std::uint32_t(t.style);
    if (t.type == texture_type::image && t.image) {
      const auto [at, added] =
          first_of.try_emplace(t.image.get(), std::uint32_t(out.texels.size()));
      if (added)
        out.texels.insert(out.texels.end(), t.image->texels.begin(), t.image->texels.end());
      r.first = at->second;
      r.width = std::uint32_t(t.image->width);
      r.height = std::uint32_t(t.image->height);
      r.style = std::uint32_t(t.wrap_u) | std::uint32_t(t.wrap_v) << 2;
    }
    out.records.push_back(r);
  }
  return out;
}

std::string wrap_name(image_wrap w) {
  switch (w) {
    case image_wrap::clamp:
      return "clamp";
    case image_wrap::repeat:
      return "repeat";
    case image_wrap::mirror:
      return "mirror";
  }
  return "clamp";
}

std::string type_name(texture_type t) {
  switch (t) {
    case texture_type::checker:
      return "checker";
    case texture_type::image:
      return "image";
    case texture_type::noise:
      return "noise";
  }
  return "checker";
}

std::string style_name(noise_style s) {
  switch (s) {
    case noise_style::smooth:
      return "smooth";
    case noise_style::turbulence:
      return "turbulence";
    case noise_style::marble:
      return "marble";
  }
  return "marble";
}

}  // namespace rtvk
