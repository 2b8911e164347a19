#include "cli/loglog_chart.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string_view>

#include "io/atomic_file.h"
#include "io/png_encoder.h"

#include <stb_easy_font.h>

namespace sculpt {

namespace {

using Rgb = std::array<uint8_t, 3>;

constexpr Rgb kInk = {40, 40, 40};
constexpr Rgb kFrame = {90, 90, 90};
constexpr Rgb kMajorGrid = {214, 214, 214};
constexpr Rgb kMinorGrid = {238, 238, 238};
constexpr Rgb kWhite = {255, 255, 255};

// stb_easy_font glyphs are 1-pixel bars, 7 pixels from the top of a digit to its baseline;
// integer scales keep them crisp.
constexpr int kTextScale = 2;
constexpr int kTitleScale = 3;
constexpr int kGlyphHeight = 7;
constexpr double kLineWidth = 2.5;
constexpr double kMarkerRadius = 4.0;

bool plottable(double x, double y) {
  return std::isfinite(x) && std::isfinite(y) && x > 0.0 && y > 0.0;
}

/// Printable ASCII only: stb_easy_font indexes its glyph table by (char - 32). A UTF-8
/// character outside ASCII becomes one '?', control characters become spaces.
std::string printable(std::string_view text) {
  std::string out;
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte >= 0x80) {
      if ((byte & 0xC0) != 0x80) out += '?';  // lead byte; continuation bytes are dropped
    } else {
      out += byte < 32 || byte == 127 ? ' ' : c;
    }
  }
  return out;
}

int textWidth(std::string_view text, int scale) {
  std::string s = printable(text);
  // The last advance includes one pixel of spacing after the glyph
  return s.empty() ? 0 : (stb_easy_font_width(s.data()) - 1) * scale;
}

std::string decadeLabel(int exponent) { return "1e" + std::to_string(exponent); }

/// Labels every `step` decades so that labels never collide.
int labelStep(int decades, double pixels, double pixelsPerLabel) {
  const int fit = std::max(1, int(pixels / pixelsPerLabel));
  return std::max(1, (decades + fit - 1) / fit);
}

bool labelled(int exponent, int step) { return ((exponent % step) + step) % step == 0; }

/// An 8-bit RGB raster with coverage-blended drawing.
class Canvas {
 public:
  Canvas(int width, int height)
      : width_(width), height_(height), rgb_(std::size_t(width) * std::size_t(height) * 3, 255) {}

  int width() const { return width_; }
  int height() const { return height_; }
  const uint8_t* data() const { return rgb_.data(); }

  void blend(int x, int y, const Rgb& c, double alpha) {
    if (x < 0 || y < 0 || x >= width_ || y >= height_ || alpha <= 0.0) return;
    alpha = std::min(alpha, 1.0);
    uint8_t* p = &rgb_[(std::size_t(y) * std::size_t(width_) + std::size_t(x)) * 3];
    for (std::size_t k = 0; k < 3; ++k) {
      p[k] = uint8_t(std::lround(double(p[k]) * (1.0 - alpha) + double(c[k]) * alpha));
    }
  }

  /// Fills the pixels [x0, x1) x [y0, y1).
  void fillRect(int x0, int y0, int x1, int y1, const Rgb& c, double alpha = 1.0) {
    for (int y = std::max(y0, 0); y < std::min(y1, height_); ++y) {
      for (int x = std::max(x0, 0); x < std::min(x1, width_); ++x) blend(x, y, c, alpha);
    }
  }

  /// A round-capped segment of width `lineWidth`, antialiased by the distance of each pixel
  /// centre to the segment.
  void segment(double ax, double ay, double bx, double by, double lineWidth, const Rgb& c) {
    const double half = 0.5 * lineWidth;
    const double dx = bx - ax, dy = by - ay;
    const double length2 = dx * dx + dy * dy;
    const int x0 = int(std::floor(std::min(ax, bx) - half - 1.0));
    const int x1 = int(std::ceil(std::max(ax, bx) + half + 1.0));
    const int y0 = int(std::floor(std::min(ay, by) - half - 1.0));
    const int y1 = int(std::ceil(std::max(ay, by) + half + 1.0));
    for (int y = std::max(y0, 0); y <= std::min(y1, height_ - 1); ++y) {
      for (int x = std::max(x0, 0); x <= std::min(x1, width_ - 1); ++x) {
        const double px = x + 0.5 - ax, py = y + 0.5 - ay;
        const double t = length2 > 0.0 ? std::clamp((px * dx + py * dy) / length2, 0.0, 1.0) : 0.0;
        const double distance = std::hypot(px - t * dx, py - t * dy);
        blend(x, y, c, half + 0.5 - distance);
      }
    }
  }

