#include "sim/ecology/plants.hpp"

#include <tbb/task_group.h>

namespace eco {

void Plants::removeDead() {
  std::vector<std::size_t> kept;
  kept.reserve(size());
  for (std::size_t i = 0; i < size(); ++i)
    if (alive[i]) kept.push_back(i);
  if (kept.size() == size()) return;
  // The columns are independent: compacted side by side.
  tbb::task_group columns;
  forEachColumn([&](auto& column) {
    columns.run([&kept, &column] {
      for (std::size_t k = 0; k < kept.size(); ++k) column[k] = column[kept[k]];
      column.resize(kept.size());
    });
  });
  columns.wait();
}

}  // namespace eco
