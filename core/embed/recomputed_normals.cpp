#include "embed/recomputed_normals.h"

#include <stdexcept>
#include <string>

#include <Eigen/Geometry>

namespace sculpt {
namespace {

/// The area vector of polygon `face` (Newell's method, about its first corner so that surfaces
/// far from the origin lose no precision): |a| is the area of a planar polygon, and a points to
/// the side from which the corners run counter-clockwise. Out-of-range positions are skipped.
Eigen::Vector3d areaVector(std::span<const SurfaceCorner> face, const Points& positions) {
  const auto rows = static_cast<uint32_t>(positions.rows());
  if (face.empty() || face[0].position >= rows) return Eigen::Vector3d::Zero();
  const Eigen::Vector3d origin = positions.row(face[0].position).transpose();
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (size_t i = 1; i + 1 < face.size(); ++i) {
    const uint32_t a = face[i].position, b = face[i + 1].position;
    if (a >= rows || b >= rows) continue;
    sum += (positions.row(a).transpose() - origin).cross(positions.row(b).transpose() - origin);
  }
  return 0.5 * sum;
}

}  // namespace

Points recomputedNormals(const SurfaceMesh& surface, const Points& deformed,
                         std::span<const uint32_t> anchors) {
  if (deformed.rows() != surface.positions.rows())
    throw std::invalid_argument("recomputedNormals: " + std::to_string(deformed.rows()) +
                                " deformed positions for a surface of " +
                                std::to_string(surface.positions.rows()));
  const auto numNormals = static_cast<uint32_t>(surface.normals.rows());
  Points restSum = Points::Zero(numNormals, 3);
  Points deformedSum = Points::Zero(numNormals, 3);

  // Accumulate each face's area vector into the normals it uses at their anchors
  for (uint32_t f = 0; f < surface.numFaces(); ++f) {
    const auto face = surface.faces.row(f);
    bool computed = false;
    Eigen::Vector3d restArea, deformedArea;
    for (size_t c = 0; c < face.size(); ++c) {
      const uint32_t j = face[c].normal;
      if (j >= numNormals || j >= anchors.size() || face[c].position != anchors[j]) continue;
      if (!computed) {
        restArea = areaVector(face, surface.positions);
        deformedArea = areaVector(face, deformed);
        computed = true;
      }
      restSum.row(j) += restArea.transpose();
      deformedSum.row(j) += deformedArea.transpose();
    }
  }

  // Normalise, orient as the file does, keep the rest normal where nothing is defined
  Points out = surface.normals;
  for (uint32_t j = 0; j < numNormals; ++j) {
    const Eigen::Vector3d sum = deformedSum.row(j).transpose();
    const double length = sum.norm();
    if (!(length > 1e-300) || !sum.allFinite()) continue;
    Eigen::Vector3d normal = sum / length;
    if (restSum.row(j).dot(surface.normals.row(j)) < 0.0) normal = -normal;
    out.row(j) = normal.transpose();
  }
  return out;
}

Points vertexNormals(const SurfaceMesh& surface) {
  // Normal i belongs to position i at every corner; zero rest normals keep the faces' winding.
  SurfaceMesh perVertex = surface;
  perVertex.normals.setZero(surface.positions.rows(), 3);
  for (SurfaceCorner& corner : perVertex.faces.values) corner.normal = corner.position;
  return recomputedNormals(perVertex, perVertex.positions, normalAnchors(perVertex));
}

}  // namespace sculpt
