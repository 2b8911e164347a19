#pragma once
// Moves a detailed point set with a deforming cell mesh, every frame.
//
// Precomputed once (double precision): the embedding, the node-gradient stencil
// (gradient_scheme.h), the points sorted by cell in structure-of-arrays form and, for the
// attribute method, each point's metaball neighbours.
// Per frame: setFrame() computes node gradients through the stencil and turns each cell's
// interpolant into a small polynomial (O(nodes + cells)); evaluate*() then costs a few dozen
// multiply-adds per point (O(points), single precision on the fast path, both cores).
//
// The per-cell polynomial: with X(xi) = sum_b beta_b X_b the interpolant
//   f = sum_a beta_a x_a + alpha sum_{a<b} beta_a beta_b (F_a - F_b)(X_b - X_a)
// is quadratic in the barycentric weights of a tetrahedron (4 node + 6 edge coefficients; the
// same quadratic as the 10-node tetrahedron, section 3.3 of James 2020). The edge coefficient
// depends on the edge only, so it is computed once per mesh edge (a lattice has 4.4x fewer edges
// than tetrahedron-edge pairs) and gathered by the point kernel. On a hexahedron the interpolant
// is triquadratic, stored per cell as its 27 nodal values at xi in {0, 1/2, 1}^3.

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "embed/attribute_transfer.h"
#include "embed/deformation_gradients.h"
#include "embed/embedding.h"
#include "embed/gradient_scheme.h"
#include "embed/interpolation_method.h"
#include "mesh/volume_mesh.h"
#include "util/progress.h"

namespace sculpt {

struct DeformerSettings {
  double eps = 1.0;              ///< regulariser of the cell-to-node weights
  GradientScheme gradients = kDefaultGradientScheme;  ///< how node gradients are reconstructed
  double attributeRadius = 0.0;  ///< attribute method radius; 0: 1.5 x the mean edge length
  bool buildAttributeWeights = true;  ///< false skips the attribute precompute (not needed)
};

/// Structure-of-arrays single-precision positions.
struct FloatPositions {
  std::vector<float> x, y, z;
  void resize(size_t n) { x.resize(n), y.resize(n), z.resize(n); }
};

class EmbeddedDeformer {
 public:
  /// Precomputes everything for `points` embedded in `rest`. Throws std::invalid_argument for an
  /// empty mesh, non-finite points or bad settings.
  EmbeddedDeformer(VolumeMesh rest, const Points& points, const DeformerSettings& settings = {},
                   ProgressReporter* progress = nullptr);
  /// The same with the embedding of `points` already made (embedPoints(rest, points)).
  EmbeddedDeformer(VolumeMesh rest, const Points& points, Embedding embedding,
                   const DeformerSettings& settings = {});

  const VolumeMesh& rest() const { return rest_; }
  const Embedding& embedding() const { return embedding_; }
  GradientScheme gradientScheme() const { return gradientScheme_; }
  double attributeRadius() const { return attributeRadius_; }
  uint32_t numPoints() const { return embedding_.numPoints(); }
  /// Sorted position k holds input point sortedToInput()[k].
  const std::vector<uint32_t>& sortedToInput() const { return sortedToInput_; }

  /// Stage 1 of a frame: gradients and per-cell coefficients for `method` from deformed nodes
  /// (#nodes by 3, same order as the rest mesh). Throws std::invalid_argument on a row count
  /// mismatch or non-finite positions.
  void setFrame(const Points& deformedNodes, InterpolationMethod method);
  InterpolationMethod method() const { return method_; }

  /// Stage 2, fast path: single-precision positions in cell-sorted order (numPoints() each).
  void evaluateSorted(float* x, float* y, float* z) const;
  /// Double-precision positions in input order (same polynomials, evaluated in double).
  Points positions() const;
  /// Single-precision positions (fast path) in input order.
  Points positionsSinglePrecision() const;

  /// Node and cell gradients of the current frame (for the renderer and for tests).
  const std::vector<Eigen::Matrix3d>& nodeGradients() const { return nodeGradients_; }
  /// d f / d X at input point p for the current frame (linear/vertex/phong; for the attribute
  /// method the gradient of the phong map is returned, as that method has no useful one).
  Eigen::Matrix3d gradientAt(uint32_t point) const;
  /// Deformed normals: rest normal j sits at input point anchors[j] (kNoIndex: left unchanged).
  Points deformNormals(const Points& restNormals, std::span<const uint32_t> anchors) const;

 private:
  /// Per-frame coefficients read by the point kernel.
  template <typename T>
  struct Coefficients {
    std::vector<T> nodes;  ///< 3 per node: position (attribute method: displacement)
    std::vector<T> edges;  ///< 3 per tetrahedron edge: alpha (F_a - F_b)(X_b - X_a)
    std::vector<T> hexes;  ///< 81 per hexahedron: triquadratic nodal values (quadratic methods)
  };
  template <typename T>
  void fillCoefficients(Coefficients<T>& coefficients) const;
  template <typename T>
  void evaluateRange(uint32_t cellBegin, uint32_t cellEnd, const Coefficients<T>& coefficients,
                     T* x, T* y, T* z) const;
  template <typename T>
  void evaluateAll(const Coefficients<T>& coefficients, T* x, T* y, T* z) const;
  /// Adds gradient x offset for the points of embedding().offsetPoints (sorted-order outputs).
  template <typename T>
  void applyOffsets(T* x, T* y, T* z) const;

  VolumeMesh rest_;
  Embedding embedding_;
  GradientScheme gradientScheme_;
  NodeGradientStencil gradientStencil_;
  double attributeRadius_ = 0.0;
  CompressedRows<NodeWeight> attributeWeights_;  ///< rows in sorted order
  std::vector<std::array<uint32_t, 2>> edgeNodes_;  ///< distinct tetrahedron edges
  std::vector<Eigen::Vector3d> edgeVectors_;        ///< X_b - X_a per edge (rest)
  std::vector<uint32_t> cellSlot_;   ///< tetrahedron: first of its 6 entries in tetEdges_;
                                     ///< hexahedron: its index among the hexahedra
  std::vector<uint32_t> tetEdges_;   ///< per tetrahedron, its edges in kTetPairs order

  // Points sorted by cell.
  std::vector<uint32_t> sortedToInput_;
  std::vector<uint32_t> offsetSorted_;          ///< sorted index of each offset point
  std::vector<uint32_t> cellPointBegin_;        ///< #cells+1
  std::vector<uint32_t> workerCellBegin_;       ///< cell ranges of equal point counts per worker
  std::vector<float> localF_[3];                ///< sorted local coordinates
  std::vector<double> localD_[3];
  std::vector<float> restF_[3];                 ///< sorted rest positions (attribute method)
  std::vector<double> restD_[3];

  // Current frame.
  InterpolationMethod method_ = InterpolationMethod::Linear;
  Points nodes_;
  std::vector<Eigen::Matrix3d> nodeGradients_;
  Coefficients<float> coefficientsF_;  ///< double ones are made on demand (positions())
};

/// Mean length of the distinct edges of the mesh's cells (tetrahedra: 6, hexahedra: 12).
double meanEdgeLength(const VolumeMesh& mesh);

}  // namespace sculpt
