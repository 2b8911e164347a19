// Properties of the embedded interpolants (James 2020, section 3.3): interpolation of nodes,
// affine invariance, reduction to linear for constant gradients, continuity across shared faces,
// analytic gradients and normals against finite differences, and the fast single-precision path
// against the double-precision reference.

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cstdio>
#include <random>
#include <string>

#include "embed/cell_coordinates.h"
#include "embed/cell_interpolant.h"
#include "embed/embedded_deformer.h"
#include "mesh/lattice_mesh.h"
#include "util/compressed_rows.h"

namespace sculpt {
namespace {

const InterpolationMethod kCellMethods[] = {
    InterpolationMethod::Linear, InterpolationMethod::Vertex, InterpolationMethod::Phong};

Eigen::Vector3d smoothMap(const Eigen::Vector3d& X) {
  return X + 0.15 * Eigen::Vector3d(std::sin(2 * X.y()) + X.z() * X.z(),
                                    std::cos(1.5 * X.z()) * X.x(),
                                    X.x() * X.y() - X.z() * X.z() * X.z());
}

Points mapNodes(const Points& rest,
                const std::function<Eigen::Vector3d(const Eigen::Vector3d&)>& f) {
  Points out(rest.rows(), 3);
  for (Eigen::Index i = 0; i < rest.rows(); ++i)
    out.row(i) = f(rest.row(i).transpose()).transpose();
  return out;
}

void measured(const char* what, const char* mesh, InterpolationMethod method, double value) {
  std::printf("[ measured ] %s, %s, %s: %.2e\n", what, mesh,
              std::string(methodName(method)).c_str(), value);
}

struct MeshCase {
  const char* name;
  VolumeMesh mesh;
};

std::vector<MeshCase> testMeshes() {
  LatticeSpec spec;
  spec.cubes = {4, 3, 3};
  spec.spacing = 0.25;
  spec.origin = Eigen::Vector3d(-0.5, -0.4, -0.3);
  VolumeMesh tets = tetLattice(spec);
  jitterLattice(tets, spec, 0.15, 7);
  VolumeMesh hexes = hexLattice(spec);
  jitterLattice(hexes, spec, 0.15, 8);
  return {{"jittered tets", std::move(tets)}, {"jittered hexes", std::move(hexes)}};
}

/// Random points inside the mesh's cells (fixed local coordinates per cell).
Points pointsInCells(const VolumeMesh& mesh, uint32_t perCell, uint32_t seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> uniform(0.02, 0.98);
  Points points(static_cast<Eigen::Index>(mesh.numCells()) * perCell, 3);
  Eigen::Index row = 0;
  for (uint32_t c = 0; c < mesh.numCells(); ++c)
    for (uint32_t k = 0; k < perCell; ++k) {
      Eigen::Vector3d xi(uniform(random), uniform(random), uniform(random));
      if (mesh.isTetrahedron(c) && xi.sum() > 0.98) xi *= 0.9 / xi.sum();
      points.row(row++) = cellPoint(mesh, c, xi).transpose();
    }
  return points;
}

/// How far `to` is from the image of `from` under x -> A x + t: the largest distance between
/// matching rows.
double maxAffineError(const Eigen::Matrix3d& A, const Eigen::Vector3d& t, const Points& from,
                      const Points& to) {
  double worst = 0.0;
  for (Eigen::Index p = 0; p < from.rows(); ++p)
    worst = std::max(worst, (A * from.row(p).transpose() + t - to.row(p).transpose()).norm());
  return worst;
}

TEST(PhongProperties, InterpolatesNodePositions) {
  for (const MeshCase& test : testMeshes()) {
    const EmbeddedDeformer deformerTemplate(test.mesh, test.mesh.positions);
    EmbeddedDeformer deformer = deformerTemplate;
    const Points deformed = mapNodes(test.mesh.positions, smoothMap);
    for (InterpolationMethod method : kCellMethods) {
      deformer.setFrame(deformed, method);
      const Points result = deformer.positions();
      measured("interpolation at nodes", test.name, method,
               (result - deformed).cwiseAbs().maxCoeff());
      EXPECT_LT((result - deformed).cwiseAbs().maxCoeff(), 1e-12)
          << test.name << ' ' << methodName(method);
    }
  }
}

TEST(PhongProperties, AffineInvariance) {
  Eigen::Matrix3d A;
  A << 1.2, 0.3, -0.4, 0.1, 0.8, 0.5, -0.2, 0.6, 1.1;
  const Eigen::Vector3d t(0.3, -1.2, 2.0);
  for (const MeshCase& test : testMeshes()) {
    const Points points = pointsInCells(test.mesh, 3, 11);
    EmbeddedDeformer deformer(test.mesh, points);
    const Points deformed = mapNodes(test.mesh.positions, smoothMap);
    const Points transformed =
        mapNodes(deformed, [&](const Eigen::Vector3d& x) -> Eigen::Vector3d { return A * x + t; });
    for (InterpolationMethod method : kCellMethods) {
      deformer.setFrame(deformed, method);
      const Points before = deformer.positions();
      deformer.setFrame(transformed, method);
      const Points after = deformer.positions();
      measured("affine invariance", test.name, method, maxAffineError(A, t, before, after));
      EXPECT_LT(maxAffineError(A, t, before, after), 1e-12)
          << test.name << ' ' << methodName(method);
    }
  }
}

TEST(PhongProperties, ConstantGradientsReduceToLinearExactly) {
  // An affine deformation makes every cell and node gradient equal: Phong and the vertex model
  // must then equal linear interpolation, which is exact for affine maps.
  Eigen::Matrix3d A;
  A << 0.9, -0.3, 0.2, 0.4, 1.1, 0.0, 0.1, 0.2, 1.3;
  const Eigen::Vector3d t(-0.1, 0.2, 0.05);
  for (const MeshCase& test : testMeshes()) {
    const Points points = pointsInCells(test.mesh, 3, 12);
    EmbeddedDeformer deformer(test.mesh, points);
    const Points deformed =
        mapNodes(test.mesh.positions,
                 [&](const Eigen::Vector3d& X) -> Eigen::Vector3d { return A * X + t; });
    deformer.setFrame(deformed, InterpolationMethod::Phong);
    for (const Eigen::Matrix3d& F : deformer.nodeGradients()) EXPECT_LT((F - A).norm(), 1e-12);
    for (InterpolationMethod method : kCellMethods) {
      deformer.setFrame(deformed, method);
      const Points result = deformer.positions();
      measured("affine map reproduced", test.name, method, maxAffineError(A, t, points, result));
      EXPECT_LT(maxAffineError(A, t, points, result), 1e-12)
          << test.name << ' ' << methodName(method);
    }
  }
}

TEST(PhongProperties, ContinuousAcrossSharedFaces) {
  for (const MeshCase& test : testMeshes()) {
    EmbeddedDeformer deformer(test.mesh, test.mesh.positions.topRows(1));
    deformer.setFrame(mapNodes(test.mesh.positions, smoothMap), InterpolationMethod::Phong);
    const Points nodes = mapNodes(test.mesh.positions, smoothMap);
    const NodeFrame frame{&nodes, &deformer.nodeGradients()};
    // Every pair of cells sharing a face (3 or 4 common nodes): points on that face evaluated
    // from both sides agree.
    const CompressedRows<uint32_t> nodeCells =
        invertIncidence(test.mesh.cells, test.mesh.numNodes());
    std::mt19937 random(3);
    std::uniform_real_distribution<double> uniform(0.05, 0.95);
    int faces = 0;
    double worst = 0.0;
    for (uint32_t c = 0; c < test.mesh.numCells(); ++c) {
      std::vector<uint32_t> neighbours;
      for (uint32_t node : test.mesh.cells.row(c))
        for (uint32_t other : nodeCells.row(node))
          if (other > c) neighbours.push_back(other);
      std::sort(neighbours.begin(), neighbours.end());
      neighbours.erase(std::unique(neighbours.begin(), neighbours.end()), neighbours.end());
      for (uint32_t other : neighbours) {
        std::vector<uint32_t> shared;
        for (uint32_t a : test.mesh.cells.row(c))
          for (uint32_t b : test.mesh.cells.row(other))
            if (a == b) shared.push_back(a);
        if (shared.size() < 3) continue;
        ++faces;
        const double u = uniform(random), v = uniform(random);
        Eigen::Vector3d X;
        if (test.mesh.isTetrahedron(c)) {
          const double a = u * (1 - v), b = u * v;
          X = (1 - a - b) * test.mesh.positions.row(shared[0]).transpose() +
              a * test.mesh.positions.row(shared[1]).transpose() +
              b * test.mesh.positions.row(shared[2]).transpose();
        } else {
          // The shared quad is the face of c where one local coordinate is constant.
          Eigen::Vector3d xi(u, v, 0.5 * (u + v));
          const Eigen::Vector3d corner =
              cellLocalCoordinates(test.mesh, c, test.mesh.positions.row(shared[0]).transpose());
          for (int d = 0; d < 3; ++d) {
            bool constant = true;
            for (uint32_t node : shared)
              constant = constant &&
                         std::abs(cellLocalCoordinates(
                                      test.mesh, c, test.mesh.positions.row(node).transpose())[d] -
                                  corner[d]) < 1e-9;
            if (constant) xi[d] = std::round(corner[d]);
          }
          X = cellPoint(test.mesh, c, xi);
        }
        const Eigen::Vector3d xiC = cellLocalCoordinates(test.mesh, c, X);
        const Eigen::Vector3d xiO = cellLocalCoordinates(test.mesh, other, X);
        for (double alpha : {0.0, 0.5, 1.0}) {
          const Eigen::Vector3d fromC = interpolatePosition(test.mesh, frame, c, xiC, alpha);
          const Eigen::Vector3d fromO = interpolatePosition(test.mesh, frame, other, xiO, alpha);
          worst = std::max(worst, (fromC - fromO).norm());
        }
      }
    }
    EXPECT_GT(faces, 20) << test.name;
    std::printf("[ measured ] %s: %d shared faces, largest jump %.2e\n", test.name, faces, worst);
    EXPECT_LT(worst, 1e-11) << test.name;
  }
}

TEST(PhongProperties, GradientAndNormalsMatchFiniteDifferences) {
  for (const MeshCase& test : testMeshes()) {
    const Points points = pointsInCells(test.mesh, 1, 21);
    EmbeddedDeformer deformer(test.mesh, points);
    const Points nodes = mapNodes(test.mesh.positions, smoothMap);
    for (InterpolationMethod method : kCellMethods) {
      deformer.setFrame(nodes, method);
      const NodeFrame frame{&nodes, &deformer.nodeGradients()};
      double worstGradient = 0.0, worstNormal = 0.0;
      for (uint32_t p = 0; p < deformer.numPoints(); ++p) {
        const uint32_t cell = deformer.embedding().cells[p];
        const Eigen::Vector3d X = points.row(p).transpose();
        const Eigen::Matrix3d G = deformer.gradientAt(p);
        // Central differences of f in rest space, staying inside the same cell's polynomial.
        const double h = 1e-6;
        Eigen::Matrix3d fd;
        for (int d = 0; d < 3; ++d) {
          const Eigen::Vector3d e = h * Eigen::Vector3d::Unit(d);
          const auto f = [&](const Eigen::Vector3d& Y) {
            return interpolatePosition(test.mesh, frame, cell,
                                       cellLocalCoordinates(test.mesh, cell, Y),
                                       gradientBlend(method));
          };
          fd.col(d) = (f(X + e) - f(X - e)) / (2 * h);
        }
        worstGradient = std::max(worstGradient, (G - fd).norm() / G.norm());
        // The normal of a small deformed triangle in the plane orthogonal to N.
        const Eigen::Vector3d N = Eigen::Vector3d(0.3, -0.5, 0.8).normalized();
        const Eigen::Vector3d t1 = N.unitOrthogonal(), t2 = N.cross(t1);
        const Eigen::Vector3d expected = ((fd * t1).cross(fd * t2)).normalized();
        worstNormal = std::max(worstNormal, (deformNormal(G, N) - expected).norm());
      }
      measured("gradient vs FD (relative)", test.name, method, worstGradient);
      measured("normal vs FD triangle", test.name, method, worstNormal);
      EXPECT_LT(worstGradient, 1e-7) << test.name << ' ' << methodName(method);
      EXPECT_LT(worstNormal, 1e-7) << test.name << ' ' << methodName(method);
    }
  }
}

TEST(PhongProperties, FastPathsMatchTheReference) {
  for (const MeshCase& test : testMeshes()) {
    const Points points = pointsInCells(test.mesh, 40, 5);  // enough to run on both threads
    EmbeddedDeformer deformer(test.mesh, points);
    const Points nodes = mapNodes(test.mesh.positions, smoothMap);
    for (InterpolationMethod method : kCellMethods) {
      deformer.setFrame(nodes, method);
      const NodeFrame frame{&nodes, &deformer.nodeGradients()};
      const Points fast = deformer.positions();
      const Points single = deformer.positionsSinglePrecision();
      double worst = 0.0, worstSingle = 0.0;
      for (uint32_t p = 0; p < deformer.numPoints(); ++p) {
        const Eigen::Vector3d reference = interpolatePosition(
            test.mesh, frame, deformer.embedding().cells[p],
            deformer.embedding().local.row(p).transpose(), gradientBlend(method));
        worst = std::max(worst, (fast.row(p).transpose() - reference).norm());
        worstSingle = std::max(worstSingle, (single.row(p).transpose() - reference).norm());
      }
      measured("fast double path vs reference", test.name, method, worst);
      measured("single precision vs reference", test.name, method, worstSingle);
      EXPECT_LT(worst, 1e-13) << test.name << ' ' << methodName(method);
      EXPECT_LT(worstSingle, 2e-6) << test.name << ' ' << methodName(method);
    }
  }
}

TEST(PhongEmbedding, LocatesInsideAndExtrapolatesOutside) {
  LatticeSpec spec;
  spec.cubes = {5, 5, 5};
  spec.spacing = 0.2;
  VolumeMesh mesh = tetLattice(spec);
  jitterLattice(mesh, spec, 0.15, 4);
  std::mt19937 random(9);
  std::uniform_real_distribution<double> uniform(-0.3, 1.3);
  Points points(3000, 3);
  for (Eigen::Index p = 0; p < points.rows(); ++p)
    points.row(p) << uniform(random), uniform(random), uniform(random);
  const Embedding embedding = embedPoints(mesh, points);
  uint32_t outside = 0;
  for (uint32_t p = 0; p < embedding.numPoints(); ++p) {
    const Eigen::Vector3d X = points.row(p).transpose();
    ASSERT_TRUE(embedding.local.row(p).allFinite());
    // The local coordinates reproduce the point (also extrapolated outside the mesh).
    EXPECT_LT((cellPoint(mesh, embedding.cells[p], embedding.local.row(p).transpose()) - X).norm(),
              1e-12);
    const bool insideBox = (X.array() >= 0.0).all() && (X.array() <= 1.0).all();
    if (!insideBox) {
      ++outside;
      continue;
    }
    EXPECT_LE(localExcursion(true, embedding.local.row(p).transpose()), 1e-9) << p;
  }
  EXPECT_EQ(embedding.outsideCount, outside);
  // Outside points go to a near cell: the box distance bounds the distance to the mesh.
  EXPECT_LT(embedding.maxOutsideDistance, 0.3 * std::sqrt(3.0) + 0.1);
}

}  // namespace
}  // namespace sculpt
