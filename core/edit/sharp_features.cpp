// Local changes to the subdivision rules (McDonnell–Qin Fig. 7b): crease edges and corner
// vertices on the boundary, which MacCracken–Joy and Catmull–Clark keep sharp.

#include <algorithm>
#include <numeric>

#include "edit/edit_support.h"
#include "edit/topology_edit.h"

namespace sculpt {
namespace {

// The unchanged mesh with identity vertex map, to receive new tags.
TopologyEdit sameMesh(const CellComplex& mesh) {
  TopologyEdit edit;
  edit.mesh = mesh;
  edit.newVertexOfOld = edit::identityVertexMap(mesh.numVertices());
  return edit;
}

}  // namespace

TopologyEdit setCreases(const CellComplex& mesh, std::span<const std::array<uint32_t, 2>> edges,
                        bool tagged) {
  const Topology topology = edit::checkedTopology(mesh);
  if (edges.empty()) edit::reject("no edges are selected.");
  TopologyEdit edit = sameMesh(mesh);
  auto& creases = edit.mesh.creases;
  for (auto& crease : creases)
    if (crease[0] > crease[1]) std::swap(crease[0], crease[1]);
  for (const auto& [a, b] : edges) {
    const std::string name = "edge (" + std::to_string(a) + ", " + std::to_string(b) + ")";
    const int64_t e = topology.findEdge(a, b);
    if (e < 0) edit::reject(name + " is not an edge of the mesh.");
    if (!topology.edgeIsBoundary[static_cast<size_t>(e)])
      edit::reject(name + " is an interior edge; only boundary edges can be creases.");
    const std::array<uint32_t, 2> key{std::min(a, b), std::max(a, b)};
    if (tagged)
      creases.push_back(key);
    else
      std::erase(creases, key);
  }
  return edit::finishEdit(std::move(edit), tagged ? "Tag creases" : "Clear creases");
}

TopologyEdit setCorners(const CellComplex& mesh, std::span<const uint32_t> vertices, bool tagged) {
  const Topology topology = edit::checkedTopology(mesh);
  if (vertices.empty()) edit::reject("no vertices are selected.");
  TopologyEdit edit = sameMesh(mesh);
  for (uint32_t v : vertices) {
    if (v >= mesh.numVertices())
      edit::reject("vertex " + std::to_string(v) + " is out of range (the mesh has " +
                   std::to_string(mesh.numVertices()) + " vertices).");
    if (!topology.vertexIsBoundary[v])
      edit::reject("vertex " + std::to_string(v) +
                   " is an interior vertex; only boundary vertices can be corners.");
    if (tagged)
      edit.mesh.corners.push_back(v);
    else
      std::erase(edit.mesh.corners, v);
  }
  return edit::finishEdit(std::move(edit), tagged ? "Tag corners" : "Clear corners");
}

}  // namespace sculpt
