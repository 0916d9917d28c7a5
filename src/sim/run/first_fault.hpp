// Checking a file's rows side by side (a run's checkpoint or snapshot holds millions of
// plants) while reporting the fault a reader going row by row would: the first one.
#pragma once

#include <atomic>
#include <cstddef>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace eco {

// The smallest index below `count` for which `faulty(i)` is true, whatever the thread
// count, or `count` when there is none. Rows past a fault already found are not looked at.
template <typename Faulty>
std::size_t firstFaulty(std::size_t count, const Faulty& faulty) {
  std::atomic<std::size_t> first{count};
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, 65536), [&](const auto& range) {
    for (std::size_t i = range.begin(); i < range.end() && i < first.load(); ++i)
      if (faulty(i)) {
        std::size_t seen = first.load();
        while (i < seen && !first.compare_exchange_weak(seen, i)) {
        }
        return;
      }
  });
  return first.load();
}

}  // namespace eco
