#include "render/overlay_geometry.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace sculpt::render {
namespace {

// clang-format off
constexpr std::array<std::array<int, 2>, 12> kHexEdges = {{
    {0, 1}, {1, 2}, {2, 3}, {3, 0},    // bottom
    {4, 5}, {5, 6}, {6, 7}, {7, 4},    // top
    {0, 4}, {1, 5}, {2, 6}, {3, 7}}};  // sides
// clang-format on
constexpr std::array<std::array<int, 2>, 6> kTetEdges = {
    {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}}};

}  // namespace

void LineList::addVertex(const glm::vec3& p, const glm::vec3& colour) {
  xyz.insert(xyz.end(), {p.x, p.y, p.z});
  rgb.insert(rgb.end(), {colour.r, colour.g, colour.b});
}

void LineList::addSegment(const glm::vec3& a, const glm::vec3& b, const glm::vec3& colour) {
  addVertex(a, colour);
  addVertex(b, colour);
}

void LineList::append(const LineList& other) {
  xyz.insert(xyz.end(), other.xyz.begin(), other.xyz.end());
  rgb.insert(rgb.end(), other.rgb.begin(), other.rgb.end());
}

glm::vec3 elementTypeColour(int type) {
  switch (type) {
    case 0: return {0.30f, 0.52f, 0.80f};  // tricubic: calm blue, the bulk of the cells
    case 1: return {0.98f, 0.55f, 0.12f};  // trilinear (extraordinary): orange
    case 2: return {0.90f, 0.20f, 0.80f};  // pyramid (centre-split): magenta
    default: return {0.6f, 0.6f, 0.6f};
  }
}

LineList groundGrid(const glm::vec3& centre, float halfExtent, float spacing) {
  if (!(std::isfinite(halfExtent) && std::isfinite(spacing) && halfExtent > 0.0f && spacing > 0.0f))
    throw std::invalid_argument("groundGrid: the half extent and spacing must be positive");
  const float ratio = std::floor(halfExtent / spacing);
  if (ratio > 1000.0f)
    throw std::invalid_argument("groundGrid: more than 1000 lines a side (spacing too small)");
  const int n = static_cast<int>(ratio);
  const float reach = static_cast<float>(n) * spacing;
  const glm::vec3 line(0.32f), centreLine(0.52f);
  LineList grid;
  for (int k = -n; k <= n; ++k) {
    const float s = static_cast<float>(k) * spacing;
    const glm::vec3& colour = k == 0 ? centreLine : line;
    grid.addSegment(centre + glm::vec3(s, 0.0f, -reach), centre + glm::vec3(s, 0.0f, reach),
                    colour);
    grid.addSegment(centre + glm::vec3(-reach, 0.0f, s), centre + glm::vec3(reach, 0.0f, s),
                    colour);
  }
  return grid;
}

LineList axes(const glm::vec3& origin, float length) {
  LineList lines;
  lines.addSegment(origin, origin + glm::vec3(length, 0, 0), {0.90f, 0.22f, 0.22f});
  lines.addSegment(origin, origin + glm::vec3(0, length, 0), {0.30f, 0.80f, 0.25f});
  lines.addSegment(origin, origin + glm::vec3(0, 0, length), {0.25f, 0.45f, 0.95f});
  return lines;
}