  void disc(double cx, double cy, double radius, const Rgb& c) {
    segment(cx, cy, cx, cy, 2 * radius, c);
  }

  /// Draws printable text with its top-left corner at (x, y); `rotated` turns it a quarter
  /// counter-clockwise (reading upwards), with (x, y) then its bottom-left corner.
  void text(std::string_view text, int x, int y, int scale, const Rgb& c, bool rotated = false) {
    std::string s = printable(text);
    // stb_easy_font emits quads of 4 vertices of 16 bytes; about 270 bytes a character
    std::vector<char> buffer(s.size() * 1024 + 64);
    const int quads =
        stb_easy_font_print(0.0f, 0.0f, s.data(), nullptr, buffer.data(), int(buffer.size()));
    for (int q = 0; q < quads; ++q) {
      float u0 = std::numeric_limits<float>::max(), v0 = u0, u1 = -u0, v1 = -u0;
      for (int k = 0; k < 4; ++k) {
        const float* vertex = reinterpret_cast<const float*>(&buffer[std::size_t(q * 64 + k * 16)]);
        u0 = std::min(u0, vertex[0]), u1 = std::max(u1, vertex[0]);
        v0 = std::min(v0, vertex[1]), v1 = std::max(v1, vertex[1]);
      }
      const int a0 = int(u0) * scale, a1 = int(u1) * scale;
      const int b0 = int(v0) * scale, b1 = int(v1) * scale;
      if (rotated) {
        fillRect(x + b0, y - a1, x + b1, y - a0, c);
      } else {
        fillRect(x + a0, y + b0, x + a1, y + b1, c);
      }
    }
  }

 private:
  int width_, height_;
  std::vector<uint8_t> rgb_;
};

/// The plottable runs of a series in pixels: skipped points split the polyline.
std::vector<std::vector<std::array<double, 2>>> pixelRuns(const ChartAxes& axes,
                                                          const ChartSeries& series) {
  std::vector<std::vector<std::array<double, 2>>> runs(1);
  for (std::size_t i = 0; i < series.x.size(); ++i) {
    if (plottable(series.x[i], series.y[i])) {
      runs.back().push_back(axes.pixel(series.x[i], series.y[i]));
    } else if (!runs.back().empty()) {
      runs.emplace_back();
    }
  }
  if (runs.back().empty()) runs.pop_back();
  return runs;
}

/// A polyline, solid or dashed (the dash pattern runs on across vertices).
void drawPolyline(Canvas& canvas, const std::vector<std::array<double, 2>>& points, const Rgb& c,
                  bool dashed, double lineWidth) {
  constexpr double kDashOn = 11.0, kDashPeriod = 18.0;
  double arc = 0.0;
  for (std::size_t i = 1; i < points.size(); ++i) {
    const auto& [ax, ay] = points[i - 1];
    const auto& [bx, by] = points[i];
    const double length = std::hypot(bx - ax, by - ay);
    if (!dashed) {
      canvas.segment(ax, ay, bx, by, lineWidth, c);
      continue;
    }
    // Cut the on-intervals of the dash pattern out of [arc, arc + length)
    double s = 0.0;
    while (s < length) {
      const double phase = std::fmod(arc + s, kDashPeriod);
      const double end = phase < kDashOn ? std::min(length, s + kDashOn - phase)
                                         : std::min(length, s + kDashPeriod - phase);
      if (phase < kDashOn && length > 0.0) {
        const double t0 = s / length, t1 = end / length;
        canvas.segment(ax + t0 * (bx - ax), ay + t0 * (by - ay), ax + t1 * (bx - ax),
                       ay + t1 * (by - ay), lineWidth, c);
      }
      s = end;
    }
    arc += length;
  }
}

