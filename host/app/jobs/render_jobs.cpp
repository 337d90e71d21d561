#include "render_jobs.h"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <optional>
#include <set>

#include "errors.h"
#include "format.h"
#include "image_io.h"
#include "light_sources.h"
#include "partial_image.h"
#include "render_cpu.h"

namespace rtvk {
namespace {

bool parse_int(std::string_view s, int& out) {
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
  return ec == std::errc() && end == s.data() + s.size() && !s.empty();
}

std::string names_of(const scene& s) {
  std::string out;
  for (const named_camera& c : s.cameras) out += (out.empty() ? "" : ", ") + c.name;
  return out;
}

// Narrows s.cameras to the ones asked for, keeping the scene's order.
void select_cameras(scene& s, const std::vector<std::string>& asked) {
  if (asked.empty()) {
    s.cameras.resize(1);
    return;
  }
  if (std::find(asked.begin(), asked.end(), "all") != asked.end()) return;
  for (const std::string& name : asked)
    if (std::none_of(s.cameras.begin(), s.cameras.end(),
                     [&](const named_camera& c) { return c.name == name; }))
      throw usage_error("--camera " + name + ": " + s.name + " has no such camera (it has " +
                        names_of(s) + ")");
  std::erase_if(s.cameras, [&](const named_camera& c) {
    return std::find(asked.begin(), asked.end(), c.name) == asked.end();
  });
}

// Appends each value's bytes (fields one by one: no struct padding).
template <typename... T>
void append_bytes(std::string& out, const T&... values) {
  (out.append(reinterpret_cast<const char*>(&values), sizeof values), ...);
}

// What identifies the image a job draws, whatever machine draws it: every number of the scene that
// changes a pixel -- render settings but the sample count (pieces of one render may come from
// runs with different --spp as long as their sample ranges do not overlap; not under lights
// sampling, whose stratified spots depend on --spp: the strata are part of it), the sky, the
// materials, the spheres -- as their binary values, then the job's pose. Bytes, not the scene's
// JSON text: formatting a million spheres as text took longer than rendering them small. The
// scene part is the same for every job of a run: made once, and only for pieces (.exr).
std::string scene_identity(const scene& s) {
  std::string out = "rtvk scene identity 2|";
  const render_settings& r = s.render;
  append_bytes(out, r.width, r.aspect, r.max_depth, r.seed, r.gamma, r.jitter);
  // The view transform and exposure after a marker, where they are not the books' power law at
  // 0 EV: renders encoded as before keep their identity.
  if (r.transform != view_transform::gamma || r.exposure != 0)
    append_bytes(out, std::uint8_t(0x56), r.transform, r.exposure);
  append_bytes(out, s.sky.horizon, s.sky.zenith);
  for (const named_material& m : s.materials)
    append_bytes(out, m.m.type, m.m.albedo, m.m.fuzz, m.m.ir);
  for (const sphere& sp : s.spheres) {
    append_bytes(out, sp.center, sp.radius, sp.material);
    // A moving sphere's center at time 1 (after a marker); still ones add nothing, so still
    // scenes keep the identity they always had.
    if (sp.center1) append_bytes(out, std::uint8_t(0x4d), *sp.center1);
  }
  // Quads and triangles after markers of their own: sphere-only scenes keep their identity.
  for (const quad& q : s.quads) append_bytes(out, std::uint8_t(0x51), q.Q, q.u, q.v, q.material);
  const auto triangles = [&](const std::vector<triangle>& list,
                             const std::vector<triangle_shading>& shading) {
    for (const triangle& t : list) {
      append_bytes(out, std::uint8_t(0x54), t.p, t.material);
      if (t.shading >= 0 && shading[std::size_t(t.shading)].has_normals())
        append_bytes(out, shading[std::size_t(t.shading)].normal);
    }
  };
  triangles(s.triangles, s.shading);
  // Disks after a marker of their own, the groups' with them: scenes without keep their identity.
  const auto disks = [&](const std::vector<disk>& list) {
    for (const disk& d : list)
      append_bytes(out, std::uint8_t(0x44), d.center, d.normal, d.radius, d.material);
  };
  disks(s.disks);
  // Groups and their instances after markers of their own: scenes without keep their identity.
  for (const object_group& g : s.groups) {
    append_bytes(out, std::uint8_t(0x47), g.spheres.size(), g.quads.size(), g.triangles.size());
    for (const sphere& sp : g.spheres) append_bytes(out, sp.center, sp.radius, sp.material);
    for (const quad& q : g.quads) append_bytes(out, q.Q, q.u, q.v, q.material);
    triangles(g.triangles, g.shading);
    disks(g.disks);
  }
  for (const instance& i : s.instances)
    append_bytes(out, std::uint8_t(0x49), i.group, i.placement.linear, i.placement.offset);
  // Lights sampling after a marker of its own, with what it aims at and the strata (pieces of a
  // stratified render share --spp): plain renders keep their identity.
  if (samples_lights(s, r)) {
    append_bytes(out, std::uint8_t(0x4c), pixel_strata(r, true));
    for (const light_record& l : scene_lights(s))
      append_bytes(out, l.kind, l.a, l.u, l.v, l.radius);
  }
  // Next-event estimation likewise, with the lamps it draws and what they emit, and the version
  // of its low-discrepancy numbers (2: Sobol in every dimension, no strata), so that pieces drawn
  // by an older build do not merge with these.
  if (uses_nee(r.sampling)) {
    append_bytes(out, std::uint8_t(0x4e), std::uint8_t(2));
    for (const light_record& l : scene_lamps(s))
      append_bytes(out, l.kind, l.a, l.u, l.v, l.radius, l.flags, l.emission);
  }
  for (const named_material& m : s.materials)
    if (m.m.one_sided) append_bytes(out, std::uint8_t(0x31), m.name);
  // The environment map after a marker of its own, its texels and settings: scenes without keep
  // their identity.
  if (s.environment) {
    const environment_map& e = *s.environment;
    append_bytes(out, std::uint8_t(0x45), e.image->width, e.image->height, e.rotation, e.strength,
                 e.visible);
    out.append(reinterpret_cast<const char*>(e.image->texels.data()),
               e.image->texels.size() * sizeof(std::uint32_t));
  }
  return out;
}

// `instants`: when the view's shutter is open, absolute seconds; part of the fingerprint only
// where spheres move (elsewhere the time changes nothing, and older pieces keep theirs).
std::string job_fingerprint(const std::string& scene_text, const camera_pose& p,
                            const std::optional<time_span>& instants) {
  char pose[512];
  std::snprintf(pose, sizeof pose,
                "%.17g %.17g %.17g|%.17g %.17g %.17g|%.17g %.17g %.17g|%.17g %.17g %.17g",
                p.lookfrom.x, p.lookfrom.y, p.lookfrom.z, p.lookat.x, p.lookat.y, p.lookat.z,
                p.vup.x, p.vup.y, p.vup.z, p.vfov, p.aperture, p.focus_dist);
  // The model only where it is not the lesson's, so perspective pieces keep their fingerprints.
  std::string model;
  if (p.projection != projection::perspective || p.fisheye_fov != camera_pose{}.fisheye_fov) {
    char fov[64];
    std::snprintf(fov, sizeof fov, " %.17g", p.fisheye_fov);
    model = "|" + std::string(projection_name(p.projection)) + fov;
  }
  if (is_calibrated(p.projection) || p.readout != 0) {  // the lens and the rolling shutter
    const lens_intrinsics& l = p.intrinsics;
    char lens[512];
    std::snprintf(lens, sizeof lens, "|lens %d %d %.17g %.17g %.17g %.17g %.17g|ro %.17g", l.width,
                  l.height, l.fx, l.fy, l.cx, l.cy, l.radius, p.readout);
    model += lens;
    for (double k : l.k) {
      char digits[32];
      std::snprintf(digits, sizeof digits, " %.17g", k);
      model += digits;
    }
  }
  std::string time;
  if (instants) {
    char t[96];
    std::snprintf(t, sizeof t, "|t %.17g %.17g", instants->lo, instants->hi);
    time = t;
  }
  return fingerprint_of(scene_text + pose + model + time);
}

}  // namespace

int_range parse_range(const std::string& text, const std::string& flag, int lo, int hi,
                      const std::string& hi_note) {
  const auto colon = text.find(':');
  int_range r;
  bool ok;
  if (colon == std::string::npos) {
    ok = parse_int(text, r.begin) && r.begin < hi;
    r.end = r.begin + 1;
  } else {
    ok = parse_int(std::string_view(text).substr(0, colon), r.begin) &&
         parse_int(std::string_view(text).substr(colon + 1), r.end);
  }
  if (!ok || r.begin < lo || r.end > hi || r.begin >= r.end)
    throw usage_error(flag + ": '" + text + "' is not A:B (A up to, not including, B) or N with " +
                      std::to_string(lo) + " <= A < B <= " + std::to_string(hi) + hi_note);
  return r;
}

render_window parse_region(const std::string& text, const std::string& flag) {
  int v[4];
  std::string_view rest = text;
  for (int k = 0; k < 4; ++k) {
    const auto comma = k < 3 ? rest.find(',') : std::string_view::npos;
    if ((k < 3 && comma == std::string_view::npos) || !parse_int(rest.substr(0, comma), v[k]))
      throw usage_error(flag + ": '" + text + "' is not x,y,w,h (four integers, pixels)");
    rest = k < 3 ? rest.substr(comma + 1) : std::string_view();
  }
  return {v[0], v[1], v[2], v[3], 0, 0};
}

namespace {

// The frames asked for, checked: --fps, the number of images, and a -o that names each image
// apart.
int_range plan_frames(const scene& s, const job_request& req, const output_pattern& output) {
  const int_range frames =
      req.frames.empty() ? int_range{0, 1} : parse_range(req.frames, "--frames", 0, 1'000'000);
  if (!(req.fps > 0)) throw usage_error("--fps: " + format_number(req.fps) + " is not > 0");
  const std::size_t count = s.cameras.size() * std::size_t(frames.end - frames.begin);
  if (count > 100'000)
    throw usage_error("--frames " + req.frames + ": " + std::to_string(count) +
                      " images in one run; the most is 100000");
  if (s.cameras.size() > 1 && !output.has_camera())
    throw usage_error("--output " + req.output + ": " + std::to_string(s.cameras.size()) +
                      " cameras would share it; put {camera} in the name");
  if (frames.end - frames.begin > 1 && !output.has_frame())
    throw usage_error("--output " + req.output + ": " + std::to_string(frames.end - frames.begin) +
                      " frames would share it; put {frame} or {frame:04} in the name");
  return frames;
}

// One job per selected camera and frame, in that order; no two write one file, and every
// output folder is writable.
std::vector<render_job> make_jobs(const scene& s, const job_request& req,
                                  const output_pattern& output, const scene_overrides& overrides,
                                  int_range frames) {
  // Only pieces for `rtvk merge` carry a fingerprint.
  const bool pieces = format_for_path(output.expand(s.cameras.front().name, frames.begin),
                                      "--output") == file_format::exr;
  const std::string scene_text = pieces ? scene_identity(s) : std::string();
  const bool moves = scene_moves(s);
  std::vector<render_job> jobs;
  std::set<std::string> outputs;
  for (const named_camera& c : s.cameras)
    for (int f = frames.begin; f < frames.end; ++f) {
      const camera_pose pose = c.path.at(f / req.fps);
      const camera cam = overrides.make_camera(
          s, pose, "camera " + c.name + " of " + s.name + " at frame " + std::to_string(f),
          f / req.fps);
      const std::optional<time_span> instants =
          moves ? std::optional<time_span>({cam.time_open(), cam.time_close()}) : std::nullopt;
      render_job job{c.name, f, cam, output.expand(c.name, f),
                     pieces ? job_fingerprint(scene_text, pose, instants) : std::string()};
      if (!outputs.insert(job.output).second)
        throw usage_error("--output " + req.output + ": two images would be written to " +
                          job.output);
      jobs.push_back(std::move(job));
    }
  for (const std::string& path : outputs) check_output_path(path, "--output", true);
  return jobs;
}

// The part of the image (--region) and of its samples (--samples) to draw, checked against
// the image `cam` draws and the scene's samples per pixel.
render_window plan_window(const scene& s, const job_request& req, const camera& cam) {
  const int width = cam.image_width(), height = cam.image_height();
  render_window window = req.region.empty() ? whole_render(width, height, s.render.spp)
                                            : parse_region(req.region, "--region");
  if (!req.region.empty()) {
    try {
      check_window({window.x, window.y, window.width, window.height, 0, 1}, width, height);
    } catch (const std::invalid_argument& e) {
      throw usage_error("--region " + req.region + ": " + e.what());
    }
  }
  const int_range samples = req.samples.empty()
                                ? int_range{0, s.render.spp}
                                : parse_range(req.samples, "--samples", 0, s.render.spp,
                                              " (the samples per pixel, --spp)");
  window.sample_begin = samples.begin;
  window.sample_end = samples.end;
  return window;
}

}  // namespace

std::vector<render_job> plan_jobs(scene& s, const job_request& req, const output_pattern& output,
                                  const scene_overrides& overrides, render_window& window) {
  overrides.apply_cameras(s);
  // A COLMAP model's views are all rendered unless --camera picks some.
  select_cameras(
      s, req.cameras.empty() && overrides.colmap ? std::vector<std::string>{"all"} : req.cameras);
  overrides.apply(s);
  const int_range frames = plan_frames(s, req, output);
  std::vector<render_job> jobs = make_jobs(s, req, output, overrides, frames);
  window = plan_window(s, req, jobs[0].cam);
  // The BVHs bound moving spheres over exactly the instants these images sample.
  s.motion = {jobs[0].cam.time_open(), jobs[0].cam.time_close()};
  for (const render_job& j : jobs)
    s.motion = {std::min(s.motion.lo, j.cam.time_open()),
                std::max(s.motion.hi, j.cam.time_close())};
  return jobs;
}

}  // namespace rtvk
