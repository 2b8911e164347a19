// Deletion (McDonnell–Qin Fig. 7a): the selected cells go, and with them the vertices that no
// remaining cell uses.

#include <numeric>

#include "edit/edit_support.h"
#include "edit/topology_edit.h"

namespace sculpt {

TopologyEdit deleteCells(const CellComplex& mesh, std::span<const uint32_t> cells) {
  edit::checkedTopology(mesh);
  const std::vector<uint32_t> selected = edit::cellSelection(mesh, cells);
  if (selected.size() == mesh.numCells())
    edit::reject("cannot delete every cell (at least one must remain).");
  std::vector<uint8_t> keep(mesh.numCells(), 1);
  for (uint32_t c : selected) keep[c] = 0;
  std::vector<uint32_t> identity(mesh.numVertices());
  std::iota(identity.begin(), identity.end(), 0u);
  return edit::finishEdit(edit::keepCells(mesh, keep, identity, mesh.positions),
                          selected.size() == 1 ? "Delete cell" : "Delete cells");
}

}  // namespace sculpt