void drawMarker(Canvas& canvas, double x, double y, const Rgb& c) {
  canvas.disc(x, y, kMarkerRadius + 1.5, kWhite);
  canvas.disc(x, y, kMarkerRadius, c);
}

// Legend geometry, in pixels
constexpr int kLegendPad = 10;
constexpr int kLegendRow = 26;
constexpr int kLegendSample = 40;
constexpr int kLegendInset = 12;

struct Box {
  int x0, y0, x1, y1;
  bool contains(double x, double y) const { return x >= x0 && x < x1 && y >= y0 && y < y1; }
};

/// The legend box in the plot corner that hides the fewest data points and line samples.
Box legendBox(const ChartAxes& axes, const LogLogChart& chart) {
  int nameWidth = 0;
  for (const ChartSeries& s : chart.series)
    nameWidth = std::max(nameWidth, textWidth(s.name, kTextScale));
  const int w = 2 * kLegendPad + kLegendSample + 10 + nameWidth;
  const int h = 2 * kLegendPad + int(chart.series.size()) * kLegendRow -
                (kLegendRow - kGlyphHeight * kTextScale);
  const int xl = axes.left + kLegendInset, xr = axes.right - kLegendInset - w;
  const int yt = axes.top + kLegendInset, yb = axes.bottom - kLegendInset - h;
  const std::array<Box, 4> corners = {Box{xr, yt, xr + w, yt + h}, Box{xl, yt, xl + w, yt + h},
                                      Box{xr, yb, xr + w, yb + h}, Box{xl, yb, xl + w, yb + h}};
  Box best = corners[0];
  int fewest = std::numeric_limits<int>::max();
  for (const Box& corner : corners) {
    // Markers and lines hidden under the box or touching its edge
    const int m = int(kMarkerRadius) + 2;
    const Box box{corner.x0 - m, corner.y0 - m, corner.x1 + m, corner.y1 + m};
    int hidden = 0;
    for (const ChartSeries& s : chart.series) {
      for (const auto& run : pixelRuns(axes, s)) {
        for (std::size_t i = 0; i < run.size(); ++i) {
          hidden += box.contains(run[i][0], run[i][1]) ? 8 : 0;  // a marker weighs more
          if (i == 0) continue;
          // Sample the segment every few pixels
          const double length = std::hypot(run[i][0] - run[i - 1][0], run[i][1] - run[i - 1][1]);
          const int samples = std::max(1, int(length / 4.0));
          for (int k = 1; k < samples; ++k) {
            const double t = double(k) / samples;
            hidden += box.contains(run[i - 1][0] + t * (run[i][0] - run[i - 1][0]),
                                   run[i - 1][1] + t * (run[i][1] - run[i - 1][1]));
          }
        }
      }
    }
    if (hidden < fewest) fewest = hidden, best = corner;
  }
  return best;
}

void drawLegend(Canvas& canvas, const ChartAxes& axes, const LogLogChart& chart) {
  const Box box = legendBox(axes, chart);
  canvas.fillRect(box.x0, box.y0, box.x1, box.y1, kWhite);
  canvas.fillRect(box.x0, box.y0, box.x1, box.y0 + 1, kFrame);
  canvas.fillRect(box.x0, box.y1 - 1, box.x1, box.y1, kFrame);
  canvas.fillRect(box.x0, box.y0, box.x0 + 1, box.y1, kFrame);
  canvas.fillRect(box.x1 - 1, box.y0, box.x1, box.y1, kFrame);
  for (std::size_t i = 0; i < chart.series.size(); ++i) {
    const ChartSeries& s = chart.series[i];
    const int top = box.y0 + kLegendPad + int(i) * kLegendRow;
    const double mid = top + 0.5 * kGlyphHeight * kTextScale;
    const double x0 = box.x0 + kLegendPad, x1 = x0 + kLegendSample;
    drawPolyline(canvas, {{x0, mid}, {x1, mid}}, s.rgb, s.dashed, kLineWidth);
    drawMarker(canvas, 0.5 * (x0 + x1), mid, s.rgb);
    canvas.text(s.name, int(x1) + 10, top, kTextScale, kInk);
  }
}

}  // namespace

