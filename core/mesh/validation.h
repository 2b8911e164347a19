#pragma once
// Validation of a cell complex: every problem with the element index and a sentence.

#include <cstdint>
#include <string>
#include <vector>

#include "mesh/cell_complex.h"
#include "mesh/cell_geometry.h"  // cellVolume, for the callers that check volumes themselves

namespace sculpt {

struct ValidationIssue {
  /// Frozen values: they appear in reports and tests.
  enum class Kind : int {
    IndexOutOfRange = 1,
    NonFiniteCoordinate = 2,
    CellNotClosed = 3,
    InconsistentOrientation = 4,
    FaceSharedByMoreThanTwoCells = 5,
    InteriorEdgeValenceTwo = 6,
    NonManifoldBoundaryEdge = 7,
    NonManifoldBoundaryVertex = 8,
    NonPositiveVolume = 9,
    UnusedVertex = 10,
    DegenerateFace = 11,
    EmptyMesh = 12,
    BadTag = 13,
    CellNotBall = 14,     ///< a closed cell whose faces are not one sphere-like surface
    InvertedCorner = 15,  ///< a positive-volume cell with a corner pushed through it
  };
  enum class Severity { Error, Warning };
  /// What the element index refers to.
  enum class Element { Mesh, Vertex, Face, Cell, Edge };

  Kind kind;
  Severity severity;
  Element element;
  uint32_t index;       ///< cell / vertex index (or the edge's first vertex)
  std::string message;  ///< one sentence naming the element and the problem
};

/// Checks the complex; returns every problem found (errors and warnings).
std::vector<ValidationIssue> validate(const CellComplex& complex);

/// True when no issue is an error.
bool isValid(const std::vector<ValidationIssue>& issues);

/// The message of the first error, or an empty string when there is none.
std::string firstErrorMessage(const std::vector<ValidationIssue>& issues);

}  // namespace sculpt
