#include "subdiv/mj_refiner.h"

#include <algorithm>
#include <string>

#include "subdiv/stencil_builder.h"

namespace sculpt {
namespace {

// Accumulates one stencil row over old vertices with a dense scratch array (one per worker).
class RowBuilder {
 public:
  explicit RowBuilder(const Topology& t)
      : t_(t), weights_(t.numVertices, 0.0), touched_(t.numVertices, 0) {}

  void add(uint32_t v, double w) {
    if (!touched_[v]) {
      touched_[v] = 1;
      columns_.push_back(v);
    }
    weights_[v] += w;
  }
  void addAverage(std::span<const uint32_t> vertices, double w) {
    const double each = w / double(vertices.size());
    for (uint32_t v : vertices) add(v, each);
  }
  void addCellCentroid(uint32_t c, double w) { addAverage(t_.cellVertices.row(c), w); }
  void addFaceCentroid(uint32_t f, double w) { addAverage(t_.faceVertices.row(f), w); }
  void addMidpoint(uint32_t e, double w) {
    add(t_.edgeVertices[e][0], 0.5 * w);
    add(t_.edgeVertices[e][1], 0.5 * w);
  }
  /// Moves the row (sorted by column) to the output arrays and resets the scratch.
  void flush(std::vector<uint32_t>& indices, std::vector<double>& weights) {
    std::sort(columns_.begin(), columns_.end());
    for (uint32_t v : columns_) {
      indices.push_back(v);
      weights.push_back(weights_[v]);
      weights_[v] = 0.0;
      touched_[v] = 0;
    }
    columns_.clear();
  }

