#include "sim/ecology/plants.hpp"

#include <algorithm>

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

}  // namespace eco
