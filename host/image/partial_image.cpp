#include "partial_image.h"

#include <ImfChannelList.h>
#include <ImfDoubleAttribute.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfInputFile.h>
#include <ImfIntAttribute.h>
#include <ImfOutputFile.h>
#include <ImfStringAttribute.h>
#include <ImfVecAttribute.h>

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <exception>
#include <optional>

#include "atomic_file.h"
#include "errors.h"
#include "format.h"
#include "image_io.h"
#include "image_size.h"
#include "input_file.h"
#include "memory_check.h"

namespace rtvk {
namespace {

// OpenEXR writes through a stream; this one collects the bytes, so the file can be written
// atomically afterwards like every other rtvk output.
class memory_stream final : public Imf::OStream {
 public:
  memory_stream() : Imf::OStream("memory") {}
  void write(const char c[], int n) override {
    if (pos_ + std::size_t(n) > bytes_.size()) bytes_.resize(pos_ + std::size_t(n));
    std::memcpy(bytes_.data() + pos_, c, std::size_t(n));
    pos_ += std::size_t(n);
  }
  uint64_t tellp() override { return pos_; }
  void seekp(uint64_t pos) override { pos_ = std::size_t(pos); }
  const std::string& bytes() const { return bytes_; }

 private:
  std::string bytes_;
  std::size_t pos_ = 0;
};

// OpenEXR reads through a stream; this one reads the descriptor rtvk opened and checked, so the
// file read is the file checked.
class descriptor_stream final : public Imf::IStream {
 public:
  explicit descriptor_stream(const regular_file& file)
      : Imf::IStream(file.path().c_str()), file_(file) {}
  bool read(char c[], int n) override {
    std::size_t got = 0;
    while (got < std::size_t(n)) {
      const ssize_t r = ::pread(file_.fd(), c + got, std::size_t(n) - got, off_t(pos_ + got));
      if (r < 0 && errno == EINTR) continue;
      if (r <= 0)
        throw std::runtime_error("early end of file: read " + std::to_string(got) + " of " +
                                 std::to_string(n) + " bytes at " + std::to_string(pos_));
      got += std::size_t(r);
    }
    pos_ += std::uint64_t(n);
    return pos_ < file_.size();
  }
  uint64_t tellg() override { return pos_; }
  void seekg(uint64_t pos) override { pos_ = pos; }

