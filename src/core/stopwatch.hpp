// Elapsed wall time in milliseconds, for the timings commands print (render --stats).
#pragma once

#include <chrono>

namespace eco {

inline double millisecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

}  // namespace eco
