// The log-log chart: the PNG decodes, data land where the axes mapping says, unplottable points
// are skipped, and a chart with nothing to plot is refused with a clear message.

#include "cli/loglog_chart.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#include <stb_image.h>

namespace sculpt {
namespace {

using Rgb = std::array<uint8_t, 3>;

/// A decoded 8-bit RGB image.
struct Image {
  int width = 0, height = 0;
  std::vector<uint8_t> rgb;

  Rgb at(int x, int y) const {
    const std::size_t i = (std::size_t(y) * std::size_t(width) + std::size_t(x)) * 3;
    return {rgb[i], rgb[i + 1], rgb[i + 2]};
  }
};

Image decode(const std::string& png) {
  Image image;
  int channels = 0;
  stbi_uc* pixels =
      stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(png.data()), int(png.size()),
                            &image.width, &image.height, &channels, 3);
  if (pixels == nullptr) throw std::runtime_error("PNG does not decode");
  image.rgb.assign(pixels, pixels + std::size_t(image.width) * std::size_t(image.height) * 3);
  stbi_image_free(pixels);
  return image;
}

bool near(const Rgb& a, const Rgb& b, int tolerance = 2) {
  for (std::size_t k = 0; k < 3; ++k) {
    if (std::abs(int(a[k]) - int(b[k])) > tolerance) return false;
  }
  return true;
}

/// Whether `colour` appears within `radius` pixels of the continuous position p.
bool colourNear(const Image& image, std::array<double, 2> p, const Rgb& colour, int radius = 1) {
  const int cx = int(std::floor(p[0])), cy = int(std::floor(p[1]));
  for (int y = cy - radius; y <= cy + radius; ++y) {
    for (int x = cx - radius; x <= cx + radius; ++x) {
      if (x >= 0 && y >= 0 && x < image.width && y < image.height && near(image.at(x, y), colour)) {
        return true;
      }
    }
  }
  return false;
}

/// A convergence plot like the study command draws: three rates, one reference dashed.
LogLogChart convergenceChart() {
  LogLogChart chart;
  chart.title = "Phong vs linear: error vs mesh size";
  chart.xLabel = "mean edge length h";
  chart.yLabel = "max vertex error";
  std::vector<double> h, phong, linear, attribute, reference;
  for (int k = 0; k < 6; ++k) {
    const double hk = 0.4 * std::pow(0.5, k);
    h.push_back(hk);
    phong.push_back(0.3 * hk * hk * hk);
    linear.push_back(0.3 * hk * hk);
    attribute.push_back(0.2 * hk);
    reference.push_back(0.05 * hk * hk);
  }
  chart.series = {{"phong (slope 3)", h, phong, {214, 39, 40}, false},
                  {"linear (slope 2)", h, linear, {31, 119, 180}, false},
                  {"attribute (slope 1)", h, attribute, {44, 160, 44}, false},
                  {"h^2 reference", h, reference, {120, 120, 120}, true}};
  return chart;
}

TEST(LogLogChart, DecodesWithRequestedSizeAndWhiteCorners) {
  LogLogChart chart = convergenceChart();
  chart.width = 800;
  chart.height = 500;
  const Image image = decode(renderLogLogChartPng(chart));
  ASSERT_EQ(image.width, 800);
  ASSERT_EQ(image.height, 500);
  const Rgb white = {255, 255, 255};
  EXPECT_EQ(image.at(0, 0), white);
  EXPECT_EQ(image.at(799, 0), white);
  EXPECT_EQ(image.at(0, 499), white);
  EXPECT_EQ(image.at(799, 499), white);
}

TEST(LogLogChart, AxesArePaddedToWholeDecades) {
  const ChartAxes axes = chartAxes(convergenceChart());
  // h in [0.0125, 0.4]; errors in [0.3 * 0.0125^3 = 5.9e-7, 0.08]
  EXPECT_EQ(axes.log10XMin, -2);
  EXPECT_EQ(axes.log10XMax, 0);
  EXPECT_EQ(axes.log10YMin, -7);
  EXPECT_EQ(axes.log10YMax, -1);
  // Decades map onto the plot rectangle's edges
  EXPECT_DOUBLE_EQ(axes.pixel(1e-2, 1e-7)[0], axes.left + 0.5);
  EXPECT_DOUBLE_EQ(axes.pixel(1e-2, 1e-7)[1], axes.bottom + 0.5);
  EXPECT_DOUBLE_EQ(axes.pixel(1.0, 0.1)[0], axes.right + 0.5);
  EXPECT_DOUBLE_EQ(axes.pixel(1.0, 0.1)[1], axes.top + 0.5);
  // One decade of exact-decade data still gets a decade of room
  LogLogChart one;
  one.series = {{"point", {1e-3}, {1e2}, {0, 0, 0}}};
  const ChartAxes single = chartAxes(one);
  EXPECT_EQ(single.log10XMin, -3);
  EXPECT_EQ(single.log10XMax, -2);
  EXPECT_EQ(single.log10YMin, 2);
  EXPECT_EQ(single.log10YMax, 3);
}

TEST(LogLogChart, SeriesColoursAtTheirDataPoints) {
  const LogLogChart chart = convergenceChart();
  const ChartAxes axes = chartAxes(chart);
  const Image image = decode(renderLogLogChartPng(chart));
  for (const ChartSeries& s : chart.series) {
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      EXPECT_TRUE(colourNear(image, axes.pixel(s.x[i], s.y[i]), s.rgb)) << s.name << " point " << i;
    }
    // A solid line also shows between markers
    if (!s.dashed) {
      const auto a = axes.pixel(s.x[0], s.y[0]), b = axes.pixel(s.x[1], s.y[1]);
      EXPECT_TRUE(colourNear(image, {0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])}, s.rgb)) << s.name;
    }
  }
  // And not elsewhere: the far corner of the plot from the data holds no series colour
  const auto empty = axes.pixel(0.5, 1e-7);
  for (const ChartSeries& s : chart.series) {
    EXPECT_FALSE(colourNear(image, {empty[0] - 6, empty[1] - 6}, s.rgb, 3)) << s.name;
  }
}

