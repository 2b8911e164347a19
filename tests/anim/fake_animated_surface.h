#pragma once
// An analytic AnimatedSurface for the writers' tests: an open grid of quads (with texture
// coordinates, OBJ-style corners, one normal per position) over one hexahedron and its centre
// split in tetrahedra, moved by a known motion. Segment s (of `segments`) has a grid of
// (4 + s) x 3 positions, so every segment has its own topology.

#include <cmath>
#include <vector>

#include "anim/animated_surface.h"

namespace sculpt::test {

class FakeAnimatedSurface : public AnimatedSurface {
 public:
  /// `frames` frames at `fps`, split into `segments` equal segments; `amplitude` in metres.
  FakeAnimatedSurface(uint32_t frames, double fps, uint32_t segments = 1, double amplitude = 0.1)
      : fps_(fps), frames_(frames), amplitude_(amplitude) {
    for (uint32_t s = 0; s < segments; ++s) {
      Segment seg;
      seg.range.first = frames * s / segments;
      seg.range.count = frames * (s + 1) / segments - seg.range.first;
      const uint32_t nx = 4 + s, ny = 3;
      SurfaceMesh& m = seg.rest;
      m.positions.resize(nx * ny, 3);
      m.texcoords.resize(nx * ny, 2);
      m.normals.resize(nx * ny, 3);
      for (uint32_t j = 0; j < ny; ++j)
        for (uint32_t i = 0; i < nx; ++i) {
          const uint32_t v = j * nx + i;
          m.positions.row(v) << double(i) / (nx - 1), double(j) / (ny - 1), 0.25;
          m.texcoords.row(v) << double(i) / (nx - 1), double(j) / (ny - 1);
          m.normals.row(v) << 0.0, 0.0, 1.0;
        }
      std::vector<SurfaceCorner> corners;
      std::vector<uint32_t> offsets{0};
      for (uint32_t j = 0; j + 1 < ny; ++j)
        for (uint32_t i = 0; i + 1 < nx; ++i) {
          for (const uint32_t v :
               {j * nx + i, j * nx + i + 1, (j + 1) * nx + i + 1, (j + 1) * nx + i}) {
            corners.push_back({v, v, v});
          }
          const uint32_t a = j * nx + i, b = a + 1, c = a + nx + 1, d = a + nx;
          seg.triangles.insert(seg.triangles.end(), {a, b, c, a, c, d});
          offsets.push_back(static_cast<uint32_t>(corners.size()));
        }
      m.faces.offsets = std::move(offsets);
      m.faces.values = std::move(corners);
      seg.normals.assign(3 * nx * ny, 0.0f);
      for (uint32_t v = 0; v < nx * ny; ++v) seg.normals[3 * v + 2] = 1.0f;
      // The solid: the unit cube as one hexahedron (VTK order) and a tetrahedron beside it.
      seg.solid.positions.resize(9, 3);
      seg.solid.positions << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1,
          2, 0, 0;
      seg.solid.addHexahedron({0, 1, 2, 3, 4, 5, 6, 7});
      seg.solid.addTetrahedron({1, 8, 2, 5});
      segments_.push_back(std::move(seg));
    }
  }

  double fps() const override { return fps_; }
  uint32_t frameCount() const override { return frames_; }
  uint32_t segmentCount() const override { return static_cast<uint32_t>(segments_.size()); }
  FrameRange segment(uint32_t s) const override { return segments_[s].range; }
  const SurfaceMesh& restSurface(uint32_t s) const override { return segments_[s].rest; }
  const std::vector<float>& restVertexNormals(uint32_t s) const override {
    return segments_[s].normals;
  }
  const std::vector<uint32_t>& triangles(uint32_t s) const override {
    return segments_[s].triangles;
  }
  const VolumeMesh& restSolid(uint32_t s) const override { return segments_[s].solid; }

  /// The known motion: a travelling wave along z, w(x, t) = amplitude sin(2 pi (x - t)).
  double offset(double x, double t) const { return amplitude_ * std::sin(2.0 * M_PI * (x - t)); }

  void evaluateSurface(uint32_t frame, SurfaceFrameData& out) const override {
    const Segment& seg = segments_[segmentOf(frame)];
    const double t = frameTime(frame);
    const uint32_t n = seg.rest.numVertices();
    out.positions.resize(3 * n);
    out.normals.resize(3 * n);
    for (uint32_t v = 0; v < n; ++v) {
      const double x = seg.rest.positions(v, 0);
      out.positions[3 * v] = static_cast<float>(x);
      out.positions[3 * v + 1] = static_cast<float>(seg.rest.positions(v, 1));
      out.positions[3 * v + 2] = static_cast<float>(seg.rest.positions(v, 2) + offset(x, t));
      const double slope = amplitude_ * 2.0 * M_PI * std::cos(2.0 * M_PI * (x - t));
      const double length = std::sqrt(1.0 + slope * slope);
      out.normals[3 * v] = static_cast<float>(-slope / length);
      out.normals[3 * v + 1] = 0.0f;
      out.normals[3 * v + 2] = static_cast<float>(1.0 / length);
    }
    out.sourceNormals = out.normals;  // one source normal per position
  }

  void evaluateSolid(uint32_t frame, SolidFrameData& out) const override {
    const Segment& seg = segments_[segmentOf(frame)];
    const double t = frameTime(frame);
    out.nodes = seg.solid.positions;
    for (Eigen::Index i = 0; i < out.nodes.rows(); ++i)
      out.nodes(i, 2) += offset(out.nodes(i, 0), t);
    out.displacement = out.nodes - seg.solid.positions;
    const size_t cells = seg.solid.numCells();
    out.fields.youngs.assign(cells, static_cast<float>(1.0e5 * (1.0 + frame)));
    out.fields.density.assign(cells, 1000.0f);
    out.fields.damping.assign(cells, 2.0f);
  }

 private:
  struct Segment {
    FrameRange range;
    SurfaceMesh rest;
    std::vector<float> normals;
    std::vector<uint32_t> triangles;
    VolumeMesh solid;
  };
  double fps_;
  uint32_t frames_;
  double amplitude_;
  std::vector<Segment> segments_;
};

}  // namespace sculpt::test
