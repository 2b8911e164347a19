#include "tools/deformed_boundary.h"

#include <Eigen/Geometry>

#include <cmath>
#include <limits>

#include "sim/load_forms.h"

namespace sculpt {
namespace {

Eigen::Vector3d row(const Points& p, uint32_t i) { return p.row(i).transpose(); }

// Solid angle of triangle (a, b, c) seen from the origin, signed by orientation (Van Oosterom and
// Strackee's formula).
double solidAngle(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const double la = a.norm(), lb = b.norm(), lc = c.norm();
  const double numerator = a.dot(b.cross(c));
  const double denominator = la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la;
  return 2.0 * std::atan2(numerator, denominator);
}

}  // namespace

Eigen::Vector3d closestPointOnTriangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                       const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  // Which Voronoi region of the triangle p projects into: a vertex, an edge or the face.
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return {1, 0, 0};
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return {0, 1, 0};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    const double v = d1 / (d1 - d3);
    return {1 - v, v, 0};
  }
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return {0, 0, 1};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    const double w = d2 / (d2 - d6);
    return {1 - w, 0, w};
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return {0, 1 - w, w};
  }
  const double total = va + vb + vc;
  if (!(total > 0)) return {1, 0, 0};  // a degenerate triangle: its first vertex
  const double v = vb / total, w = vc / total;
  return {1 - v - w, v, w};
}

DeformedBoundary::DeformedBoundary(const FemModel& model)
    : triangles_(boundaryTriangles(model)), rest_(model.subdivision().finest().positions) {}

DeformedBoundary::DeformedBoundary(const FemModel& model, const MaterialPointLocator& locator,
                                   const Points& restVertices,
                                   const std::vector<uint32_t>& triangles)
    : rest_(restVertices) {
  for (size_t t = 0; t + 2 < triangles.size(); t += 3)
    triangles_.push_back({triangles[t], triangles[t + 1], triangles[t + 2]});
  weights_.resize(static_cast<size_t>(restVertices.rows()));
  for (uint32_t v = 0; v < restVertices.rows(); ++v) {
    const std::optional<MaterialPoint> point = locator.locate(row(restVertices, v));
    if (point) weights_[v] = nodeWeights(model.mesh(), *point);
  }
}

void DeformedBoundary::deformedVertices(const Points& nodes, Points& out) const {
  out.resize(rest_.rows(), 3);
  for (uint32_t v = 0; v < rest_.rows(); ++v) {
    if (weights_[v].empty()) {  // outside every element: stays at rest
      out.row(v) = rest_.row(v);
      continue;
    }
    Eigen::RowVector3d x = Eigen::RowVector3d::Zero();
    for (const auto& [node, w] : weights_[v]) x += w * nodes.row(node);
    out.row(v) = x;
  }
}

std::optional<BoundaryHit> DeformedBoundary::nearest(const Points& nodes,
                                                     const Eigen::Vector3d& position) const {
  if (triangles_.empty() || !position.allFinite()) return std::nullopt;
  Points embedded;
  if (!weights_.empty()) deformedVertices(nodes, embedded);
  const Points& vertices = weights_.empty() ? nodes : embedded;

  BoundaryHit best;
  double bestSquared = std::numeric_limits<double>::infinity(), winding = 0.0;
  for (uint32_t t = 0; t < triangles_.size(); ++t) {
    const auto& tri = triangles_[t];
    const Eigen::Vector3d a = row(vertices, tri[0]), b = row(vertices, tri[1]),
                          c = row(vertices, tri[2]);
    winding += solidAngle(a - position, b - position, c - position);
    const Eigen::Vector3d bary = closestPointOnTriangle(position, a, b, c);
    const Eigen::Vector3d q = bary[0] * a + bary[1] * b + bary[2] * c;
    const double squared = (position - q).squaredNorm();
    if (squared < bestSquared) {
      bestSquared = squared;
      best.point = q;
      best.triangle = t;
      best.barycentric = bary;
    }
  }
  winding /= 4.0 * M_PI;
  const bool inside = std::abs(winding) > 0.5;
  const auto& tri = triangles_[best.triangle];
  const Eigen::Vector3d a = row(vertices, tri[0]), b = row(vertices, tri[1]),
                        c = row(vertices, tri[2]);
  Eigen::Vector3d faceNormal = (b - a).cross(c - a);
  faceNormal =
      faceNormal.norm() > 0 ? Eigen::Vector3d(faceNormal.normalized()) : Eigen::Vector3d::UnitZ();
  if (winding < -0.5) faceNormal = -faceNormal;  // an inward-oriented surface
  const double distance = std::sqrt(bestSquared);
  const Eigen::Vector3d out = best.point - position;
  best.normal = inside && distance > 1e-12 ? Eigen::Vector3d(out / distance) : faceNormal;
  best.signedDistance = inside ? -distance : distance;
  return best;
}

Eigen::Vector3d DeformedBoundary::restPoint(const BoundaryHit& hit) const {
  const auto& tri = triangles_[hit.triangle];
  return hit.barycentric[0] * row(rest_, tri[0]) + hit.barycentric[1] * row(rest_, tri[1]) +
         hit.barycentric[2] * row(rest_, tri[2]);
}

}  // namespace sculpt
