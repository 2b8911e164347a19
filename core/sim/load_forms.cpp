#include "sim/load_forms.h"

#include <Eigen/Geometry>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace sculpt {
namespace {

std::string text(double value) {
  std::ostringstream s;
  s << value;
  return s.str();
}

std::string text(const Eigen::Vector3d& v) {
  std::ostringstream s;
  s << "(" << v[0] << ", " << v[1] << ", " << v[2] << ")";
  return s.str();
}

[[noreturn]] void reject(const std::string& sentence) { throw std::invalid_argument(sentence); }

void checkPoint(const FemModel& model, const MaterialPoint& point, const char* form) {
  if (point.element >= model.mesh().numElements())
    reject(std::string(form) + ": material point element " + std::to_string(point.element) +
           " is out of range (the model has " + std::to_string(model.mesh().numElements()) +
           " elements).");
  if (!point.local.allFinite() || (point.local.array() < 0.0).any() ||
      (point.local.array() > 1.0).any())
    reject(std::string(form) + ": material point local coordinates " + text(point.local) +
           " must be finite and lie in [0, 1]^3.");
}

void checkVector(const Eigen::Vector3d& v, const char* form, const char* what) {
  if (!v.allFinite())
    reject(std::string(form) + ": the " + what + " " + text(v) + " is not finite.");
}

void checkStiffness(double k, const char* form, const char* unit) {
  if (!std::isfinite(k) || k < 0)
    reject(std::string(form) + ": the stiffness " + text(k) + " " + unit +
           " must be finite and non-negative.");
}

Eigen::Vector3d weightedSum(const std::vector<std::pair<uint32_t, double>>& weights,
                            const Points& control) {
  Eigen::Vector3d x = Eigen::Vector3d::Zero();
  for (const auto& [id, w] : weights) x += w * control.row(id).transpose();
  return x;
}

void scatter(const std::vector<std::pair<uint32_t, double>>& weights, const Eigen::Vector3d& v,
             Points& out) {
  for (const auto& [id, w] : weights) out.row(id) += w * v.transpose();
}

Eigen::Vector3d row(const Points& p, uint32_t i) { return p.row(i).transpose(); }

}  // namespace

// ---------------------------------------------------------------------------------------------

PointForceForm::PointForceForm(const FemModel& model, const MaterialPoint& point,
                               const Eigen::Vector3d& force)
    : point_(point), force_(Eigen::Vector3d::Zero()) {
  checkPoint(model, point, "point force");
  setForce(force);
  weights_ = controlWeights(model.mesh(), point);
}

void PointForceForm::setForce(const Eigen::Vector3d& force) {
  checkVector(force, "point force", "force");
  force_ = force;
}

Eigen::Vector3d PointForceForm::position(const Points& control) const {
  return weightedSum(weights_, control);
}

double PointForceForm::energy(const FormState& x) const {
  return -force_.dot(position(x.control));
}

void PointForceForm::addGradient(const FormState&, FormGradient& g) const {
  scatter(weights_, -force_, g.control);
}

// ---------------------------------------------------------------------------------------------

PenaltySpringForm::PenaltySpringForm(const FemModel& model, const MaterialPoint& point,
                                     const Eigen::Vector3d& target, double stiffness)
    : point_(point), target_(Eigen::Vector3d::Zero()), stiffness_(0.0) {
  checkPoint(model, point, "penalty spring");
  setTarget(target);
  setStiffness(stiffness);
  weights_ = controlWeights(model.mesh(), point);
}

void PenaltySpringForm::setTarget(const Eigen::Vector3d& target) {
  checkVector(target, "penalty spring", "target");
  target_ = target;
}

void PenaltySpringForm::setStiffness(double stiffness) {
  checkStiffness(stiffness, "penalty spring", "N/m");
  stiffness_ = stiffness;
}

Eigen::Vector3d PenaltySpringForm::position(const Points& control) const {
  return weightedSum(weights_, control);
}

