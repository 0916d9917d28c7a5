#include "render/scene/frame_size.hpp"

#include <cstdio>

namespace eco {

std::optional<FrameSize> parseFrameSize(const std::string& text) {
  FrameSize size;
  char x = 0, rest = 0;
  if (std::sscanf(text.c_str(), "%d%c%d%c", &size.width, &x, &size.height, &rest) != 3 || x != 'x')
    return std::nullopt;
  for (int side : {size.width, size.height})
    if (side < kMinFrameSide || side > kMaxFrameSide) return std::nullopt;
  return size;
}

std::string toString(FrameSize size) {
  return std::to_string(size.width) + "x" + std::to_string(size.height);
}

}  // namespace eco
