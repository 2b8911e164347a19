#pragma once
// The cross-section of a cell mesh by a plane, as triangles carrying a scalar per vertex: what the
// window draws to show a field (stiffness, density, displacement, strain energy) inside the solid.
//
// Each hexahedron is split into the 6 tetrahedra around its 0-6 diagonal (the Kuhn split, so
// neighbouring lattice cells cut their shared faces alike and the slice has no cracks), and every
// tetrahedron is cut by marching tetrahedra: nothing, one triangle or one quadrilateral.

#include <cstdint>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "mesh/cell_complex.h"
#include "mesh/volume_mesh.h"

namespace sculpt {

struct PlaneSlice {
  std::vector<float> positions;     ///< xyz per vertex (3 floats each)
  std::vector<float> values;        ///< one scalar per vertex
  std::vector<uint32_t> triangles;  ///< 3 vertex ids per triangle, wound counter-clockwise seen
                                    ///< from the side the plane normal points to

  uint32_t numVertices() const { return static_cast<uint32_t>(values.size()); }
  uint32_t numTriangles() const { return static_cast<uint32_t>(triangles.size() / 3); }
};

/// Cuts `mesh` by the plane {x : normal . x = offset}.
/// @param[in] mesh         cells (tetrahedra and VTK-ordered hexahedra); its positions are unused
/// @param[in] nodes        #nodes by 3 node positions (possibly deformed), mesh numbering
/// @param[in] normal       plane normal, any non-zero finite length
/// @param[in] offset       plane offset in units of |normal| times metres
/// @param[in] nodeValues   #nodes scalars, interpolated linearly along the cut edges, or empty
/// @param[in] cellValues   #cells scalars, constant on each cell's polygons, or empty
/// At most one of nodeValues and cellValues may be given; with neither, all values are 0.
/// With node values (or none) vertices on a shared edge are shared; with cell values each cell
/// has its own vertices so that colours do not bleed. A node exactly on the plane counts as
/// below it, so a cell face lying in the plane is produced once (by the cell above it).
/// Throws std::invalid_argument for a zero or non-finite normal, a non-finite offset, sizes that
/// do not match the mesh, both value arrays given, or a cell that is neither a tetrahedron nor a
/// hexahedron or names a node out of range.
PlaneSlice slicePlane(const VolumeMesh& mesh, const Points& nodes, const Eigen::Vector3d& normal,
                      double offset, std::span<const double> nodeValues,
                      std::span<const double> cellValues);

}  // namespace sculpt
