// rtvk view in a real X server (Xvfb) on lavapipe with validation on: scripted screenshots are
// the bytes rtvk render --backend gpu writes, the camera it prints renders the same frame, and
// the bad situations (no display, Ctrl-C) end as documented.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "bvh_world.h"
#include "camera.h"
#include "ci.h"
#include "fault_layer.h"
#include "image_io.h"
#include "mesh_helpers.h"
#include "process.h"
#include "render_cpu.h"
#include "sanitizers.h"
#include "scene.h"
#include "temp_dir.h"
#include "x_window_pixels.h"

namespace rtvk {
namespace {

using namespace std::chrono_literals;

// A private X server for the test's windows, on a display of its own.
class XvfbTest : public testing::Test {
 protected:
  void SetUp() override {
    if (!on_path("Xvfb")) {
      if (test::in_ci()) FAIL() << "Xvfb not found (Debian: apt install xvfb); CI must run this";
      GTEST_SKIP() << "Xvfb not found (Debian: apt install xvfb)";
    }
    // A display number of this process's own; -displayfd says when it accepts connections. It
    // is checked from a client too, and the next number tried if it fails.
    for (int attempt = 0; attempt < 5 && display_.empty(); ++attempt) {
      start_xvfb(1000 + (getpid() * 5 + attempt) % 20000);
      if (display_.empty()) continue;
      std::this_thread::sleep_for(300ms);
      if (run_tool_in({"xdotool", "version"}).empty() ||  // nothing to check with
          !run_tool_in({"xdotool", "getdisplaygeometry"}).empty())
        break;
      stop_xvfb();
    }
    ASSERT_FALSE(display_.empty()) << "Xvfb did not start, or could not be reached";
  }

  void start_xvfb(int display) {
    int fds[2];
    if (pipe(fds) != 0) return;
    std::vector<std::string> args{"Xvfb", ":" + std::to_string(display), "-displayfd", "3",
                                  "-screen", "0", "1280x1024x24", "-nolisten", "tcp",
                                  // an X server resets when its last client leaves, refusing
                                  // connections meanwhile: xdotool's come and go
                                  "-noreset"};
    const int rc = spawn_quietly(args, xvfb_, fds[1], fds[0]);
    close(fds[1]);
    std::string number;
    if (rc == 0) {
      pollfd ready{fds[0], POLLIN, 0};
      char c = 0;
      while (poll(&ready, 1, 20000) == 1 && read(fds[0], &c, 1) == 1 && c != '\n') number += c;
    }
    close(fds[0]);
    if (!number.empty()) display_ = ":" + number;
  }

  // Starts args[0] from PATH with stdout and stderr to /dev/null; `fd3`, unless -1, becomes its
  // fd 3, after `unused` is closed there. 0, or posix_spawnp's error.
  static int spawn_quietly(std::vector<std::string> args, pid_t& pid, int fd3 = -1,
                           int unused = -1) {
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_addopen(&fa, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&fa, 2, "/dev/null", O_WRONLY, 0);
    if (unused >= 0)  // before the dup2: it may be fd 3 itself
      posix_spawn_file_actions_addclose(&fa, unused);
    if (fd3 >= 0) posix_spawn_file_actions_adddup2(&fa, fd3, 3);
    const int rc = posix_spawnp(&pid, argv[0], &fa, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&fa);
    return rc;
  }

  void stop_xvfb() {
    stop(window_manager_);
    stop(xvfb_);
    display_.clear();
  }
  // SIGTERM, and SIGKILL after 5 s: twm ignores SIGTERM once its server has gone.
  static void stop(pid_t& pid) {
    if (pid > 0) {
      ::kill(pid, SIGTERM);
      int status = 0;
      for (int i = 0; i < 50 && waitpid(pid, &status, WNOHANG) == 0; ++i)
        std::this_thread::sleep_for(100ms);
      if (waitpid(pid, &status, WNOHANG) == 0) {
        ::kill(pid, SIGKILL);
        waitpid(pid, &status, 0);
      }
    }
    pid = -1;
  }

  void TearDown() override { stop_xvfb(); }

