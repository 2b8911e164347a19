#pragma once
// A topology operation as data (what a session script's "topology" event or a window tool
// asks for), and running it on a mesh with the functions of topology_edit.h.

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "edit/topology_edit.h"

namespace sculpt {

/// Frozen names in scripts: "delete", "extrude", "bridge", "weld", "subdivide", "crease",
/// "corner".
enum class TopologyOp { Delete, Extrude, Bridge, Weld, Subdivide, Crease, Corner };

const char* topologyOpName(TopologyOp op);
/// The op of a script name; nullopt for an unknown name.
std::optional<TopologyOp> parseTopologyOp(std::string_view name);

struct TopologyOperation {
  TopologyOp op = TopologyOp::Delete;
  std::vector<uint32_t> cells;                 ///< delete, subdivide
  std::vector<FaceRef> faces;                  ///< extrude (any number), bridge and weld (2)
  double distanceM = 0;                        ///< extrude
  double toleranceM = 1e-6;                    ///< weld
  std::vector<std::array<uint32_t, 2>> edges;  ///< crease
  std::vector<uint32_t> vertices;              ///< corner
  bool untag = false;                          ///< crease, corner: remove the tags instead
};

/// Runs the operation. Throws std::invalid_argument (one sentence) as the operation does, and
/// when bridge or weld is not given exactly two faces.
TopologyEdit applyTopologyOperation(const CellComplex& mesh, const TopologyOperation& operation);

}  // namespace sculpt
