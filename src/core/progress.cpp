#include "core/progress.hpp"

#include <unistd.h>
#include <cstdio>

namespace eco {

Progress::Progress(std::string label, bool enabled) : label_(std::move(label)), enabled_(enabled) {}

Progress::~Progress() {
  if (enabled_) std::fprintf(stderr, "\r%-24s done\n", label_.c_str());
}

bool Progress::stderrIsTerminal() {
  return ::isatty(STDERR_FILENO) != 0;
}

void Progress::update(double fraction) {
  if (!enabled_) return;
  std::unique_lock lock(mutex_, std::try_to_lock);
  if (!lock) return;  // another thread is printing
  auto now = std::chrono::steady_clock::now();
  if (now - last_ < std::chrono::milliseconds(100)) return;
  last_ = now;
  std::fprintf(stderr, "\r%-24s %3d%%", label_.c_str(), static_cast<int>(fraction * 100.0));
  std::fflush(stderr);
}

}  // namespace eco
