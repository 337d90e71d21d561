#pragma once
#include <chrono>
#include <string>

namespace rtvk {

// A one-line progress bar on stderr: percent, elapsed and estimated time left. Drawn only when
// enabled and stderr is a terminal, and only once the work has taken a second (or
// RTVK_PROGRESS_DELAY seconds), so short renders and logs stay clean.
class progress_bar {
 public:
  progress_bar(std::string what, int total, bool enabled);
  ~progress_bar() { finish(); }
  progress_bar(const progress_bar&) = delete;
  progress_bar& operator=(const progress_bar&) = delete;

  void update(int done);
  void finish();  // erases the bar, if drawn

 private:
  using clock = std::chrono::steady_clock;
  std::string what_;          // "rendering", ...
  int total_;                 // units of work
  bool enabled_;              // asked for and stderr is a terminal
  bool drawn_ = false;        // something is on the line
  clock::time_point start_;   // when the work began
  clock::time_point last_{};  // last redraw
  double delay_ = 1.0;        // seconds before the first draw
};

}  // namespace rtvk
