#pragma once
// What every animation writer reads: a take's frames, evaluated on demand. A take is a list of
// frames at a fixed simulated frame rate, in segments of one topology each (a new segment starts
// where the surface's topology changed, e.g. after a topology edit rebuilt the scene). Each frame
// gives the embedded surface's positions and normals (float32, as the window draws them) and the
// level-K solid's node positions and painted per-cell fields (for VTK).
//
// evaluate*() reuse per-frame state: an AnimatedSurface is used by one thread at a time.

#include <cstdint>
#include <memory>
#include <vector>

#include "mesh/surface_mesh.h"
#include "mesh/volume_mesh.h"

namespace sculpt {

/// Frames [first, first + count) share one topology.
struct FrameRange {
  uint32_t first = 0;
  uint32_t count = 0;
};

/// One frame of the embedded surface. Positions and normals are per position of the source
/// surface (SurfaceMesh::positions), in its order; sourceNormals per normal of the source
/// surface (SurfaceMesh::normals, empty when it has none), moved with the surface.
struct SurfaceFrameData {
  std::vector<float> positions;      ///< 3 per vertex
  std::vector<float> normals;        ///< 3 per vertex, unit length
  std::vector<float> sourceNormals;  ///< 3 per source normal
  /// Set false before evaluating when only positions are needed (normals cost more than them).
  bool withNormals = true;
};

/// Per cell of the level-K solid: the painted material, as the window shows it.
struct CellFields {
  std::vector<float> youngs;   ///< Pa
  std::vector<float> density;  ///< kg/m^3
  std::vector<float> damping;  ///< kg/(m^3 s)
};

/// One frame of the level-K solid.
struct SolidFrameData {
  Points nodes;          ///< #cell-mesh nodes by 3, deformed
  Points displacement;   ///< nodes minus the rest nodes
  CellFields fields;
};

class AnimatedSurface {
 public:
  virtual ~AnimatedSurface() = default;

  virtual double fps() const = 0;
  virtual uint32_t frameCount() const = 0;
  /// Seconds from the take's start: frame / fps.
  double frameTime(uint32_t frame) const { return frame / fps(); }

  virtual uint32_t segmentCount() const = 0;
  virtual FrameRange segment(uint32_t s) const = 0;
  uint32_t segmentOf(uint32_t frame) const;

  /// The surface at rest, as its file has it: positions (the morph base), faces with their
  /// texture-coordinate and normal indices, texture coordinates and normals (either may be empty).
  virtual const SurfaceMesh& restSurface(uint32_t segment) const = 0;
  /// Per vertex rest normals (unit), 3 per vertex.
  virtual const std::vector<float>& restVertexNormals(uint32_t segment) const = 0;
  /// The drawn triangles: 3 position indices each (faces fanned).
  virtual const std::vector<uint32_t>& triangles(uint32_t segment) const = 0;
  /// The level-K solid at rest: hexahedra and tetrahedra (VolumeMesh).
  virtual const VolumeMesh& restSolid(uint32_t segment) const = 0;

  /// Fills `out` for `frame` (< frameCount()).
  virtual void evaluateSurface(uint32_t frame, SurfaceFrameData& out) const = 0;
  virtual void evaluateSolid(uint32_t frame, SolidFrameData& out) const = 0;
};

inline uint32_t AnimatedSurface::segmentOf(uint32_t frame) const {
  for (uint32_t s = 0; s < segmentCount(); ++s) {
    const FrameRange r = segment(s);
    if (frame >= r.first && frame < r.first + r.count) return s;
  }
  return segmentCount() == 0 ? 0 : segmentCount() - 1;
}

}  // namespace sculpt
