#include "sim/ecology/plants.hpp"

#include <algorithm>
#include <type_traits>

#include <tbb/task_group.h>

#include "core/memory.hpp"

namespace eco {

void Plants::removeDead() {
  const auto kept = static_cast<std::size_t>(
      std::count_if(alive.begin(), alive.end(), [](std::uint8_t flag) { return flag != 0; }));
  if (kept == size()) return;
  // The columns are independent: compacted side by side, each in place by the alive flags
  // (a list of the kept rows would cost 8 bytes a plant; a landscape has 100 million).
  tbb::task_group columns;
  forEachColumn([&](auto& column) {
    // The flags are read by every other column's task: they are compacted last, below.
    if (static_cast<const void*>(&column) == static_cast<const void*>(&alive)) return;
    columns.run([this, &column, kept] {
      // Without a branch: each row is written to the next place and kept there by its flag
      // (a flag is 0 or 1). The dead come in runs a branch predictor cannot learn (a
      // regeneration cell's seedlings, a stand's thinned trees).
      std::size_t k = 0;
      for (std::size_t i = 0; i < column.size(); ++i) {
        column[k] = column[i];
        k += alive[i];
      }
      column.resize(kept);
      releaseUnusedCapacity(column);
    });
  });
  columns.wait();
  alive.assign(kept, 1);
  releaseUnusedCapacity(alive);
}

void Plants::mergeTail(std::size_t first, const std::vector<std::uint32_t>& tail,
                       const std::vector<std::uint32_t>& place) {
  tbb::task_group columns;
  forEachColumn([&](auto& column) {
    columns.run([&column, first, &tail, &place] {
      using Value = typename std::decay_t<decltype(column)>::value_type;
      std::vector<Value> moved(tail.size());
      for (std::size_t j = 0; j < tail.size(); ++j) moved[j] = column[tail[j]];
      // From the end: the rows before the tail between two new rows' places move as a block
      // towards the end, by the number of new rows they will follow; each block is read
      // before its place is written, as rows only move towards the end.
      std::size_t end = first;  // the rows before the tail not moved yet: [0, end)
      for (std::size_t j = tail.size(); j-- > 0;) {
        std::copy_backward(column.begin() + place[j], column.begin() + end,
                           column.begin() + end + j + 1);
        column[place[j] + j] = moved[j];
        end = place[j];
      }
    });
  });
  columns.wait();
}

}  // namespace eco
