#pragma once
// The geometry of one cell as validation judges it: its volume and the orientation of its
// corners, measured in the cell's own bounding box. Each axis is mapped onto [0, 1] there (after
// an exact power-of-two scaling, so that no extent overflows), which changes no sign, so that a
// check made there does not depend on the units, on the scale of each axis (100 x 0.1 x 0.1), or
// on how large the numbers are (1e300). Each term of a triple product there is at most of order
// one, so its rounding error is a few 1e-16 whatever the cell's scales were.

#include <cstdint>
#include <optional>

#include "mesh/cell_complex.h"

namespace sculpt {

/// Signed volume of cell c (positive for outward-oriented faces): faces are fanned from their
/// centroid and the tetrahedra are taken against the cell centroid. In the mesh's units, so it
/// overflows for cells of size beyond about 1e102.
double cellVolume(const CellComplex& complex, uint32_t c);

/// Cell c's volume over the product of its bounding box's extents: 1 for a box, 1/6 for a
/// tetrahedron at a corner of one, negative for an inside-out cell, 0 for a cell whose box is
/// flat along an axis; NaN when a coordinate is not finite. Never overflows.
double relativeCellVolume(const CellComplex& complex, uint32_t c);

/// A corner of a cell that is inside out.
struct InvertedCorner {
  uint32_t vertex;  ///< the corner's vertex
  double volume;    ///< the corner's volume over the bounding box's (not positive)
};

/// The most inverted corner of cell c, if any corner's volume is at most `tolerance` (relative
/// to the bounding box's). The corners split the cell as one MacCracken-Joy step does, with
/// plain averages for its points: the corner of vertex v is bounded by v, the midpoints of the
/// cell's edges at v, the centres of its faces at v and the centre of the cell (the average of
/// its vertices); the corners' volumes add up to the cell's. Each is positive in a convex cell
/// (a vertex on a straight edge or amid a flat face included). A vertex pushed through the cell,
/// towards its centre and past, turns its corner inside out, and the subdivided child there with
/// it, while the volume of the whole cell can stay positive.
std::optional<InvertedCorner> findInvertedCorner(const CellComplex& complex, uint32_t c,
                                                 double tolerance);

}  // namespace sculpt
