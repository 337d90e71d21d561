#pragma once
// rtvk as a library: a scene, cameras, and a renderer that keeps the scene on its device across
// renders, returning scene-linear float images and their ground truth. The Python module (`import
// rtvk`) is this API with NumPy arrays; the `rtvk` executable draws the same images from the
// same inputs (docs/library.md). This header is all a program needs: it names no other header of
// rtvk's, and no Vulkan, Embree or GLM type.
//
//   #include <rtvk/rtvk.h>
//   rtvk::api::Scene scene("cornell-box");                  // a built-in, a scene file or a mesh
//   rtvk::api::Renderer renderer(scene, "gpu");             // or "cpu"; the scene is set up once
//   rtvk::api::Image image = renderer.render(rtvk::api::Camera::from_scene(scene));
//
// Bad input throws rtvk::api::bad_input (a std::invalid_argument) with the one-line message the
// CLI prints for it; a device failure throws std::runtime_error naming the failing call.
#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

// What librtvk.so exports: this header's classes and functions, nothing else of rtvk's.
#define RTVK_API __attribute__((visibility("default")))

namespace rtvk::api {

// Input the CLI would refuse with exit status 2: its message, one line, names the field or flag.
class RTVK_API bad_input : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// A render stopped by its cancel poll (RenderOptions::cancelled) before it finished.
class RTVK_API cancelled : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A scene: its objects, materials, lights, render settings and named cameras.
class RTVK_API Scene {
 public:
  // A built-in scene (`rtvk scene list`: "seed", "cornell-box", ..., "spheres:N"), a .json scene
  // file or a mesh file (.obj, .gltf, .glb), as `rtvk render --scene` reads them.
  explicit Scene(const std::string& name_or_file);
  // A scene in the scene-file format (docs/scene-format.md); files it names are relative to
  // `folder`.
  static Scene from_json(const std::string& json, const std::string& folder = ".");
  // The scene in the scene-file format; from_json of it is the same scene.
  std::string to_json() const;
  std::string name() const;
  // Its cameras' names, the first the main one.
  std::vector<std::string> camera_names() const;
  // Replaces material `name` with `material_json`, one material as a scene file writes it
  // ({"type": "lambertian", "albedo": [...]}). A renderer made from this scene sees the change
  // at its next render (it sets the scene up again).
  void set_material(const std::string& name, const std::string& material_json);

  // One object as --aov object-id numbers it: a sphere, quad, box, triangle, mesh file, disk or
  // instance.
  struct Object {
    std::uint32_t id = 0;        // 1 and up, the object-id AOV's value where it is seen
    std::string kind;            // sphere, quad, box, triangle, mesh, disk or instance
    std::string material;        // its (first primitive's) material; empty for an instance
    std::string group;           // an instance's group; else empty
    std::size_t primitives = 1;  // quads of a box, triangles of a mesh, objects of a group; else 1
    std::array<double, 3> lo, hi;  // the box around it where it is now, scene units
  };
  std::vector<Object> objects() const;
  // Places object `id` by `matrix` (4x4 row-major, last row 0 0 0 1; or 12 numbers, 3 rows)
  // after the placement the scene gave it: the identity puts it back where the scene had it, and
  // each call replaces the last (they do not compound). Spheres and disks take turns, moves and
  // one scale only; an instance takes any affine placement. A renderer made from this scene sees
  // the change at its next render.
  void place(std::uint32_t id, const std::vector<double>& matrix);

  struct impl;
  std::shared_ptr<impl> impl_;  // shared by copies: a copy is the same scene

 private:
  explicit Scene(std::shared_ptr<impl> i);
};

// A camera: a pose and a model (pinhole, thin lens, orthographic, fisheye, the calibrated
// OpenCV, COLMAP and polynomial models, ...) and the image size it draws.
class RTVK_API Camera {
 public:
  // The scene's camera `name` (empty: its main camera), at the scene's image size, as `rtvk
  // render` draws it with no flags.
  static Camera from_scene(const Scene& scene, const std::string& name = "");
  // A pinhole (aperture 0) or thin-lens camera at `lookfrom` looking at `lookat`; vertical field
  // of view in degrees; `projection` as --projection names it (perspective, orthographic,
  // equirectangular, fisheye-equidistant, ...).
  static Camera look_at(const std::array<double, 3>& lookfrom, const std::array<double, 3>& lookat,
                        int width, int height, double vfov = 40,
                        const std::array<double, 3>& vup = {0, 1, 0}, double aperture = 0,
                        double focus_dist = 1, const std::string& projection = "perspective");
  // A calibrated camera as OpenCV holds one: the 4x4 world-to-camera matrix (row-major; the
  // camera looks down +z with +y down, OpenCV's and COLMAP's convention), the intrinsics in
  // pixels, and the distortion coefficients by model (docs/camera.md): "opencv" k1, k2, p1,
  // p2[, k3[, k4, k5, k6]]; "opencv-fisheye" k1..k4; "fisheye-polynomial" k0..k4 (the angle from
  // the axis a polynomial of the radius in pixels; fx, fy unread; `image_circle` its radius in
  // pixels, 0: none); "cylindrical" none (fx pixels per radian across, fy up the cylinder).
  static Camera from_opencv(const std::array<double, 16>& world_to_camera, double fx, double fy,
                            double cx, double cy, int width, int height,
                            const std::vector<double>& distortion = {},
                            const std::string& model = "opencv", double image_circle = 0);
  // The same with the intrinsics, distortion, model and image size of an OpenCV calibration file
  // (YAML or JSON as cv::FileStorage writes it, ROS camera_info files too), as `rtvk render
  // --calibration` reads one.
  static Camera from_opencv_file(const std::array<double, 16>& world_to_camera,
                                 const std::string& calibration_file);
  // The registered images of a COLMAP model (DIR/cameras.txt and images.txt, or the .bin pair),
  // in its images file's order: each view's name (as `rtvk render --colmap` names the camera)
  // and its camera, at the size its COLMAP camera was calibrated at. `names`: only those views
  // (an unknown one is bad input); empty: all of them.
  static std::vector<std::pair<std::string, Camera>> from_colmap(
      const std::string& folder, const std::vector<std::string>& names = {});
  int width() const;
  int height() const;