  // twm in this server (Xvfb alone has no window manager, so nothing can be minimized), placing
  // windows itself rather than asking for a click. False, having failed the test in CI or
  // skipped it elsewhere, when twm is missing.
  bool start_window_manager(const std::filesystem::path& folder) {
    if (!on_path("twm")) {
      if (test::in_ci())
        ADD_FAILURE() << "twm not found (Debian: apt install twm); CI must run this";
      else
        [] { GTEST_SKIP() << "twm not found (Debian: apt install twm)"; }();
      return false;
    }
    const std::string rc = (folder / "twmrc").string();
    std::ofstream(rc) << "RandomPlacement\nNoGrabServer\n"  // Xvfb's own font: no xfonts-base
                      << "TitleFont \"fixed\"\nResizeFont \"fixed\"\nMenuFont \"fixed\"\n"
                      << "IconFont \"fixed\"\nIconManagerFont \"fixed\"\n";
    if (spawn_quietly({"twm", "-display", display_, "-f", rc}, window_manager_) != 0) {
      ADD_FAILURE() << "twm did not start";
      return false;
    }
    std::this_thread::sleep_for(500ms);  // managing the root window before rtvk's appears
    return true;
  }

  // The environment of an rtvk that shows its window in this server, validation on.
  std::vector<std::string> env() const {
    // Validated, synchronization included: the frames in flight, the device-kept image and
    // the overlay composed on the device must be free of hazards. Not under AddressSanitizer:
    // both together slow these input-timed tests to a few frames a second on two cores, and the
    // ci preset (and the second lavapipe's pass) run them with the checks.
    const std::string enables =
        RTVK_ASAN ? "" : "VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT";
    return {"DISPLAY=" + display_, "WAYLAND_DISPLAY=", "RTVK_VALIDATE=1",
            "VK_LOADER_LAYERS_ENABLE=*validation", "VK_LAYER_ENABLES=" + enables};
  }

  // The id of rtvk view's window, mapped, once its first batch is rendered (its title then counts
  // samples), or "" after 60 s: input sent earlier could reach the root window instead.
  std::string shown_window() const {
    for (int i = 0; i < 600; ++i) {
      const std::string ids =
          run_tool_in({"xdotool", "search", "--onlyvisible", "--name", "rtvk view: .* spp"});
      if (!ids.empty()) return ids.substr(0, ids.find('\n'));
      std::this_thread::sleep_for(100ms);
    }
    return "";
  }
  std::string run_tool_in(const std::vector<std::string>& args) const;

  // False, having failed the test in CI or skipped it elsewhere, when xdotool is missing.
  bool xdotool_ready() {
    if (!run_tool_in({"xdotool", "version"}).empty()) return true;
    if (test::in_ci())
      ADD_FAILURE() << "xdotool not found (Debian: apt install xdotool); CI must run this";
    else
      [] { GTEST_SKIP() << "xdotool not found"; }();  // GTEST_SKIP returns void
    return false;
  }

  // Runs rtvk view with `args` and the test's environment, holds F and clicks the window's pixel
  // (x, y), closes it with Escape and gives the --focus-dist of the flags it printed in `focus`.
  void focus_after_click(const std::vector<std::string>& args, int x, int y, double& focus);

  // One xdotool command in this server, then a moment for rtvk view to handle its events.
  void xdo(std::vector<std::string> args) const {
    args.insert(args.begin(), "xdotool");
    run_tool_in(args);
    std::this_thread::sleep_for(200ms);
  }

  static bool on_path(const std::string& program) {
    const char* path = std::getenv("PATH");
    std::stringstream dirs(path ? path : "");
    for (std::string dir; std::getline(dirs, dir, ':');)
      if (!dir.empty() && access((dir + "/" + program).c_str(), X_OK) == 0) return true;
    return false;
  }

  // The samples per pixel the window's title shows ("rtvk view: NAME - N spp"), or -1.
  int title_samples(const std::string& id) const {
    const std::string title = run_tool_in({"xdotool", "getwindowname", id});
    const std::size_t dash = title.rfind(" - ");
    return dash == std::string::npos ? -1 : std::atoi(title.c_str() + dash + 3);
  }
  // Waits up to 60 s for the title to show more than `samples`; what it shows then.
  int samples_beyond(const std::string& id, int samples) const {
    int now = title_samples(id);
    for (int i = 0; i < 600 && now <= samples; ++i) {
      std::this_thread::sleep_for(100ms);
      now = title_samples(id);
    }
    return now;
  }

