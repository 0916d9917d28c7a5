// Pictures a comparison draws (docs/planning.md), with OpenImageIO's drawing and DejaVu Sans:
// a line chart of measures over the years, and stills side by side with a caption each.
#pragma once

#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "core/image.hpp"

namespace eco {

struct ChartSeries {
  std::string label;
  std::vector<glm::dvec2> points;  // (x, y), x ascending
};

struct LineChart {
  std::string title;
  std::string xLabel, yLabel;
  std::vector<ChartSeries> series;
  std::vector<double> markedX;  // drawn as thin vertical lines (the compared years)
};

// The chart on white: axes from 0 (or the data's least value, if negative) to a round number
// above the largest, ticks at 1, 2 or 5 times a power of ten, one colour per series
// (Okabe and Ito's palette for colour-blind readers) and a legend.
Image drawLineChart(const LineChart& chart, int width = 900, int height = 520);

// The pictures in a row (each scaled to the first one's height is not needed: all must have
// one size), each with its caption above it on a dark band.
Image sideBySide(const std::vector<Image>& pictures, const std::vector<std::string>& captions);

// The nice tick step for a range: 1, 2 or 5 times a power of ten, about `ticks` per range.
double niceTickStep(double range, int ticks = 5);

}  // namespace eco
