#pragma once
// Pieces shared by the topology operations (topology_edit.h): checked input, selections, face
// geometry, renumbering and the final normalise-and-validate step. Internal to core/edit.

#include <Eigen/Core>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "edit/topology_edit.h"
#include "mesh/topology.h"
#include "mesh/validation.h"

namespace sculpt::edit {

/// Throws std::invalid_argument with `sentence` (which ends with a full stop).
[[noreturn]] void reject(const std::string& sentence);

/// The message of the first error among `issues`, empty when there is none.
std::string firstError(const std::vector<ValidationIssue>& issues);

/// The topology of `mesh`; throws when the mesh does not validate (edits need a valid input).
Topology checkedTopology(const CellComplex& mesh);

/// A number for messages: up to 6 significant digits ("0.5", "1e-06", "-1").
std::string number(double value);

/// "face 2 of cell 5".
std::string faceName(FaceRef face);

/// The face id of a boundary face; throws when the cell or face index is out of range or the
/// face is interior.
uint32_t boundaryFaceId(const CellComplex& mesh, const Topology& topology, FaceRef face);

/// The cells sorted without repeats; throws when empty or when one is out of range.
std::vector<uint32_t> cellSelection(const CellComplex& mesh, std::span<const uint32_t> cells);

/// Newell's area vector of a loop: its direction is the loop's normal (counter-clockwise seen
/// from its tip), its length the area of a planar loop.
Eigen::Vector3d areaVector(const CellComplex& mesh, std::span<const uint32_t> loop);

Eigen::Vector3d position(const CellComplex& mesh, uint32_t v);

/// 0, 1, ..., numVertices - 1: the vertex map of an edit that keeps every vertex's id.
std::vector<int64_t> identityVertexMap(uint32_t numVertices);

/// Keeps the cells with keep[c] set and replaces every vertex v by representative[v], then drops
/// the vertices no kept cell uses and numbers the rest in increasing order. Tags follow their
/// vertices (dropped when a vertex goes or a crease collapses). Positions are taken from
/// `positions` (#V(old) rows). Returns the mesh and, for each old vertex, the new id of its
/// representative (-1 when that was dropped).
TopologyEdit keepCells(const CellComplex& mesh, const std::vector<uint8_t>& keep,
                       const std::vector<uint32_t>& representative, const Points& positions);

/// Normalises the tags of `edit.mesh` (creases as (low, high), sorted lists without repeats),
/// drops the tags that are not on the boundary, and validates; throws with the first error when
/// the edited mesh would be invalid. Returns the edit with `label` set.
TopologyEdit finishEdit(TopologyEdit edit, std::string label);

}  // namespace sculpt::edit