  std::string display_;        // ":N"
  pid_t xvfb_ = -1;            // the server
  pid_t window_manager_ = -1;  // twm, when a test asked for one
};

// The words of the one line rtvk view prints on stdout, without the leading "rtvk".
std::vector<std::string> printed_flags(const std::string& out) {
  std::stringstream words(out.substr(0, out.find('\n')));
  std::vector<std::string> flags;
  for (std::string w; words >> w;) flags.push_back(w);
  if (!flags.empty() && flags.front() == "rtvk") flags.erase(flags.begin());
  return flags;
}

// Runs a tool (xdotool) in the test's display and waits; its stdout, or "" when it failed.
std::string run_tool(const std::vector<std::string>& args, const std::string& display) {
  const test::temp_dir dir;
  const std::string out = (dir.path() / "out").string();
  std::vector<std::string> storage = args;
  std::vector<char*> argv;
  for (auto& a : storage) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::vector<std::string> env = test::environment_with({"DISPLAY=" + display});
  std::vector<char*> envp;
  for (auto& e : env) envp.push_back(e.data());
  envp.push_back(nullptr);
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, 1, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&fa, 2, "/dev/null", O_WRONLY, 0);
  pid_t pid = -1;
  const int rc = posix_spawnp(&pid, argv[0], &fa, nullptr, argv.data(), envp.data());
  posix_spawn_file_actions_destroy(&fa);
  if (rc != 0) return "";
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) && WEXITSTATUS(status) == 0 ? test::slurp(out) : "";
}

std::string XvfbTest::run_tool_in(const std::vector<std::string>& args) const {
  return run_tool(args, display_);
}

// The numbers of a printed flag's value, "x,y,z".
std::vector<double> numbers_after(const std::vector<std::string>& flags, const std::string& flag) {
  std::vector<double> out;
  for (std::size_t i = 0; i + 1 < flags.size(); ++i)
    if (flags[i] == flag) {
      std::stringstream parts(flags[i + 1]);
      for (std::string p; std::getline(parts, p, ',');) out.push_back(std::stod(p));
    }
  return out;
}

// The scene `name` with the camera object rtvk view printed after its flags ("camera": {...})
// in place of its own, written to `file`.
void write_scene_with_printed_camera(const std::string& name, const std::string& out,
                                     const std::filesystem::path& file) {
  const std::string marker = "\"camera\": ";
  const std::size_t at = out.rfind(marker);
  ASSERT_NE(at, std::string::npos) << "no camera object printed: " << out;
  const std::string object =
      out.substr(at + marker.size(), out.find('\n', at) - at - marker.size());
  const test::process_result dumped = test::run_rtvk({"scene", "dump", name});
  ASSERT_EQ(dumped.status, 0) << dumped.err;
  nlohmann::json scene = nlohmann::json::parse(dumped.out);
  scene["camera"] = nlohmann::json::parse(object);
  std::ofstream(file) << scene.dump();
}

// `view` and `render` take the same scene flags: the screenshot must be the bytes render writes,
// and the printed camera must render them again.
// `view_err`, when given, receives what the viewer wrote to stderr.
void expect_screenshot_is_the_render(const std::vector<std::string>& env,
                                     const std::vector<std::string>& flags,
                                     std::string* view_err = nullptr) {
  const test::temp_dir dir;
  const std::string shot = (dir.path() / "view.png").string();
  const std::string direct = (dir.path() / "render.png").string();
  const std::string again = (dir.path() / "again.png").string();
  std::vector<std::string> view{"view"};
  view.insert(view.end(), flags.begin(), flags.end());
  view.insert(view.end(), {"--screenshot", shot});
  const test::process_result v = test::run_rtvk_within(120s, view, env);
  if (view_err) *view_err = v.err;
  ASSERT_EQ(v.status, 0) << v.err;
  EXPECT_EQ(v.err.find("validation"), std::string::npos) << v.err;

  std::vector<std::string> render{"render"};
  render.insert(render.end(), flags.begin(), flags.end());
  render.insert(render.end(), {"--backend", "gpu", "-q", "-o", direct});
  ASSERT_EQ(test::run_rtvk(render).status, 0);
  EXPECT_EQ(test::slurp(shot), test::slurp(direct)) << "the screenshot is not render's bytes";

  std::vector<std::string> printed = printed_flags(v.out);
  ASSERT_FALSE(printed.empty()) << v.out;
  EXPECT_EQ(printed.front(), "render");
  printed.insert(printed.end(), {"--backend", "gpu", "-q", "-o", again});
  ASSERT_EQ(test::run_rtvk(printed).status, 0) << v.out;
  EXPECT_EQ(test::slurp(again), test::slurp(shot)) << "the printed camera frames another shot";
}

