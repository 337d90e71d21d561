// The glTF reader's input: the file parsed by tinygltf, its images kept encoded, the files it
// names (external buffers and images) read through rtvk's own reader where the guard allows.
#include <algorithm>

#include "gltf_reader.h"
#include "input_file.h"

namespace rtvk {
namespace {

// Images are kept as their encoded bytes: rtvk decodes the ones a material's base color uses,
// with its own limits (textures.h's decode_texel_image), when the material is made.
bool keep_image_undecoded(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                          const unsigned char* bytes, int size, void*) {
  if (image && bytes && size > 0) image->image.assign(bytes, bytes + size);
  return true;
}

// The files a glTF names (its external buffers and images) are read through rtvk's own reader:
// regular files only, at most max_mesh_file_bytes, paths taken as written (tinygltf's default
// expands them as a shell would), and only where the guard allows. No guard (the user data)
// means the bytes came without a folder to look in: then no file is read at all.
struct gltf_files {
  const path_guard* guard = nullptr;  // where its files may lie; null: nowhere
  std::string refused;                // the first file refused by the guard, as tinygltf named it
};
bool file_exists(const std::string& path, void* user) {
  const auto* files = static_cast<const gltf_files*>(user);
  if (!files || !files->guard) return false;
  // A file outside the folder "exists", so that reading it is refused with its reason (and
  // whether such a file exists is not told).
  std::error_code ec;
  return !files->guard->allows(path) || std::filesystem::is_regular_file(path, ec);
}
std::string path_as_written(const std::string& path, void*) {
  return path;
}
bool read_whole_file(std::vector<unsigned char>* out, std::string* err, const std::string& path,
                     void* user) {
  auto* files = static_cast<gltf_files*>(user);
  if (!files || !files->guard) {
    if (err) *err += "external file " + path + " not read ";
    return false;
  }
  if (!files->guard->allows(path)) {
    if (files->refused.empty()) files->refused = path;
    if (err) *err += files->guard->outside(path) + " ";
    return false;
  }
  try {
    const std::string bytes = read_regular_file(path, max_mesh_file_bytes, "glTF buffer");
    out->assign(bytes.begin(), bytes.end());
    return true;
  } catch (const usage_error& e) {
    if (err) *err += std::string(e.what()) + " ";
    return false;
  }
}
bool write_nothing(std::string*, const std::string&, const std::vector<unsigned char>&, void*) {
  return false;
}

}  // namespace

// Parses a glTF (its images kept encoded, its external files read by rtvk's reader where `guard`
// allows). A file outside that folder is refused by name, even where tinygltf would only warn
// (an image it could not read).
tinygltf::Model parse_gltf(const std::string& bytes, bool binary, const std::string& name,
                           const std::filesystem::path& base, const path_guard& guard) {
  if (bytes.size() > 0xffffffffu) throw usage_error(name + ": larger than 4 GiB");
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(keep_image_undecoded, nullptr);
  gltf_files files{base.empty() ? nullptr : &guard, {}};
  loader.SetFsCallbacks({file_exists, path_as_written, read_whole_file, write_nothing, &files});
  tinygltf::Model model;
  std::string err, warn;
  const bool ok =
      binary ? loader.LoadBinaryFromMemory(&model, &err, &warn,
                                           reinterpret_cast<const unsigned char*>(bytes.data()),
                                           unsigned(bytes.size()), base.string())
             : loader.LoadASCIIFromString(&model, &err, &warn, bytes.data(), unsigned(bytes.size()),
                                          base.string());
  if (!files.refused.empty()) throw usage_error(name + ": " + guard.outside(files.refused));
  if (!ok) {
    std::replace(err.begin(), err.end(), '\n', ' ');
    while (!err.empty() && err.back() == ' ') err.pop_back();
    throw usage_error(name + ": " + (err.empty() ? "not a glTF 2.0 file" : err));
  }
  return model;
}

}  // namespace rtvk
