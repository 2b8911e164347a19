#include "edit/topology_operation.h"

#include "edit/edit_support.h"

namespace sculpt {
namespace {

constexpr const char* kOpNames[] = {"delete",    "extrude", "bridge", "weld",
                                    "subdivide", "crease",  "corner"};

}  // namespace

const char* topologyOpName(TopologyOp op) { return kOpNames[static_cast<int>(op)]; }

std::optional<TopologyOp> parseTopologyOp(std::string_view name) {
  for (int i = 0; i < static_cast<int>(std::size(kOpNames)); ++i)
    if (name == kOpNames[i]) return static_cast<TopologyOp>(i);
  return std::nullopt;
}

TopologyEdit applyTopologyOperation(const CellComplex& mesh, const TopologyOperation& operation) {
  const auto facePair = [&]() {
    if (operation.faces.size() != 2)
      edit::reject(std::string(topologyOpName(operation.op)) + " needs exactly 2 faces (got " +
                   std::to_string(operation.faces.size()) + ").");
    return std::pair{operation.faces[0], operation.faces[1]};
  };
  switch (operation.op) {
    case TopologyOp::Delete:
      return deleteCells(mesh, operation.cells);
    case TopologyOp::Extrude:
      return extrudeFaces(mesh, operation.faces, operation.distanceM);
    case TopologyOp::Bridge: {
      const auto [a, b] = facePair();
      return bridgeFaces(mesh, a, b);
    }
    case TopologyOp::Weld: {
      const auto [a, b] = facePair();
      return weldFaces(mesh, a, b, operation.toleranceM);
    }
    case TopologyOp::Subdivide:
      return subdivideCells(mesh, operation.cells);
    case TopologyOp::Crease:
      return setCreases(mesh, operation.edges, !operation.untag);
    case TopologyOp::Corner:
      return setCorners(mesh, operation.vertices, !operation.untag);
  }
  edit::reject("unknown topology operation.");
}

}  // namespace sculpt
