// Overlay drawing of the sculpt window: the colour map (CPU against matplotlib's viridis table and
// against the GLSL copy drawn by SliceRenderer), LineRenderer's lines and points read back from
// an off-screen target, and the counts and colours of the overlay line lists.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <limits>
#include <set>
#include <stdexcept>
#include <utility>
#include <vector>

#include "support/gl_context.h"

#include "mesh/lattice_mesh.h"
#include "mesh/plane_slice.h"
#include "render/colour_map.h"
#include "render/line_renderer.h"
#include "render/offscreen_target.h"
#include "render/overlay_geometry.h"
#include "render/slice_renderer.h"

namespace sculpt {
namespace {

/// A hidden window with an OpenGL 3.3 core context for the test's lifetime.
class OverlayRender : public testing::GlContextTest {};

/// RGBA8 pixels (top row first) of a target: the pixel at column x, row y.
struct Image {
  int width, height;
  std::vector<uint8_t> rgba;
  const uint8_t* at(int x, int y) const { return &rgba[4 * (static_cast<size_t>(y) * width + x)]; }
};

Image clearAndRead(const render::OffscreenTarget& target, const std::function<void()>& drawCalls) {
  target.bind();
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glDisable(GL_DEPTH_TEST);
  drawCalls();
  glFinish();
  return {target.width(), target.height(), target.readPixels()};
}

/// Largest channel difference between a pixel and a colour in [0,1], in 1/255 steps.
int channelError(const uint8_t* pixel, const glm::vec3& colour) {
  int worst = 0;
  for (int c = 0; c < 3; ++c)
    worst = std::max(worst, std::abs(pixel[c] - static_cast<int>(std::lround(colour[c] * 255.0f))));
  return worst;
}

// ---------------------------------------------------------------------------------------------
// Colour map

TEST(ColourMap, FollowsMatplotlibsViridisTable) {
  // Rows 0, 64, 128, 192 and 255 of matplotlib's 256-entry viridis table (t = row / 255).
  const std::array<std::pair<int, glm::vec3>, 5> table = {{
      {0, {0.26700401f, 0.00487433f, 0.32941519f}},
      {64, {0.22973926f, 0.32236127f, 0.54570633f}},
      {128, {0.12756771f, 0.56694891f, 0.55055551f}},
      {192, {0.3692142f, 0.78888793f, 0.38291438f}},
      {255, {0.99324789f, 0.90615657f, 0.1439362f}},
  }};
  for (const auto& [row, expected] : table) {
    const glm::vec3 c = render::colourMap(static_cast<float>(row) / 255.0f);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(c[k], expected[k], 0.015) << "row " << row;
  }
}

TEST(ColourMap, ClampsAndBrightensMonotonically) {
  EXPECT_EQ(render::colourMap(-3.0f), render::colourMap(0.0f));
  EXPECT_EQ(render::colourMap(7.0f), render::colourMap(1.0f));
  EXPECT_EQ(render::colourMap(std::numeric_limits<float>::quiet_NaN()), render::colourMap(0.0f));
  // Perceptual: luminance rises steadily from dark violet to bright yellow.
  float previous = -1.0f;
  for (int k = 0; k <= 200; ++k) {
    const glm::vec3 c = render::colourMap(static_cast<float>(k) / 200.0f);
    const float luminance = 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b;
    EXPECT_GT(luminance, previous) << "t = " << k / 200.0;
    previous = luminance;
    for (int i = 0; i < 3; ++i) {
      EXPECT_GE(c[i], 0.0f);
      EXPECT_LE(c[i], 1.0f);
    }
  }
}

/// Two triangles covering the viewport with the value running 0 -> 1 from left to right.
PlaneSlice fullScreenRamp() {
  PlaneSlice s;
  s.positions = {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0};
  s.values = {0, 1, 1, 0};
  s.triangles = {0, 1, 2, 0, 2, 3};
  return s;
}

TEST_F(OverlayRender, SliceShaderColoursAgreeWithTheCpuColourMap) {
  render::OffscreenTarget target(256, 4);
  render::SliceRenderer renderer;
  renderer.setSlice(fullScreenRamp());
  ASSERT_EQ(renderer.numTriangles(), 2);
  const glm::mat4 identity(1.0f);
  // Full range, then [0.25, 0.75] so that both ends saturate.
  for (const auto& [low, high] : {std::pair(0.0f, 1.0f), std::pair(0.25f, 0.75f)}) {
    const Image image = clearAndRead(target, [&] { renderer.draw(identity, identity, low, high); });
    int worst = 0;
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x) {
        const float value = (static_cast<float>(x) + 0.5f) / static_cast<float>(image.width);
        worst = std::max(
            worst, channelError(image.at(x, y), render::colourMap((value - low) / (high - low))));
      }
    std::printf("[ measured ] slice colours [%.2f, %.2f]: worst channel error %d/255\n", low, high,
                worst);
    EXPECT_LE(worst, 2);
  }
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(OverlayRender, SliceOfALatticeCoversItsProjection) {
  // The section z = 0.5 of the unit cube seen straight down with an orthographic projection that
  // maps [0,1]^2 to the viewport: every pixel is covered, in the colour of the cell value there.
  LatticeSpec spec;
  spec.cubes = {4, 4, 4};
  spec.spacing = 0.25;
  const VolumeMesh mesh = hexLattice(spec);
  std::vector<double> values(mesh.numCells());
  for (uint32_t c = 0; c < mesh.numCells(); ++c) values[c] = c % 4;  // the column index i
  render::SliceRenderer renderer;
  renderer.setSlice(slicePlane(mesh, mesh.positions, {0, 0, 1}, 0.5, {}, values));
  glm::mat4 projection(1.0f);
  projection[0][0] = projection[1][1] = 2.0f;
  projection[3][0] = projection[3][1] = -1.0f;
  render::OffscreenTarget target(32, 32);
  const Image image =
      clearAndRead(target, [&] { renderer.draw(glm::mat4(1.0f), projection, 0.0f, 3.0f); });
  int worst = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      worst = std::max(
          worst, channelError(image.at(x, y), render::colourMap(static_cast<float>(x / 8) / 3.0f)));
  EXPECT_LE(worst, 2);
}

// ---------------------------------------------------------------------------------------------
// Lines and points

int countPixels(const Image& image, int x0, int x1, int y0, int y1,
                const std::function<bool(const uint8_t*)>& test) {
  int n = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) n += test(image.at(x, y)) ? 1 : 0;
  return n;
}

bool isRed(const uint8_t* p) { return p[0] == 255 && p[1] == 0 && p[2] == 0; }
bool isGreen(const uint8_t* p) { return p[0] == 0 && p[1] == 255 && p[2] == 0; }
bool isLit(const uint8_t* p) { return p[0] || p[1] || p[2]; }

TEST_F(OverlayRender, LineRendererDrawsAHorizontalLineAcrossTheMiddle) {
  render::OffscreenTarget target(64, 64);
  render::LineRenderer lines;
  // Through the centres of the pixel row 32 from the bottom (row 31 from the top).
  const float y = 32.5f / 32.0f - 1.0f;
  const std::vector<float> xyz = {-1.0f, y, 0.0f, 1.0f, y, 0.0f}, rgb = {1, 0, 0, 1, 0, 0};
  lines.setLines(xyz, rgb);
  EXPECT_EQ(lines.numLineVertices(), 2);
  const glm::mat4 identity(1.0f);
  const Image image = clearAndRead(target, [&] { lines.draw(identity, identity, 1.0f); });
  EXPECT_GE(countPixels(image, 0, 64, 31, 32, isRed), 62);
  EXPECT_EQ(countPixels(image, 0, 64, 5, 6, isLit), 0);
  EXPECT_EQ(countPixels(image, 0, 64, 0, 64, isLit), countPixels(image, 0, 64, 31, 32, isLit))
      << "the line is one pixel thick";
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(OverlayRender, PointsOfSizeNineCoverANineByNineDisc) {
  render::OffscreenTarget target(64, 64);
  render::LineRenderer renderer;
  // The centre of pixel (20, 40) counted from the bottom left.
  const std::vector<float> xyz = {20.5f / 32.0f - 1.0f, 40.5f / 32.0f - 1.0f, 0.0f},
                           rgb = {0, 1, 0};
  renderer.setPoints(xyz, rgb);
  const glm::mat4 identity(1.0f);
  const Image image = clearAndRead(target, [&] { renderer.draw(identity, identity, 9.0f); });
  int xMin = 64, xMax = -1, yMin = 64, yMax = -1;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x)
      if (isLit(image.at(x, y))) {
        EXPECT_TRUE(isGreen(image.at(x, y)));
        xMin = std::min(xMin, x), xMax = std::max(xMax, x);
        yMin = std::min(yMin, y), yMax = std::max(yMax, y);
      }
  EXPECT_EQ(xMin, 16);
  EXPECT_EQ(xMax, 24);
  EXPECT_EQ(yMin, 63 - 44);
  EXPECT_EQ(yMax, 63 - 36);
  // A round point: the 69 pixel centres within 4.5 pixels of the point's centre.
  const int lit = countPixels(image, 0, 64, 0, 64, isLit);
  EXPECT_GE(lit, 60);
  EXPECT_LT(lit, 81);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(OverlayRender, BadVertexArraysAreRejected) {
  render::LineRenderer lines;
  const std::vector<float> oneVertex = {0, 0, 0}, twoVertices = {0, 0, 0, 1, 1, 1};
  EXPECT_THROW(lines.setLines(oneVertex, oneVertex), std::invalid_argument);
  EXPECT_THROW(lines.setLines(twoVertices, oneVertex), std::invalid_argument);
  EXPECT_THROW(lines.setPoints(std::vector<float>{0, 0}, std::vector<float>{0, 0}),
               std::invalid_argument);
  render::SliceRenderer slice;
  PlaneSlice bad = fullScreenRamp();
  bad.triangles.back() = 4;
  EXPECT_THROW(slice.setSlice(bad), std::invalid_argument);
  bad = fullScreenRamp();
  bad.values.pop_back();
  EXPECT_THROW(slice.setSlice(bad), std::invalid_argument);
}

// ---------------------------------------------------------------------------------------------
// Line lists

using Segment = std::pair<std::array<float, 3>, std::array<float, 3>>;

std::array<float, 3> vertexOf(const render::LineList& l, uint32_t v) {
  return {l.xyz[3 * v], l.xyz[3 * v + 1], l.xyz[3 * v + 2]};
}
glm::vec3 colourOf(const render::LineList& l, uint32_t v) {
  return {l.rgb[3 * v], l.rgb[3 * v + 1], l.rgb[3 * v + 2]};
}
/// Segments with their ends in a canonical order, so that a-b and b-a compare equal.
std::set<Segment> segmentSet(const render::LineList& l) {
  std::set<Segment> s;
  for (uint32_t i = 0; i < l.numSegments(); ++i)
    s.insert(std::minmax(vertexOf(l, 2 * i), vertexOf(l, 2 * i + 1)));
  return s;
}

TEST(OverlayGeometry, HexLatticeEdgesAreListedOnce) {
  LatticeSpec spec;
  spec.cubes = {2, 2, 2};
  const VolumeMesh mesh = hexLattice(spec);
  const render::LineList edges = render::cellEdges(mesh, mesh.positions, {});
  // 3 x 3 lines of 2 unit edges along each of the 3 axes.
  EXPECT_EQ(edges.numSegments(), 54u);
  EXPECT_EQ(segmentSet(edges).size(), 54u);
  for (uint32_t i = 0; i < edges.numSegments(); ++i) {
    const auto a = vertexOf(edges, 2 * i), b = vertexOf(edges, 2 * i + 1);
    EXPECT_FLOAT_EQ(std::abs(a[0] - b[0]) + std::abs(a[1] - b[1]) + std::abs(a[2] - b[2]), 1.0f);
    EXPECT_EQ(colourOf(edges, 2 * i), render::elementTypeColour(0));
  }
  // A cube split into 6 tetrahedra: 12 cube edges, 6 face diagonals, 1 body diagonal.
  spec.cubes = {1, 1, 1};
  const VolumeMesh tets = tetLattice(spec);
  EXPECT_EQ(render::cellEdges(tets, tets.positions, {}).numSegments(), 19u);
}

TEST(OverlayGeometry, SharedEdgesTakeTheHighestColourIndex) {
  // A unit hexahedron with a tetrahedron on half of its top face (nodes 4, 5, 6): edges 4-5 and
  // 5-6 belong to both cells.
  VolumeMesh mesh;
  mesh.positions.resize(9, 3);
  mesh.positions << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1, 0.8,
      0.3, 2;
  mesh.addHexahedron({0, 1, 2, 3, 4, 5, 6, 7});
  mesh.addTetrahedron({4, 5, 6, 8});
  const std::vector<uint8_t> kinds = {0, 2};
  const render::LineList edges = render::cellEdges(mesh, mesh.positions, kinds);
  EXPECT_EQ(edges.numSegments(), 12u + 6u - 2u);
  int blue = 0, magenta = 0;
  for (uint32_t i = 0; i < edges.numSegments(); ++i) {
    const glm::vec3 c = colourOf(edges, 2 * i);
    if (c == render::elementTypeColour(0)) ++blue;
    if (c == render::elementTypeColour(2)) ++magenta;
  }
  EXPECT_EQ(blue, 10);
  EXPECT_EQ(magenta, 6);
  // With an explicit palette the same rule holds.
  const std::vector<glm::vec3> palette = {{1, 1, 1}, {0, 0, 0}, {0, 1, 0}};
  const render::LineList custom = render::cellEdges(mesh, mesh.positions, kinds, palette);
  int green = 0;
  for (uint32_t i = 0; i < custom.numSegments(); ++i)
    green += colourOf(custom, 2 * i) == palette[2];
  EXPECT_EQ(green, 6);
  // Bad input.
  EXPECT_THROW(render::cellEdges(mesh, mesh.positions, std::vector<uint8_t>{0}),
               std::invalid_argument);
  EXPECT_THROW(render::cellEdges(mesh, mesh.positions, std::vector<uint8_t>{0, 3}, palette),
               std::invalid_argument);
  EXPECT_THROW(render::cellEdges(mesh, mesh.positions.topRows(8), kinds), std::invalid_argument);
}

TEST(OverlayGeometry, CachedEdgesFollowTheNodes) {
  LatticeSpec spec;
  spec.cubes = {3, 2, 2};
  const VolumeMesh mesh = hexLattice(spec);
  const std::vector<render::CellEdge> edges = render::distinctCellEdges(mesh, {});
  // (3+1)(2+1)(2+1) nodes: 3*3*3 x-edges, 4*2*3 y-edges, 4*3*2 z-edges.
  EXPECT_EQ(edges.size(), 27u + 24u + 24u);
  const Points doubled = 2.0 * mesh.positions;
  const render::LineList lines = render::edgeLines(edges, doubled);
  EXPECT_EQ(lines.xyz, render::cellEdges(mesh, doubled, {}).xyz);
  for (uint32_t i = 0; i < lines.numSegments(); ++i) {
    const auto a = vertexOf(lines, 2 * i), b = vertexOf(lines, 2 * i + 1);
    EXPECT_FLOAT_EQ(std::abs(a[0] - b[0]) + std::abs(a[1] - b[1]) + std::abs(a[2] - b[2]), 2.0f);
  }
  EXPECT_THROW(render::edgeLines(edges, doubled.topRows(3)), std::invalid_argument);
}

TEST(OverlayGeometry, GroundGridLiesInItsPlaneWithABrighterCentreCross) {
  const glm::vec3 centre(1.0f, -2.0f, 3.0f);
  const render::LineList grid = render::groundGrid(centre, 1.05f, 0.25f);
  // Lines at -4..4 spacings in each direction, reaching 4 spacings out.
  EXPECT_EQ(grid.numSegments(), 18u);
  int brighter = 0;
  for (uint32_t v = 0; v < grid.numVertices(); ++v) {
    const auto p = vertexOf(grid, v);
    EXPECT_EQ(p[1], -2.0f);
    EXPECT_LE(std::abs(p[0] - 1.0f), 1.0f + 1e-6f);
    EXPECT_LE(std::abs(p[2] - 3.0f), 1.0f + 1e-6f);
  }
  for (uint32_t i = 0; i < grid.numSegments(); ++i) {
    const glm::vec3 c = colourOf(grid, 2 * i);
    if (c.r > colourOf(grid, 0).r || c.r > colourOf(grid, 2).r) {
      ++brighter;
      // The centre lines pass through the centre.
      const auto a = vertexOf(grid, 2 * i), b = vertexOf(grid, 2 * i + 1);
      EXPECT_NEAR(0.5f * (a[0] + b[0]), 1.0f, 1e-6f);
      EXPECT_NEAR(0.5f * (a[2] + b[2]), 3.0f, 1e-6f);
    }
  }
  EXPECT_EQ(brighter, 2);
  EXPECT_THROW(render::groundGrid(centre, 1.0f, 0.0f), std::invalid_argument);
  EXPECT_THROW(render::groundGrid(centre, -1.0f, 0.1f), std::invalid_argument);
  EXPECT_THROW(render::groundGrid(centre, 1.0f, 1e-6f), std::invalid_argument);
}

TEST(OverlayGeometry, AxesAreRedGreenBlue) {
  const render::LineList a = render::axes({1, 2, 3}, 0.5f);
  ASSERT_EQ(a.numSegments(), 3u);
  for (uint32_t axis = 0; axis < 3; ++axis) {
    const auto from = vertexOf(a, 2 * axis), to = vertexOf(a, 2 * axis + 1);
    for (uint32_t d = 0; d < 3; ++d)
      EXPECT_FLOAT_EQ(to[d] - from[d], d == axis ? 0.5f : 0.0f) << "axis " << axis;
    EXPECT_EQ(from, (std::array<float, 3>{1, 2, 3}));
    const glm::vec3 c = colourOf(a, 2 * axis);
    for (uint32_t d = 0; d < 3; ++d) {
      if (d == axis) continue;
      EXPECT_GT(c[axis], c[d] + 0.3f) << "axis " << axis;
    }
  }
}

TEST(OverlayGeometry, ControlEdgesAndElementColours) {
  const std::vector<float> positions = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  const std::vector<std::array<uint32_t, 2>> edges = {{0, 1}, {1, 2}};
  const render::LineList lines = render::controlEdges(edges, positions, {1, 1, 0});
  EXPECT_EQ(lines.numSegments(), 2u);
  EXPECT_EQ(vertexOf(lines, 3), (std::array<float, 3>{0, 1, 0}));
  const std::vector<std::array<uint32_t, 2>> outOfRange = {{0, 3}};
  EXPECT_THROW(render::controlEdges(outOfRange, positions, {1, 1, 0}), std::invalid_argument);
  // Blue, orange, magenta: distinct, each in its own hue.
  const glm::vec3 regular = render::elementTypeColour(0),
                  extraordinary = render::elementTypeColour(1),
                  pyramid = render::elementTypeColour(2);
  EXPECT_GT(regular.b, regular.r);
  EXPECT_GT(extraordinary.r, extraordinary.g);
  EXPECT_GT(extraordinary.g, extraordinary.b);
  EXPECT_GT(pyramid.r, pyramid.g);
  EXPECT_GT(pyramid.b, pyramid.g);
}

}  // namespace
}  // namespace sculpt