double PenaltySpringForm::energy(const FormState& x) const {
  return 0.5 * stiffness_ * (position(x.control) - target_).squaredNorm();
}

void PenaltySpringForm::addGradient(const FormState& x, FormGradient& g) const {
  scatter(weights_, stiffness_ * (position(x.control) - target_), g.control);
}

void PenaltySpringForm::addHessianProduct(const FormState&, const FormState& dx,
                                          FormGradient& r) const {
  scatter(weights_, stiffness_ * position(dx.control), r.control);
}

// ---------------------------------------------------------------------------------------------

std::vector<std::array<uint32_t, 3>> boundaryTriangles(const FemModel& model,
                                                       const SphereRegion& region) {
  checkVector(region.centre, "pressure", "region centre");
  if (std::isnan(region.radius) || region.radius < 0)
    reject("pressure: the region radius " + text(region.radius) +
           " m must be non-negative (infinity for the whole boundary).");
  std::vector<std::array<uint32_t, 3>> triangles;
  const CellComplex& cells = model.subdivision().finest();
  const Topology& topology = model.subdivision().finestTopology();
  const bool everywhere = std::isinf(region.radius);
  for (uint32_t f = 0; f < topology.numFaces(); ++f) {
    if (!topology.faceIsBoundary[f]) continue;
    const auto cell = static_cast<uint32_t>(topology.faceCells[f][0]);
    const int slot = topology.faceSlot(cell, f);
    if (slot < 0) continue;  // not reachable for a well-formed topology
    const std::vector<uint32_t> loop = topology.outwardLoop(cell, static_cast<uint32_t>(slot));
    if (loop.size() < 3) continue;
    if (!everywhere) {
      Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
      for (uint32_t v : loop) centroid += row(cells.positions, v);
      centroid /= static_cast<double>(loop.size());
      if ((centroid - region.centre).norm() > region.radius) continue;
    }
    for (size_t i = 1; i + 1 < loop.size(); ++i)
      triangles.push_back({loop[0], loop[i], loop[i + 1]});
  }
  return triangles;
}

PressureForm::PressureForm(const FemModel& model, double pressure, const SphereRegion& region)
    : pressure_(0.0) {
  setPressure(pressure);
  triangles_ = boundaryTriangles(model, region);
}

void PressureForm::setPressure(double pressure) {
  if (!std::isfinite(pressure))
    reject("pressure: the pressure " + text(pressure) + " Pa is not finite.");
  pressure_ = pressure;
}

double PressureForm::regionVolume(const Points& nodes) const {
  double volume = 0;
  for (const auto& t : triangles_)
    volume += row(nodes, t[0]).dot(row(nodes, t[1]).cross(row(nodes, t[2])));
  return volume / 6.0;
}

double PressureForm::energy(const FormState& x) const { return -pressure_ * regionVolume(x.nodes); }

void PressureForm::addGradient(const FormState& x, FormGradient& g) const {
  const double s = -pressure_ / 6.0;
  for (const auto& t : triangles_) {
    const Eigen::Vector3d x0 = row(x.nodes, t[0]), x1 = row(x.nodes, t[1]), x2 = row(x.nodes, t[2]);
    g.nodes.row(t[0]) += s * x1.cross(x2).transpose();
    g.nodes.row(t[1]) += s * x2.cross(x0).transpose();
    g.nodes.row(t[2]) += s * x0.cross(x1).transpose();
  }
}

