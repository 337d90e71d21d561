#pragma once
// What the library's handles hold (rtvk.h's impl structs), and the one place where rtvk's own
// errors become the library's.
#include <cstdint>
#include <map>
#include <stdexcept>
#include <utility>

#include "camera.h"
#include "errors.h"
#include "image_io.h"
#include "object_placement.h"
#include "rtvk.h"
#include "scene.h"
#include "scene_overrides.h"

namespace rtvk::api {

struct Scene::impl {
  explicit impl(scene s_) : s(std::move(s_)) {}
  static scene checked(scene s);  // check_scene's refusals, as for `rtvk render`
  scene s;
  std::uint64_t version = 0;  // counts edits: a renderer set up for an older version redoes it
  bool builtin = false;       // a built-in scene: --precision auto draws it with the reference
  // Objects moved by place: each as first found, and the placement it has now.
  struct placed_object {
    object_original original;
    transform now;
  };
  std::map<std::uint32_t, placed_object> placed;
};

struct Camera::impl {
  camera cam;
};

// Runs f, turning rtvk's usage_error (bad input: the CLI's exit 2) and std::invalid_argument
// into bad_input, and render_cancelled into cancelled; anything else passes as it is.
template <typename F>
auto translate(F&& f) -> decltype(f()) {
  try {
    return f();
  } catch (const usage_error& e) {
    throw bad_input(e.what());
  } catch (const render_cancelled& e) {
    throw cancelled(e.what());
  } catch (const image_read_error& e) {
    throw bad_input(e.what());
  } catch (const bad_input&) {
    throw;
  } catch (const std::invalid_argument& e) {
    throw bad_input(e.what());
  }
}

}  // namespace rtvk::api
