#include "tools/deformed_boundary.h"

#include <Eigen/Geometry>

#include <cmath>
#include <limits>

#include "sim/load_forms.h"

namespace sculpt {
namespace {

Eigen::Vector3d row(const Points& p, uint32_t i) { return p.row(i).transpose(); }

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
    : model_(model), triangles_(boundaryTriangles(model)) {}

std::optional<BoundaryHit> DeformedBoundary::nearest(const Points& nodes,
                                                     const Eigen::Vector3d& position) const {
  if (triangles_.empty() || !position.allFinite()) return std::nullopt;
  BoundaryHit best;
  double bestSquared = std::numeric_limits<double>::infinity();
  for (uint32_t t = 0; t < triangles_.size(); ++t) {
    const auto& tri = triangles_[t];
    const Eigen::Vector3d a = row(nodes, tri[0]), b = row(nodes, tri[1]), c = row(nodes, tri[2]);
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
  const auto& tri = triangles_[best.triangle];
  const Eigen::Vector3d a = row(nodes, tri[0]), b = row(nodes, tri[1]), c = row(nodes, tri[2]);
  const Eigen::Vector3d n = (b - a).cross(c - a);
  best.normal = n.norm() > 0 ? Eigen::Vector3d(n.normalized()) : Eigen::Vector3d::UnitZ();
  // Near an edge or a vertex the face normal and the direction to the point can disagree; the
  // sign comes from the face normal (the side of the nearest face's plane).
  best.signedDistance = (position - best.point).dot(best.normal);
  const double distance = std::sqrt(bestSquared);
  best.signedDistance = best.signedDistance < 0 ? -distance : distance;
  return best;
}

Eigen::Vector3d DeformedBoundary::restPoint(const BoundaryHit& hit) const {
  const Points& rest = model_.subdivision().finest().positions;
  const auto& tri = triangles_[hit.triangle];
  return hit.barycentric[0] * row(rest, tri[0]) + hit.barycentric[1] * row(rest, tri[1]) +
         hit.barycentric[2] * row(rest, tri[2]);
}

}  // namespace sculpt