void PressureForm::addHessianProduct(const FormState& x, const FormState& dx,
                                     FormGradient& r) const {
  const double s = -pressure_ / 6.0;
  for (const auto& t : triangles_) {
    const Eigen::Vector3d x0 = row(x.nodes, t[0]), x1 = row(x.nodes, t[1]), x2 = row(x.nodes, t[2]);
    const Eigen::Vector3d d0 = row(dx.nodes, t[0]), d1 = row(dx.nodes, t[1]),
                          d2 = row(dx.nodes, t[2]);
    r.nodes.row(t[0]) += s * (d1.cross(x2) + x1.cross(d2)).transpose();
    r.nodes.row(t[1]) += s * (d2.cross(x0) + x2.cross(d0)).transpose();
    r.nodes.row(t[2]) += s * (d0.cross(x1) + x0.cross(d1)).transpose();
  }
}

// ---------------------------------------------------------------------------------------------

GroundContactForm::GroundContactForm(const FemModel& model, const Eigen::Vector3d& normal,
                                     double offset, double stiffness)
    : normal_(Eigen::Vector3d::UnitZ()), offset_(0.0), stiffness_(0.0) {
  checkVector(normal, "ground contact", "normal");
  const double length = normal.norm();
  if (!(length > 0) || !std::isfinite(length))
    reject("ground contact: the normal " + text(normal) + " must be a non-zero vector.");
  if (!std::isfinite(offset))
    reject("ground contact: the offset " + text(offset) + " m is not finite.");
  setStiffness(stiffness);
  normal_ = normal / length;
  offset_ = offset;

  const CellComplex& cells = model.subdivision().finest();
  const Topology& topology = model.subdivision().finestTopology();
  std::vector<double> area(cells.numVertices(), 0.0);
  for (uint32_t f = 0; f < topology.numFaces(); ++f) {
    if (!topology.faceIsBoundary[f]) continue;
    const auto loop = topology.faceVertices.row(f);
    if (loop.size() < 3) continue;
    // Norm of the vector area, fanned from the first vertex (the area for a planar face).
    Eigen::Vector3d vectorArea = Eigen::Vector3d::Zero();
    const Eigen::Vector3d p0 = row(cells.positions, loop[0]);
    for (size_t i = 1; i + 1 < loop.size(); ++i)
      vectorArea += (row(cells.positions, loop[i]) - p0)
                        .cross(row(cells.positions, loop[i + 1]) - p0);
    const double share = 0.5 * vectorArea.norm() / static_cast<double>(loop.size());
    for (uint32_t v : loop) area[v] += share;
  }
  for (uint32_t v = 0; v < cells.numVertices(); ++v)
    if (topology.vertexIsBoundary[v] && area[v] > 0) nodeAreas_.emplace_back(v, area[v]);
}

void GroundContactForm::setStiffness(double stiffness) {
  checkStiffness(stiffness, "ground contact", "N/m^3");
  stiffness_ = stiffness;
}

size_t GroundContactForm::numInContact(const Points& nodes) const {
  size_t count = 0;
  for (const auto& [v, a] : nodeAreas_)
    if (offset_ - normal_.dot(row(nodes, v)) > 0) ++count;
  return count;
}

double GroundContactForm::energy(const FormState& x) const {
  double sum = 0;
  for (const auto& [v, a] : nodeAreas_) {
    const double depth = offset_ - normal_.dot(row(x.nodes, v));
    if (depth > 0) sum += a * depth * depth;
  }
  return 0.5 * stiffness_ * sum;
}

void GroundContactForm::addGradient(const FormState& x, FormGradient& g) const {
  for (const auto& [v, a] : nodeAreas_) {
    const double depth = offset_ - normal_.dot(row(x.nodes, v));
    if (depth > 0) g.nodes.row(v) -= (stiffness_ * a * depth) * normal_.transpose();
  }
}

void GroundContactForm::addHessianProduct(const FormState& x, const FormState& dx,
                                          FormGradient& r) const {
  for (const auto& [v, a] : nodeAreas_) {
    const double depth = offset_ - normal_.dot(row(x.nodes, v));
    if (depth > 0)
      r.nodes.row(v) += (stiffness_ * a * normal_.dot(row(dx.nodes, v))) * normal_.transpose();
  }
}

}  // namespace sculpt
