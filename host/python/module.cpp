// `import rtvk`: the library (rtvk.h) with NumPy arrays. The GIL is released while a render
// runs; Ctrl-C stops it at its next pass and raises KeyboardInterrupt; bad input raises
// ValueError with the message the CLI prints, a device failure RuntimeError. Its typed signatures
// are rtvk.pyi beside it; docs/python.md shows it at work.
#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <atomic>

#include "rtvk.h"

namespace py = pybind11;
using namespace rtvk::api;

namespace {

// A camera argument: a Camera, or a scene (or a scene's name) whose main camera to take.
Camera camera_arg(const py::object& o) {
  if (py::isinstance<Camera>(o)) return o.cast<Camera>();
  if (py::isinstance<Scene>(o)) return Camera::from_scene(o.cast<Scene>());
  return Camera::from_scene(Scene(o.cast<std::string>()));
}

// n numbers from anything NumPy reads as an array of that many (a list, a tuple, an array); n 0:
// any number of them.
std::vector<double> numbers(const py::object& o, std::size_t n, const char* what) {
  const py::array_t<double, py::array::c_style | py::array::forcecast> a =
      py::module_::import("numpy").attr("asarray")(o, "float64");
  if (n != 0 && std::size_t(a.size()) != n)
    throw bad_input(std::string(what) + ": expected " + std::to_string(n) + " numbers, got " +
                    std::to_string(a.size()));
  return std::vector<double>(a.data(), a.data() + a.size());
}

template <typename T>
py::array_t<T> array(const std::vector<T>& v, std::vector<py::ssize_t> shape) {
  py::array_t<T> a(shape);
  std::copy(v.begin(), v.end(), a.mutable_data());
  return a;
}

py::object image_result(const Image& im, unsigned aovs) {
  const py::ssize_t h = im.height, w = im.width;
  py::array_t<float> rgb = array(im.rgb, {h, w, 3});
  if (aovs == 0) return rgb;
  py::dict d;
  if (aovs & aov_depth) {
    d["depth"] = array(im.depth, {h, w});
    d["distance"] = array(im.distance, {h, w});
  }
  if (aovs & aov_normal) d["normal"] = array(im.normal, {h, w, 3});
  if (aovs & aov_albedo) d["albedo"] = array(im.albedo, {h, w, 3});
  if (aovs & aov_object_id) d["object_id"] = array(im.object_id, {h, w});
  if (aovs & aov_material_id) d["material_id"] = array(im.material_id, {h, w});
  return py::make_tuple(rgb, d);
}

unsigned aov_bits(const std::vector<std::string>& names) {
  unsigned bits = 0;
  for (const std::string& n : names) {
    if (n == "depth")
      bits |= aov_depth;
    else if (n == "normal")
      bits |= aov_normal;
    else if (n == "albedo")
      bits |= aov_albedo;
    else if (n == "object-id" || n == "object_id")
      bits |= aov_object_id;
    else if (n == "material-id" || n == "material_id")
      bits |= aov_material_id;
    else
      throw bad_input("aovs: " + n +
                      " is not one of depth, normal, albedo, object-id, material-id");
  }
  return bits;
}

// Renders with the GIL released; the cancel poll takes it back to ask Python about signals.
py::object render(Renderer& r, const py::object& cameras, int spp, int max_depth, std::int64_t seed,
                  const std::vector<std::string>& aov_names, const py::object& progress) {
  const bool several = py::isinstance<py::list>(cameras) || py::isinstance<py::tuple>(cameras);
  std::vector<Camera> views;
  if (several)
    for (const py::handle c : cameras)
      views.push_back(camera_arg(py::reinterpret_borrow<py::object>(c)));
  else
    views.push_back(camera_arg(cameras));
  RenderOptions o;
  o.spp = spp;
  o.max_depth = max_depth;
  o.seed = seed;
  o.aovs = aov_bits(aov_names);
  auto interrupted = std::make_shared<std::atomic<bool>>(false);
  // Python runs its signal handlers on the main thread only, which renders too (the CPU's
  // calling thread takes chunks; the GPU's waits there between submissions).
  o.cancelled = [interrupted] {
    if (interrupted->load()) return true;
    py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) interrupted->store(true);
    return interrupted->load();
  };
  // The progress callback runs on the calling thread, which holds no GIL while rendering.
  if (!progress.is_none())
    o.progress = [callback = progress.ptr()](double done) {  // borrowed: no reference counted
      py::gil_scoped_acquire gil;                            // without the GIL
      py::handle f(callback);
      f(done);
    };
  std::vector<Image> drawn;
  try {
    py::gil_scoped_release release;
    drawn = r.render(views, o);
  } catch (const cancelled&) {
    if (PyErr_Occurred()) throw py::error_already_set();  // KeyboardInterrupt, from the handler
    throw;
  }
  if (!several) return image_result(drawn.front(), o.aovs);
  py::list out;
  for (const Image& im : drawn) out.append(image_result(im, o.aovs));
  return out;
}

}  // namespace