TEST_F(XvfbTest, ScreenshotsAreTheBytesRtvkRenderWrites) {
  expect_screenshot_is_the_render(env(), {"--scene", "seed", "--spp", "1"});
  expect_screenshot_is_the_render(env(), {"--scene", "book-final", "--width", "200", "--spp", "8"});
}

// Moving spheres under a shutter open past time 1: the viewer bounds them over it (it once
// refused), its screenshot is render's bytes, and the printed flags carry the shutter.
TEST_F(XvfbTest, AMotionBlurredScreenshotIsTheBytesRtvkRenderWrites) {
  expect_screenshot_is_the_render(
      env(), {"--scene", "bouncing-spheres", "--width", "120", "--spp", "4", "--shutter", "0:2"});
}

// Quads and a mesh file in the viewer: the window's pixels are rtvk render's bytes.
TEST_F(XvfbTest, QuadsAndAMeshFileScreenshotAreTheBytesRtvkRenderWrites) {
  expect_screenshot_is_the_render(env(), {"--scene", "quads", "--width", "120", "--spp", "4"});
  const test::temp_dir dir;
  const std::string obj = (dir.path() / "knot.obj").string();
  std::ofstream(obj) << test::obj_text(test::torus_knot(2000));
  expect_screenshot_is_the_render(env(), {"--scene", obj, "--width", "120", "--spp", "4"});
}

TEST_F(XvfbTest, CtrlCClosesTheWindowWithExit0AndNoScreenshot) {
  const test::temp_dir dir;
  const std::string shot = (dir.path() / "never.png").string();
  test::running_rtvk view(
      {"view", "--scene", "book-final", "--width", "320", "--spp", "1000000", "--screenshot", shot},
      env());
  ASSERT_TRUE(view.wait_until_catching(SIGINT, 30s));
  std::this_thread::sleep_for(1s);  // the window is up and accumulating
  view.signal(SIGINT);
  const test::process_result r = view.wait_at_most(60s);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_FALSE(std::filesystem::exists(shot));
  const std::vector<std::string> printed = printed_flags(r.out);
  ASSERT_FALSE(printed.empty()) << "nothing printed on the way out: " << r.err;
  EXPECT_EQ(printed.front(), "render") << "the camera is printed on the way out";
  EXPECT_NE(r.err.find("was not written"), std::string::npos) << r.err;
}

// Real input through the X server: a left-drag of 100 pixels to the right must turn the eye
// 25 degrees (0.25 per pixel) counter-clockwise about vup round the look-at point, at the same
// distance and height; the O key's screenshot at --spp must be what rtvk render makes of the
// camera printed on exit.
TEST_F(XvfbTest, ADragOrbitsByTheControlsAngleAndTheShotRendersFromThePrintedCamera) {
  if (!xdotool_ready()) return;
  const test::temp_dir dir;
  const std::filesystem::path before = std::filesystem::current_path();
  std::filesystem::current_path(dir.path());  // the O key writes into the current folder
  test::running_rtvk view({"view", "--scene", "book-final", "--width", "200", "--spp", "4"}, env());
  std::filesystem::current_path(before);
  const std::string id = shown_window();
  ASSERT_FALSE(id.empty()) << "no window showed a frame: " << view.stderr_so_far();
  xdo({"mousemove", "--window", id, "50", "60"});
  xdo({"mousedown", "1"});
  xdo({"mousemove", "--window", id, "150", "60"});
  xdo({"mouseup", "1"});
  std::this_thread::sleep_for(3s);  // 4 samples of 200x133 take well under a second
  xdo({"key", "--window", id, "o"});
  xdo({"key", "--window", id, "Escape"});
  const test::process_result r = view.wait_at_most(60s);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err.find("validation"), std::string::npos) << r.err;
  ASSERT_NE(r.err.find("200x133, 4 spp -> rtvk-view-1.png"), std::string::npos) << r.err;

  const std::vector<std::string> printed = printed_flags(r.out.substr(r.out.rfind("rtvk render")));
  const std::vector<double> from = numbers_after(printed, "--lookfrom");
  ASSERT_EQ(from.size(), 3u) << r.out;
  // book-final's camera: lookfrom 13,2,3, lookat 0,0,0, vup +y. Turned 25 degrees about +y:
  const double a = 25 * 3.14159265358979323846 / 180;
  EXPECT_NEAR(from[0], 13 * std::cos(a) + 3 * std::sin(a), 1e-9);
  EXPECT_NEAR(from[1], 2, 1e-9);
  EXPECT_NEAR(from[2], -13 * std::sin(a) + 3 * std::cos(a), 1e-9);

  std::vector<std::string> render = printed;
  const std::string again = (dir.path() / "again.png").string();
  render.insert(render.end(), {"--backend", "gpu", "-q", "-o", again});
  ASSERT_EQ(test::run_rtvk(render).status, 0);
  EXPECT_EQ(test::slurp(dir.path() / "rtvk-view-1.png"), test::slurp(again))
      << "the screenshot after the drag is not what the printed camera renders";

  // The camera object printed beside the flags, in a scene file, frames the same shot.
  const std::filesystem::path file = dir.path() / "framed.json";
  write_scene_with_printed_camera("book-final", r.out, file);
  const std::string from_file = (dir.path() / "from-file.png").string();
  ASSERT_EQ(test::run_rtvk({"render", "--scene", file.string(), "--width", "200", "--spp", "4",
                            "--backend", "gpu", "-q", "-o", from_file})
                .status,
            0);
  EXPECT_EQ(test::slurp(from_file), test::slurp(again))
      << "the printed camera object frames another shot";
}

