#include "progress.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>

namespace rtvk {

progress_bar::progress_bar(std::string what, int total, bool enabled)
    : what_(std::move(what)),
      total_(total > 0 ? total : 1),
      enabled_(enabled && ::isatty(STDERR_FILENO)),
      start_(clock::now()) {
  if (const char* d = std::getenv("RTVK_PROGRESS_DELAY")) delay_ = std::atof(d);
}

void progress_bar::update(int done) {
  if (!enabled_) return;
  const auto now = clock::now();
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  if (elapsed < delay_ || now - last_ < std::chrono::milliseconds(100)) return;
  last_ = now;
  const double fraction = double(done) / total_;
  constexpr int width = 30;
  const int filled = int(fraction * width);
  std::string bar(std::size_t(filled), '#');
  bar.resize(width, ' ');
  const double left = fraction > 0 ? elapsed * (1 - fraction) / fraction : 0;
  std::fprintf(stderr, "\rrtvk: %s [%s] %3d%%  %.1f s elapsed, %.1f s left\033[K", what_.c_str(),
               bar.c_str(), int(100 * fraction), elapsed, left);
  std::fflush(stderr);
  drawn_ = true;
}

void progress_bar::finish() {
  if (!drawn_) return;
  std::fputs("\r\033[K", stderr);
  std::fflush(stderr);
  drawn_ = false;
}

}  // namespace rtvk
