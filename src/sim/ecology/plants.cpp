#include "sim/ecology/plants.hpp"

#include <algorithm>
#include <type_traits>

#include <tbb/task_group.h>

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
      std::size_t k = 0;
      for (std::size_t i = 0; i < column.size(); ++i)
        if (alive[i]) column[k++] = column[i];
      column.resize(kept);
    });
  });
  columns.wait();
  alive.assign(kept, 1);
}

void Plants::mergeTail(std::size_t first, const std::vector<std::uint32_t>& tail,
                       const std::vector<bool>& fromTail) {
  tbb::task_group columns;
  forEachColumn([&](auto& column) {
    columns.run([&column, first, &tail, &fromTail] {
      using Value = typename std::decay_t<decltype(column)>::value_type;
      std::vector<Value> moved(tail.size());
      for (std::size_t j = 0; j < tail.size(); ++j) moved[j] = column[tail[j]];
      // From the end: a row before the tail only moves towards the end, so each is read
      // before its place is written.
      std::size_t before = first, after = tail.size();
      for (std::size_t k = column.size(); k-- > 0;)
        column[k] = fromTail[k] ? moved[--after] : column[--before];
    });
  });
  columns.wait();
}

}  // namespace eco
