// The glTF reader's input: the file parsed by tinygltf, its images kept encoded, the files it
// names (external buffers and images) read through rtvk's own reader where the guard allows.
#include <algorithm>
#include <cctype>
#include <string_view>

#include "gltf_reader.h"
#include "input_file.h"

namespace rtvk {
namespace {

// What a file that should be a glTF, a buffer or an image is instead, or "": a git-lfs pointer (a
// clone without git lfs) or an HTML page (a web page's link saved rather than the raw file).
std::string impostor(std::string_view bytes) {
  if (bytes.rfind("version https://git-lfs.github.com/spec/", 0) == 0)
    return "a git-lfs pointer, not the file (fetch it with git lfs pull)";
  std::string head(bytes.substr(0, 256));
  head.erase(0, std::min(head.find_first_not_of(" \t\r\n"), head.size()));
  std::transform(head.begin(), head.end(), head.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  if (head.rfind("<!doctype html", 0) == 0 || head.rfind("<html", 0) == 0)
    return "an HTML page, not the file (saved from a web page rather than the raw file?)";
  return "";
}

// tinygltf's message with each data URI in it cut to its media type and length: a bad one would
// otherwise be printed whole, megabytes of base64.
std::string without_data_uris(std::string err) {
  for (std::size_t at = err.find("data:"); at != std::string::npos;
       at = err.find("data:", at + 1)) {
    const std::size_t end = std::min(err.find_first_of(" \n\"'", at), err.size());
    const std::size_t comma = std::min(err.find(',', at), end);
    const std::string cut = err.substr(at, comma - at) + ",... (a data URI of " +
                            std::to_string(end - at) + " characters)";
    err.replace(at, end - at, cut);
    at += cut.size() - 1;
  }
  return err;
}

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
  std::string base;                   // the folder its files are looked for in
  std::string missing;                // the first file looked for and not found
  std::string broken;                 // the first file read that is not what it should be, why
};
bool file_exists(const std::string& path, void* user) {
  auto* files = static_cast<gltf_files*>(user);
  if (!files || !files->guard) return false;
  // A file outside the folder "exists", so that reading it is refused with its reason (and
  // whether such a file exists is not told).
  // tinygltf looks in the current folder after the glTF's own: that second look finds nothing.
  if (path.rfind(files->base, 0) != 0) return false;
  std::error_code ec;
  const bool found = !files->guard->allows(path) || std::filesystem::is_regular_file(path, ec);
  if (!found && files->missing.empty()) files->missing = path;
  return found;
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
    if (const std::string what = impostor(bytes); !what.empty()) {
      if (files->broken.empty()) files->broken = path + " is " + what;
      if (err) *err += path + " is " + what + " ";
      return false;
    }
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
  if (const std::string what = impostor(bytes); !what.empty())
    throw usage_error(name + ": " + what);
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(keep_image_undecoded, nullptr);
  gltf_files files;
  files.guard = base.empty() ? nullptr : &guard;
  files.base = base.string();
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
  if (!files.broken.empty()) throw usage_error(name + ": " + files.broken);
  if (!ok && !files.missing.empty())
    throw usage_error(name + ": " + files.missing + " not found (a file the glTF names)");
  if (!ok) {
    err = without_data_uris(err);
    std::replace(err.begin(), err.end(), '\n', ' ');
    while (!err.empty() && err.back() == ' ') err.pop_back();
    throw usage_error(name + ": " + (err.empty() ? "not a glTF 2.0 file" : err));
  }
  // An image not read (tinygltf only warns) is refused when a material uses it: its uri becomes
  // the path looked for, for that message.
  for (tinygltf::Image& img : model.images)
    if (img.image.empty() && !img.uri.empty() && img.uri.rfind("data:", 0) != 0)
      img.uri = base.empty() ? img.uri + " (not read: no folder to look in)"
                             : (base / img.uri).lexically_normal().string();
  return model;
}

}  // namespace rtvk
