// The size of a frame in pixels: stills, the view window and time-lapse frames, with the
// one default they share.
#pragma once

#include <optional>
#include <string>

namespace eco {

struct FrameSize {
  int width = 1280;
  int height = 720;
  bool operator==(const FrameSize&) const = default;
};

inline constexpr int kMinFrameSide = 16, kMaxFrameSide = 8192;

// "1280x720" -> {1280, 720}; nullopt unless both are kMinFrameSide..kMaxFrameSide.
std::optional<FrameSize> parseFrameSize(const std::string& text);
std::string toString(FrameSize size);

}  // namespace eco
