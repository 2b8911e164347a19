#include "embed/embedded_deformer.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "embed/cell_interpolant.h"
#include "util/parallel_for.h"

namespace sculpt {
namespace {

/// The six vertex pairs of a tetrahedron, in the order of its pair coefficients.
constexpr int kTetPairs[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};

/// Fewer points than this are evaluated on the calling thread.
constexpr uint32_t kParallelPoints = 16384;

}  // namespace

double meanEdgeLength(const VolumeMesh& mesh) {
  static constexpr int kTetEdges[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
  static constexpr int kHexEdges[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                           {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
  std::vector<uint64_t> edges;
  edges.reserve(mesh.cells.values.size() * 2);
  for (uint32_t c = 0; c < mesh.numCells(); ++c) {
    const auto nodes = mesh.cells.row(c);
    const bool tet = nodes.size() == 4;
    const int count = tet ? 6 : 12;
    for (int e = 0; e < count; ++e) {
      const uint32_t a = nodes[tet ? kTetEdges[e][0] : kHexEdges[e][0]];
      const uint32_t b = nodes[tet ? kTetEdges[e][1] : kHexEdges[e][1]];
      edges.push_back((static_cast<uint64_t>(std::min(a, b)) << 32) | std::max(a, b));
    }
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  if (edges.empty()) return 0.0;
  double sum = 0.0;
  for (uint64_t e : edges)
    sum += (mesh.positions.row(static_cast<uint32_t>(e >> 32)) -
            mesh.positions.row(static_cast<uint32_t>(e & 0xffffffffu)))
               .norm();
  return sum / static_cast<double>(edges.size());
}

EmbeddedDeformer::EmbeddedDeformer(VolumeMesh rest, const Points& points,
                                   const DeformerSettings& settings, ProgressReporter* progress)
    : EmbeddedDeformer(rest, points, embedPoints(rest, points, progress), settings) {}

EmbeddedDeformer::EmbeddedDeformer(VolumeMesh rest, const Points& points, Embedding embedding,
                                   const DeformerSettings& settings)
    : rest_(std::move(rest)), embedding_(std::move(embedding)) {
  if (embedding_.numPoints() != points.rows())
    throw std::invalid_argument("the embedding does not match the points");
  gradientScheme_ = settings.gradients;
  gradientStencil_ = nodeGradientStencil(rest_, settings.gradients, settings.eps);

  // Distinct tetrahedron edges and each cell's slot.
  {
    std::vector<std::pair<uint64_t, uint32_t>> keyed;  // (edge key, tetEdges_ entry)
    cellSlot_.resize(rest_.numCells());
    uint32_t hexCount = 0;
    for (uint32_t c = 0; c < rest_.numCells(); ++c) {
      const auto nodes = rest_.cells.row(c);
      if (nodes.size() != 4) {
        cellSlot_[c] = hexCount++;
        continue;
      }
      cellSlot_[c] = static_cast<uint32_t>(tetEdges_.size());
      for (const auto& pair : kTetPairs) {
        const uint32_t a = nodes[pair[0]], b = nodes[pair[1]];
        keyed.emplace_back((static_cast<uint64_t>(std::min(a, b)) << 32) | std::max(a, b),
                           static_cast<uint32_t>(tetEdges_.size()));
        tetEdges_.push_back(0);
      }
    }
    std::sort(keyed.begin(), keyed.end());
    for (size_t i = 0; i < keyed.size(); ++i) {
      if (i == 0 || keyed[i].first != keyed[i - 1].first)
        edgeNodes_.push_back({static_cast<uint32_t>(keyed[i].first >> 32),
                              static_cast<uint32_t>(keyed[i].first & 0xffffffffu)});
      tetEdges_[keyed[i].second] = static_cast<uint32_t>(edgeNodes_.size() - 1);
    }
    edgeVectors_.reserve(edgeNodes_.size());
    for (const auto& [a, b] : edgeNodes_)
      edgeVectors_.push_back((rest_.positions.row(b) - rest_.positions.row(a)).transpose());
  }

  // Sort points by cell (counting sort keeps input order within a cell).
  const uint32_t numCells = rest_.numCells();
  const uint32_t n = embedding_.numPoints();
  cellPointBegin_.assign(numCells + 1, 0);
  for (uint32_t cell : embedding_.cells) ++cellPointBegin_[cell + 1];
  for (uint32_t c = 0; c < numCells; ++c) cellPointBegin_[c + 1] += cellPointBegin_[c];
  sortedToInput_.resize(n);
  {
    std::vector<uint32_t> cursor(cellPointBegin_.begin(), cellPointBegin_.end() - 1);
    for (uint32_t p = 0; p < n; ++p) sortedToInput_[cursor[embedding_.cells[p]]++] = p;
  }
  {
    std::vector<uint32_t> inputToSorted(n);
    for (uint32_t k = 0; k < n; ++k) inputToSorted[sortedToInput_[k]] = k;
    for (uint32_t p : embedding_.offsetPoints) offsetSorted_.push_back(inputToSorted[p]);
  }
  for (int d = 0; d < 3; ++d) {
    localF_[d].resize(n);
    localD_[d].resize(n);
    restF_[d].resize(n);
    restD_[d].resize(n);
    for (uint32_t k = 0; k < n; ++k) {
      const uint32_t p = sortedToInput_[k];
      localD_[d][k] = embedding_.local(p, d);
      localF_[d][k] = static_cast<float>(localD_[d][k]);
      restD_[d][k] = points(p, d);
      restF_[d][k] = static_cast<float>(restD_[d][k]);
    }
  }
  // Worker ranges: contiguous cells holding about the same number of points.
  const unsigned workers = std::max(1u, workerCount());
  workerCellBegin_.assign(workers + 1, numCells);
  workerCellBegin_[0] = 0;
  uint32_t cell = 0;
  for (unsigned w = 1; w < workers; ++w) {
    const uint64_t target = static_cast<uint64_t>(n) * w / workers;
    while (cell < numCells && cellPointBegin_[cell] < target) ++cell;
    workerCellBegin_[w] = cell;
  }

  attributeRadius_ = settings.attributeRadius > 0.0
                         ? settings.attributeRadius
                         : defaultAttributeRadius(meanEdgeLength(rest_));
  if (settings.buildAttributeWeights) {
    Points sortedPoints(n, 3);
    for (uint32_t k = 0; k < n; ++k) sortedPoints.row(k) = points.row(sortedToInput_[k]);
    attributeWeights_ = attributeTransferWeights(rest_.positions, sortedPoints, attributeRadius_);
  }
}

void EmbeddedDeformer::setFrame(const Points& deformedNodes, InterpolationMethod method) {
  if (deformedNodes.rows() != rest_.positions.rows())
    throw std::invalid_argument("the deformed mesh has " + std::to_string(deformedNodes.rows()) +
                                " nodes but the rest mesh has " +
                                std::to_string(rest_.positions.rows()));
  if (!deformedNodes.allFinite())
    throw std::invalid_argument("the deformed node positions contain NaN or infinity");
  if (method == InterpolationMethod::Attribute && attributeWeights_.numRows() != numPoints())
    throw std::invalid_argument("the attribute method was not prepared (buildAttributeWeights)");
  method_ = method;
  nodes_ = deformedNodes;
  if (method != InterpolationMethod::Linear) {
    applyNodeGradientStencil(gradientStencil_, nodes_, nodeGradients_);
  }
  fillCoefficients(coefficientsF_);
}

template <typename T>
void EmbeddedDeformer::fillCoefficients(Coefficients<T>& coefficients) const {
  const uint32_t numNodes = rest_.numNodes();
  coefficients.nodes.resize(3 * static_cast<size_t>(numNodes));
  const bool attribute = method_ == InterpolationMethod::Attribute;
  for (uint32_t i = 0; i < numNodes; ++i)
    for (int d = 0; d < 3; ++d)
      coefficients.nodes[3 * i + d] =
          static_cast<T>(attribute ? nodes_(i, d) - rest_.positions(i, d) : nodes_(i, d));
  if (attribute || method_ == InterpolationMethod::Linear) return;

  const double alpha = gradientBlend(method_);
  const uint32_t numEdges = static_cast<uint32_t>(edgeNodes_.size());
  coefficients.edges.resize(3 * static_cast<size_t>(numEdges));
  parallelChunks(numEdges, 8192, [&](uint32_t begin, uint32_t end, unsigned) {
    for (uint32_t e = begin; e < end; ++e) {
      const auto [a, b] = edgeNodes_[e];
      const Eigen::Vector3d value =
          alpha * ((nodeGradients_[a] - nodeGradients_[b]) * edgeVectors_[e]);
      for (int d = 0; d < 3; ++d) coefficients.edges[3 * e + d] = static_cast<T>(value[d]);
    }
  });

  const uint32_t numCells = rest_.numCells();
  const uint32_t numHexes = numCells - static_cast<uint32_t>(tetEdges_.size() / 6);
  coefficients.hexes.resize(81 * static_cast<size_t>(numHexes));
  if (numHexes == 0) return;
  const NodeFrame frame{&nodes_, &nodeGradients_};
  parallelChunks(numCells, 1024, [&](uint32_t begin, uint32_t end, unsigned) {
    for (uint32_t c = begin; c < end; ++c) {
      if (rest_.isTetrahedron(c)) continue;
      // The triquadratic interpolant through its 27 nodal values.
      T* k = coefficients.hexes.data() + 81 * static_cast<size_t>(cellSlot_[c]);
      int index = 0;
      for (int iu = 0; iu < 3; ++iu)
        for (int it = 0; it < 3; ++it)
          for (int is = 0; is < 3; ++is, ++index) {
            const Eigen::Vector3d xi(0.5 * is, 0.5 * it, 0.5 * iu);
            const Eigen::Vector3d value = interpolatePosition(rest_, frame, c, xi, alpha);
            for (int d = 0; d < 3; ++d) k[3 * index + d] = static_cast<T>(value[d]);
          }
    }
  });
}

template <typename T>
void EmbeddedDeformer::evaluateRange(uint32_t cellBegin, uint32_t cellEnd,
                                     const Coefficients<T>& coefficients, T* __restrict x,
                                     T* __restrict y, T* __restrict z) const {
  const std::vector<T>* local;
  const std::vector<T>* restPositions;
  if constexpr (std::is_same_v<T, float>) {
    local = localF_;
    restPositions = restF_;
  } else {
    local = localD_;
    restPositions = restD_;
  }
  const T* __restrict l0 = local[0].data();
  const T* __restrict l1 = local[1].data();
  const T* __restrict l2 = local[2].data();

  if (method_ == InterpolationMethod::Attribute) {
    const T* d = coefficients.nodes.data();
    for (uint32_t p = cellPointBegin_[cellBegin]; p < cellPointBegin_[cellEnd]; ++p) {
      T sx = restPositions[0][p], sy = restPositions[1][p], sz = restPositions[2][p];
      for (const NodeWeight& w : attributeWeights_.row(p)) {
        const T weight = static_cast<T>(w.weight);
        sx += weight * d[3 * w.node];
        sy += weight * d[3 * w.node + 1];
        sz += weight * d[3 * w.node + 2];
      }
      x[p] = sx, y[p] = sy, z[p] = sz;
    }
    return;
  }

  const bool quadratic = method_ != InterpolationMethod::Linear;
  for (uint32_t c = cellBegin; c < cellEnd; ++c) {
    const uint32_t begin = cellPointBegin_[c], end = cellPointBegin_[c + 1];
    if (begin == end) continue;
    // Gathered into a local array: the compiler then knows the coefficients do not alias the
    // outputs and keeps them in registers across the point loop.
    T k[81];
    const auto nodes = rest_.cells.row(c);
    const bool tetrahedron = nodes.size() == 4;
    if (!quadratic || tetrahedron)
      for (size_t a = 0; a < nodes.size(); ++a)
        for (int d = 0; d < 3; ++d) k[3 * a + d] = coefficients.nodes[3 * nodes[a] + d];
    if (quadratic && tetrahedron) {
      const uint32_t* edges = tetEdges_.data() + cellSlot_[c];
      for (int e = 0; e < 6; ++e)
        for (int d = 0; d < 3; ++d) k[12 + 3 * e + d] = coefficients.edges[3 * edges[e] + d];
    }
    if (quadratic && !tetrahedron)
      std::copy_n(coefficients.hexes.data() + 81 * static_cast<size_t>(cellSlot_[c]), 81, k);
    if (tetrahedron) {
      if (!quadratic) {
        for (uint32_t p = begin; p < end; ++p) {
          const T b1 = l0[p], b2 = l1[p], b3 = l2[p], b0 = T(1) - b1 - b2 - b3;
          x[p] = b0 * k[0] + b1 * k[3] + b2 * k[6] + b3 * k[9];
          y[p] = b0 * k[1] + b1 * k[4] + b2 * k[7] + b3 * k[10];
          z[p] = b0 * k[2] + b1 * k[5] + b2 * k[8] + b3 * k[11];
        }
      } else {
        for (uint32_t p = begin; p < end; ++p) {
          const T b1 = l0[p], b2 = l1[p], b3 = l2[p], b0 = T(1) - b1 - b2 - b3;
          const T q01 = b0 * b1, q02 = b0 * b2, q03 = b0 * b3;
          const T q12 = b1 * b2, q13 = b1 * b3, q23 = b2 * b3;
          x[p] = b0 * k[0] + b1 * k[3] + b2 * k[6] + b3 * k[9] + q01 * k[12] + q02 * k[15] +
                 q03 * k[18] + q12 * k[21] + q13 * k[24] + q23 * k[27];
          y[p] = b0 * k[1] + b1 * k[4] + b2 * k[7] + b3 * k[10] + q01 * k[13] + q02 * k[16] +
                 q03 * k[19] + q12 * k[22] + q13 * k[25] + q23 * k[28];
          z[p] = b0 * k[2] + b1 * k[5] + b2 * k[8] + b3 * k[11] + q01 * k[14] + q02 * k[17] +
                 q03 * k[20] + q12 * k[23] + q13 * k[26] + q23 * k[29];
        }
      }
      continue;
    }
    if (!quadratic) {
      for (uint32_t p = begin; p < end; ++p) {
        const T s = l0[p], t = l1[p], u = l2[p];
        const T w[8] = {(1 - s) * (1 - t) * (1 - u), s * (1 - t) * (1 - u), s * t * (1 - u),
                        (1 - s) * t * (1 - u),       (1 - s) * (1 - t) * u, s * (1 - t) * u,
                        s * t * u,                   (1 - s) * t * u};
        T sx = 0, sy = 0, sz = 0;
        for (int a = 0; a < 8; ++a) {
          sx += w[a] * k[3 * a];
          sy += w[a] * k[3 * a + 1];
          sz += w[a] * k[3 * a + 2];
        }
        x[p] = sx, y[p] = sy, z[p] = sz;
      }
      continue;
    }
    for (uint32_t p = begin; p < end; ++p) {
      // Quadratic Lagrange basis on {0, 1/2, 1} per direction.
      T L[3][3];
      const T xi[3] = {l0[p], l1[p], l2[p]};
      for (int d = 0; d < 3; ++d) {
        const T v = xi[d];
        L[d][0] = (1 - v) * (1 - 2 * v);
        L[d][1] = 4 * v * (1 - v);
        L[d][2] = v * (2 * v - 1);
      }
      T sx = 0, sy = 0, sz = 0;
      int index = 0;
      for (int iu = 0; iu < 3; ++iu)
        for (int it = 0; it < 3; ++it) {
          const T wtu = L[1][it] * L[2][iu];
          for (int is = 0; is < 3; ++is, ++index) {
            const T w = L[0][is] * wtu;
            sx += w * k[3 * index];
            sy += w * k[3 * index + 1];
            sz += w * k[3 * index + 2];
          }
        }
      x[p] = sx, y[p] = sy, z[p] = sz;
    }
  }
}

template <typename T>
void EmbeddedDeformer::evaluateAll(const Coefficients<T>& coefficients, T* x, T* y, T* z) const {
  const uint32_t numCells = rest_.numCells();
  if (numPoints() < kParallelPoints) {
    evaluateRange(0, numCells, coefficients, x, y, z);
    return;
  }
  const uint32_t chunks = static_cast<uint32_t>(workerCellBegin_.size() - 1);
  parallelChunks(chunks, 1, [&](uint32_t begin, uint32_t end, unsigned) {
    for (uint32_t chunk = begin; chunk < end; ++chunk)
      evaluateRange(workerCellBegin_[chunk], workerCellBegin_[chunk + 1], coefficients, x, y, z);
  });
}

template <typename T>
void EmbeddedDeformer::applyOffsets(T* x, T* y, T* z) const {
  if (method_ == InterpolationMethod::Attribute) return;  // it moves X itself, offset included
  for (size_t k = 0; k < offsetSorted_.size(); ++k) {
    const Eigen::Vector3d correction =
        gradientAt(embedding_.offsetPoints[k]) * embedding_.offsetVectors[k];
    const uint32_t s = offsetSorted_[k];
    x[s] += static_cast<T>(correction[0]);
    y[s] += static_cast<T>(correction[1]);
    z[s] += static_cast<T>(correction[2]);
  }
}

void EmbeddedDeformer::evaluateSorted(float* x, float* y, float* z) const {
  evaluateAll(coefficientsF_, x, y, z);
  applyOffsets(x, y, z);
}

Points EmbeddedDeformer::positions() const {
  const uint32_t n = numPoints();
  Coefficients<double> coefficients;
  fillCoefficients(coefficients);
  std::vector<double> x(n), y(n), z(n);
  evaluateAll(coefficients, x.data(), y.data(), z.data());
  applyOffsets(x.data(), y.data(), z.data());
  Points out(n, 3);
  for (uint32_t k = 0; k < n; ++k) out.row(sortedToInput_[k]) << x[k], y[k], z[k];
  return out;
}

Points EmbeddedDeformer::positionsSinglePrecision() const {
  const uint32_t n = numPoints();
  FloatPositions sorted;
  sorted.resize(n);
  evaluateSorted(sorted.x.data(), sorted.y.data(), sorted.z.data());
  Points out(n, 3);
  for (uint32_t k = 0; k < n; ++k)
    out.row(sortedToInput_[k]) << sorted.x[k], sorted.y[k], sorted.z[k];
  return out;
}

Eigen::Matrix3d EmbeddedDeformer::gradientAt(uint32_t point) const {
  const double alpha =
      method_ == InterpolationMethod::Attribute ? 0.5 : gradientBlend(method_);
  const NodeFrame frame{&nodes_, &nodeGradients_};
  return evaluateCellInterpolant(rest_, frame, embedding_.cells[point],
                                 embedding_.local.row(point).transpose(), alpha)
      .gradient;
}

Points EmbeddedDeformer::deformNormals(const Points& restNormals,
                                       std::span<const uint32_t> anchors) const {
  Points out = restNormals;
  const uint32_t count =
      static_cast<uint32_t>(std::min<size_t>(anchors.size(), restNormals.rows()));
  parallelChunks(count, 4096, [&](uint32_t begin, uint32_t end, unsigned) {
    for (uint32_t j = begin; j < end; ++j) {
      if (anchors[j] >= numPoints()) continue;
      out.row(j) = deformNormal(gradientAt(anchors[j]), restNormals.row(j).transpose()).transpose();
    }
  });
  return out;
}

}  // namespace sculpt
