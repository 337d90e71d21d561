// Google Benchmark microbenchmarks: ray-sphere, BVH build, BVH traversal: the CPU's four-wide
// traversal beside the binary traversal it replaced (kept here, on the same tree, as the
// reference) and the linear scan, on camera rays and on book-final's bounce rays; and sobol.h's
// numbers beside rnd's. Built with the project, run on demand (build/<preset>/rtvk_microbench),
// not in CI's tests.
#include <benchmark/benchmark.h>

#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

#include "bvh.h"
#include "bvh_world.h"
#include "camera.h"
#include "hittable_sphere.h"
#include "random.h"
#include "scene.h"
#include "shading.h"
#include "random.h"
#include "world.h"

namespace rtvk {
namespace {

// Camera rays of the book-final view, from the same random numbers every run.
std::vector<ray> camera_rays(const scene& s, int count) {
  const camera cam(main_camera(s).pose, 16.0 / 9.0, 1200);
  std::vector<ray> rays;
  rays.reserve(std::size_t(count));
  for (int i = 0; i < count; ++i) {
    const random_stream r = pixel_sample_stream(1, std::uint32_t(i), 0);
    rays.push_back(cam.get_ray(rnd(r, 0), rnd(r, 1), random_in_unit_disk(rnd(r, 2), rnd(r, 3))));
  }
  return rays;
}

void BM_RaySphere(benchmark::State& state) {
  const sphere s(point3(0, 0, -1), 0.5);
  const std::vector<ray> rays = camera_rays(builtin_scene("seed"), 1024);
  std::size_t i = 0;
  for (auto _ : state) {
    double t;
    benchmark::DoNotOptimize(hit_distance(s, rays[i++ & 1023], 0.001, 1e30, t));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_RaySphere);

void BM_BvhBuild(benchmark::State& state) {
  const scene s = builtin_scene("spheres:" + std::to_string(state.range(0)));
  for (auto _ : state) {
    const bvh tree(s.spheres);
    benchmark::DoNotOptimize(tree.nodes().data());
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_BvhBuild)->RangeMultiplier(10)->Range(1000, 1000000)->Unit(benchmark::kMillisecond);

// The binary traversal the four-wide one replaced (commit 0df5599), on the same tree: nearer
// child first, one remembered child per level. Its box tests are the scalar ray_box_entry (the
// old code tested both children with one SSE instruction: a little faster than here). Same hits;
// kept as the reference the wide traversal is measured against in one run.
class binary_bvh_world final : public hittable {
 public:
  explicit binary_bvh_world(const std::vector<sphere>& spheres) : tree_(spheres) {
    for (const std::uint32_t i : tree_.order()) spheres_.push_back(spheres[i]);
  }

  bool hit(const ray& r, double t_min, double t_max, hit_record& rec) const override {
    const std::vector<bvh_node>& nodes = tree_.nodes();
    const glm::vec3 o(r.origin), inv_d = safe_inverse(glm::vec3(r.direction));
    const float margin = origin_margin(o), box_min = float(t_min) * (1.0f - 0x1p-20f);
    std::uint32_t stack_ref[RTVK_BVH_STACK], stack_count[RTVK_BVH_STACK];
    float stack_entry[RTVK_BVH_STACK];
    int top = 0;
    std::uint32_t first = 0, count = 0;
    double best = t_max;
    std::int64_t best_scene = -1;
    std::uint32_t best_slot = 0;
    while (true) {
      if (count == 0) {
        const bvh_node& n = nodes[first];
        const float box_max = float(best) * (1.0f + 0x1p-20f);
        const float t[2] = {ray_box_entry(o, inv_d, n, 0, box_min, box_max, margin),
                            ray_box_entry(o, inv_d, n, 1, box_min, box_max, margin)};
        const int a = t[0] <= t[1] ? 0 : 1, b = 1 - a;
        if (t[a] >= 0 && t[b] >= 0) {
          stack_ref[top] = n.first[b];
          stack_count[top] = n.count[b];
          stack_entry[top++] = t[b];
        }
        if (t[a] >= 0 || t[b] >= 0) {
          const int c = t[a] >= 0 ? a : b;
          first = n.first[c];
          count = n.count[c];
          continue;
        }
      } else {
        const std::int64_t i = tree_.order()[first];
        double t;
        if (hit_distance(spheres_[first], r, t_min, best, t) && (t < best || i > best_scene)) {
          best = t;
          best_scene = i;
          best_slot = first;
        }
      }
      const float reach = float(best) * (1.0f + 0x1p-20f);
      while (top > 0 && stack_entry[top - 1] > reach) --top;
      if (top == 0) break;
      --top;
      first = stack_ref[top];
      count = stack_count[top];
    }
    if (best_scene < 0) return false;
    record_hit(spheres_[best_slot], r, best, rec);
    return true;
  }

 private:
  bvh tree_;
  std::vector<sphere> spheres_;
};

enum class traversal { wide, binary, linear };

std::unique_ptr<hittable> make_world(const scene& s, traversal how) {
  if (how == traversal::wide) return std::make_unique<bvh_world>(s.spheres);
  if (how == traversal::binary) return std::make_unique<binary_bvh_world>(s.spheres);
  return make_accelerated_world(s, false);
}

template <traversal How>
void BM_Traversal(benchmark::State& state) {
  const scene s = builtin_scene("spheres:" + std::to_string(state.range(0)));
  const std::unique_ptr<hittable> world = make_world(s, How);
  const std::vector<ray> rays = camera_rays(s, 4096);
  std::size_t i = 0;
  for (auto _ : state) {
    hit_record rec{};
    benchmark::DoNotOptimize(world->hit(rays[i++ & 4095], 0.001, 1e30, rec));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_Traversal<traversal::wide>)
    ->Name("BM_BvhTraversal")
    ->RangeMultiplier(10)
    ->Range(10, 1000000);
BENCHMARK(BM_Traversal<traversal::binary>)
    ->Name("BM_BinaryBvhTraversal")
    ->RangeMultiplier(10)
    ->Range(10, 1000000);
BENCHMARK(BM_Traversal<traversal::linear>)
    ->Name("BM_LinearScan")
    ->RangeMultiplier(10)
    ->Range(10, 10000);

// book-final's rays as the renderer traces them: camera rays, and the rays that leave their
// first hits by the hit's material (most of a path's rays are such bounce rays).
std::vector<ray> book_final_rays(int count) {
  const scene s = builtin_scene("book-final");
  const std::unique_ptr<hittable> world = make_world(s, traversal::wide);
  const std::vector<material> materials = scene_materials(s);
  std::vector<ray> rays = camera_rays(s, count / 2);
  for (int i = 0; int(rays.size()) < count; ++i) {
    const ray& in = rays[std::size_t(i)];
    hit_record rec{};
    if (!world->hit(in, 0.001, std::numeric_limits<double>::infinity(), rec)) continue;
    color attenuation;
    ray out;
    if (scatter(materials[std::size_t(rec.material)], in, rec,
                at_bounce(pixel_sample_stream(2, std::uint32_t(i), 0), 1), attenuation, out))
      rays.push_back(out);
  }
  return rays;
}

template <traversal How>
void BM_BookFinalRays(benchmark::State& state) {
  const std::unique_ptr<hittable> world = make_world(builtin_scene("book-final"), How);
  const std::vector<ray> rays = book_final_rays(8192);
  std::size_t i = 0;
  for (auto _ : state) {
    hit_record rec{};
    benchmark::DoNotOptimize(
        world->hit(rays[i++ & 8191], 0.001, std::numeric_limits<double>::infinity(), rec));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_BookFinalRays<traversal::wide>)->Name("BM_BookFinalRays/wide");
BENCHMARK(BM_BookFinalRays<traversal::binary>)->Name("BM_BookFinalRays/binary");

// sobol.h's low-discrepancy numbers against rnd's independent ones (issue 46): one number, and
// one pair, for 1024 pixel samples' streams at bounce 1 in turn. Items are numbers drawn.
std::vector<random_stream> bounce_streams() {
  std::vector<random_stream> streams;
  for (std::uint32_t i = 0; i < 1024; ++i)
    streams.push_back(at_bounce(pixel_sample_stream(1, i / 16, i % 16), 1));
  return streams;
}

void BM_Rnd(benchmark::State& state) {
  const std::vector<random_stream> streams = bounce_streams();
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(rnd(streams[i++ & 1023], dim_mixture));
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_Rnd);

void BM_SobolRnd(benchmark::State& state) {
  const std::vector<random_stream> streams = bounce_streams();
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(sobol_rnd(streams[i++ & 1023], dim_mixture));
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_SobolRnd);

void BM_RndPair(benchmark::State& state) {
  const std::vector<random_stream> streams = bounce_streams();
  std::size_t i = 0;
  for (auto _ : state) {
    const random_stream& s = streams[i++ & 1023];
    benchmark::DoNotOptimize(real2(rnd(s, dim_direction_a), rnd(s, dim_direction_b)));
  }
  state.SetItemsProcessed(2 * state.iterations());
}
BENCHMARK(BM_RndPair);

void BM_SobolRnd2(benchmark::State& state) {
  const std::vector<random_stream> streams = bounce_streams();
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(sobol_rnd2(streams[i++ & 1023], dim_direction_a));
  state.SetItemsProcessed(2 * state.iterations());
}
BENCHMARK(BM_SobolRnd2);

}  // namespace
}  // namespace rtvk

BENCHMARK_MAIN();
