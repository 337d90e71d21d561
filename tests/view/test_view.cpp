// rtvk view in a real X server (Xvfb) on lavapipe with validation on: scripted screenshots are
// the bytes rtvk render --backend gpu writes, the camera it prints renders the same frame, and
// the bad situations (no display, Ctrl-C) end as documented.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "ci.h"
#include "process.h"
#include "temp_dir.h"

namespace rtvk {
namespace {

using namespace std::chrono_literals;

// A private X server for the test's windows, on a display of its own.
class XvfbTest : public testing::Test {
 protected:
  void SetUp() override {
    if (!find_xvfb()) {
      if (test::in_ci()) FAIL() << "Xvfb not found (Debian: apt install xvfb); CI must run this";
      GTEST_SKIP() << "Xvfb not found (Debian: apt install xvfb)";
    }
    display_ = ":" + std::to_string(200 + getpid() % 700);
    const std::string socket = "/tmp/.X11-unix/X" + display_.substr(1);
    std::vector<std::string> args{"Xvfb",         display_,    "-screen", "0",
                                  "1280x1024x24", "-nolisten", "tcp"};
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_addopen(&fa, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&fa, 2, "/dev/null", O_WRONLY, 0);
    ASSERT_EQ(posix_spawnp(&xvfb_, "Xvfb", &fa, nullptr, argv.data(), environ), 0);
    posix_spawn_file_actions_destroy(&fa);
    const auto end = std::chrono::steady_clock::now() + 10s;
    while (!std::filesystem::exists(socket) && std::chrono::steady_clock::now() < end)
      std::this_thread::sleep_for(20ms);
    ASSERT_TRUE(std::filesystem::exists(socket)) << "Xvfb did not start on " << display_;
  }
  void TearDown() override {
    if (xvfb_ > 0) {
      ::kill(xvfb_, SIGTERM);
      int status = 0;
      waitpid(xvfb_, &status, 0);
    }
  }

  // The environment of an rtvk that shows its window in this server, validation on.
  std::vector<std::string> env() const {
    return {"DISPLAY=" + display_, "WAYLAND_DISPLAY=", "RTVK_VALIDATE=1",
            "VK_LOADER_LAYERS_ENABLE=*validation"};
  }

  static bool find_xvfb() {
    const char* path = std::getenv("PATH");
    std::stringstream dirs(path ? path : "");
    for (std::string dir; std::getline(dirs, dir, ':');)
      if (!dir.empty() && access((dir + "/Xvfb").c_str(), X_OK) == 0) return true;
    return false;
  }

  std::string display_;  // ":N"
  pid_t xvfb_ = -1;      // the server
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

// `view` and `render` take the same scene flags: the screenshot must be the bytes render writes,
// and the printed camera must render them again.
void expect_screenshot_is_the_render(const std::vector<std::string>& env,
                                     const std::vector<std::string>& flags) {
  const test::temp_dir dir;
  const std::string shot = (dir.path() / "view.png").string();
  const std::string direct = (dir.path() / "render.png").string();
  const std::string again = (dir.path() / "again.png").string();
  std::vector<std::string> view{"view"};
  view.insert(view.end(), flags.begin(), flags.end());
  view.insert(view.end(), {"--screenshot", shot});
  const test::process_result v = test::run_rtvk_within(120s, view, env);
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
  EXPECT_EQ(printed_flags(r.out).front(), "render") << "the camera is printed on the way out";
  EXPECT_NE(r.err.find("was not written"), std::string::npos) << r.err;
}

// Real input through the X server: a left-drag of 100 pixels to the right must turn the eye
// 25 degrees (0.25 per pixel) counter-clockwise about vup round the look-at point, at the same
// distance and height; the O key's screenshot at --spp must be what rtvk render makes of the
// camera printed on exit.
TEST_F(XvfbTest, ADragOrbitsByTheControlsAngleAndTheShotRendersFromThePrintedCamera) {
  if (run_tool({"xdotool", "version"}, display_).empty()) {
    if (test::in_ci()) FAIL() << "xdotool not found (Debian: apt install xdotool)";
    GTEST_SKIP() << "xdotool not found";
  }
  const test::temp_dir dir;
  const std::filesystem::path before = std::filesystem::current_path();
  std::filesystem::current_path(dir.path());  // the O key writes into the current folder
  test::running_rtvk view({"view", "--scene", "book-final", "--width", "200", "--spp", "4"}, env());
  std::filesystem::current_path(before);
  std::string id;
  for (int i = 0; i < 300 && id.empty(); ++i) {
    id = run_tool({"xdotool", "search", "--name", "rtvk view"}, display_);
    if (id.empty()) std::this_thread::sleep_for(100ms);
  }
  ASSERT_FALSE(id.empty()) << "no window appeared";
  id = id.substr(0, id.find('\n'));
  const auto x = [&](std::vector<std::string> args) {
    args.insert(args.begin(), "xdotool");
    run_tool(args, display_);
    std::this_thread::sleep_for(200ms);
  };
  x({"mousemove", "--window", id, "50", "60"});
  x({"mousedown", "1"});
  x({"mousemove", "--window", id, "150", "60"});
  x({"mouseup", "1"});
  std::this_thread::sleep_for(3s);  // 4 samples of 200x133 take well under a second
  x({"key", "--window", id, "o"});
  x({"key", "--window", id, "Escape"});
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
