#include "subdiv/regularity.h"

#include <algorithm>

#include "mesh/hexahedron.h"

namespace sculpt {

bool isRegularVertex(const Topology& t, uint32_t v) {
  if (t.vertexIsBoundary[v] || t.vertexCells.rowSize(v) != 8 || t.vertexEdges.rowSize(v) != 6)
    return false;
  for (uint32_t c : t.vertexCells.row(v))
    if (!t.isHexahedron(c)) return false;
  for (uint32_t e : t.vertexEdges.row(v))
    if (t.edgeCells.rowSize(e) != 4 || t.edgeFaces.rowSize(e) != 4) return false;
  return true;
}

namespace {

bool allCornersRegular(const Topology& t, uint32_t c, const std::vector<uint8_t>& regularVertex) {
  for (uint32_t v : t.cellVertices.row(c))
    if (!regularVertex[v]) return false;
  return true;
}

}  // namespace

std::vector<CellRegularity> classifyCells(const Topology& t) {
  std::vector<uint8_t> regularVertex(t.numVertices);
  for (uint32_t v = 0; v < t.numVertices; ++v) regularVertex[v] = isRegularVertex(t, v);
  std::vector<CellRegularity> result(t.numCells());
  for (uint32_t c = 0; c < t.numCells(); ++c) {
    if (!t.isHexahedron(c)) result[c] = CellRegularity::Irregular;
    else if (allCornersRegular(t, c, regularVertex)) result[c] = CellRegularity::Regular;
    else result[c] = CellRegularity::Extraordinary;
  }
  return result;
}

namespace {

using Index3 = std::array<int, 3>;

// A hexahedron of the 3x3x3 block with its 8 vertices placed on block indices.
struct PlacedCell {
  uint32_t cell;
  Index3 coordinate;  // block coordinate of the cell, each in 0..2 (the centre cell is 1,1,1)
  std::array<std::pair<uint32_t, Index3>, 8> corners;
  int numCorners = 0;
  const Index3* indexOf(uint32_t v) const {
    for (int i = 0; i < numCorners; ++i)
      if (corners[size_t(i)].first == v) return &corners[size_t(i)].second;
    return nullptr;
  }
};

// Places the four vertices of hexahedron `cell` opposite a known face: each known vertex's
// cell neighbour off the face sits one step along `axis`.
bool placeOppositeFace(const Topology& t, PlacedCell& placed,
                       const std::array<std::pair<uint32_t, Index3>, 4>& face, int axis, int step) {
  std::array<uint32_t, 4> ids;
  for (size_t i = 0; i < 4; ++i) ids[i] = face[i].first;
  const auto opposite = hexOppositeFace(t, placed.cell, ids);
  if (!opposite) return false;
  for (size_t i = 0; i < 4; ++i) {
    Index3 target = face[i].second;
    target[size_t(axis)] += step;
    placed.corners[size_t(placed.numCorners++)] = {(*opposite)[i], target};
  }
  return true;
}

}  // namespace

std::optional<ControlBlock> regularControlBlock(const Topology& t, uint32_t cell) {
  if (!t.isHexahedron(cell)) return std::nullopt;
  for (uint32_t v : t.cellVertices.row(cell))
    if (!isRegularVertex(t, v)) return std::nullopt;

  // Seed the centre cell from its first face: loop[0] at (1,1,1), previous vertex along u, next
  // along v, and w pointing into the cell.
  const std::vector<uint32_t> loop = t.outwardLoop(cell, 0);
  PlacedCell centre{cell, {1, 1, 1}, {}, 0};
  const std::array<std::pair<uint32_t, Index3>, 4> seed = {
      {{loop[0], {1, 1, 1}}, {loop[3], {2, 1, 1}}, {loop[1], {1, 2, 1}}, {loop[2], {2, 2, 1}}}};
  for (const auto& s : seed) centre.corners[size_t(centre.numCorners++)] = s;
  if (!placeOppositeFace(t, centre, seed, 2, +1)) return std::nullopt;

  // Walk across faces to the 26 neighbours (breadth first, so every cell is reached from a
  // placed one through a shared face).
  std::vector<PlacedCell> placed{centre};
  bool visited[3][3][3] = {};
  visited[1][1][1] = true;
  for (size_t next = 0; next < placed.size(); ++next) {
    const PlacedCell current = placed[next];
    for (uint32_t f : t.cellFaces.row(current.cell)) {
      std::array<std::pair<uint32_t, Index3>, 4> face;
      auto fv = t.faceVertices.row(f);
      for (size_t i = 0; i < 4; ++i) face[i] = {fv[i], *current.indexOf(fv[i])};
      // The axis along which the face is constant, and which side of the cell it is on.
      int axis = -1;
      for (int a = 0; a < 3; ++a) {
        bool constant = true;
        for (const auto& q : face) constant &= q.second[size_t(a)] == face[0].second[size_t(a)];
        if (constant) axis = a;
      }
      if (axis < 0) return std::nullopt;
      const int step = face[0].second[size_t(axis)] == current.coordinate[size_t(axis)] ? -1 : +1;
      Index3 coordinate = current.coordinate;
      coordinate[size_t(axis)] += step;
      if (coordinate[size_t(axis)] < 0 || coordinate[size_t(axis)] > 2) continue;
      if (visited[coordinate[0]][coordinate[1]][coordinate[2]]) continue;
      const auto& fc = t.faceCells[f];
      const int32_t neighbour = fc[0] == int32_t(current.cell) ? fc[1] : fc[0];
      if (neighbour == kNoCell || !t.isHexahedron(uint32_t(neighbour))) return std::nullopt;
      PlacedCell cellPlaced{uint32_t(neighbour), coordinate, {}, 0};
      for (const auto& q : face) cellPlaced.corners[size_t(cellPlaced.numCorners++)] = q;
      if (!placeOppositeFace(t, cellPlaced, face, axis, step)) return std::nullopt;
      visited[coordinate[0]][coordinate[1]][coordinate[2]] = true;
      placed.push_back(cellPlaced);
    }
  }
  if (placed.size() != 27) return std::nullopt;

  ControlBlock block;
  std::array<bool, 64> filled{};
  for (const PlacedCell& p : placed)
    for (const auto& [v, index] : p.corners) {
      for (int a : index)
        if (a < 0 || a > 3) return std::nullopt;
      const size_t slot = size_t(index[0] * 16 + index[1] * 4 + index[2]);
      block[slot] = v;
      filled[slot] = true;
    }
  if (!std::all_of(filled.begin(), filled.end(), [](bool b) { return b; })) return std::nullopt;
  return block;
}

}  // namespace sculpt
