#include "sim/run/charts.hpp"

#include <algorithm>
#include <cmath>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <fmt/format.h>

#include "core/error.hpp"

namespace eco {
namespace {

namespace Algo = OIIO::ImageBufAlgo;

// DejaVu Sans comes with Debian's fonts-dejavu-core (scripts/setup installs it); without it
// the chart keeps its lines and the CSV holds the numbers.
constexpr const char* kFont = "DejaVuSans";

// Okabe and Ito (2008), "Color Universal Design": told apart by colour-blind readers too.
constexpr float kPalette[][3] = {{0.0f, 0.447f, 0.698f},   {0.835f, 0.369f, 0.0f},
                                 {0.0f, 0.620f, 0.451f},   {0.800f, 0.475f, 0.655f},
                                 {0.902f, 0.624f, 0.0f},   {0.337f, 0.706f, 0.914f},
                                 {0.941f, 0.894f, 0.259f}, {0.0f, 0.0f, 0.0f}};

Image toImage(const OIIO::ImageBuf& buffer) {
  const OIIO::ImageSpec& spec = buffer.spec();
  Image image(spec.width, spec.height);
  std::vector<std::uint8_t> rgb(static_cast<std::size_t>(spec.width) * spec.height * 3);
  buffer.get_pixels(OIIO::ROI::All(), OIIO::TypeDesc::UINT8, rgb.data());
  for (std::size_t p = 0; p < static_cast<std::size_t>(spec.width) * spec.height; ++p) {
    std::copy_n(&rgb[3 * p], 3, &image.rgba[4 * p]);
    image.rgba[4 * p + 3] = 255;
  }
  return image;
}

void text(OIIO::ImageBuf& image, int x, int y, const std::string& words, int size,
          const float* color, Algo::TextAlignX alignX = Algo::TextAlignX::Left,
          Algo::TextAlignY alignY = Algo::TextAlignY::Baseline) {
  Algo::render_text(image, x, y, words, size, kFont, {color, 3}, alignX, alignY);
  image.geterror();  // a missing font is not worth failing the comparison for
}

std::string tickLabel(double value, double step) {
  const int decimals = step >= 1.0 ? 0 : static_cast<int>(std::ceil(-std::log10(step)));
  return fmt::format("{:.{}f}", value, decimals);
}

}  // namespace

double niceTickStep(double range, int ticks) {
  if (!(range > 0.0)) return 1.0;
  const double raw = range / ticks;
  const double power = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0})
    if (m * power >= raw) return m * power;
  return 10.0 * power;
}

Image drawLineChart(const LineChart& chart, int width, int height) {
  OIIO::ImageBuf image(OIIO::ImageSpec(width, height, 3, OIIO::TypeDesc::UINT8));
  Algo::fill(image, {1.0f, 1.0f, 1.0f});
  const float black[3] = {0.1f, 0.1f, 0.1f}, grey[3] = {0.85f, 0.85f, 0.85f},
              mark[3] = {0.6f, 0.6f, 0.6f};
  const int left = 80, right = width - 20, top = 50, bottom = height - 60;
  double xMax = 1.0, yMax = 0.0, yMin = 0.0, xMin = 0.0;
  for (const ChartSeries& s : chart.series)
    for (const glm::dvec2& p : s.points) {
      xMax = std::max(xMax, p.x);
      yMax = std::max(yMax, p.y);
      yMin = std::min(yMin, p.y);
    }
  const double xStep = niceTickStep(xMax - xMin), yStep = niceTickStep(yMax - yMin);
  xMax = std::ceil(xMax / xStep) * xStep;
  yMax = std::max(yStep, std::ceil(yMax / yStep) * yStep);
  yMin = std::floor(yMin / yStep) * yStep;
  auto px = [&](double x) {
    return static_cast<int>(std::lround(left + (x - xMin) / (xMax - xMin) * (right - left)));
  };
  auto py = [&](double y) {
    return static_cast<int>(std::lround(bottom - (y - yMin) / (yMax - yMin) * (bottom - top)));
  };
  for (double y = yMin; y <= yMax + 0.5 * yStep; y += yStep) {
    Algo::render_line(image, left, py(y), right, py(y), grey);
    text(image, left - 8, py(y), tickLabel(y, yStep), 13, black, Algo::TextAlignX::Right,
         Algo::TextAlignY::Center);
  }
  for (double x = xMin; x <= xMax + 0.5 * xStep; x += xStep) {
    Algo::render_line(image, px(x), bottom, px(x), bottom + 5, black);
    text(image, px(x), bottom + 20, tickLabel(x, xStep), 13, black, Algo::TextAlignX::Center);
  }
  for (double x : chart.markedX) Algo::render_line(image, px(x), top, px(x), bottom, mark);
  Algo::render_line(image, left, bottom, right, bottom, black);
  Algo::render_line(image, left, top, left, bottom, black);
  text(image, (left + right) / 2, height - 18, chart.xLabel, 14, black, Algo::TextAlignX::Center);
  text(image, left, top - 12, chart.yLabel, 14, black);
  text(image, width / 2, 24, chart.title, 18, black, Algo::TextAlignX::Center);
  for (std::size_t k = 0; k < chart.series.size(); ++k) {
    const float* color = kPalette[k % std::size(kPalette)];
    const std::vector<glm::dvec2>& points = chart.series[k].points;
    // Two pixels wide: the line and its copy one pixel lower.
    for (std::size_t i = 1; i < points.size(); ++i)
      for (int d : {0, 1})
        Algo::render_line(image, px(points[i - 1].x), py(points[i - 1].y) + d, px(points[i].x),
                          py(points[i].y) + d, {color, 3});
    const int ly = top + 16 + 20 * static_cast<int>(k);
    Algo::render_box(image, left + 14, ly - 9, left + 34, ly - 3, {color, 3}, true);
    text(image, left + 42, ly, chart.series[k].label, 14, black);
  }
  return toImage(image);
}

Image sideBySide(const std::vector<Image>& pictures, const std::vector<std::string>& captions) {
  ECO_ASSERT(!pictures.empty() && pictures.size() == captions.size(), "a caption per picture");
  const int w = pictures.front().width, h = pictures.front().height, band = 30;
  for (const Image& p : pictures)
    ECO_ASSERT(p.width == w && p.height == h, "side by side pictures share one size");
  OIIO::ImageBuf image(
      OIIO::ImageSpec(w * static_cast<int>(pictures.size()), h + band, 3, OIIO::TypeDesc::UINT8));
  Algo::fill(image, {0.12f, 0.12f, 0.12f});
  const float white[3] = {0.95f, 0.95f, 0.95f};
  for (std::size_t k = 0; k < pictures.size(); ++k) {
    const int x0 = static_cast<int>(k) * w;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const glm::vec4 c = pictures[k].get(x, y);
        const float rgb[3] = {c.r, c.g, c.b};
        image.setpixel(x0 + x, band + y, rgb);
      }
    text(image, x0 + w / 2, band / 2, captions[k], 16, white, Algo::TextAlignX::Center,
         Algo::TextAlignY::Center);
  }
  return toImage(image);
}

}  // namespace eco
