#include "mesh/topology.h"

#include <algorithm>
#include <numeric>
#include <string>

namespace sculpt {
namespace {

uint64_t edgeKey(uint32_t a, uint32_t b) {
  if (a > b) std::swap(a, b);
  return (uint64_t(a) << 32) | b;
}

// Index of `value` in `loop`, or -1.
int positionIn(std::span<const uint32_t> loop, uint32_t value) {
  for (size_t i = 0; i < loop.size(); ++i)
    if (loop[i] == value) return static_cast<int>(i);
  return -1;
}

enum class LoopRelation { Same, Reversed, Other };

// How `loop` relates to `reference` (same vertex set): same cyclic order, reversed, or neither.
LoopRelation relateLoops(std::span<const uint32_t> reference, std::span<const uint32_t> loop) {
  const size_t m = reference.size();
  const int j = positionIn(loop, reference[0]);
  if (j < 0 || loop.size() != m) return LoopRelation::Other;
  bool same = true, reversed = true;
  for (size_t i = 0; i < m; ++i) {
    if (loop[(size_t(j) + i) % m] != reference[i]) same = false;
    if (loop[(size_t(j) + m - i) % m] != reference[i]) reversed = false;
  }
  return same ? LoopRelation::Same : reversed ? LoopRelation::Reversed : LoopRelation::Other;
}

// Groups the complex's face loops into unique faces (same vertex set). Returns the face id of
// each loop; face ids follow the order of first appearance.
std::vector<uint32_t> groupLoopsIntoFaces(const CellComplex& complex, uint32_t& numFaces) {
  const uint32_t numLoops = static_cast<uint32_t>(complex.loopBegin.size() - 1);
  std::vector<uint32_t> sortedIds(complex.loopVertices);
  for (uint32_t l = 0; l < numLoops; ++l)
    std::sort(sortedIds.begin() + complex.loopBegin[l],
              sortedIds.begin() + complex.loopBegin[l + 1]);
  auto key = [&](uint32_t l) {
    return std::span<const uint32_t>(sortedIds.data() + complex.loopBegin[l],
                                     complex.loopBegin[l + 1] - complex.loopBegin[l]);
  };
  auto sameKey = [&](uint32_t a, uint32_t b) {
    auto ka = key(a), kb = key(b);
    return ka.size() == kb.size() && std::equal(ka.begin(), ka.end(), kb.begin());
  };
  // Sort loops by a hash of their sorted vertex ids; equal faces end up adjacent, ordered by
  // loop index, and full keys are compared only inside runs of equal hash.
  std::vector<std::pair<uint64_t, uint32_t>> keyed(numLoops);
  for (uint32_t l = 0; l < numLoops; ++l) {
    uint64_t h = 0x9e3779b97f4a7c15ull ^ key(l).size();
    for (uint32_t v : key(l)) h = (h ^ v) * 0x100000001b3ull + (h >> 29);
    keyed[l] = {h, l};
  }
  std::sort(keyed.begin(), keyed.end());
  std::vector<uint32_t> representative(numLoops);
  for (size_t i = 0; i < numLoops;) {
    size_t j = i;
    while (j < numLoops && keyed[j].first == keyed[i].first) ++j;
    for (size_t a = i; a < j; ++a) {
      const uint32_t loop = keyed[a].second;
      representative[loop] = loop;
      for (size_t b = i; b < a; ++b)
        if (sameKey(keyed[b].second, loop)) {
          representative[loop] = representative[keyed[b].second];
          break;
        }
    }
    i = j;
  }
  std::vector<uint32_t> faceOfLoop(numLoops);
  numFaces = 0;
  for (uint32_t l = 0; l < numLoops; ++l)
    faceOfLoop[l] = representative[l] == l ? numFaces++ : faceOfLoop[representative[l]];
  return faceOfLoop;
}

// Appends v to row unless already present (rows are short: a cell's vertices or edges).
void appendUnique(std::vector<uint32_t>& values, uint32_t rowBegin, uint32_t v) {
  for (uint32_t i = rowBegin; i < values.size(); ++i)
    if (values[i] == v) return;
  values.push_back(v);
}

}  // namespace

int64_t Topology::findEdge(uint32_t a, uint32_t b) const {
  if (a >= numVertices || b >= numVertices) return -1;
  for (uint32_t e : vertexEdges.row(a)) {
    const auto& ev = edgeVertices[e];
    if ((ev[0] == a && ev[1] == b) || (ev[0] == b && ev[1] == a)) return e;
  }
  return -1;
}

int Topology::faceSlot(uint32_t c, uint32_t f) const {
  auto faces = cellFaces.row(c);
  for (size_t i = 0; i < faces.size(); ++i)
    if (faces[i] == f) return static_cast<int>(i);
  return -1;
}

std::vector<uint32_t> Topology::outwardLoop(uint32_t c, uint32_t slot) const {
  const uint32_t entry = cellFaces.offsets[c] + slot;
  auto loop = faceVertices.row(cellFaces.values[entry]);
  std::vector<uint32_t> out(loop.begin(), loop.end());
  if (cellFaceReversed[entry]) std::reverse(out.begin() + 1, out.end());
  return out;
}

bool Topology::isHexahedron(uint32_t c) const {
  if (cellFaces.rowSize(c) != 6 || cellVertices.rowSize(c) != 8 || cellEdges.rowSize(c) != 12)
    return false;
  for (uint32_t f : cellFaces.row(c))
    if (faceVertices.rowSize(f) != 4) return false;
  return true;
}

Topology buildTopology(const CellComplex& complex) {
  Topology t;
  t.numVertices = complex.numVertices();
  const uint32_t numCells = complex.numCells();
  const uint32_t numLoops = static_cast<uint32_t>(complex.loopBegin.size() - 1);
  auto loopOf = [&](uint32_t l) {
    return std::span<const uint32_t>(complex.loopVertices.data() + complex.loopBegin[l],
                                     complex.loopBegin[l + 1] - complex.loopBegin[l]);
  };
  std::vector<uint32_t> cellOfLoop(numLoops);
  for (uint32_t c = 0; c < numCells; ++c)
    for (uint32_t l = complex.cellFaceBegin[c]; l < complex.cellFaceBegin[c + 1]; ++l)
      cellOfLoop[l] = c;

  // Unique faces, stored in the orientation of their first cell.
  uint32_t numFaces = 0;
  const std::vector<uint32_t> faceOfLoop = groupLoopsIntoFaces(complex, numFaces);
  std::vector<uint32_t> firstLoop(numFaces, UINT32_MAX);
  for (uint32_t l = 0; l < numLoops; ++l)
    if (firstLoop[faceOfLoop[l]] == UINT32_MAX) firstLoop[faceOfLoop[l]] = l;
  t.faceVertices.offsets.reserve(numFaces + 1);
  t.faceVertices.values.reserve(complex.loopVertices.size());
  for (uint32_t f = 0; f < numFaces; ++f) {
    auto loop = loopOf(firstLoop[f]);
    t.faceVertices.values.insert(t.faceVertices.values.end(), loop.begin(), loop.end());
    t.faceVertices.closeRow();
  }

  // Cells: their faces, orientation flags, and the face-to-cell relation.
  t.faceCells.assign(numFaces, {kNoCell, kNoCell});
  t.cellFaceReversed.reserve(numLoops);
  t.cellFaces.values.reserve(numLoops);
  t.cellFaces.offsets.reserve(numCells + 1);
  for (uint32_t c = 0; c < numCells; ++c) {
    for (uint32_t l = complex.cellFaceBegin[c]; l < complex.cellFaceBegin[c + 1]; ++l) {
      const uint32_t f = faceOfLoop[l];
      const uint32_t slot = l - complex.cellFaceBegin[c];
      auto loop = loopOf(l);
      bool reversed = false;
      if (l == firstLoop[f]) {
        t.faceCells[f][0] = static_cast<int32_t>(c);
      } else {
        const LoopRelation relation = relateLoops(t.faceVertices.row(f), loop);
        reversed = relation == LoopRelation::Reversed;
        if (t.faceCells[f][1] != kNoCell) {
          t.problems.push_back({TopologyProblem::Kind::FaceSharedByMoreThanTwoCells, c, slot,
                                "cell " + std::to_string(c) + ", face " + std::to_string(slot) +
                                    ": the face is shared by more than two cells"});
        } else {
          t.faceCells[f][1] = static_cast<int32_t>(c);
          if (relation != LoopRelation::Reversed)
            t.problems.push_back(
                {TopologyProblem::Kind::InconsistentFaceOrientation, c, slot,
                 "cell " + std::to_string(c) + ", face " + std::to_string(slot) + ": cell " +
                     std::to_string(cellOfLoop[firstLoop[f]]) +
                     " sees the shared face with the same orientation (faces must wind "
                     "counter-clockwise seen from outside each cell)"});
        }
      }
      t.cellFaces.values.push_back(f);
      t.cellFaceReversed.push_back(reversed ? 1 : 0);
    }
    t.cellFaces.closeRow();
  }

  // Degenerate faces: fewer than three vertices or a repeated vertex.
  for (uint32_t f = 0; f < numFaces; ++f) {
    std::vector<uint32_t> ids(t.faceVertices.row(f).begin(), t.faceVertices.row(f).end());
    std::sort(ids.begin(), ids.end());
    if (ids.size() < 3 || std::adjacent_find(ids.begin(), ids.end()) != ids.end()) {
      const uint32_t l = firstLoop[f];
      const uint32_t c = cellOfLoop[l];
      const uint32_t slot = l - complex.cellFaceBegin[c];
      t.problems.push_back({TopologyProblem::Kind::DegenerateFace, c, slot,
                            "cell " + std::to_string(c) + ", face " + std::to_string(slot) +
                                ": the face has fewer than three distinct vertices"});
    }
  }

  // Edges from the unique faces: sort (edge key, face-edge slot) pairs and number the runs.
  t.faceEdges.offsets = t.faceVertices.offsets;
  t.faceEdges.values.assign(t.faceVertices.values.size(), 0);
  std::vector<std::pair<uint64_t, uint32_t>> slots;
  slots.reserve(t.faceVertices.values.size());
  for (uint32_t f = 0; f < numFaces; ++f) {
    auto loop = t.faceVertices.row(f);
    const uint32_t begin = t.faceVertices.offsets[f];
    for (size_t i = 0; i < loop.size(); ++i)
      slots.push_back({edgeKey(loop[i], loop[(i + 1) % loop.size()]), begin + uint32_t(i)});
  }
  std::sort(slots.begin(), slots.end());
  for (size_t i = 0; i < slots.size(); ++i) {
    if (i == 0 || slots[i].first != slots[i - 1].first) {
      // A degenerate a == b "edge" becomes an edge too; validation rejects such meshes.
      t.edgeVertices.push_back({uint32_t(slots[i].first >> 32), uint32_t(slots[i].first)});
    }
    t.faceEdges.values[slots[i].second] = uint32_t(t.edgeVertices.size() - 1);
  }

  // Distinct vertices and edges of each cell.
  t.cellVertices.values.reserve(size_t(numCells) * 8);
  t.cellEdges.values.reserve(size_t(numCells) * 12);
  t.cellVertices.offsets.reserve(numCells + 1);
  t.cellEdges.offsets.reserve(numCells + 1);
  for (uint32_t c = 0; c < numCells; ++c) {
    const uint32_t vBegin = static_cast<uint32_t>(t.cellVertices.values.size());
    const uint32_t eBegin = static_cast<uint32_t>(t.cellEdges.values.size());
    for (uint32_t f : t.cellFaces.row(c)) {
      for (uint32_t v : t.faceVertices.row(f)) appendUnique(t.cellVertices.values, vBegin, v);
      for (uint32_t e : t.faceEdges.row(f)) appendUnique(t.cellEdges.values, eBegin, e);
    }
    t.cellVertices.closeRow();
    t.cellEdges.closeRow();
  }

  // Vertex incidences.
  CompressedRows<uint32_t> edgeRows;
  for (const auto& ev : t.edgeVertices) {
    edgeRows.values.push_back(ev[0]);
    edgeRows.values.push_back(ev[1]);
    edgeRows.closeRow();
  }
  t.vertexEdges = invertIncidence(edgeRows, t.numVertices);
  t.vertexFaces = invertIncidence(t.faceVertices, t.numVertices);
  t.vertexCells = invertIncidence(t.cellVertices, t.numVertices);

  // Boundary classification.
  t.faceIsBoundary.assign(numFaces, 0);
  t.edgeIsBoundary.assign(t.numEdges(), 0);
  t.vertexIsBoundary.assign(t.numVertices, 0);
  for (uint32_t f = 0; f < numFaces; ++f) {
    if (t.faceCells[f][1] != kNoCell) continue;
    t.faceIsBoundary[f] = 1;
    for (uint32_t e : t.faceEdges.row(f)) t.edgeIsBoundary[e] = 1;
    for (uint32_t v : t.faceVertices.row(f)) t.vertexIsBoundary[v] = 1;
  }

  // Faces and cells around each edge, in cyclic order (walking face -> cell -> face).
  const CompressedRows<uint32_t> facesOfEdge = invertIncidence(t.faceEdges, t.numEdges());
  auto otherFaceOfCellAtEdge = [&](uint32_t c, uint32_t e, uint32_t notFace) -> int64_t {
    for (uint32_t f : t.cellFaces.row(c)) {
      if (f == notFace) continue;
      for (uint32_t fe : t.faceEdges.row(f))
        if (fe == e) return f;
    }
    return -1;
  };
  std::vector<uint32_t> ringFaces, ringCells;
  t.edgeFaces.values.reserve(t.faceEdges.values.size());
  t.edgeCells.values.reserve(t.faceEdges.values.size());
  t.edgeFaces.offsets.reserve(t.numEdges() + 1);
  t.edgeCells.offsets.reserve(t.numEdges() + 1);
  for (uint32_t e = 0; e < t.numEdges(); ++e) {
    auto faces = facesOfEdge.row(e);
    ringFaces.clear();
    ringCells.clear();
    uint32_t start = faces.empty() ? 0 : faces[0];
    for (uint32_t f : faces)
      if (t.faceIsBoundary[f]) {
        start = f;
        break;
      }
    if (!faces.empty()) {
      ringFaces.push_back(start);
      int32_t previousCell = kNoCell;
      uint32_t current = start;
      for (size_t guard = 0; guard <= faces.size(); ++guard) {
        const auto& fc = t.faceCells[current];
        const int32_t cell = fc[0] != previousCell ? fc[0] : fc[1];
        if (cell == kNoCell) break;
        ringCells.push_back(static_cast<uint32_t>(cell));
        const int64_t next = otherFaceOfCellAtEdge(static_cast<uint32_t>(cell), e, current);
        if (next < 0 || uint32_t(next) == start) break;
        if (std::find(ringFaces.begin(), ringFaces.end(), uint32_t(next)) != ringFaces.end()) break;
        ringFaces.push_back(static_cast<uint32_t>(next));
        previousCell = cell;
        current = static_cast<uint32_t>(next);
      }
      // Non-manifold configurations leave faces off the walk; keep them so nothing is lost.
      for (uint32_t f : faces)
        if (std::find(ringFaces.begin(), ringFaces.end(), f) == ringFaces.end()) {
          ringFaces.push_back(f);
          for (int32_t c : t.faceCells[f])
            if (c != kNoCell &&
                std::find(ringCells.begin(), ringCells.end(), uint32_t(c)) == ringCells.end())
              ringCells.push_back(static_cast<uint32_t>(c));
        }
    }
    t.edgeFaces.values.insert(t.edgeFaces.values.end(), ringFaces.begin(), ringFaces.end());
    t.edgeFaces.closeRow();
    t.edgeCells.values.insert(t.edgeCells.values.end(), ringCells.begin(), ringCells.end());
    t.edgeCells.closeRow();
  }

  // Sharp-feature tags.
  t.edgeIsCrease.assign(t.numEdges(), 0);
  t.vertexIsCorner.assign(t.numVertices, 0);
  for (const auto& crease : complex.creases) {
    const int64_t e = t.findEdge(crease[0], crease[1]);
    if (e >= 0) t.edgeIsCrease[size_t(e)] = 1;
  }
  for (uint32_t v : complex.corners)
    if (v < t.numVertices) t.vertexIsCorner[v] = 1;
  return t;
}

}  // namespace sculpt
