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
