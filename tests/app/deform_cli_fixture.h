#pragma once
// The deform CLI tests' scene: a unit lattice of tetrahedra or hexahedra, test maps (affine,
// a bend), surfaces and the fixture that writes them as VTK/OBJ and runs sculpt-cli deform.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Dense>

#include "embed/recomputed_normals.h"
#include "io/obj_surface.h"
#include "io/surface_file.h"
#include "io/vtk_volume_mesh.h"
#include "mesh/lattice_mesh.h"
#include "mesh/surface_mesh.h"
#include "support/cli_fixture.h"

namespace sculpt::deform_cli {


namespace fs = std::filesystem;

using test::CliResult;
using test::quote;
using test::readText;
using test::writeText;

using Map = std::function<Eigen::Vector3d(const Eigen::Vector3d&)>;

// The affine test map x = A X + b (det A > 0).
inline Eigen::Matrix3d affineMatrix() {
  Eigen::Matrix3d a;
  a << 1.1, 0.2, 0.0,  //
      0.1, 0.9, 0.15,  //
      -0.05, 0.1, 1.2;
  return a;
}
inline const Eigen::Vector3d kShift(0.3, -0.2, 0.1);

inline Eigen::Vector3d affine(const Eigen::Vector3d& X) { return affineMatrix() * X + kShift; }

// Bends the unit cube around an axis parallel to z (radius 1 at y = 0.5).
inline Eigen::Vector3d bend(const Eigen::Vector3d& X) {
  const double radius = 1.0 + X.y() - 0.5;
  const double angle = X.x() - 0.5;
  return {0.5 + radius * std::sin(angle), -0.5 + radius * std::cos(angle), X.z()};
}

// cof(A) N normalised: how normals move under the affine map.
inline Eigen::Vector3d cofactorNormal(const Eigen::Vector3d& normal) {
  const Eigen::Matrix3d a = affineMatrix();
  return (a.determinant() * a.inverse().transpose() * normal).normalized();
}

inline VolumeMesh mapped(VolumeMesh mesh, const Map& map) {
  for (Eigen::Index i = 0; i < mesh.positions.rows(); ++i)
    mesh.positions.row(i) = map(mesh.positions.row(i).transpose()).transpose();
  return mesh;
}

// The unit cube as a lattice of 4^3 cubes (tetrahedra or hexahedra).
inline VolumeMesh unitLattice(bool hexahedra = false) {
  LatticeSpec spec;
  spec.cubes = {4, 4, 4};
  spec.spacing = 0.25;
  return hexahedra ? hexLattice(spec) : tetLattice(spec);
}

// A latitude-longitude sphere: position, normal and texture coordinate i belong together and
// every corner uses the same index for all three (so glTF keeps the vertex count).
inline SurfaceMesh sphereSurface(const Eigen::Vector3d& center, double radius, int rings = 8,
                          int segments = 12) {
  std::vector<Eigen::Vector3d> directions;
  std::vector<Eigen::Vector2d> uvs;
  directions.emplace_back(0, 0, 1);
  uvs.emplace_back(0.5, 1.0);
  for (int r = 1; r < rings; ++r)
    for (int s = 0; s < segments; ++s) {
      const double theta = std::numbers::pi * r / rings;
      const double phi = 2 * std::numbers::pi * s / segments;
      directions.emplace_back(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                              std::cos(theta));
      uvs.emplace_back(static_cast<double>(s) / segments, 1.0 - static_cast<double>(r) / rings);
    }
  directions.emplace_back(0, 0, -1);
  uvs.emplace_back(0.5, 0.0);
  const auto n = static_cast<Eigen::Index>(directions.size());
  SurfaceMesh surface;
  surface.positions.resize(n, 3);
  surface.normals.resize(n, 3);
  surface.texcoords.resize(n, 2);
  for (Eigen::Index i = 0; i < n; ++i) {
    surface.positions.row(i) = (center + radius * directions[i]).transpose();
    surface.normals.row(i) = directions[i].transpose();
    surface.texcoords.row(i) = uvs[i].transpose();
  }
  const auto ring = [&](int r, int s) -> uint32_t {
    return static_cast<uint32_t>(1 + (r - 1) * segments + (s % segments));
  };
  const auto triangle = [&](uint32_t a, uint32_t b, uint32_t c) {
    for (uint32_t v : {a, b, c}) surface.faces.values.push_back({v, v, v});
    surface.faces.closeRow();
  };
  const uint32_t south = static_cast<uint32_t>(n - 1);
  for (int s = 0; s < segments; ++s) {
    triangle(0, ring(1, s), ring(1, s + 1));
    for (int r = 1; r + 1 < rings; ++r) {
      triangle(ring(r, s), ring(r + 1, s), ring(r + 1, s + 1));
      triangle(ring(r, s), ring(r + 1, s + 1), ring(r, s + 1));
    }
    triangle(ring(rings - 1, s), south, ring(rings - 1, s + 1));
  }
  return surface;
}

// A flat-shaded box: 8 positions, 6 normals (one per face, used by its 4 corners), no texcoords.
inline SurfaceMesh boxSurface(const Eigen::Vector3d& low, const Eigen::Vector3d& high) {
  SurfaceMesh surface;
  surface.positions.resize(8, 3);
  for (uint32_t i = 0; i < 8; ++i)
    surface.positions.row(i) << (i & 1 ? high.x() : low.x()), (i & 2 ? high.y() : low.y()),
        (i & 4 ? high.z() : low.z());
  surface.normals.resize(6, 3);
  surface.normals << -1, 0, 0, 1, 0, 0, 0, -1, 0, 0, 1, 0, 0, 0, -1, 0, 0, 1;
  const uint32_t quads[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  for (uint32_t f = 0; f < 6; ++f) {
    for (uint32_t v : quads[f]) surface.faces.values.push_back({v, SurfaceCorner::kNoIndex, f});
    surface.faces.closeRow();
  }
  return surface;
}

/// Root-mean-square distance between the rows of `exact` and the positions of `out`.
inline double rmsDistance(const Points& exact, const SurfaceMesh& out) {
  EXPECT_EQ(out.positions.rows(), exact.rows());
  if (out.positions.rows() != exact.rows()) return INFINITY;
  return std::sqrt((out.positions - exact).rowwise().squaredNorm().mean());
}

inline double maxRowDistance(const Points& a, const Points& b) {
  EXPECT_EQ(a.rows(), b.rows());
  if (a.rows() != b.rows()) return INFINITY;
  double worst = 0;
  for (Eigen::Index i = 0; i < a.rows(); ++i) worst = std::max(worst, (a.row(i) - b.row(i)).norm());
  return worst;
}

inline Points mappedPoints(const Points& points, const Map& map) {
  Points out(points.rows(), 3);
  for (Eigen::Index i = 0; i < points.rows(); ++i)
    out.row(i) = map(points.row(i).transpose()).transpose();
  return out;
}

class DeformCliTest : public test::CliFixture {
 protected:
  DeformCliTest() : CliFixture("sculpt_deform_cli_test_") {}

  // Writes rest.vtk, the surface (surface.obj) and the rest mesh under `map` as `deformed`.
  void writeScene(const VolumeMesh& rest, const SurfaceMesh& surface, const Map& map,
                  const std::string& deformed = "deformed.vtk") const {
    writeVtkVolumeMesh(path("rest.vtk"), rest, false);
    writeObjSurface(path("surface.obj"), surface);
    writeVtkVolumeMesh(path(deformed), mapped(rest, map), false);
  }

  std::string sceneArgs(const std::string& deformed = "deformed.vtk") const {
    return "deform --rest " + quote(path("rest.vtk")) + " --deformed " + quote(path(deformed)) +
           " --surface " + quote(path("surface.obj"));
  }

  // RMS distance to the exact bend of a sphere of `radius` in the unit lattice, deformed with
  // `extra` options to `out`.
  double bendError(double radius, const std::string& extra, const std::string& out) const {
    const SurfaceMesh surface = sphereSurface({0.5, 0.5, 0.5}, radius, 16, 24);
    writeScene(unitLattice(), surface, bend);
    return rmsDistance(mappedPoints(surface.positions, bend), deform(extra, out));
  }

  // Runs deform with `extra` options to `out`; expects success and returns the surface written.
  SurfaceMesh deform(const std::string& extra, const std::string& out,
                     CliResult* result = nullptr) const {
    const std::string args = sceneArgs() + " " + extra + " --out " + quote(path(out));
    SCOPED_TRACE(args);
    const CliResult ran = run(args);
    EXPECT_FALSE(ran.signaled);
    EXPECT_EQ(ran.exitCode, 0) << ran.err;
    if (result) *result = ran;
    if (ran.exitCode != 0) return {};
    return readSurfaceFile(path(out)).surface();
  }
};

}  // namespace sculpt::deform_cli