  struct impl;
  std::shared_ptr<const impl> impl_;
};

// What a render draws besides the color, as --aov names them.
enum aov : unsigned {
  aov_depth = 1u << 0,        // z depth along the camera's axis, scene units; +inf: nothing
  aov_normal = 1u << 1,       // world-space unit normal, 3 a pixel; 0: nothing
  aov_albedo = 1u << 2,       // the material's linear color, 3 a pixel
  aov_object_id = 1u << 3,    // rtvk's object id (rtvk scene objects), 0: nothing
  aov_material_id = 1u << 4,  // the material's index + 1, 0: nothing
};

// A render's result: row-major from the top row.
struct RTVK_API Image {
  int width = 0, height = 0;             // pixels
  std::vector<float> rgb;                // width * height * 3, scene-linear mean color
  std::vector<float> depth;              // width * height when asked (aov_depth)
  std::vector<float> distance;           // along the camera ray, with aov_depth
  std::vector<float> normal;             // width * height * 3 when asked
  std::vector<float> albedo;             // width * height * 3 when asked
  std::vector<std::uint32_t> object_id;  // width * height when asked
  std::vector<std::uint32_t> material_id;
};

struct RTVK_API RenderOptions {
  int spp = 0;             // samples per pixel; 0: the scene's
  int max_depth = 0;       // most bounces; 0: the scene's
  std::int64_t seed = -1;  // random seed, 0 to 2^32 - 1; -1: the scene's
  unsigned aovs = 0;       // aov bits
  // Polled between passes (a CPU chunk, a GPU submission): true stops the render, which throws
  // `cancelled`. Empty: never.
  std::function<bool()> cancelled;
  // Called from the calling thread as the render goes, with the share done (0 to 1) of the
  // images asked for. Empty: not called.
  std::function<void(double)> progress;
};

// Renders a scene on one backend: "cpu" (precision "auto", "fast" or "reference": --precision),
// "gpu" (device: as --device selects it; empty: RTVK_DEVICE, else the best) or "auto" (the GPU
// where a Vulkan device exists, else the CPU). The scene is set up once (on the GPU its device
// buffers, BVH and pipelines; on the CPU its BVH or Embree's trees and its shading tables) and
// kept across renders until it changes. A Scene and the Renderers made from it are used by one
// thread at a time.
class RTVK_API Renderer {
 public:
  explicit Renderer(const Scene& scene, const std::string& backend = "cpu",
                    const std::string& device = "", const std::string& precision = "auto");
  ~Renderer();
  Renderer(Renderer&&) noexcept;
  Renderer& operator=(Renderer&&) noexcept;

  Image render(const Camera& camera, const RenderOptions& options = {});
  // Several views of the scene: on the GPU in one stream of submissions, as the CLI's
  // multi-view renders. Every camera must have the same image size.
  std::vector<Image> render(const std::vector<Camera>& cameras, const RenderOptions& options = {});
  // What draws: "cpu (fast)", "cpu (reference)" or "gpu (DEVICE, PATH)".
  std::string description() const;
  // How many times the scene was set up on the backend: 1 after the first render; an edit of the
  // scene, or a camera whose shutter reaches outside the instants set up for, adds one.
  std::uint64_t set_ups() const;

  struct impl;

 private:
  std::unique_ptr<impl> impl_;
};

// Every built-in scene's name, as `rtvk scene list` prints them.
RTVK_API std::vector<std::string> builtin_scenes();
// rtvk's version, as `rtvk --version` prints it.
RTVK_API std::string version();

}  // namespace rtvk::api
