#include "mesh/cell_complex.h"

namespace sculpt {

void CellComplex::addCell(const std::vector<std::vector<uint32_t>>& faceLoops) {
  for (const auto& loop : faceLoops) addLoop(loop);
  finishCell();
}

}  // namespace sculpt
