// Google Benchmark microbenchmarks: ray-sphere, BVH build, BVH traversal (against the linear
// scan). Built with the project, run on demand (build/<preset>/rtvk_microbench), not in CI's tests.
#include <benchmark/benchmark.h>

#include <memory>
#include <vector>

#include "bvh.h"
#include "camera.h"
#include "hittable_sphere.h"
#include "random.h"
#include "scene.h"
#include "world.h"

namespace rtvk {
namespace {

// Camera rays of the book-final view, from the same random numbers every run.
std::vector<ray> camera_rays(const scene& s, int count) {
  const camera cam(main_camera(s).pose, 16.0 / 9.0, 1200);
  std::vector<ray> rays;
  rays.reserve(std::size_t(count));
  for (int i = 0; i < count; ++i) {
    const random_stream r{1, std::uint32_t(i), 0, 0};
    rays.push_back(cam.get_ray(r(0), r(1), random_in_unit_disk(r(2), r(3))));
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

template <bool UseBvh>
void BM_Traversal(benchmark::State& state) {
  const scene s = builtin_scene("spheres:" + std::to_string(state.range(0)));
  const std::unique_ptr<hittable> world = make_accelerated_world(s, UseBvh);
  const std::vector<ray> rays = camera_rays(s, 4096);
  std::size_t i = 0;
  for (auto _ : state) {
    hit_record rec;
    benchmark::DoNotOptimize(world->hit(rays[i++ & 4095], 0.001, 1e30, rec));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_Traversal<true>)->Name("BM_BvhTraversal")->RangeMultiplier(10)->Range(10, 1000000);
BENCHMARK(BM_Traversal<false>)->Name("BM_LinearScan")->RangeMultiplier(10)->Range(10, 10000);

}  // namespace
}  // namespace rtvk

BENCHMARK_MAIN();
