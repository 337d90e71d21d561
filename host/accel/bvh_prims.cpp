#include "bvh_build.h"

#include <oneapi/tbb/blocked_range.h>
#include <oneapi/tbb/parallel_reduce.h>

namespace rtvk::bvh_build {
namespace {

// The box of object i, in primitive_spans' numbering: each shape's own bounds, or the box given.
std::array<point3, 2> object_box(const primitive_spans& objects, std::size_t i, time_span motion) {
  if (i < objects.spheres.size()) return objects.spheres[i].bounds(motion);
  i -= objects.spheres.size();
  if (i < objects.quads.size()) return objects.quads[i].bounds();
  i -= objects.quads.size();
  if (i < objects.triangles.size()) return objects.triangles[i].bounds();
  i -= objects.triangles.size();
  if (i < objects.disks.size()) return objects.disks[i].bounds();
  return objects.boxes[i - objects.disks.size()];
}

}  // namespace

range_info make_prims(const primitive_spans& objects, time_span motion, prim_vector& prims) {
  prims.resize(objects.size());
  return tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, objects.size(), 4096), range_info{},
      [&](const tbb::blocked_range<std::size_t>& r, range_info info) {
        for (std::size_t i = r.begin(); i < r.end(); ++i) {
          const std::array<point3, 2> box = object_box(objects, i, motion);
          prim& p = prims[i];
          p.lo = p.hi = splat4(0);
          for (int k = 0; k < 3; ++k) {
            p.lo[k] = next_down(float(box[0][k]));
            p.hi[k] = next_up(float(box[1][k]));
          }
          p.object = std::uint32_t(i);
          info.bounds.grow(p.lo, p.hi);
          info.centroids.grow(p.centroid());
        }
        return info;
      },
      [](range_info a, const range_info& b) {
        a.bounds.grow(b.bounds);
        a.centroids.grow(b.centroids);
        return a;
      });
}

}  // namespace rtvk::bvh_build