std::array<double, 2> ChartAxes::pixel(double x, double y) const {
  // Decade boundaries fall on pixel centres, so grid lines and data share one mapping
  const double tx = (std::log10(x) - log10XMin) / double(log10XMax - log10XMin);
  const double ty = (std::log10(y) - log10YMin) / double(log10YMax - log10YMin);
  return {left + 0.5 + tx * (right - left), bottom + 0.5 - ty * (bottom - top)};
}

ChartAxes chartAxes(const LogLogChart& chart) {
  if (chart.width < 320 || chart.height < 240 || chart.width > 8192 || chart.height > 8192) {
    throw std::invalid_argument("log-log chart: size " + std::to_string(chart.width) + "x" +
                                std::to_string(chart.height) + " outside 320x240..8192x8192");
  }
  // Data range in log10 over the plottable points
  double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = x0, y1 = -x0;
  for (const ChartSeries& s : chart.series) {
    if (s.x.size() != s.y.size()) {
      throw std::invalid_argument("log-log chart: series '" + s.name + "' has " +
                                  std::to_string(s.x.size()) + " x values but " +
                                  std::to_string(s.y.size()) + " y values");
    }
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      if (!plottable(s.x[i], s.y[i])) continue;
      x0 = std::min(x0, std::log10(s.x[i])), x1 = std::max(x1, std::log10(s.x[i]));
      y0 = std::min(y0, std::log10(s.y[i])), y1 = std::max(y1, std::log10(s.y[i]));
    }
  }
  if (!(x0 <= x1)) {
    throw std::invalid_argument("log-log chart '" + chart.title +
                                "': nothing to plot (no point with finite, positive x and y)");
  }

  // Pad to whole decades; the slack absorbs log10 rounding (log10(1e-3) may be -2.9999...)
  ChartAxes axes;
  const auto decadeBelow = [](double v) { return int(std::floor(v + 1e-9)); };
  const auto decadeAbove = [](double v) { return int(std::ceil(v - 1e-9)); };
  axes.log10XMin = decadeBelow(x0), axes.log10XMax = std::max(decadeAbove(x1), axes.log10XMin + 1);
  axes.log10YMin = decadeBelow(y0), axes.log10YMax = std::max(decadeAbove(y1), axes.log10YMin + 1);

  // Margins: title above; y label and the widest decade label on the left; labels below
  const int labelHeight = kGlyphHeight * kTextScale;
  int yLabelWidth = 0;
  for (int k = axes.log10YMin; k <= axes.log10YMax; ++k) {
    yLabelWidth = std::max(yLabelWidth, textWidth(decadeLabel(k), kTextScale));
  }
  axes.top = 20 + (chart.title.empty() ? 0 : kGlyphHeight * kTitleScale + 20);
  axes.left = 16 + (chart.yLabel.empty() ? 0 : labelHeight + 16) + yLabelWidth + 12;
  axes.bottom =
      chart.height - (16 + labelHeight + 12 + (chart.xLabel.empty() ? 0 : labelHeight + 16));
  axes.right =
      chart.width - std::max(28, textWidth(decadeLabel(axes.log10XMax), kTextScale) / 2 + 12);
  return axes;
}

