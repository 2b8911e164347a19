#include "subdiv/refinement_cost.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <vector>

#include "util/available_memory.h"

namespace sculpt {
namespace {

// A stencil entry (column id and weight) and a row offset, as StencilTable stores them.
constexpr double kEntryBytes = 12.0;
constexpr double kRowBytes = 4.0;
// Entries per row of one level's stencils S_k on hexahedra (measured: 15.6 on block10).
constexpr double kLevelEntriesPerRow = 16.0;
// Entries per row of the composed A = S_K ... S_1 on hexahedra: the support of a level-K point
// grows towards the 4x4x4 control points of a tricubic B-spline (measured on block10: 28.5 at
// level 2, 40 at level 3).
double composedEntriesPerRow(int level) { return level <= 2 ? 28.5 : level == 3 ? 40.0 : 50.0; }
// Above these sizes a face or cell is wide: its quadratic term is counted on its own.
constexpr uint32_t kPlainFaceVertices = 4;
constexpr uint32_t kPlainCellVertices = 8;
// Entries of A per squared vertex count of a wide face or cell from level 2 on, times 8 per
// further level (measured on n-gon prisms, n = 100 to 600: 40.8 n^2 at level 2, 318 n^2 at
// level 3, with two n-gon faces and a cell of 2n vertices).
constexpr double kWideFaceEntries = 12.0;
constexpr double kWideCellEntries = 3.0;

// The sizes that the MJ rules need to count the next level.
struct Counts {
  double vertices = 0, edges = 0, faces = 0, cells = 0;
  double faceCorners = 0;  // sum of face sizes
  double cellFaces = 0;    // sum over cells of their face counts
  double cellEdges = 0;    // sum over cells of their edge counts
  double cellCorners = 0;  // sum over cells of their vertex counts
  // From level 1 on, the cells by the number k of faces at the corner they came from: a corner
  // of k faces gives a cell of 2k quads around its vertex point and its cell point (k = 3: a
  // hexahedron; k = 4: the cell at a pyramid's apex), which gives two such cells again.
  std::map<uint32_t, double> byValence;
};

Counts controlCounts(const Topology& t) {
  Counts c;
  c.vertices = t.numVertices;
  c.edges = t.numEdges();
  c.faces = t.numFaces();
  c.cells = t.numCells();
  c.faceCorners = double(t.faceVertices.values.size());
  c.cellFaces = double(t.cellFaces.values.size());
  c.cellEdges = double(t.cellEdges.values.size());
  c.cellCorners = double(t.cellVertices.values.size());
  return c;
}

// How many corners of the control cells have k faces, for every k.
std::map<uint32_t, double> cornerValences(const Topology& t) {
  std::map<uint32_t, double> valences;
  std::vector<uint32_t> faces(t.numVertices, 0);
  for (uint32_t c = 0; c < t.numCells(); ++c) {
    for (uint32_t f : t.cellFaces.row(c))
      for (uint32_t v : t.faceVertices.row(f)) ++faces[v];
    for (uint32_t v : t.cellVertices.row(c)) {
      valences[faces[v]] += 1;
      faces[v] = 0;
    }
  }
  return valences;
}

// One vertex per vertex, edge, face and cell; two edges per edge, one per face corner (face
// point to edge point) and one per cell face (cell point to face point); one quad per face
// corner and one per cell edge; one cell per cell corner. `control` is given for the first
// step, whose cells come from the control cells' corners.
Counts refined(const Counts& c, const Topology* control) {
  Counts n;
  n.vertices = c.vertices + c.edges + c.faces + c.cells;
  n.edges = 2 * c.edges + c.faceCorners + c.cellFaces;
  n.faces = c.faceCorners + c.cellEdges;
  n.faceCorners = 4 * n.faces;
  if (control) {
    n.byValence = cornerValences(*control);
  } else {
    for (const auto& [k, cells] : c.byValence) {
      n.byValence[3] += (k == 3 ? 8.0 : 2.0 * k) * cells;
      if (k != 3) n.byValence[k] += 2 * cells;
    }
  }
  for (const auto& [k, cells] : n.byValence) {
    n.cells += cells;
    n.cellCorners += (2.0 * k + 2) * cells;
    n.cellFaces += 2.0 * k * cells;
    n.cellEdges += 4.0 * k * cells;
  }
  return n;
}

// The arrays of one level's CellComplex and Topology.
double storageBytes(const Counts& c) {
  const double complex = 4 * c.cells + 4 * c.cellFaces + 4 * 2 * c.faceCorners + 24 * c.vertices;
  const double faces = 2 * 4 * (c.faceCorners + c.faces) + 8 * c.faces + c.faces;
  const double edges = 8 * c.edges + 2 * 4 * (c.faceCorners + c.edges) + 2 * c.edges;
  const double cells = 5 * c.cellFaces + 4 * (c.cellCorners + c.cellEdges + 3 * c.cells);
  const double vertices =
      4 * (2 * c.edges + c.faceCorners + c.cellCorners + 3 * c.vertices) + 2 * c.vertices;
  return complex + faces + edges + cells + vertices;
}

// Entries that wide elements add, per control cell: at level 1 (the rows that read a wide
// face's or cell's centroid, each with all its vertices) and, per 8^(K-2), from level 2 on.
struct WideEntries {
  std::vector<double> levelOne, perLevel;
  double levelOneTotal = 0, perLevelTotal = 0;
};

WideEntries wideEntries(const Topology& t) {
  WideEntries wide;
  wide.levelOne.assign(t.numCells(), 0.0);
  wide.perLevel.assign(t.numCells(), 0.0);
  for (uint32_t f = 0; f < t.numFaces(); ++f) {
    const double k = t.faceVertices.rowSize(f);
    if (k <= kPlainFaceVertices) continue;
    // Its face point, the edge points of its edges and the vertex points of its vertices.
    const uint32_t owner = uint32_t(t.faceCells[f][0]);
    wide.levelOne[owner] += k * (1 + 2 * k);
    wide.perLevel[owner] += kWideFaceEntries * k * k;
  }
  for (uint32_t c = 0; c < t.numCells(); ++c) {
    const double m = t.cellVertices.rowSize(c);
    if (m <= kPlainCellVertices) continue;
    // Its cell point and the points of its interior faces, edges and vertices.
    double rows = 1;
    for (uint32_t f : t.cellFaces.row(c)) rows += !t.faceIsBoundary[f];
    for (uint32_t e : t.cellEdges.row(c)) rows += !t.edgeIsBoundary[e];
    for (uint32_t v : t.cellVertices.row(c)) rows += !t.vertexIsBoundary[v];
    wide.levelOne[c] += m * rows;
    wide.perLevel[c] += kWideCellEntries * m * m;
  }
  for (uint32_t c = 0; c < t.numCells(); ++c) {
    wide.levelOneTotal += wide.levelOne[c];
    wide.perLevelTotal += wide.perLevel[c];
  }
  return wide;
}

uint64_t saturated(double value) {
  constexpr double kMax = double(std::numeric_limits<uint64_t>::max());
  return value >= kMax ? std::numeric_limits<uint64_t>::max() : uint64_t(std::max(0.0, value));
}

}  // namespace

RefinementCost estimateRefinementCost(const Topology& control, int levels, LevelWork work) {
  RefinementCost cost;
  cost.levels = levels;
  Counts counts = controlCounts(control);
  double storage = storageBytes(counts);
  if (levels <= 0) {
    // Trilinear elements on the control mesh: A is the identity.
    cost.cells = saturated(counts.cells);
    cost.vertices = saturated(counts.vertices);
    cost.stencilEntries = cost.vertices;
    cost.bytes = saturated(storage + work.bytesPerCell * counts.cells +
                           work.bytesPerStencilEntry * counts.vertices);
    return cost;
  }
  const WideEntries wide = wideEntries(control);
  double levelStencils = 0, previous = 0, composed = 0;
  for (int k = 1; k <= levels; ++k) {
    counts = refined(counts, k == 1 ? &control : nullptr);
    storage += storageBytes(counts);
    previous = composed;
    if (k == 1) {
      composed = kLevelEntriesPerRow * counts.vertices + wide.levelOneTotal;
      levelStencils += kEntryBytes * composed;
    } else {
      composed =
          composedEntriesPerRow(k) * counts.vertices + wide.perLevelTotal * std::pow(8.0, k - 2);
      levelStencils += kEntryBytes * kLevelEntriesPerRow * counts.vertices;
    }
    levelStencils += kRowBytes * counts.vertices;
  }
  // Composing keeps A_(K-1) while the workers' blocks and the joined A_K both exist; the work
  // comes after, on A_K alone.
  const double kept = storage + levelStencils + kEntryBytes * composed;
  const double composing = kept + kEntryBytes * (previous + composed);
  const double working =
      kept + work.bytesPerCell * counts.cells + work.bytesPerStencilEntry * composed;
  cost.cells = saturated(counts.cells);
  cost.vertices = saturated(counts.vertices);
  cost.stencilEntries = saturated(composed);
  cost.bytes = saturated(std::max(composing, working));

  double widest = 0;
  for (uint32_t c = 0; c < control.numCells(); ++c) {
    const double entries =
        levels == 1 ? wide.levelOne[c] : wide.perLevel[c] * std::pow(8.0, levels - 2);
    if (entries > widest) {
      widest = entries;
      cost.widestCell = c;
    }
  }
  cost.widestCellFaces = widest > 0 ? control.cellFaces.rowSize(cost.widestCell) : 0;
  cost.widestCellVertices = widest > 0 ? control.cellVertices.rowSize(cost.widestCell) : 0;
  cost.widestCellBytes = saturated(widest * (2.0 * kEntryBytes + work.bytesPerStencilEntry));
  return cost;
}

std::string refinementRefusal(const RefinementCost& cost, const std::string& name,
                              uint64_t availableBytes) {
  const std::string level = std::to_string(cost.levels);
  if (cost.cells > kMaxRefinedCells)
    return name + ": level " + level + " would have about " + std::to_string(cost.cells) +
           " cells (more than " + std::to_string(kMaxRefinedCells) + "); use fewer levels";
  if (cost.bytes <= availableBytes) return {};
  std::string sentence = "level " + level + " of " + name + " needs about " +
                         memoryText(cost.bytes) + " (" + groupedNumber(cost.cells) + " cells";
  // Name the cell when it alone is a good part of the need: fewer levels help less than
  // splitting it.
  std::string advice = "use fewer levels";
  if (cost.widestCellBytes * 4 >= cost.bytes) {
    const std::string cell = "cell " + std::to_string(cost.widestCell);
    sentence += "; " + cell + " (" + std::to_string(cost.widestCellFaces) + " faces, " +
                std::to_string(cost.widestCellVertices) + " vertices) alone takes about " +
                memoryText(cost.widestCellBytes) + ", as every level-" + level +
                " point near it depends on all its vertices";
    advice += " or split " + cell;
  }
  return sentence + "); " + availableMemoryPhrase(availableBytes) + "; " + advice;
}

std::string refinementRefusal(const Topology& control, int levels, const std::string& name,
                              LevelWork work) {
  return refinementRefusal(estimateRefinementCost(control, levels, work), name,
                           availableMemoryBytes());
}

}  // namespace sculpt
