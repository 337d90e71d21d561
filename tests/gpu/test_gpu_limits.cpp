// Every buffer a GPU render allocates is checked against the device's limits before any is: a
// scene too large for the device is refused with a message, never bound past a limit (a wrong
// image or a device fault on devices without robust buffer access). Limits are lowered through
// gpu_options::caps to prove each check fires.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "errors.h"
#include "gpu_fixture.h"
#include "mesh_helpers.h"
#include "render_helpers.h"

namespace rtvk {
namespace {

class GpuLimits : public test::GpuTest {
 protected:
  // Renders `s` small on a context whose limits are lowered to `caps`; returns the refusal's
  // message, or "" when it rendered.
  std::string render_with(const scene& s, const gpu::device_limit_caps& caps) {
    gpu::gpu_options o = test::gpu_test_options();
    o.caps = caps;
    gpu::gpu_context ctx(o);
    try {
      gpu::render_gpu(ctx, test::scene_camera(s), s, s.render);
    } catch (const usage_error& e) {
      EXPECT_EQ(ctx.validation_messages(), 0u);
      return e.what();
    }
    EXPECT_EQ(ctx.validation_messages(), 0u);
    return "";
  }
};

scene two_thousand_spheres() {
  scene s = builtin_scene("spheres:2000");
  s.render.width = 16;
  s.render.spp = 1;
  return s;
}

TEST_F(GpuLimits, AStorageBufferAboveTheRangeIsRefused) {
  // 2000 spheres and the ground: 971 four-wide BVH nodes of 128 bytes, 124,288 bytes in one
  // storage buffer.
  const std::string refused = render_with(two_thousand_spheres(), {.storage_range = 100 << 10});
  EXPECT_EQ(refused,
            "--scene spheres:2000: the BVH needs 121.375 KiB in one storage buffer; "
            "device '" +
                gpu().device().name + "' allows 100 KiB");
}

// A mesh too large for the device's storage-buffer range: refused before anything is allocated,
// naming the buffer and the limit, rather than read past the range. 2 x 40 x 40 x 6 = 19,200
// triangles: 900 KiB of them at 48 bytes, and their BVH, the largest buffer (one object a leaf:
// 1.106 MiB of four-wide nodes), is the one named.
TEST_F(GpuLimits, AMeshAboveTheStorageRangeIsRefusedNamingTheBuffer) {
  scene s = builtin_scene("seed");
  test::add_triangles(s, test::cube_sphere(40, 0.4), 0);
  s.render.width = 16;
  EXPECT_THAT(render_with(s, {.storage_range = 1 << 20}),
              testing::HasSubstr("the BVH needs 1.10645 MiB in one storage buffer; device '"));
  EXPECT_THAT(render_with(s, {.storage_range = 1 << 20}), testing::HasSubstr("allows 1 MiB"));
  EXPECT_EQ(render_with(s, {.storage_range = 1200 << 10}), "") << "1200 KiB holds it";
}

// An image texture too large for the device's storage-buffer range: refused naming the texels'
// buffer and the limit (512 x 512 texels are 1 MiB), rendered where it fits.
TEST_F(GpuLimits, AnImageTextureAboveTheStorageRangeIsRefusedNamingIt) {
  scene s = builtin_scene("seed");
  s.render.width = 16;
  texture t;
  t.type = texture_type::image;
  t.image = std::make_shared<texel_image>(
      texel_image{512, 512, std::vector<std::uint32_t>(512 * 512, 0xff808080u)});
  s.textures.push_back(t);
  s.materials[0].m = {material_type::lambertian, color(1), 0, 1.5, 0};
  EXPECT_EQ(render_with(s, {.storage_range = 512 << 10}),
            "--scene seed: the image textures' texels needs 1 MiB in one storage buffer; device '" +
                gpu().device().name + "' allows 512 KiB");
  EXPECT_EQ(render_with(s, {.storage_range = 2 << 20}), "");
}

TEST_F(GpuLimits, EachLimitIsCheckedAndRendersWithinThemStillWork) {
  const scene s = two_thousand_spheres();
  EXPECT_EQ(render_with(s, {.storage_range = 200 << 10}), "") << "everything fits 200 KiB";
  // lavapipe's memory is the host's: the scene is written in place, its arrays in one
  // allocation: 2001 spheres (62.5 KiB), the materials, 971 four-wide BVH nodes (121.4 KiB), and
  // one unused element each of the velocity (nothing moves), quad, triangle, vertex normal,
  // instance, texture coordinate, texture, texel, medium, light, disk and vertex tangent arrays
  // (none there), the noise tables (7 KiB), the punctual lights' unused element (count 0) and
  // the environment map's two (no map), and the light tree's unused node (no lamp: 64 bytes).
  EXPECT_THAT(
      render_with(s, {.allocation_size = 150 << 10}),
      testing::HasSubstr("the sphere array and the material array and the BVH and the "
                         "velocity array and the quad array and the triangle array and "
                         "the vertex normal array and the instance array and the texture "
                         "coordinate array and the texture array and the image textures' "
                         "texels and the noise tables and the media array and the light array "
                         "and the disk array and the vertex tangent array and the PBR "
                         "material array and the BSDF tables and the punctual light array and "
                         "the environment map's texels and the environment map's sampling "
                         "table and the light tree need 195.852 KiB in one memory allocation"));
  EXPECT_EQ(render_with(s, {.allocation_size = 200 << 10}), "");
  // Three allocations in all: the scene's arrays, the targets' device-local and readback
  // buffers.
  EXPECT_EQ(render_with(s, {.allocations = 3}), "");
  EXPECT_NE(
      render_with(s, {.allocations = 2}).find("the render needs 3 memory allocations; device '"),
      std::string::npos);
  EXPECT_NE(render_with(s, {.heap_size = 128 << 10}).find("of memory heap 0; device '"),
            std::string::npos);
}

}  // namespace
}  // namespace rtvk
