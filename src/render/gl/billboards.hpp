// Pictures for the glTF export's billboard level (render/scene/forest_export.hpp): each
// tree type seen from the east and from the south, the forest renderer's impostor frames
// nearest those directions (its albedo with alpha, sRGB), side by side. Needs a current
// OpenGL context (HeadlessGl).
#pragma once

#include <span>

#include "render/scene/forest_export.hpp"
#include "render/scene/impostor.hpp"
#include "render/scene/tree_library.hpp"

namespace eco {

// Frames of 256 pixels: a far tree's picture, sharper than the renderer's 64.
inline const ImpostorSettings kBillboardImpostors{.frames = 8, .tilePixels = 256, .bakeLod = 1};

// The pictures of these types (a forest's: typesOf); the other types' stay empty.
Billboards bakeBillboards(const TreeLibrary& library, std::span<const int> types,
                          const ImpostorSettings& settings = kBillboardImpostors);

}  // namespace eco