 private:
  const regular_file& file_;  // open and checked
  std::uint64_t pos_ = 0;     // where the next read starts
};

Imf::FrameBuffer slices(float* rgb, const Imath::Box2i& data_window) {
  Imf::FrameBuffer fb;
  const char* names[] = {"R", "G", "B"};
  for (int c = 0; c < 3; ++c)
    fb.insert(names[c],
              Imf::Slice::Make(Imf::FLOAT, rgb + c, data_window, 3 * sizeof(float),
                               std::size_t(data_window.size().x + 1) * 3 * sizeof(float)));
  return fb;
}

// The channels of the AOVs `which` of `a` (aov_image.h's names), declared and sliced.
void add_aov_channels(const aov_image& a, unsigned which, const Imath::Box2i& data, Imf::Header& h,
                      Imf::FrameBuffer& fb) {
  const std::size_t row = std::size_t(data.size().x + 1);
  const auto add = [&](const char* name, Imf::PixelType type, const void* base, int stride) {
    h.channels().insert(name, Imf::Channel(type));
    // Slices take non-const pointers for both directions; an OutputFile only reads them.
    char* p = static_cast<char*>(const_cast<void*>(base));
    fb.insert(name, Imf::Slice::Make(type, p, data, std::size_t(stride), row * stride));
  };
  if (which & aov_depth) {
    add("distance", Imf::FLOAT, a.distance.data(), sizeof(float));
    add("Z", Imf::FLOAT, a.depth.data(), sizeof(float));
  }
  const auto add3 = [&](const char* const(&names)[3], const float* base) {
    for (int c = 0; c < 3; ++c) add(names[c], Imf::FLOAT, base + c, 3 * sizeof(float));
  };
  if (which & aov_normal) add3({"N.X", "N.Y", "N.Z"}, a.normal.data());
  if (which & aov_albedo) add3({"albedo.R", "albedo.G", "albedo.B"}, a.albedo.data());
  if (which & aov_object_id) add("object_id", Imf::UINT, a.object_id.data(), sizeof(std::uint32_t));
  if (which & aov_material_id)
    add("material_id", Imf::UINT, a.material_id.data(), sizeof(std::uint32_t));
}

// Encodes `rows` rows of `fb` under header `h` in memory, then writes the file atomically.
void encode_and_write(const Imf::Header& h, const Imf::FrameBuffer& fb, int rows,
                      const std::filesystem::path& path) {
  memory_stream out;
  try {
    Imf::OutputFile file(out, h, 1);
    file.setFrameBuffer(fb);
    file.writePixels(rows);
  } catch (const std::exception& e) {
    throw std::runtime_error("OpenEXR: encoding " + path.string() + ": " + e.what());
  }
  write_file_atomically(path, out.bytes());
}

// The value of an attribute rtvk 0.1.0 pieces may lack, or empty.
std::string optional_string(const Imf::Header& h, const char* name) {
  const Imf::StringAttribute* a = h.findTypedAttribute<Imf::StringAttribute>(name);
  return a ? a->value() : std::string();
}

// The piece's view transform and exposure, where it has them (gamma at 0 EV where not).
void read_encoding(const Imf::Header& h, const std::string& file, partial_image& p) {
  const std::string word = optional_string(h, "rtvk.view_transform");
  if (!word.empty()) {
    const auto t = view_transform_from_name(word);
    if (!t) throw image_read_error(file + ": rtvk.view_transform is \"" + word + "\"");
    p.transform = *t;
  }
  if (const auto* e = h.findTypedAttribute<Imf::DoubleAttribute>("rtvk.exposure")) {
    if (!(std::abs(e->value()) <= max_exposure))
      throw image_read_error(file + ": rtvk.exposure is " + std::to_string(e->value()));
    p.exposure = e->value();
  }
}

template <typename Attr>
const Attr& attribute(const Imf::Header& h, const char* name, const std::string& file) {
  const Attr* a = h.findTypedAttribute<Attr>(name);
  if (!a)
    throw image_read_error(file + ": not an rtvk partial render (no " + std::string(name) +
                           " attribute in its OpenEXR header)");
  return *a;
}

// The header, not the file's size, says how many pixels there are: a forged header could claim
// any window up to the largest image. Refused before anything is allocated for it.
void check_piece_memory(const render_window& w, const std::string& name) {
  const std::uint64_t need = std::uint64_t(w.width) * std::uint64_t(w.height) * 3 * sizeof(float);
  const std::uint64_t have = available_memory_bytes();
  if (have != 0 && need > have / 2)
    throw image_read_error(name + ": its data window of " + std::to_string(w.width) + "x" +
                           std::to_string(w.height) + " pixels needs " + format_bytes(need) + "; " +
                           format_bytes(have) + " of memory is available");
}

// The pixels, a band of rows at a time, the buffer growing only as rows arrive: a header that
// claims more rows than the file holds fails at the first missing band, not after allocating
// the whole claim.
void read_in_bands(Imf::InputFile& file, const Imath::Box2i& data, std::vector<float>& rgb) {
  constexpr int band = 64;
  const std::size_t row_floats = std::size_t(data.max.x - data.min.x + 1) * 3;
  for (int y0 = data.min.y; y0 <= data.max.y; y0 += band) {
    const int y1 = std::min(y0 + band - 1, data.max.y);
    rgb.resize(std::size_t(y1 - data.min.y + 1) * row_floats);
    const Imath::Box2i rows(Imath::V2i(data.min.x, y0), Imath::V2i(data.max.x, y1));
    file.setFrameBuffer(slices(rgb.data() + std::size_t(y0 - data.min.y) * row_floats, rows));
    file.readPixels(y0, y1);
  }
}

}  // namespace

partial_image make_partial(const framebuffer& fb, partial_image header) {
  partial_image p = std::move(header);
  p.rgb.clear();
  p.rgb.reserve(std::size_t(fb.width()) * std::size_t(fb.height()) * 3);
  for (int y = 0; y < fb.height(); ++y)
    for (int x = 0; x < fb.width(); ++x)
      for (int c = 0; c < 3; ++c) p.rgb.push_back(float(fb.at(x, y)[c]));
  return p;
}

void write_partial_exr(const partial_image& p, const std::filesystem::path& path,
                       const aov_image* aovs) {
  const Imath::Box2i display(Imath::V2i(0, 0), Imath::V2i(p.image_width - 1, p.image_height - 1));
  const Imath::Box2i data(
      Imath::V2i(p.window.x, p.window.y),
      Imath::V2i(p.window.x + p.window.width - 1, p.window.y + p.window.height - 1));
  Imf::Header h(display, data, 1, Imath::V2f(0, 0), 1, Imf::INCREASING_Y, Imf::ZIP_COMPRESSION);
  for (const char* c : {"R", "G", "B"}) h.channels().insert(c, Imf::Channel(Imf::FLOAT));
  h.insert("rtvk.samples",
           Imf::V2iAttribute(Imath::V2i(p.window.sample_begin, p.window.sample_end)));
  h.insert("rtvk.gamma", Imf::DoubleAttribute(p.gamma));
  h.insert("rtvk.fingerprint", Imf::StringAttribute(p.fingerprint));
  h.insert("rtvk.scene", Imf::StringAttribute(p.scene));
  h.insert("rtvk.camera", Imf::StringAttribute(p.camera));
  h.insert("rtvk.frame", Imf::IntAttribute(p.frame));
  h.insert("rtvk.version", Imf::StringAttribute(p.version));
  h.insert("rtvk.shader", Imf::StringAttribute(p.shader));
  if (p.transform != view_transform::gamma)  // renders encoded as before keep their bytes
    h.insert("rtvk.view_transform", Imf::StringAttribute(view_transform_name(p.transform)));
  if (p.exposure != 0) h.insert("rtvk.exposure", Imf::DoubleAttribute(p.exposure));
  // Slices take non-const pointers for both directions; an OutputFile only reads them.
  Imf::FrameBuffer fb = slices(const_cast<float*>(p.rgb.data()), data);
  if (aovs) add_aov_channels(*aovs, aovs->which, data, h, fb);
  encode_and_write(h, fb, p.window.height, path);
}

void write_aov_exr(const aov_image& a, aov_bit which, int image_width, int image_height,
                   const render_window& window, const std::filesystem::path& path) {
  const Imath::Box2i display(Imath::V2i(0, 0), Imath::V2i(image_width - 1, image_height - 1));
  const Imath::Box2i data(Imath::V2i(window.x, window.y),
                          Imath::V2i(window.x + window.width - 1, window.y + window.height - 1));
  Imf::Header h(display, data, 1, Imath::V2f(0, 0), 1, Imf::INCREASING_Y, Imf::ZIP_COMPRESSION);
  Imf::FrameBuffer fb;
  add_aov_channels(a, unsigned(which), data, h, fb);
  encode_and_write(h, fb, window.height, path);
}

partial_image read_partial_exr(const std::filesystem::path& path) {
  const std::string name = path.string();
  std::optional<regular_file> input;
  try {
    input.emplace(path, "OpenEXR piece");
  } catch (const usage_error& e) {
    throw image_read_error(e.what());
  }
  partial_image p;
  try {
    descriptor_stream stream(*input);
    Imf::InputFile file(stream, 1);
    const Imf::Header& h = file.header();
    const Imath::Box2i display = h.displayWindow(), data = h.dataWindow();
    if (display.max.x >= max_image_side || display.max.y >= max_image_side)
      throw image_read_error(name + ": display window is larger than " +
                             std::to_string(max_image_side) + " pixels a side");
    if (display.min != Imath::V2i(0, 0) || data.min.x < 0 || data.min.y < 0 ||
        data.max.x > display.max.x || data.max.y > display.max.y || data.isEmpty())
      throw image_read_error(name + ": data window is not inside a display window at 0,0");
    const Imath::V2i samples = attribute<Imf::V2iAttribute>(h, "rtvk.samples", name).value();
    p.gamma = attribute<Imf::DoubleAttribute>(h, "rtvk.gamma", name).value();
    p.fingerprint = attribute<Imf::StringAttribute>(h, "rtvk.fingerprint", name).value();
    p.scene = attribute<Imf::StringAttribute>(h, "rtvk.scene", name).value();
    p.camera = attribute<Imf::StringAttribute>(h, "rtvk.camera", name).value();
    p.frame = attribute<Imf::IntAttribute>(h, "rtvk.frame", name).value();
    p.version = optional_string(h, "rtvk.version");  // pieces of earlier rtvk have none
    p.shader = optional_string(h, "rtvk.shader");
    read_encoding(h, name, p);
    for (const char* c : {"R", "G", "B"})
      if (!h.channels().findChannel(c))
        throw image_read_error(name + ": no " + std::string(c) + " channel");
    p.image_width = display.max.x + 1;
    p.image_height = display.max.y + 1;
    p.window = {data.min.x, data.min.y, data.max.x - data.min.x + 1, data.max.y - data.min.y + 1,
                samples.x,  samples.y};
    if (p.window.sample_begin < 0 || p.window.sample_end <= p.window.sample_begin)
      throw image_read_error(name + ": rtvk.samples " + std::to_string(samples.x) + ":" +
                             std::to_string(samples.y) + " is not a sample range");
    check_piece_memory(p.window, name);
    read_in_bands(file, data, p.rgb);
  } catch (const image_read_error&) {
    throw;
  } catch (const std::exception& e) {
    throw image_read_error(name + ": cannot read as OpenEXR: " + e.what());
  }
  return p;
}

std::string fingerprint_of(const std::string& text) {
  std::uint64_t h = 0xcbf29ce484222325ull;  // FNV-1a, 64 bits
  for (unsigned char c : text) h = (h ^ c) * 0x100000001b3ull;
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016" PRIx64, h);
  return buf;
}

}  // namespace rtvk
