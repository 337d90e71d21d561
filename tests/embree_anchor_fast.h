#pragma once
// The fast mode's world as the anchor benchmark drives it: no kernel type crosses this header.
#include <cstddef>
#include <memory>
#include <vector>

#include "scene_arrays.h"

namespace rtvk::anchor {

class fast_tracer {
 public:
  explicit fast_tracer(const gpu::scene_arrays& a);  // the arrays must outlive it
  ~fast_tracer();
  // Traces each ray (origin xyz, direction xyz: six floats) to its closest hit past 1e-3, the
  // record made; returns how many hit.
  std::size_t trace(const std::vector<float>& rays) const;

 private:
  struct impl;
  std::unique_ptr<impl> impl_;
};

}  // namespace rtvk::anchor
