#include "sim/ecology/plants.hpp"

namespace eco {

void Plants::removeDead() {
  std::vector<std::size_t> kept;
  kept.reserve(size());
  for (std::size_t i = 0; i < size(); ++i)
    if (alive[i]) kept.push_back(i);
  if (kept.size() == size()) return;
  forEachColumn([&](auto& column) {
    for (std::size_t k = 0; k < kept.size(); ++k) column[k] = column[kept[k]];
    column.resize(kept.size());
  });
}

}  // namespace eco