std::vector<CellEdge> distinctCellEdges(const VolumeMesh& mesh,
                                        std::span<const uint8_t> cellColourIndex) {
  if (!cellColourIndex.empty() && cellColourIndex.size() != mesh.numCells())
    throw std::invalid_argument("cellEdges: " + std::to_string(cellColourIndex.size()) +
                                " colour indices for " + std::to_string(mesh.numCells()) +
                                " cells");
  // Every cell's edges with their cell's index.
  std::vector<CellEdge> all;
  all.reserve(12 * static_cast<size_t>(mesh.numCells()));
  for (uint32_t c = 0; c < mesh.numCells(); ++c) {
    const auto cell = mesh.cells.row(c);
    const uint8_t index = cellColourIndex.empty() ? 0 : cellColourIndex[c];
    const auto addEdges = [&](const auto& local) {
      for (const auto& [i, j] : local) {
        const uint32_t a = cell[i], b = cell[j];
        if (a >= mesh.numNodes() || b >= mesh.numNodes())
          throw std::invalid_argument("cellEdges: cell " + std::to_string(c) +
                                      " names a node out of range");
        all.push_back({std::min(a, b), std::max(a, b), index});
      }
    };
    if (cell.size() == 8)
      addEdges(kHexEdges);
    else if (cell.size() == 4)
      addEdges(kTetEdges);
    else
      throw std::invalid_argument("cellEdges: cell " + std::to_string(c) + " has " +
                                  std::to_string(cell.size()) +
                                  " nodes; only tetrahedra and hexahedra are drawn");
  }
  // Bucket by low node (counting sort, linear time), then sort each small bucket by high node
  // and keep one edge per run with the run's highest index.
  std::vector<uint32_t> begin(mesh.numNodes() + 1, 0);
  for (const CellEdge& e : all) ++begin[e.a + 1];
  for (uint32_t n = 0; n < mesh.numNodes(); ++n) begin[n + 1] += begin[n];
  std::vector<CellEdge> bucketed(all.size());
  std::vector<uint32_t> cursor(begin.begin(), begin.end() - 1);
  for (const CellEdge& e : all) bucketed[cursor[e.a]++] = e;
  std::vector<CellEdge> distinct;
  distinct.reserve(all.size() / 3);
  for (uint32_t n = 0; n < mesh.numNodes(); ++n) {
    const auto first = bucketed.begin() + begin[n], last = bucketed.begin() + begin[n + 1];
    std::sort(first, last, [](const CellEdge& p, const CellEdge& q) { return p.b < q.b; });
    for (auto e = first; e != last; ++e) {
      if (e == first || e->b != distinct.back().b)
        distinct.push_back(*e);
      else
        distinct.back().colourIndex = std::max(distinct.back().colourIndex, e->colourIndex);
    }
  }
  return distinct;
}

LineList edgeLines(std::span<const CellEdge> edges, const Points& nodes,
                   std::span<const glm::vec3> palette) {
  const auto numNodes = static_cast<uint32_t>(nodes.rows());
  LineList lines;
  lines.xyz.resize(6 * edges.size());
  lines.rgb.resize(6 * edges.size());
  float* xyz = lines.xyz.data();
  float* rgb = lines.rgb.data();
  for (const CellEdge& e : edges) {
    if (e.a >= numNodes || e.b >= numNodes)
      throw std::invalid_argument("edgeLines: edge " + std::to_string(e.a) + "-" +
                                  std::to_string(e.b) + " beyond the " + std::to_string(numNodes) +
                                  " node positions");
    if (!palette.empty() && e.colourIndex >= palette.size())
      throw std::invalid_argument("edgeLines: colour index " + std::to_string(e.colourIndex) +
                                  " but the palette holds " + std::to_string(palette.size()));
    const glm::vec3 colour =
        palette.empty() ? elementTypeColour(e.colourIndex) : palette[e.colourIndex];
    for (uint32_t n : {e.a, e.b}) {
      for (int d = 0; d < 3; ++d) *xyz++ = static_cast<float>(nodes(n, d));
      for (int d = 0; d < 3; ++d) *rgb++ = colour[d];
    }
  }
  return lines;
}

LineList cellEdges(const VolumeMesh& mesh, const Points& nodes,
                   std::span<const uint8_t> cellColourIndex, std::span<const glm::vec3> palette) {
  if (nodes.rows() != static_cast<Eigen::Index>(mesh.numNodes()))
    throw std::invalid_argument("cellEdges: " + std::to_string(nodes.rows()) +
                                " node positions for a mesh of " + std::to_string(mesh.numNodes()) +
                                " nodes");
  return edgeLines(distinctCellEdges(mesh, cellColourIndex), nodes, palette);
}

LineList controlEdges(std::span<const std::array<uint32_t, 2>> edges,
                      std::span<const float> positions, const glm::vec3& colour) {
  if (positions.size() % 3 != 0)
    throw std::invalid_argument("controlEdges: positions must hold 3 floats per vertex");
  const size_t numVertices = positions.size() / 3;
  const auto point = [&](uint32_t v) {
    return glm::vec3(positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]);
  };
  LineList lines;
  lines.xyz.reserve(6 * edges.size());
  lines.rgb.reserve(6 * edges.size());
  for (const auto& [a, b] : edges) {
    if (a >= numVertices || b >= numVertices)
      throw std::invalid_argument("controlEdges: edge " + std::to_string(a) + "-" +
                                  std::to_string(b) + " names a vertex beyond the " +
                                  std::to_string(numVertices) + " given");
    lines.addSegment(point(a), point(b), colour);
  }
  return lines;
}

}  // namespace sculpt::render
