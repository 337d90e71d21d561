// An outside anchor for the CPU traversal (docs/benchmarks.md): the same rays through the same
// triangle mesh, closest hits, single-threaded, through rtvk's BVH (bvh_world::hit, the hit
// record included: what a render pays per ray) and through Intel's Embree (Debian's
// libembree-dev, rtcIntersect1; its build at high quality). A benchmark-only dependency: without
// Embree this program is not built.
//
//   rtvk_embree_anchor --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>
#include <embree3/rtcore.h>

#include <limits>
#include <random>
#include <stdexcept>

#include "bvh_world.h"
#include "camera.h"
#include "embree_anchor_fast.h"
#include "mesh_helpers.h"

namespace rtvk {
namespace {

// The mesh and the rays both tracers are given: camera rays over the knot (coherent), and rays
// from random points around it in random directions (incoherent, as diffuse bounces are).
struct workload {
  test::indexed_mesh mesh;
  std::vector<ray> rays;
};

const workload& load(std::size_t triangles, bool coherent) {
  static std::map<std::pair<std::size_t, bool>, workload> cache;
  workload& w = cache[{triangles, coherent}];
  if (!w.mesh.faces.empty()) return w;
  w.mesh = test::torus_knot(triangles);
  if (coherent) {
    camera_pose pose;
    pose.lookfrom = point3(0, -2, 9);
    pose.lookat = point3(0, 0, 0);
    pose.vfov = 45;
    const camera cam(pose, 1.0, 256);
    for (int j = 0; j < 256; ++j)
      for (int i = 0; i < 256; ++i) w.rays.push_back(cam.get_ray((i + 0.5) / 256, (j + 0.5) / 256));
  } else {
    std::mt19937 gen(3);
    std::uniform_real_distribution<double> box(-3.5, 3.5), unit(-1, 1);
    for (int k = 0; k < 65536; ++k) {
      vec3 d;
      do d = vec3(unit(gen), unit(gen), unit(gen));
      while (glm::length(d) > 1 || glm::length(d) < 1e-3);
      w.rays.push_back(ray(point3(box(gen), box(gen), 0.5 * box(gen)), d));
    }
  }
  return w;
}

void BM_Rtvk(benchmark::State& state) {
  const workload& w = load(std::size_t(state.range(0)), state.range(1) != 0);
  scene s;
  test::add_triangles(s, w.mesh, 0);
  const bvh_world world(primitive_spans{{}, {}, s.triangles}, {}, 1);
  std::size_t hits = 0;
  for (auto _ : state)
    for (const ray& r : w.rays) {
      hit_record rec;
      hits += world.hit(r, 1e-3, std::numeric_limits<double>::infinity(), rec);
    }
  state.SetItemsProcessed(std::int64_t(state.iterations() * w.rays.size()));
  state.counters["hit_share"] = double(hits) / double(state.iterations() * w.rays.size());
}

void BM_Embree(benchmark::State& state) {
  const workload& w = load(std::size_t(state.range(0)), state.range(1) != 0);
  RTCDevice device = rtcNewDevice("threads=1");
  if (!device) throw std::runtime_error("rtcNewDevice failed");
  RTCScene scene = rtcNewScene(device);
  rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_HIGH);
  RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0,
                                                        RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                                        w.mesh.positions.size()));
  for (std::size_t i = 0; i < w.mesh.positions.size(); ++i)
    for (int k = 0; k < 3; ++k) v[3 * i + std::size_t(k)] = float(w.mesh.positions[i][k]);
  auto* f = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
      geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), w.mesh.faces.size()));
  for (std::size_t i = 0; i < w.mesh.faces.size(); ++i)
    for (int k = 0; k < 3; ++k) f[3 * i + std::size_t(k)] = w.mesh.faces[i][std::size_t(k)];
  rtcCommitGeometry(geom);
  rtcAttachGeometry(scene, geom);
  rtcReleaseGeometry(geom);
  rtcCommitScene(scene);
  std::size_t hits = 0;
  const bool coherent = state.range(1) != 0;
  for (auto _ : state)
    for (const ray& r : w.rays) {
      RTCIntersectContext context;
      rtcInitIntersectContext(&context);
      context.flags =
          coherent ? RTC_INTERSECT_CONTEXT_FLAG_COHERENT : RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
      RTCRayHit rh{};
      rh.ray.org_x = float(r.origin.x);
      rh.ray.org_y = float(r.origin.y);
      rh.ray.org_z = float(r.origin.z);
      rh.ray.dir_x = float(r.direction.x);
      rh.ray.dir_y = float(r.direction.y);
      rh.ray.dir_z = float(r.direction.z);
      rh.ray.tnear = 1e-3f;
      rh.ray.tfar = std::numeric_limits<float>::infinity();
      rh.ray.mask = ~0u;
      rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
      rtcIntersect1(scene, &context, &rh);
      hits += rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
    }
  state.SetItemsProcessed(std::int64_t(state.iterations() * w.rays.size()));
  state.counters["hit_share"] = double(hits) / double(state.iterations() * w.rays.size());
  rtcReleaseScene(scene);
  rtcReleaseDevice(device);
}

// The fast mode's world over the same triangles (packed as the GPU gets them) and rays.
void BM_RtvkFast(benchmark::State& state) {
  const workload& w = load(std::size_t(state.range(0)), state.range(1) != 0);
  scene s;
  s.materials.push_back({"m", material{}});
  test::add_triangles(s, w.mesh, 0);
  const gpu::scene_arrays arrays = gpu::build_scene_arrays(s, false);
  const anchor::fast_tracer tracer(arrays);
  std::vector<float> rays;
  for (const ray& r : w.rays)
    for (const vec3 v : {r.origin, r.direction})
      for (int k = 0; k < 3; ++k) rays.push_back(float(v[k]));
  std::size_t hits = 0;
  for (auto _ : state) hits += tracer.trace(rays);
  state.SetItemsProcessed(std::int64_t(state.iterations() * w.rays.size()));
  state.counters["hit_share"] = double(hits) / double(state.iterations() * w.rays.size());
}

// (triangles, coherent)
void sizes(benchmark::internal::Benchmark* b) {
  for (const std::int64_t n : {10'000, 100'000, 1'000'000})
    for (const std::int64_t coherent : {1, 0}) b->Args({n, coherent});
  b->ArgNames({"triangles", "coherent"})->Unit(benchmark::kMillisecond);
}
BENCHMARK(BM_Rtvk)->Apply(sizes);
BENCHMARK(BM_Embree)->Apply(sizes);
BENCHMARK(BM_RtvkFast)->Apply(sizes);

}  // namespace
}  // namespace rtvk

BENCHMARK_MAIN();