// Bytes of `a` and `b` that differ in rows [first, last) (both 8-bit RGB of one size).
long differing_bytes(const image_rgb8& a, const image_rgb8& b, int first, int last) {
  long n = 0;
  for (std::size_t i = std::size_t(first) * std::size_t(a.width) * 3;
       i < std::size_t(last) * std::size_t(a.width) * 3; ++i)
    n += a.rgb[i] != b.rgb[i];
  return n;
}

// What the window shows, read back from the X server: with the overlay, its text over the top
// rows; after H, exactly the screenshot's pixels (the swapchain is UNORM and a 200-pixel render
// fills its 200-pixel window 1:1). The O key never overwrites an earlier shot: it takes the next
// free number.
TEST_F(XvfbTest, HHidesTheOverlayAndTheWindowThenShowsTheScreenshotsPixels) {
  if (!xdotool_ready()) return;
  const test::temp_dir dir;
  std::ofstream(dir.path() / "rtvk-view-1.png") << "an earlier session's shot";
  const std::filesystem::path before = std::filesystem::current_path();
  std::filesystem::current_path(dir.path());
  test::running_rtvk view({"view", "--scene", "book-final", "--width", "200", "--spp", "4"}, env());
  std::filesystem::current_path(before);
  const std::string id = shown_window();
  ASSERT_FALSE(id.empty()) << "no window showed a frame: " << view.stderr_so_far();
  ASSERT_EQ(samples_beyond(id, 3), 4) << view.stderr_so_far();
  std::this_thread::sleep_for(500ms);  // the last batch presented
  const image_rgb8 with_overlay = test::window_pixels(display_, id);
  xdo({"key", "--window", id, "o"});
  xdo({"key", "--window", id, "h"});
  std::this_thread::sleep_for(300ms);
  const image_rgb8 without = test::window_pixels(display_, id);
  xdo({"key", "--window", id, "Escape"});
  const test::process_result r = view.wait_at_most(60s);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err.find("validation"), std::string::npos) << r.err;

  EXPECT_EQ(test::slurp(dir.path() / "rtvk-view-1.png"), "an earlier session's shot");
  const image_rgb8 shot = read_image(dir.path() / "rtvk-view-2.png");  // the next free number
  ASSERT_EQ(shot.width, 200);
  ASSERT_EQ(shot.height, 133);
  ASSERT_EQ(without.width, 200) << "the window is the render's size";
  ASSERT_EQ(without.height, 133);
  ASSERT_EQ(with_overlay.width, 200);
  ASSERT_EQ(with_overlay.height, 133);
  EXPECT_EQ(differing_bytes(without, shot, 0, 133), 0) << "with H the window shows the image";
  EXPECT_GT(differing_bytes(with_overlay, shot, 0, 20), 500) << "the overlay's first lines";
  EXPECT_EQ(differing_bytes(with_overlay, shot, 120, 133), 0) << "below the overlay: the image";
  // In the overlay's band (composed on the device, overlay.comp) a pixel is white text or the
  // image darkened to a quarter, nothing else.
  int text = 0, darkened = 0, other = 0;
  for (std::size_t i = 0; i < std::size_t(200 * 20 * 3); i += 3) {
    const std::uint8_t* p = &with_overlay.rgb[i];
    const std::uint8_t* q = &shot.rgb[i];
    if (p[0] == 255 && p[1] == 255 && p[2] == 255)
      ++text;
    else if (p[0] == q[0] >> 2 && p[1] == q[1] >> 2 && p[2] == q[2] >> 2)
      ++darkened;
    else
      ++other;
  }
  EXPECT_GT(text, 200);
  EXPECT_GT(darkened, 2000);
  EXPECT_EQ(other, 0);
}

