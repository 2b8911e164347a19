// Merging (McDonnell–Qin Fig. 7c): two boundary faces are joined, either by a new cell between
// them (bridge) or, when they already touch, by identifying their vertices (weld).

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>

#include "edit/edit_support.h"
#include "edit/topology_edit.h"

namespace sculpt {
namespace {

// Two distinct boundary faces with as many vertices and no vertex in common: the vertex of `b`
// facing each vertex of `a`. Facing faces wind opposite ways, so vertex i of a meets vertex
// (s - i) mod n of b; s minimises the summed squared distances (lowest s on ties).
std::vector<uint32_t> facingVertices(const CellComplex& mesh, FaceRef a, FaceRef b,
                                     const std::string& verb, const std::string& participle) {
  const Topology topology = edit::checkedTopology(mesh);
  const uint32_t fa = edit::boundaryFaceId(mesh, topology, a);
  const uint32_t fb = edit::boundaryFaceId(mesh, topology, b);
  if (fa == fb) edit::reject("cannot " + verb + " a face with itself.");
  const auto la = mesh.cellFace(a.cell, a.face), lb = mesh.cellFace(b.cell, b.face);
  const size_t n = la.size();
  if (lb.size() != n)
    edit::reject(edit::faceName(a) + " has " + std::to_string(n) + " vertices and " +
                 edit::faceName(b) + " has " + std::to_string(lb.size()) +
                 "; they must have as many to " + verb + " them.");
  for (uint32_t v : la)
    if (std::find(lb.begin(), lb.end(), v) != lb.end())
      edit::reject(edit::faceName(a) + " and " + edit::faceName(b) + " share vertex " +
                   std::to_string(v) + "; only faces that share no vertex can be " + participle +
                   ".");
  size_t bestShift = 0;
  double best = std::numeric_limits<double>::infinity();
  for (size_t s = 0; s < n; ++s) {
    double sum = 0;
    for (size_t i = 0; i < n; ++i)
      sum +=
          (edit::position(mesh, la[i]) - edit::position(mesh, lb[(s + n - i) % n])).squaredNorm();
    if (sum < best) best = sum, bestShift = s;
  }
  std::vector<uint32_t> facing(n);
  for (size_t i = 0; i < n; ++i) facing[i] = lb[(bestShift + n - i) % n];
  return facing;
}

}  // namespace

TopologyEdit bridgeFaces(const CellComplex& mesh, FaceRef a, FaceRef b) {
  const std::vector<uint32_t> top = facingVertices(mesh, a, b, "bridge", "bridged");
  const auto bottom = mesh.cellFace(a.cell, a.face);
  const size_t n = bottom.size();
  // Like an extrusion of a whose top is b: a reversed, b reversed (= top), a quad per side.
  std::vector<std::vector<uint32_t>> cell;
  cell.emplace_back(bottom.rbegin(), bottom.rend());
  cell.push_back(top);
  for (size_t i = 0; i < n; ++i)
    cell.push_back({bottom[i], bottom[(i + 1) % n], top[(i + 1) % n], top[i]});
  TopologyEdit edit;
  edit.mesh = mesh;
  edit.mesh.addCell(cell);
  edit.newVertexOfOld = edit::identityVertexMap(mesh.numVertices());
  return edit::finishEdit(std::move(edit), "Bridge faces");
}

TopologyEdit weldFaces(const CellComplex& mesh, FaceRef a, FaceRef b, double toleranceM) {
  if (!(std::isfinite(toleranceM) && toleranceM >= 0))
    edit::reject("the weld tolerance must be a finite number >= 0 (got " +
                 edit::number(toleranceM) + ").");
  const std::vector<uint32_t> facing = facingVertices(mesh, a, b, "weld", "welded");
  const auto la = mesh.cellFace(a.cell, a.face);
  std::vector<uint32_t> representative(mesh.numVertices());
  std::iota(representative.begin(), representative.end(), 0u);
  Points positions = mesh.positions;
  for (size_t i = 0; i < la.size(); ++i) {
    const Eigen::Vector3d pa = edit::position(mesh, la[i]), pb = edit::position(mesh, facing[i]);
    if ((pa - pb).norm() > toleranceM)
      edit::reject(edit::faceName(a) + " and " + edit::faceName(b) + " do not coincide: vertex " +
                   std::to_string(la[i]) + " is " + edit::number((pa - pb).norm()) +
                   " m from vertex " + std::to_string(facing[i]) + " (tolerance " +
                   edit::number(toleranceM) + " m).");
    representative[facing[i]] = la[i];
    positions.row(la[i]) = (0.5 * (pa + pb)).transpose();
  }
  const std::vector<uint8_t> keep(mesh.numCells(), 1);
  return edit::finishEdit(edit::keepCells(mesh, keep, representative, positions), "Weld faces");
}

}  // namespace sculpt
