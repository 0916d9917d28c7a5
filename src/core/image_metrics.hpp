// How far a picture is from a reference, as a viewer would judge it: the mean absolute
// difference per channel (0..255, sRGB values as stored) and the structural similarity
// (SSIM, Wang et al. 2004) of the luma, optionally after a box downsampling that averages
// away what is below the size a viewer resolves at a glance.
#pragma once

#include "core/image.hpp"

namespace eco {

// Mean absolute difference of R, G and B over all pixels, 0..255. The images must be of one
// size.
double meanAbsoluteDifference(const Image& a, const Image& b);

// Each factor x factor block averaged into one pixel (the size rounded down).
Image downsampled(const Image& image, int factor);

// Mean SSIM of the luma (Rec. 709 weights of the stored values) over 8 x 8 windows moved by
// 4 pixels, with Wang et al.'s constants C1 = (0.01 L)^2 and C2 = (0.03 L)^2, L = 255:
// 1 for identical pictures, near 0 for unrelated ones.
double structuralSimilarity(const Image& a, const Image& b);

}  // namespace eco