// F + click: the distance in focus becomes that of the surface under the cursor along the view
// axis, found by the ray get_ray casts through that pixel (computed here the same way, on the
// CPU, from the scene).
void XvfbTest::focus_after_click(const std::vector<std::string>& args, int x, int y,
                                 double& focus) {
  std::vector<std::string> view_args{"view"};
  view_args.insert(view_args.end(), args.begin(), args.end());
  test::running_rtvk view(view_args, env());
  const std::string id = shown_window();
  ASSERT_FALSE(id.empty()) << "no window showed a frame: " << view.stderr_so_far();
  std::this_thread::sleep_for(1s);
  xdo({"mousemove", "--window", id, std::to_string(x), std::to_string(y)});
  xdo({"keydown", "f"});
  xdo({"click", "1"});
  xdo({"keyup", "f"});
  xdo({"key", "Escape"});
  const test::process_result r = view.wait_at_most(60s);
  ASSERT_EQ(r.status, 0) << r.err;
  const std::vector<std::string> printed = printed_flags(r.out.substr(r.out.rfind("rtvk render")));
  const std::vector<double> found = numbers_after(printed, "--focus-dist");
  ASSERT_EQ(found.size(), 1u) << r.out;
  focus = found[0];
}

TEST_F(XvfbTest, FAndAClickFocusOnTheSurfaceUnderTheCursor) {
  if (!xdotool_ready()) return;
  double focus = 0;
  ASSERT_NO_FATAL_FAILURE(
      focus_after_click({"--scene", "book-final", "--width", "200", "--spp", "2"}, 120, 70, focus));

  const scene s = builtin_scene("book-final");
  const camera cam(main_camera(s).pose, 1.5, 200);  // 200x133, shown 1:1 in its window
  const ray through = cam.get_ray(pixel_coordinate(120, 200), pixel_coordinate(132 - 70, 133));
  hit_record rec{};
  ASSERT_TRUE(bvh_world(s.spheres).hit(through, 1e-3, 1e300, rec)) << "the click must hit";
  const double expected = glm::dot(rec.p - cam.origin(), -cam.axis_w());
  EXPECT_NEAR(focus, expected, 1e-9);
  EXPECT_GT(std::abs(expected - 10), 0.1) << "the click must move the focus for this to mean much";
}

// F + click on a moving sphere focuses where it is drawn: at the middle of the shutter ([2, 3],
// past time 1), not where it is at time 0 (out of view; the click once missed it and left the
// focus as it was).
TEST_F(XvfbTest, FAndAClickFocusOnAMovingSphereWhereTheShutterSeesIt) {
  if (!xdotool_ready()) return;
  const test::temp_dir dir;
  const std::string file = (dir.path() / "moving.json").string();
  std::ofstream(file) << R"({"camera": {"vfov": 60, "shutter": [2, 3]},
      "render": {"gamma": 1, "width": 200, "aspect": 1.5, "spp": 2},
      "materials": {"m": {"type": "normal"}},
      "spheres": [{"center": [-10, 0, -5], "center1": [-6, 0, -5], "radius": 1, "material": "m"}]})";
  double focus = 0;
  ASSERT_NO_FATAL_FAILURE(focus_after_click({"--scene", file, "--width", "200"}, 100, 66, focus));
  // At t = 2.5 the sphere is centred at (0, 0, -5): its near side is 4 along the view.
  EXPECT_NEAR(focus, 4, 0.05);
}

// A size fixed by the flags whose sums cannot stay on the device in one storage buffer (lavapipe
// allows 128 MiB: 2.8 megapixels) is refused by its flag, exit 2, no screenshot.
TEST_F(XvfbTest, AFixedSizeTooLargeToAccumulateOnTheDeviceExits2NamingTheFlag) {
  const test::temp_dir dir;
  const std::string shot = (dir.path() / "big.png").string();
  const test::process_result r =
      test::run_rtvk_within(120s,
                            {"view", "--scene", "seed", "--width", "4000", "--aspect", "1", "--spp",
                             "1", "--screenshot", shot},
                            env());
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(r.err.rfind("rtvk: --width 4000: rtvk view keeps the whole 4000x4000 image's sums", 0),
            0u)
      << r.err;
  EXPECT_FALSE(std::filesystem::exists(shot));
}

