#include "core/image_metrics.hpp"

#include <cstdlib>
#include <vector>

#include "core/error.hpp"

namespace eco {
namespace {

void requireSameSize(const Image& a, const Image& b) {
  ECO_ASSERT(a.width == b.width && a.height == b.height,
             a.width << "x" << a.height << " against " << b.width << "x" << b.height);
}

std::vector<double> lumaOf(const Image& image) {
  std::vector<double> luma(static_cast<std::size_t>(image.width) * image.height);
  for (std::size_t p = 0; p < luma.size(); ++p)
    luma[p] = 0.2126 * image.rgba[4 * p] + 0.7152 * image.rgba[4 * p + 1] +
              0.0722 * image.rgba[4 * p + 2];
  return luma;
}

}  // namespace

double meanAbsoluteDifference(const Image& a, const Image& b) {
  requireSameSize(a, b);
  double sum = 0.0;
  for (std::size_t p = 0; p < a.rgba.size(); p += 4)
    for (int c = 0; c < 3; ++c) sum += std::abs(int(a.rgba[p + c]) - int(b.rgba[p + c]));
  return a.rgba.empty() ? 0.0 : sum / (3.0 * static_cast<double>(a.rgba.size() / 4));
}

Image downsampled(const Image& image, int factor) {
  ECO_ASSERT(factor >= 1, "factor " << factor);
  Image out(image.width / factor, image.height / factor);
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x)
      for (int c = 0; c < 4; ++c) {
        int sum = 0;
        for (int j = 0; j < factor; ++j)
          for (int i = 0; i < factor; ++i)
            sum += image.rgba[4 * (static_cast<std::size_t>(y * factor + j) * image.width +
                                   x * factor + i) +
                              c];
        out.rgba[4 * (static_cast<std::size_t>(y) * out.width + x) + c] =
            static_cast<std::uint8_t>((sum + factor * factor / 2) / (factor * factor));
      }
  return out;
}

double structuralSimilarity(const Image& a, const Image& b) {
  requireSameSize(a, b);
  constexpr int kWindow = 8, kStride = 4;
  constexpr double c1 = (0.01 * 255) * (0.01 * 255), c2 = (0.03 * 255) * (0.03 * 255);
  const std::vector<double> la = lumaOf(a), lb = lumaOf(b);
  double sum = 0.0;
  int windows = 0;
  for (int y = 0; y + kWindow <= a.height; y += kStride)
    for (int x = 0; x + kWindow <= a.width; x += kStride) {
      double ma = 0, mb = 0, vaa = 0, vbb = 0, vab = 0;
      for (int j = 0; j < kWindow; ++j)
        for (int i = 0; i < kWindow; ++i) {
          const std::size_t p = static_cast<std::size_t>(y + j) * a.width + x + i;
          ma += la[p], mb += lb[p];
          vaa += la[p] * la[p], vbb += lb[p] * lb[p], vab += la[p] * lb[p];
        }
      const double n = kWindow * kWindow;
      ma /= n, mb /= n;
      // Sample (co)variances, as Wang et al.'s estimator.
      vaa = (vaa - n * ma * ma) / (n - 1), vbb = (vbb - n * mb * mb) / (n - 1);
      vab = (vab - n * ma * mb) / (n - 1);
      sum += ((2 * ma * mb + c1) * (2 * vab + c2)) / ((ma * ma + mb * mb + c1) * (vaa + vbb + c2));
      ++windows;
    }
  return windows > 0 ? sum / windows : 1.0;
}

}  // namespace eco