TEST(LogLogChart, DrawsTitleAndLabels) {
  const LogLogChart chart = convergenceChart();
  const ChartAxes axes = chartAxes(chart);
  const Image image = decode(renderLogLogChartPng(chart));
  const auto inkIn = [&](int x0, int y0, int x1, int y1) {
    int count = 0;
    for (int y = y0; y < y1; ++y) {
      for (int x = x0; x < x1; ++x) count += image.at(x, y)[0] < 100;
    }
    return count;
  };
  EXPECT_GT(inkIn(0, 0, image.width, axes.top - 2), 200) << "title";
  EXPECT_GT(inkIn(0, axes.top, axes.left - 8, axes.bottom), 200) << "y labels";
  EXPECT_GT(inkIn(0, axes.bottom + 8, image.width, image.height), 200) << "x labels";
}

TEST(LogLogChart, SkipsUnplottablePoints) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  LogLogChart chart;
  chart.series = {{"mixed",
                   {0.1, nan, 0.01, 0.0, -1.0, 1e-3, inf},
                   {1.0, 1.0, 1e-2, 1.0, 1.0, nan, 5.0},
                   {200, 0, 0}},
                  {"empty", {}, {}, {0, 0, 200}}};
  const ChartAxes axes = chartAxes(chart);
  EXPECT_EQ(axes.log10XMin, -2);
  EXPECT_EQ(axes.log10XMax, -1);
  EXPECT_EQ(axes.log10YMin, -2);
  EXPECT_EQ(axes.log10YMax, 0);
  const Image image = decode(renderLogLogChartPng(chart));
  EXPECT_TRUE(colourNear(image, axes.pixel(0.1, 1.0), {200, 0, 0}));
  EXPECT_TRUE(colourNear(image, axes.pixel(0.01, 1e-2), {200, 0, 0}));
}

TEST(LogLogChart, RefusesChartsWithNothingToPlot) {
  const auto message = [](const LogLogChart& chart) {
    try {
      renderLogLogChartPng(chart);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no exception");
  };
  LogLogChart chart;
  chart.title = "empty";
  EXPECT_NE(message(chart).find("nothing to plot"), std::string::npos) << message(chart);
  chart.series = {{"bad", {0.0, -1.0, 1.0}, {1.0, 1.0, std::nan("")}, {0, 0, 0}}};
  EXPECT_NE(message(chart).find("nothing to plot"), std::string::npos) << message(chart);
  chart.series = {{"uneven", {1.0, 2.0}, {1.0}, {0, 0, 0}}};
  EXPECT_NE(message(chart).find("uneven"), std::string::npos) << message(chart);
  chart.series = {{"fine", {1.0}, {1.0}, {0, 0, 0}}};
  chart.width = 10;
  EXPECT_NE(message(chart).find("size"), std::string::npos) << message(chart);
}

TEST(LogLogChart, WritesThePngFile) {
  // Also the example figure to look at: <temp>/loglog_chart_example.png
  const std::filesystem::path path =
      std::filesystem::path(::testing::TempDir()) / "loglog_chart_example.png";
  const LogLogChart chart = convergenceChart();
  writeLogLogChartPng(path, chart);
  std::ifstream in(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(bytes, renderLogLogChartPng(chart));
  EXPECT_EQ(bytes.substr(1, 3), "PNG");
}

}  // namespace
}  // namespace sculpt