// A screenshot too large for the PNG encoder (docs/reliability.md) is refused by its flag before
// the window opens, whatever the device could accumulate.
TEST_F(XvfbTest, AScreenshotPastThePngEncodersSizeExits2NamingTheFlag) {
  const test::temp_dir dir;
  const std::string shot = (dir.path() / "huge.png").string();
  const test::process_result r =
      test::run_rtvk_within(120s,
                            {"view", "--scene", "seed", "--width", "20000", "--aspect", "1",
                             "--spp", "1", "--screenshot", shot},
                            env());
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("--screenshot: '" + shot + "': a 20000x20000 PNG has"), std::string::npos)
      << r.err;
  EXPECT_FALSE(std::filesystem::exists(shot));
}

// The render follows the window: resized while accumulating, it restarts at the new size, and
// what it shows is what rtvk render makes of the printed camera at that size.
TEST_F(XvfbTest, AResizedWindowRestartsAtItsNewSize) {
  if (!xdotool_ready()) return;
  const test::temp_dir dir;
  const std::filesystem::path before = std::filesystem::current_path();
  std::filesystem::current_path(dir.path());
  test::running_rtvk view({"view", "--scene", "materials", "--spp", "4"}, env());
  std::filesystem::current_path(before);
  const std::string id = shown_window();
  ASSERT_FALSE(id.empty()) << "no window showed a frame: " << view.stderr_so_far();
  std::this_thread::sleep_for(500ms);  // accumulating at 960x540
  xdo({"windowsize", id, "320", "180"});
  std::this_thread::sleep_for(3s);
  xdo({"key", "--window", id, "o"});
  xdo({"key", "--window", id, "Escape"});
  const test::process_result r = view.wait_at_most(60s);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err.find("validation"), std::string::npos) << r.err;
  ASSERT_NE(r.err.find("320x180, 4 spp -> rtvk-view-1.png"), std::string::npos) << r.err;
  std::vector<std::string> render = printed_flags(r.out.substr(r.out.rfind("rtvk render")));
  const std::string again = (dir.path() / "again.png").string();
  render.insert(render.end(), {"--backend", "gpu", "-q", "-o", again});
  ASSERT_EQ(test::run_rtvk(render).status, 0);
  EXPECT_EQ(test::slurp(dir.path() / "rtvk-view-1.png"), test::slurp(again));
}

// Minimized (iconified by the window manager) the session renders nothing -- the samples in the
// title stop -- and restored it goes on from where it was.
TEST_F(XvfbTest, MinimizedItRendersNothingAndRestoredItGoesOn) {
  if (!xdotool_ready()) return;
  const test::temp_dir dir;
  if (!start_window_manager(dir.path())) return;
  test::running_rtvk view({"view", "--scene", "book-final", "--width", "200"}, env());
  const std::string id = shown_window();
  ASSERT_FALSE(id.empty()) << "no window showed a frame: " << view.stderr_so_far();
  ASSERT_GT(samples_beyond(id, 1), 1) << "not accumulating: " << view.stderr_so_far();
  xdo({"windowminimize", id});
  bool hidden = false;
  for (int i = 0; i < 100 && !hidden; ++i, std::this_thread::sleep_for(100ms))
    hidden = run_tool_in({"xdotool", "search", "--onlyvisible", "--name", "rtvk view"}).empty();
  ASSERT_TRUE(hidden) << "twm did not minimize the window";
  std::this_thread::sleep_for(500ms);  // a batch under way when it was minimized ends
  const int minimized = title_samples(id);
  std::this_thread::sleep_for(2s);  // about 60 samples per pixel at this size when rendering
  EXPECT_EQ(title_samples(id), minimized) << "rendered while minimized";
  xdo({"windowmap", id});
  EXPECT_GT(samples_beyond(id, minimized), minimized) << "did not go on once restored";
  xdo({"key", "--window", id, "Escape"});
  const test::process_result r = view.wait_at_most(60s);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err.find("validation"), std::string::npos) << r.err;
}

