#pragma once
// Topology editing of the control mesh (McDonnell–Qin section 4.1, Fig. 7): delete cells,
// extrude boundary faces, bridge or weld two boundary faces, subdivide cells locally, and tag
// the sharp features (creases, corners) that change the subdivision rules.
//
// Every operation is a pure function: it reads a valid mesh and returns the edited copy with the
// map from old to new vertex ids, or throws std::invalid_argument with one sentence (and no
// result) for bad input or when the result would not validate. Tags of every result are
// normalised (each crease as (low, high), both lists sorted without repeats) and tags that are
// no longer on the boundary are dropped, so saves are deterministic and results always
// validate. New vertices are appended after the surviving old ones.

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "mesh/cell_complex.h"

namespace sculpt {

/// A face of the mesh named by its cell and its index within that cell's face loops.
struct FaceRef {
  uint32_t cell = 0;
  uint32_t face = 0;
  auto operator<=>(const FaceRef&) const = default;
};

/// The result of a topology operation.
struct TopologyEdit {
  CellComplex mesh;                     ///< the edited control mesh (tags mapped)
  std::vector<int64_t> newVertexOfOld;  ///< #V(old): new id of each old vertex, -1 if removed
  std::string label;                    ///< for the undo menu ("Extrude faces")
};

/// The boundary faces of a valid mesh (each as its one cell sees it), in cell and face order.
std::vector<FaceRef> boundaryFaces(const CellComplex& mesh);

/// Removes `cells` and the vertices no other cell uses (tags on them are dropped). Cells after
/// a removed one move down.
TopologyEdit deleteCells(const CellComplex& mesh, std::span<const uint32_t> cells);

/// One new cell on each boundary face, `distanceM` (> 0) along its unit normal: a quad gives a
/// hexahedron, an n-gon a prism with n side quads. Selected faces that share vertices extrude
/// as one block: each new vertex moves along the normalised mean of the unit normals of its
/// selected faces. The old faces become interior.
TopologyEdit extrudeFaces(const CellComplex& mesh, std::span<const FaceRef> faces,
                          double distanceM);

/// McDonnell–Qin "merging": one new cell joining two boundary faces with the same vertex count
/// and no shared vertex. Vertex i of `a` is joined to the vertex of `b` that faces it: of the n
/// cyclic correspondences that keep the new cell's orientation, the one with the least total
/// squared distance (the lowest shift on ties).
TopologyEdit bridgeFaces(const CellComplex& mesh, FaceRef a, FaceRef b);

/// Identifies two boundary faces whose vertices coincide (within `toleranceM`) under the
/// correspondence of bridgeFaces: each pair of vertices becomes one at their midpoint (the
/// vertex of `a` keeps its id, the vertex of `b` is removed) and the two faces become one
/// interior face.
TopologyEdit weldFaces(const CellComplex& mesh, FaceRef a, FaceRef b, double toleranceM);

/// Local subdivision: each selected cell is split linearly into one cell per corner (a
/// hexahedron at a corner with three faces) through its edge midpoints, face centroids (vertex
/// means) and cell centroid (mean of its vertices), so the solid keeps its shape. Unselected
/// neighbours stay conforming: a face they share with a split cell is split into the same
/// quads and a split edge gets its midpoint inserted into their face loops (they become general
/// polyhedra, which MacCracken–Joy refines). Split crease edges stay creased in both halves.
/// The first part of cell c keeps index c; the others are appended in order.
TopologyEdit subdivideCells(const CellComplex& mesh, std::span<const uint32_t> cells);

/// Tags (or, with tagged = false, untags) boundary edges, each given by its two vertices, as
/// creases.
TopologyEdit setCreases(const CellComplex& mesh, std::span<const std::array<uint32_t, 2>> edges,
                        bool tagged);

/// Tags (or untags) boundary vertices as corners.
TopologyEdit setCorners(const CellComplex& mesh, std::span<const uint32_t> vertices, bool tagged);

}  // namespace sculpt
