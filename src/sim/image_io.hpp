// Raster files through OpenImageIO: heightmaps in, condition maps out. Every image is
// encoded in memory and written through AtomicFile (whole or not at all, every byte checked).
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include "core/image.hpp"

namespace eco {

struct SingleChannelImage {
  int width = 0;
  int height = 0;
  std::vector<float> values;  // row 0 first; integers as stored (not divided by the type's max)
  double typeMax = 1.0;       // largest value of the stored type (255, 65535, ...); 1 for floats
};

// The largest heightmap read: 16384 x 16384 cells, whose living conditions alone take
// about 80 GB (requireMemoryForConditions says so before they are computed). Each side is
// limited, not only the area: OpenImageIO's readers buffer whole rows, 256 at a time, so a
// 52-million-pixel-wide image of 5 rows would make it allocate 13 GB.
inline constexpr int kMaxHeightmapSide = 16384;

// Reads a one-channel image. Integer pixel types come back as their stored values
// (a 16-bit 40000 is 40000.0f): OpenImageIO's normalisation is undone. Unreadable files,
// several channels, fewer than 2 x 2 pixels or more than kMaxHeightmapSide on a side
// (checked from the header, before the pixels are allocated) and NaN or infinite pixels are
// InputErrors, except NaN where the file declares NaN its no-data value.
SingleChannelImage readSingleChannel(const std::filesystem::path& file, bool nanIsNoData = false);

// A colour picture (a saved frame) as RGBA8; one without alpha comes back opaque, a grey one
// as grey. Unreadable files and pictures over kMaxHeightmapSide on a side are InputErrors.
Image readColorImage(const std::filesystem::path& file);

void writeFloatImage(const std::filesystem::path& file, int width, int height, int channels,
                     const std::vector<float>& values);
void writeUint16Image(const std::filesystem::path& file, int width, int height,
                      const std::vector<std::uint16_t>& values);
void writeRgb8Image(const std::filesystem::path& file, int width, int height,
                    const std::vector<std::uint8_t>& rgb);
// An RGBA image's colour (alpha dropped), e.g. a rendered frame as PNG.
void writeRgb8Image(const std::filesystem::path& file, const Image& image);
// An RGBA image with its alpha.
void writeRgba8Image(const std::filesystem::path& file, const Image& image);

}  // namespace eco