// Under a test layer fault (tests/view/layers) that leaves no queue the viewer can use, the
// device is refused by name before anything is rendered: exit 1, one line saying `why`, no
// screenshot.
void expect_refused(const std::vector<std::string>& env, const std::string& fault,
                    const std::string& why) {
  const test::temp_dir dir;
  const std::string shot = (dir.path() / "never.png").string();
  std::vector<std::string> with_layer = env;
  for (const std::string& e : test::fault_environment(fault)) with_layer.push_back(e);
  const test::process_result r = test::run_rtvk_within(
      60s, {"view", "--scene", "seed", "--spp", "1", "--screenshot", shot}, with_layer);
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.err.find("rtvk: error: the Vulkan device "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(why), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one line: " << r.err;
  EXPECT_FALSE(std::filesystem::exists(shot));
}

// No queue can present.
TEST_F(XvfbTest, ADeviceThatCannotPresentExits1NamingIt) {
  expect_refused(env(), "no-present", "cannot present to the window from any of its queues");
}

// The only presenting queue cannot draw (the viewer blits, a graphics command, on the queue it
// presents from): refused, not a blit on a queue that cannot run it.
TEST_F(XvfbTest, ADeviceThatPresentsOnlyFromAComputeQueueExits1NamingIt) {
  expect_refused(env(), "no-graphics-queue",
                 "presents to the window only from queues that cannot also compute and draw");
}

// A device with a compute-only queue family besides its graphics one (the layer's
// compute-queue-family; AMD's and NVIDIA's asynchronous compute queues): the viewer renders on
// the compute-only family, so its batches do not hold up the desktop's drawing, and composes,
// blits and presents on the graphics family (the layer loses the device on a blit or present
// from the compute-only one). The two queues share the image's bytes; the screenshot is still
// the bytes rtvk render writes. Before the split, every submission went to the graphics family.
TEST_F(XvfbTest, OnADeviceWithAComputeOnlyFamilyTheViewerRendersThereAndPresentsFromGraphics) {
  std::vector<std::string> env = this->env();
  for (const std::string& e : test::fault_environment("compute-queue-family")) env.push_back(e);
  std::string err;
  expect_screenshot_is_the_render(env, {"--scene", "book-final", "--width", "200", "--spp", "8"},
                                  &err);
  EXPECT_EQ(err.find("recorded for the compute-only"), std::string::npos) << err;
  const test::queue_submissions q = test::submissions_per_queue(err);
  EXPECT_GT(q.compute_only, 0) << err;  // the batches
  EXPECT_GT(q.others, 0) << err;        // the frames
}

// A device lost after the window has shown a few frames: exit 1 naming the call, the result and
// the device, with no screenshot and no hang or crash on the way out.
TEST_F(XvfbTest, ALostDeviceWhileViewingExits1AndWritesNoScreenshot) {
  const test::temp_dir dir;
  const std::string shot = (dir.path() / "never.png").string();
  std::vector<std::string> lost = env();
  for (const std::string& e : test::fault_environment("lose-device-after-present:5"))
    lost.push_back(e);
  const test::process_result r = test::run_rtvk_within(
      60s,
      {"view", "--scene", "book-final", "--width", "200", "--spp", "100000", "--screenshot", shot},
      lost);
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.err.find("vkQueueSubmit: VK_ERROR_DEVICE_LOST (device "), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(shot));
}

// A fence timeout far shorter than the work stands in for a hung device, as for rtvk render.
TEST_F(XvfbTest, AHungDeviceExits1WithTheGpuTimeoutMessageAndNoScreenshot) {
  const test::temp_dir dir;
  const std::string shot = (dir.path() / "never.png").string();
  const test::process_result r =
      test::run_rtvk_within(60s,
                            {"view", "--scene", "book-final", "--width", "600", "--spp", "20",
                             "--gpu-timeout", "0.001", "--screenshot", shot},
                            env());
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.err.find("vkWaitForFences: VK_TIMEOUT (device "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("no answer after 0.001 s"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(shot));
}

TEST(View, WithoutADisplayItExits2AndPointsToRender) {
  for (const char* display : {"DISPLAY=", "DISPLAY=:9999"}) {
    const test::process_result r =
        test::run_rtvk({"view", "--scene", "seed"}, {display, "WAYLAND_DISPLAY="});
    EXPECT_EQ(r.status, 2) << display << ": " << r.err;
    EXPECT_NE(r.err.find("rtvk view needs a window system; rtvk render works without one"),
              std::string::npos)
        << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one line: " << r.err;
  }
}

}  // namespace
}  // namespace rtvk