PYBIND11_MODULE(rtvk, m) {
  m.doc() = "rtvk: the ray tracer's scenes, cameras and renderers, with NumPy images.";
  py::register_exception<bad_input>(m, "BadInput", PyExc_ValueError);
  py::register_exception<cancelled>(m, "Cancelled", PyExc_RuntimeError);
  m.attr("__version__") = version();
  m.def("builtin_scenes", &builtin_scenes, "Every built-in scene's name, as `rtvk scene list`.");

  py::class_<Scene>(m, "Scene", "A scene: objects, materials, lights, settings, named cameras.")
      .def(py::init<const std::string&>(), py::arg("name_or_file"),
           "A built-in scene (rtvk.builtin_scenes()), a .json scene file or a mesh file "
           "(.obj, .gltf, .glb), read as `rtvk render --scene` reads it.")
      .def_static(
          "from_dict",
          [](const py::dict& d, const std::string& folder) {
            const std::string text =
                py::module_::import("json").attr("dumps")(d).cast<std::string>();
            return Scene::from_json(text, folder);
          },
          py::arg("scene"), py::arg("folder") = ".",
          "A scene from a dict in the scene-file format (docs/scene-format.md); files it names "
          "are relative to `folder`.")
      .def_static("from_json", &Scene::from_json, py::arg("text"), py::arg("folder") = ".")
      .def(
          "to_dict",
          [](const Scene& s) { return py::module_::import("json").attr("loads")(s.to_json()); },
          "The scene as a dict in the scene-file format: from_dict of it is the same scene.")
      .def("to_json", &Scene::to_json)
      .def_property_readonly("name", &Scene::name)
      .def_property_readonly("camera_names", &Scene::camera_names)
      .def(
          "set_material",
          [](Scene& s, const std::string& name, const py::dict& material) {
            s.set_material(name,
                           py::module_::import("json").attr("dumps")(material).cast<std::string>());
          },
          py::arg("name"), py::arg("material"),
          "Replaces material `name` (a dict as a scene file writes one); renderers of this "
          "scene set it up again at their next render.")
      .def(
          "objects",
          [](const Scene& s) {
            py::list out;
            for (const Scene::Object& o : s.objects()) {
              py::dict d;
              d["id"] = o.id;
              d["kind"] = o.kind;
              d["material"] = o.material;
              d["group"] = o.group;
              d["primitives"] = o.primitives;
              d["bounds"] = py::make_tuple(py::make_tuple(o.lo[0], o.lo[1], o.lo[2]),
                                           py::make_tuple(o.hi[0], o.hi[1], o.hi[2]));
              out.append(d);
            }
            return out;
          },
          "Every object as the object-id AOV numbers it: dicts of id, kind (sphere, quad, box, "
          "triangle, mesh, disk, instance), material, group (an instance's), primitives and "
          "bounds ((lo), (hi): the box around it where it is now).")
      .def(
          "place",
          [](Scene& s, std::uint32_t id, const py::object& matrix) {
            s.place(id, numbers(matrix, 0, "matrix"));
          },
          py::arg("id"), py::arg("matrix"),
          "Places object `id` by `matrix` (4x4, or its first 3 rows) after the placement the "
          "scene gave it: the identity puts it back; each call replaces the last. Renderers of "
          "this scene set it up again at their next render.");

  py::class_<Camera>(m, "Camera", "A camera: a pose, a model and the image size it draws.")
      .def_static(
          "from_scene",
          [](const py::object& scene, const std::string& name) {
            return py::isinstance<Scene>(scene)
                       ? Camera::from_scene(scene.cast<Scene>(), name)
                       : Camera::from_scene(Scene(scene.cast<std::string>()), name);
          },
          py::arg("scene"), py::arg("name") = "",
          "The scene's camera `name` (empty: its main one), as `rtvk render` draws it. `scene` "
          "may be a Scene or a built-in scene's name.")
      .def_static(
          "look_at",
          [](const py::object& lookfrom, const py::object& lookat, int width, int height,
             double vfov, const py::object& vup, double aperture, double focus_dist,
             const std::string& projection) {
            const auto v3 = [](const py::object& o, const char* w) {
              const std::vector<double> v = numbers(o, 3, w);
              return std::array<double, 3>{v[0], v[1], v[2]};
            };
            return Camera::look_at(v3(lookfrom, "lookfrom"), v3(lookat, "lookat"), width, height,
                                   vfov, v3(vup, "vup"), aperture, focus_dist, projection);
          },
          py::arg("lookfrom"), py::arg("lookat"), py::arg("width"), py::arg("height"),
          py::arg("vfov") = 40.0, py::arg("vup") = py::make_tuple(0, 1, 0),
          py::arg("aperture") = 0.0, py::arg("focus_dist") = 1.0,
          py::arg("projection") = "perspective",
          "A camera at `lookfrom` looking at `lookat` (vertical field of view in degrees).")
      .def_static(
          "from_opencv",
          [](const py::object& world_to_camera, const py::object& K, int width, int height,
             const py::object& dist, const std::string& model, double image_circle) {
            const std::vector<double> m = numbers(world_to_camera, 16, "world_to_camera");
            const std::vector<double> k = numbers(K, 9, "K");
            std::array<double, 16> w2c{};
            std::copy(m.begin(), m.end(), w2c.begin());
            std::vector<double> d;
            if (!dist.is_none()) {
              const py::array_t<double, py::array::c_style | py::array::forcecast> a =
                  py::module_::import("numpy").attr("asarray")(dist, "float64");
              d.assign(a.data(), a.data() + a.size());
            }
            return Camera::from_opencv(w2c, k[0], k[4], k[2], k[5], width, height, d, model,
                                       image_circle);
          },
          py::arg("world_to_camera"), py::arg("K"), py::arg("width"), py::arg("height"),
          py::arg("dist") = py::none(), py::arg("model") = "opencv", py::arg("image_circle") = 0.0,
          "A calibrated camera as OpenCV holds one: the 4x4 world-to-camera matrix ([R|t]; +z "
          "forward, +y down), the 3x3 camera matrix K, the image size and the distortion "
          "coefficients by model (opencv: k1, k2, p1, p2[, k3[, k4, k5, k6]]; opencv-fisheye: "
          "k1..k4; fisheye-polynomial: k0..k4, radians per pixel^n, with image_circle its "
          "radius in pixels; cylindrical: none, fx in pixels per radian).")
      .def_static(
          "from_opencv_file",
          [](const py::object& world_to_camera, const std::string& file) {
            const std::vector<double> m = numbers(world_to_camera, 16, "world_to_camera");
            std::array<double, 16> w2c{};
            std::copy(m.begin(), m.end(), w2c.begin());
            return Camera::from_opencv_file(w2c, file);
          },
          py::arg("world_to_camera"), py::arg("calibration_file"),
          "A calibrated camera posed by the 4x4 world-to-camera matrix, its intrinsics, "
          "distortion, model and image size read from an OpenCV calibration file (YAML or JSON "
          "as cv::FileStorage writes it), as `rtvk render --calibration` reads one.")
      .def_static(
          "from_colmap",
          [](const std::string& folder, const std::vector<std::string>& names) {
            py::dict views;  // in the images file's order (dicts keep insertion order)
            for (auto& [name, camera] : Camera::from_colmap(folder, names))
              views[py::str(name)] = camera;
            return views;
          },
          py::arg("folder"), py::arg("names") = std::vector<std::string>{},
          "Every registered image of a COLMAP model (cameras.txt and images.txt, or the .bin "
          "pair) as {name: Camera}, each at its calibrated size, named as `rtvk render "
          "--colmap` names them; `names`: only those.")
      .def_property_readonly("width", &Camera::width)
      .def_property_readonly("height", &Camera::height);

  py::class_<Renderer>(m, "Renderer",
                       "Renders a scene on one backend, keeping it set up across renders.")
      .def(py::init<const Scene&, const std::string&, const std::string&, const std::string&>(),
           py::arg("scene"), py::arg("backend") = "cpu", py::arg("device") = "",
           py::arg("precision") = "auto",
           "backend: 'cpu' or 'gpu'; device: as `rtvk --device` selects one (empty: "
           "RTVK_DEVICE, else the best); precision (cpu): 'auto', 'fast' or 'reference'.")
      .def("render", &render, py::arg("camera"), py::arg("spp") = 0, py::arg("max_depth") = 0,
           py::arg("seed") = -1, py::arg("aovs") = std::vector<std::string>{},
           py::arg("progress") = py::none(),
           "Renders `camera` (a Camera, or a list of them: one image each). Returns a float32 "
           "array (height, width, 3) of scene-linear color; with `aovs` (depth, normal, albedo, "
           "object-id, material-id), a tuple (image, dict of arrays). spp, max_depth, seed: 0 "
           "(-1 for seed) keeps the scene's. progress: called with the share done, 0 to 1.")
      .def_property_readonly("description", &Renderer::description)
      .def_property_readonly("set_ups", &Renderer::set_ups,
                             "How many times the scene was set up on the backend: 1 after the "
                             "first render; one more at the next render after any edits.");
}
