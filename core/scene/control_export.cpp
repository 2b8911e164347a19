#include "scene/control_export.h"

#include <stdexcept>
#include <string>

#include "io/vtk_writer.h"
#include "mesh/topology.h"

namespace sculpt {

void writeDeformedControlVtk(const CellComplex& rest, const Points& positions,
                             const std::filesystem::path& path) {
  if (positions.rows() != rest.positions.rows())
    throw std::invalid_argument("the state has " + std::to_string(positions.rows()) +
                                " control points, the control mesh " +
                                std::to_string(rest.positions.rows()));
  CellComplex deformed = rest;
  deformed.positions = positions;
  const Points displacement = positions - rest.positions;
  const VtkPointVectors field{"displacement", &displacement};
  writeVtk(deformed, buildTopology(rest), path, {&field, 1});
}

}  // namespace sculpt