std::string renderLogLogChartPng(const LogLogChart& chart) {
  const ChartAxes axes = chartAxes(chart);
  Canvas canvas(chart.width, chart.height);
  const int xDecades = axes.log10XMax - axes.log10XMin;
  const int yDecades = axes.log10YMax - axes.log10YMin;
  const double xDecadePixels = double(axes.right - axes.left) / xDecades;
  const double yDecadePixels = double(axes.bottom - axes.top) / yDecades;
  const int labelHeight = kGlyphHeight * kTextScale;
  int widestXLabel = 0;
  for (int k = axes.log10XMin; k <= axes.log10XMax; ++k) {
    widestXLabel = std::max(widestXLabel, textWidth(decadeLabel(k), kTextScale));
  }
  const int xStep = labelStep(xDecades, axes.right - axes.left, widestXLabel + 28);
  const int yStep = labelStep(yDecades, axes.bottom - axes.top, labelHeight + 22);

  // Grid: minor lines at 2..9 when a decade is wide enough, decade lines (all of them when
  // they stay apart, else only the labelled ones)
  const auto column = [&](double x) { return int(std::floor(axes.pixel(x, 1.0)[0])); };
  const auto row = [&](double y) { return int(std::floor(axes.pixel(1.0, y)[1])); };
  for (int k = axes.log10XMin; k < axes.log10XMax && xDecadePixels >= 60; ++k) {
    for (int m = 2; m <= 9; ++m) {
      const int x = column(m * std::pow(10.0, k));
      canvas.fillRect(x, axes.top, x + 1, axes.bottom, kMinorGrid);
    }
  }
  for (int k = axes.log10YMin; k < axes.log10YMax && yDecadePixels >= 60; ++k) {
    for (int m = 2; m <= 9; ++m) {
      const int y = row(m * std::pow(10.0, k));
      canvas.fillRect(axes.left, y, axes.right, y + 1, kMinorGrid);
    }
  }
  for (int k = axes.log10XMin; k <= axes.log10XMax; ++k) {
    if (xDecadePixels < 12 && !labelled(k, xStep)) continue;
    const int x = column(std::pow(10.0, k));
    canvas.fillRect(x, axes.top, x + 1, axes.bottom, kMajorGrid);
  }
  for (int k = axes.log10YMin; k <= axes.log10YMax; ++k) {
    if (yDecadePixels < 12 && !labelled(k, yStep)) continue;
    const int y = row(std::pow(10.0, k));
    canvas.fillRect(axes.left, y, axes.right, y + 1, kMajorGrid);
  }

  // Frame, ticks and decade labels
  canvas.fillRect(axes.left, axes.top, axes.right + 1, axes.top + 1, kFrame);
  canvas.fillRect(axes.left, axes.bottom, axes.right + 1, axes.bottom + 1, kFrame);
  canvas.fillRect(axes.left, axes.top, axes.left + 1, axes.bottom + 1, kFrame);
  canvas.fillRect(axes.right, axes.top, axes.right + 1, axes.bottom + 1, kFrame);
  for (int k = axes.log10XMin; k <= axes.log10XMax; ++k) {
    if (!labelled(k, xStep)) continue;
    const std::string label = decadeLabel(k);
    const int x = column(std::pow(10.0, k));
    canvas.fillRect(x, axes.bottom + 1, x + 1, axes.bottom + 7, kFrame);
    canvas.text(label, x - textWidth(label, kTextScale) / 2, axes.bottom + 12, kTextScale, kInk);
  }
  for (int k = axes.log10YMin; k <= axes.log10YMax; ++k) {
    if (!labelled(k, yStep)) continue;
    const std::string label = decadeLabel(k);
    const int y = row(std::pow(10.0, k));
    canvas.fillRect(axes.left - 6, y, axes.left, y + 1, kFrame);
    canvas.text(label, axes.left - 12 - textWidth(label, kTextScale), y - labelHeight / 2,
                kTextScale, kInk);
  }

  // Series: all lines first, then all markers on top
  for (const ChartSeries& s : chart.series) {
    for (const auto& run : pixelRuns(axes, s))
      drawPolyline(canvas, run, s.rgb, s.dashed, kLineWidth);
  }
  for (const ChartSeries& s : chart.series) {
    for (const auto& run : pixelRuns(axes, s)) {
      for (const auto& [x, y] : run) drawMarker(canvas, x, y, s.rgb);
    }
  }
  if (!chart.series.empty()) drawLegend(canvas, axes, chart);

  // Title and axis labels, centred on the plot
  const int centreX = (axes.left + axes.right) / 2;
  const int centreY = (axes.top + axes.bottom) / 2;
  canvas.text(chart.title, centreX - textWidth(chart.title, kTitleScale) / 2, 20, kTitleScale,
              kInk);
  canvas.text(chart.xLabel, centreX - textWidth(chart.xLabel, kTextScale) / 2,
              axes.bottom + 12 + labelHeight + 16, kTextScale, kInk);
  canvas.text(chart.yLabel, 16, centreY + textWidth(chart.yLabel, kTextScale) / 2, kTextScale, kInk,
              /*rotated=*/true);

  return encodePng(canvas.width(), canvas.height(), 3,
                   {canvas.data(), static_cast<size_t>(canvas.width()) * canvas.height() * 3});
}

void writeLogLogChartPng(const std::filesystem::path& path, const LogLogChart& chart) {
  writeFileAtomically(path, renderLogLogChartPng(chart));
}

}  // namespace sculpt
