#include "confined_path.h"

#include <system_error>

#include "errors.h"

namespace rtvk {
namespace {

// The path with `..`, `.` and symlinks resolved as far as it exists, or none when it cannot be
// (a component that cannot be read, a symlink loop).
std::optional<std::filesystem::path> resolved(const std::filesystem::path& p) {
  std::error_code ec;
  const std::filesystem::path abs = std::filesystem::absolute(p.empty() ? "." : p, ec);
  if (ec) return std::nullopt;
  std::filesystem::path out = std::filesystem::weakly_canonical(abs, ec);
  if (ec) return std::nullopt;
  return out.lexically_normal();
}

// Whether every named component of `root` begins `file` (a trailing separator's empty name and
// a "." are no components).
bool starts_with(const std::filesystem::path& file, const std::filesystem::path& root) {
  auto f = file.begin();
  for (const std::filesystem::path& part : root) {
    if (part.empty() || part == ".") continue;
    while (f != file.end() && (f->empty() || *f == ".")) ++f;
    if (f == file.end() || *f != part) return false;
    ++f;
  }
  return true;
}

}  // namespace

path_guard path_guard::any() {
  return {};
}

path_guard path_guard::within(const std::filesystem::path& folder) {
  path_guard g;
  const std::optional<std::filesystem::path> root = resolved(folder);
  if (!root)
    throw usage_error(folder.string() +
                      ": the folder scene files' paths are confined to cannot "
                      "be resolved");
  g.root_ = *root;
  return g;
}

path_guard path_guard::of(const file_access& access, const std::filesystem::path& scene_folder) {
  if (access.any_path) return any();
  return within(access.root.empty() ? scene_folder : access.root);
}

bool path_guard::allows(const std::filesystem::path& file) const {
  if (!root_) return true;
  const std::optional<std::filesystem::path> f = resolved(file);
  return f && starts_with(*f, *root_);
}

std::string path_guard::outside(const std::string& as_written) const {
  return "\"" + as_written + "\" is outside " + (root_ ? root_->string() : std::string("/")) +
         ", the folder the scene's files must lie in (--allow-any-path or --scene-root DIR "
         "allows it)";
}

void path_guard::check(const std::filesystem::path& file, const std::string& where,
                       const std::string& as_written) const {
  if (!allows(file)) throw usage_error(where + ": " + outside(as_written));
}

}  // namespace rtvk
