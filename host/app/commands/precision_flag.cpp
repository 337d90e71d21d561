#include "precision_flag.h"

#include <algorithm>

#include "scene_file.h"

namespace rtvk {

void add_precision_option(CLI::App& cmd, std::string& word, bool with_both) {
  std::vector<std::string> words = {"auto", "fast", "reference"};
  if (with_both) words.push_back("both");
  cmd.add_option("--precision", word,
                 "The CPU's mode: fast (float, as the GPU computes; Embree and an SSE tree find "
                 "the hits; the GPU's image within its tolerances; 1.6x the reference's speed on "
                 "a million triangles, about its speed on the books' scenes), reference (double "
                 "precision: the lesson's exact image), auto (reference for the built-in scenes, "
                 "fast for files)" +
                     std::string(with_both ? ", both (each timed)" : ""))
      ->check(CLI::IsMember(words))
      ->capture_default_str();
}

cpu_precision precision_for(const std::string& word, const std::string& scene) {
  if (word == "fast") return cpu_precision::fast;
  if (word == "reference") return cpu_precision::reference;
  const std::vector<std::string> builtin = scene_names();
  const bool is_builtin = std::find(builtin.begin(), builtin.end(), scene) != builtin.end() ||
                          scene.rfind("spheres:", 0) == 0;
  return is_builtin ? cpu_precision::reference : cpu_precision::fast;
}

}  // namespace rtvk
