// A progress line on a terminal ("label  42%"), updated at most ten times a second from
// any thread; silent when stderr is not a terminal, so logs and tests stay clean.
#pragma once

#include <atomic>
#include <chrono>
#include <mutex>
#include <string>

namespace eco {

class Progress {
 public:
  explicit Progress(std::string label, bool enabled);
  ~Progress();
  // fraction in [0, 1]; safe to call from several threads.
  void update(double fraction);
  static bool stderrIsTerminal();

 private:
  std::string label_;
  bool enabled_;
  std::mutex mutex_;
  std::chrono::steady_clock::time_point last_{};
};

}  // namespace eco