 private:
  const Topology& t_;
  std::vector<double> weights_;
  std::vector<uint8_t> touched_;
  std::vector<uint32_t> columns_;
};

// Vertex point: §2.4 inside, §3.1/§3.2 (Catmull–Clark with sharp features) on the boundary.
void vertexPointRow(const Topology& t, uint32_t v, RowBuilder& row) {
  if (!t.vertexIsBoundary[v]) {
    auto cells = t.vertexCells.row(v);
    auto faces = t.vertexFaces.row(v);
    auto edges = t.vertexEdges.row(v);
    for (uint32_t c : cells) row.addCellCentroid(c, 1.0 / 8.0 / double(cells.size()));
    for (uint32_t f : faces) row.addFaceCentroid(f, 3.0 / 8.0 / double(faces.size()));
    for (uint32_t e : edges) row.addMidpoint(e, 3.0 / 8.0 / double(edges.size()));
    row.add(v, 1.0 / 8.0);
    return;
  }
  uint32_t creaseEnds[2] = {0, 0};
  uint32_t creases = 0;
  for (uint32_t e : t.vertexEdges.row(v))
    if (t.edgeIsCrease[e]) {
      const auto& ev = t.edgeVertices[e];
      if (creases < 2) creaseEnds[creases] = ev[0] == v ? ev[1] : ev[0];
      ++creases;
    }
  if (t.vertexIsCorner[v] || creases >= 3) {
    row.add(v, 1.0);
  } else if (creases == 2) {
    row.add(creaseEnds[0], 1.0 / 8.0);
    row.add(creaseEnds[1], 1.0 / 8.0);
    row.add(v, 6.0 / 8.0);
  } else {
    // Smooth (or dart) boundary vertex: (Q + 2R + (k-3) P) / k over boundary data only.
    uint32_t k = 0, edgeCount = 0;
    for (uint32_t f : t.vertexFaces.row(v)) k += t.faceIsBoundary[f];
    for (uint32_t e : t.vertexEdges.row(v)) edgeCount += t.edgeIsBoundary[e];
    const double kd = double(k);
    for (uint32_t f : t.vertexFaces.row(v))
      if (t.faceIsBoundary[f]) row.addFaceCentroid(f, 1.0 / (kd * kd));
    for (uint32_t e : t.vertexEdges.row(v))
      if (t.edgeIsBoundary[e]) row.addMidpoint(e, 2.0 / (kd * double(edgeCount)));
    row.add(v, (kd - 3.0) / kd);
  }
}

// Edge point: §2.3 inside, crease midpoint or Catmull–Clark edge rule on the boundary.
void edgePointRow(const Topology& t, uint32_t e, RowBuilder& row) {
  const auto& ev = t.edgeVertices[e];
  auto faces = t.edgeFaces.row(e);
  if (t.edgeIsCrease[e]) {
    row.addMidpoint(e, 1.0);
  } else if (t.edgeIsBoundary[e]) {
    uint32_t boundaryFaces = 0;
    for (uint32_t f : faces) boundaryFaces += t.faceIsBoundary[f];
    row.add(ev[0], 0.25);
    row.add(ev[1], 0.25);
    for (uint32_t f : faces)
      if (t.faceIsBoundary[f]) row.addFaceCentroid(f, 0.5 / double(boundaryFaces));
  } else {
    const double n = double(faces.size());
    auto cells = t.edgeCells.row(e);
    for (uint32_t c : cells) row.addCellCentroid(c, 1.0 / n / double(cells.size()));
    for (uint32_t f : faces) row.addFaceCentroid(f, 2.0 / (n * n));
    row.addMidpoint(e, (n - 3.0) / n);
  }
}

// Face point: centroid on the boundary, (C0 + 2A + C1)/4 inside.
void facePointRow(const Topology& t, uint32_t f, RowBuilder& row) {
  if (t.faceIsBoundary[f]) {
    row.addFaceCentroid(f, 1.0);
    return;
  }
  row.addCellCentroid(uint32_t(t.faceCells[f][0]), 0.25);
  row.addFaceCentroid(f, 0.5);
  row.addCellCentroid(uint32_t(t.faceCells[f][1]), 0.25);
}

StencilTable buildStencils(const Topology& t) {
  const uint32_t V = t.numVertices, E = t.numEdges(), F = t.numFaces(), C = t.numCells();
  return buildStencilTableInParallel(V + E + F + C, V, 20, [&t, V, E, F] {
    return [&t, V, E, F, row = RowBuilder(t)](uint32_t r, std::vector<uint32_t>& indices,
                                             std::vector<double>& weights) mutable {
      if (r < V) vertexPointRow(t, r, row);
      else if (r < V + E) edgePointRow(t, r - V, row);
      else if (r < V + E + F) facePointRow(t, r - V - E, row);
      else row.addCellCentroid(r - V - E - F, 1.0);
      row.flush(indices, weights);
    };
  });
}

// Child cells (§4.1): one per (cell, corner), k quads around the vertex point and k around the
// cell point, oriented by the recipe of docs/design/mj-subdivision.md §4.1.
CellComplex buildChildCells(const Topology& t) {
  const uint32_t V = t.numVertices, E = t.numEdges(), F = t.numFaces();
  auto vertexPoint = [](uint32_t v) { return v; };
  auto edgePoint = [&](uint32_t e) { return V + e; };
  auto facePoint = [&](uint32_t f) { return V + E + f; };
  auto cellPoint = [&](uint32_t c) { return V + E + F + c; };

  CellComplex child;
  // Each corner of k faces gives a cell of 2k quads: 8 loop vertices per (cell, face, corner).
  size_t cornerFaces = 0;
  for (uint32_t c = 0; c < t.numCells(); ++c)
    for (uint32_t f : t.cellFaces.row(c)) cornerFaces += t.faceVertices.rowSize(f);
  child.cellFaceBegin.reserve(t.cellVertices.values.size() + 1);
  child.loopBegin.reserve(2 * cornerFaces + 1);
  child.loopVertices.reserve(8 * cornerFaces);
  std::vector<std::vector<uint32_t>> loops, edgeAfter;  // outward loops of the cell's faces
  struct Corner {
    uint32_t face, edgeOut, edgeIn;
  };
  std::vector<Corner> corners;
  for (uint32_t c = 0; c < t.numCells(); ++c) {
    const uint32_t numFaces = t.cellFaces.rowSize(c);
    loops.resize(numFaces);
    edgeAfter.resize(numFaces);
    for (uint32_t j = 0; j < numFaces; ++j) {
      const uint32_t entry = t.cellFaces.offsets[c] + j;
      const uint32_t f = t.cellFaces.values[entry];
      auto stored = t.faceVertices.row(f);
      auto storedEdges = t.faceEdges.row(f);
      const size_t m = stored.size();
      loops[j].resize(m);
      edgeAfter[j].resize(m);
      for (size_t i = 0; i < m; ++i) {
        if (t.cellFaceReversed[entry]) {
          loops[j][i] = stored[(m - i) % m];
          edgeAfter[j][i] = storedEdges[(2 * m - i - 1) % m];
        } else {
          loops[j][i] = stored[i];
          edgeAfter[j][i] = storedEdges[i];
        }
      }
    }
    for (uint32_t v : t.cellVertices.row(c)) {
      // The corner's faces with the cell edges leaving (v -> b) and entering (a -> v) v.
      corners.clear();
      for (uint32_t j = 0; j < numFaces; ++j) {
        const auto& loop = loops[j];
        const size_t m = loop.size();
        for (size_t i = 0; i < m; ++i)
          if (loop[i] == v) {
            corners.push_back({t.cellFaces.values[t.cellFaces.offsets[c] + j], edgeAfter[j][i],
                               edgeAfter[j][(i + m - 1) % m]});
            break;
          }
      }
      for (const Corner& k : corners) {
        const uint32_t quad[4] = {vertexPoint(v), edgePoint(k.edgeOut), facePoint(k.face),
                                  edgePoint(k.edgeIn)};
        child.addLoop(quad);
      }
      for (const Corner& g : corners) {
        // h is the face in which the same edge enters v.
        const Corner* h = nullptr;
        for (const Corner& candidate : corners)
          if (candidate.edgeIn == g.edgeOut) h = &candidate;
        if (!h) continue;  // open cell: validation rejects such input
        const uint32_t quad[4] = {facePoint(g.face), edgePoint(g.edgeOut), facePoint(h->face),
                                  cellPoint(c)};
        child.addLoop(quad);
      }
      child.finishCell();
    }
  }

  // Tags: both halves of a crease are creases; a corner's vertex point stays a corner.
  for (uint32_t e = 0; e < E; ++e)
    if (t.edgeIsCrease[e]) {
      child.creases.push_back({vertexPoint(t.edgeVertices[e][0]), edgePoint(e)});
      child.creases.push_back({edgePoint(e), vertexPoint(t.edgeVertices[e][1])});
    }
  for (uint32_t v = 0; v < V; ++v)
    if (t.vertexIsCorner[v]) child.corners.push_back(vertexPoint(v));
  return child;
}

}  // namespace

RefinementStep refineOnce(const Topology& parent) {
  RefinementStep step;
  step.stencils = buildStencils(parent);
  step.child = buildChildCells(parent);
  step.child.positions.resize(step.stencils.numRows(), 3);
  return step;
}

std::optional<Subdivision> subdivide(const CellComplex& control, int levels,
                                     ProgressReporter* progress) {
  ProgressReporter silent;
  ProgressReporter& reporter = progress ? *progress : silent;
  Subdivision result;
  result.levels.push_back(control);
  result.topologies.push_back(buildTopology(control));
  std::vector<StencilTable> perLevel;
  // Level k costs about 8x level k-1: weight the progress accordingly.
  double total = 0.0;
  for (int k = 1; k <= levels; ++k) total += double(uint64_t(1) << (3 * k));
  double done = 0.0;
  for (int k = 1; k <= levels; ++k) {
    const std::string stage = "refining level " + std::to_string(k);
    if (!reporter.report(done / total, stage)) return std::nullopt;
    RefinementStep step = refineOnce(result.topologies.back());
    step.stencils.apply(result.levels.back().positions, step.child.positions);
    if (!reporter.report((done + 0.5 * double(uint64_t(1) << (3 * k))) / total, stage))
      return std::nullopt;
    result.topologies.push_back(buildTopology(step.child));
    result.levels.push_back(std::move(step.child));
    perLevel.push_back(std::move(step.stencils));
    done += double(uint64_t(1) << (3 * k));
  }
  if (!reporter.report(1.0, "composing stencils")) return std::nullopt;
  if (perLevel.empty()) {
    result.stencils = StencilTable::identity(control.numVertices());
  } else {
    result.stencils = perLevel.front();
    for (size_t i = 1; i < perLevel.size(); ++i)
      result.stencils = StencilTable::compose(perLevel[i], result.stencils);
  }
  result.chain = StencilChain(std::move(perLevel));
  reporter.report(1.0, "done");
  return result;
}

}  // namespace sculpt
