#pragma once
// Log-log line charts written as PNG images, for the convergence plots that study commands put
// into the docs. Self-contained (stb_easy_font for text, stb_image_write for PNG), so a figure
// needs no plotting tool: white background, decade grid, markers on lines, legend, labels.

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace sculpt {

/// One polyline of a chart. Points with a non-finite or non-positive coordinate cannot sit on
/// log axes: they are skipped and break the line there.
struct ChartSeries {
  std::string name;
  std::vector<double> x, y;  ///< same length
  std::array<uint8_t, 3> rgb = {0, 0, 0};
  bool dashed = false;
};

struct LogLogChart {
  std::string title, xLabel, yLabel;  ///< ASCII; other characters are drawn as '?'
  std::vector<ChartSeries> series;
  int width = 960, height = 680;  ///< pixels, 320..8192 by 240..8192
};

/// Where data land in the image. Ranges are whole decades padded around the plottable points;
/// pixel coordinates are continuous, x to the right and y down, pixel (i, j) covering
/// [i, i + 1) x [j, j + 1).
struct ChartAxes {
  int log10XMin = 0, log10XMax = 1, log10YMin = 0, log10YMax = 1;
  int left = 0, top = 0, right = 1, bottom = 1;  ///< plot rectangle, pixels

  /// The pixel position of the data point (x, y), both > 0.
  std::array<double, 2> pixel(double x, double y) const;
};

/// The axes that renderLogLogChartPng draws `chart` with. Throws std::invalid_argument for a bad
/// size, series whose x and y differ in length, or no plottable point at all.
ChartAxes chartAxes(const LogLogChart& chart);

/// The chart as PNG bytes (8-bit RGB). Throws like chartAxes.
std::string renderLogLogChartPng(const LogLogChart& chart);

/// Renders and writes the PNG atomically (see io/atomic_file.h). Throws like chartAxes, or
/// FileError.
void writeLogLogChartPng(const std::filesystem::path& path, const LogLogChart& chart);

}  // namespace sculpt
