// The anchor's third tracer: the CPU's fast mode's world (host/fast: Embree, then the hit record
// the shared kernels make in float, what a fast render pays per ray), in a translation unit of
// its own because it compiles the kernels with float (embree_anchor.cpp's are the reference's).
#include "embree_anchor_fast.h"

#include <limits>

#include "fast_world.h"

namespace rtvk::anchor {

struct fast_tracer::impl {
  explicit impl(const gpu::scene_arrays& a) : world(a, 0, 0) {}
  fast::world world;
};

fast_tracer::fast_tracer(const gpu::scene_arrays& a) : impl_(std::make_unique<impl>(a)) {}
fast_tracer::~fast_tracer() = default;

std::size_t fast_tracer::trace(const std::vector<float>& rays) const {
  std::size_t hits = 0;
  const float far = std::numeric_limits<float>::infinity();
  for (std::size_t k = 0; k + 6 <= rays.size(); k += 6) {
    const fast::ray r(glm::vec3(rays[k], rays[k + 1], rays[k + 2]),
                      glm::vec3(rays[k + 3], rays[k + 4], rays[k + 5]));
    fast::hit_record rec;
    hits += impl_->world.hit(r, 1e-3f, far, rec);
  }
  return hits;
}

}  // namespace rtvk::anchor
