// Extrusion (McDonnell–Qin Fig. 7b): a new cell grows out of each selected boundary face.
// Faces that share vertices share the new vertices too, so a selected region rises as one block
// instead of as separate columns with slits between them.

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

#include "edit/edit_support.h"
#include "edit/topology_edit.h"

namespace sculpt {

TopologyEdit extrudeFaces(const CellComplex& mesh, std::span<const FaceRef> faces,
                          double distanceM) {
  const Topology topology = edit::checkedTopology(mesh);
  if (!(std::isfinite(distanceM) && distanceM > 0))
    edit::reject("the extrusion distance must be a finite number > 0 (got " +
                 edit::number(distanceM) + ").");
  if (faces.empty()) edit::reject("no faces are selected.");
  std::vector<FaceRef> selected(faces.begin(), faces.end());
  std::sort(selected.begin(), selected.end());
  selected.erase(std::unique(selected.begin(), selected.end()), selected.end());

  // Unit normal of each face, summed at its vertices; new vertices in order of first use.
  const uint32_t numOld = mesh.numVertices();
  std::map<uint32_t, uint32_t> copyOf;            // old vertex -> new vertex
  std::map<uint32_t, Eigen::Vector3d> normalSum;  // old vertex -> sum of unit normals
  for (const FaceRef& face : selected) {
    edit::boundaryFaceId(mesh, topology, face);
    const auto loop = mesh.cellFace(face.cell, face.face);
    const Eigen::Vector3d area = edit::areaVector(mesh, loop);
    if (!(area.norm() > 0)) edit::reject(edit::faceName(face) + " has no area, so no normal.");
    for (uint32_t v : loop) {
      if (copyOf.emplace(v, numOld + static_cast<uint32_t>(copyOf.size())).second)
        normalSum[v] = Eigen::Vector3d::Zero();
      normalSum[v] += area.normalized();
    }
  }

  TopologyEdit edit;
  edit.newVertexOfOld = edit::identityVertexMap(numOld);
  edit.mesh = mesh;
  Points& positions = edit.mesh.positions;
  positions.conservativeResize(numOld + static_cast<Eigen::Index>(copyOf.size()), 3);
  for (const auto& [v, copy] : copyOf) {
    const Eigen::Vector3d& sum = normalSum[v];
    if (!(sum.norm() > 1e-9))  // a sum of unit vectors: scale-free
      edit::reject("the selected faces around vertex " + std::to_string(v) +
                   " point in opposite directions, so it has no direction to move in.");
    positions.row(copy) = (edit::position(mesh, v) + distanceM * sum.normalized()).transpose();
  }

  // The new cell: the old face reversed (now shared), its copy on top, a quad per side.
  for (const FaceRef& face : selected) {
    const auto loop = mesh.cellFace(face.cell, face.face);
    const size_t n = loop.size();
    std::vector<std::vector<uint32_t>> cell;
    cell.emplace_back(loop.rbegin(), loop.rend());
    std::vector<uint32_t> top;
    for (uint32_t v : loop) top.push_back(copyOf[v]);
    cell.push_back(top);
    for (size_t i = 0; i < n; ++i) {
      const uint32_t a = loop[i], b = loop[(i + 1) % n];
      cell.push_back({a, b, copyOf[b], copyOf[a]});
    }
    edit.mesh.addCell(cell);
  }
  return edit::finishEdit(std::move(edit), selected.size() == 1 ? "Extrude face" : "Extrude faces");
}

}  // namespace sculpt
