#include "subdiv/surface_refiner.h"

#include <memory>
#include <stdexcept>
#include <string>

#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefinerFactory.h>

namespace sculpt {
namespace {

namespace Far = OpenSubdiv::Far;
namespace Sdc = OpenSubdiv::Sdc;

/// Primvar element for Far::PrimvarRefinerReal<double>.
struct Point3 {
  double p[3] = {0, 0, 0};
  void Clear(void* = nullptr) { p[0] = p[1] = p[2] = 0.0; }
  void AddWithWeight(const Point3& src, double weight) {
    p[0] += weight * src.p[0];
    p[1] += weight * src.p[1];
    p[2] += weight * src.p[2];
  }
};

const char* schemeName(SurfaceScheme scheme) {
  return scheme == SurfaceScheme::Loop ? "Loop" : "Catmull-Clark";
}

}  // namespace

SurfaceMesh refineSurface(const SurfaceMesh& surface, SurfaceScheme scheme, int levels,
                          bool toLimit, SurfaceBoundary boundary, const SurfaceTags& tags) {
  if (levels < 0 || levels > 8)
    throw std::invalid_argument(std::string(schemeName(scheme)) +
                                " refinement levels must be in 0..8 (got " +
                                std::to_string(levels) + ")");
  // Topology descriptor: faces, then the sharp tags.
  std::vector<int> vertsPerFace, faceVerts;
  vertsPerFace.reserve(surface.numFaces());
  faceVerts.reserve(surface.faces.values.size());
  for (uint32_t f = 0; f < surface.numFaces(); ++f) {
    const auto corners = surface.faces.row(f);
    if (scheme == SurfaceScheme::Loop && corners.size() != 3)
      throw std::invalid_argument("face " + std::to_string(f) + " has " +
                                  std::to_string(corners.size()) +
                                  " corners; Loop subdivision needs triangles");
    if (corners.size() < 3)
      throw std::invalid_argument("face " + std::to_string(f) + " has fewer than 3 corners");
    vertsPerFace.push_back(static_cast<int>(corners.size()));
    for (const SurfaceCorner& c : corners) {
      if (c.position >= surface.numVertices())
        throw std::invalid_argument("face " + std::to_string(f) + " uses a vertex out of range");
      faceVerts.push_back(static_cast<int>(c.position));
    }
  }
  std::vector<int> creasePairs, cornerIndices;
  for (const auto& [a, b] : tags.creases) {
    if (a >= surface.numVertices() || b >= surface.numVertices())
      throw std::invalid_argument("a crease uses a vertex out of range");
    creasePairs.push_back(static_cast<int>(a));
    creasePairs.push_back(static_cast<int>(b));
  }
  for (uint32_t v : tags.corners) {
    if (v >= surface.numVertices()) throw std::invalid_argument("a corner is out of range");
    cornerIndices.push_back(static_cast<int>(v));
  }
  const std::vector<float> creaseWeights(tags.creases.size(), Sdc::Crease::SHARPNESS_INFINITE);
  const std::vector<float> cornerWeights(tags.corners.size(), Sdc::Crease::SHARPNESS_INFINITE);

  Far::TopologyDescriptor desc;
  desc.numVertices = static_cast<int>(surface.numVertices());
  desc.numFaces = static_cast<int>(vertsPerFace.size());
  desc.numVertsPerFace = vertsPerFace.data();
  desc.vertIndicesPerFace = faceVerts.data();
  desc.numCreases = static_cast<int>(tags.creases.size());
  desc.creaseVertexIndexPairs = creasePairs.data();
  desc.creaseWeights = creaseWeights.data();
  desc.numCorners = static_cast<int>(tags.corners.size());
  desc.cornerVertexIndices = cornerIndices.data();
  desc.cornerWeights = cornerWeights.data();
  using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
  Sdc::Options options;
  options.SetVtxBoundaryInterpolation(boundary == SurfaceBoundary::EdgeOnly
                                          ? Sdc::Options::VTX_BOUNDARY_EDGE_ONLY
                                          : Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER);
  const Sdc::SchemeType type =
      scheme == SurfaceScheme::Loop ? Sdc::SCHEME_LOOP : Sdc::SCHEME_CATMARK;
  std::unique_ptr<Far::TopologyRefiner> refiner(
      Factory::Create(desc, Factory::Options(type, options)));
  if (!refiner) throw std::invalid_argument("OpenSubdiv refused the surface's topology");
  Far::TopologyRefiner::UniformOptions uniform(levels);
  uniform.fullTopologyInLastLevel = 1;
  refiner->RefineUniform(uniform);

  // Positions level by level, then (optionally) onto the limit surface.
  std::vector<Point3> current(surface.numVertices());
  for (uint32_t v = 0; v < surface.numVertices(); ++v)
    for (int d = 0; d < 3; ++d) current[v].p[d] = surface.positions(v, d);
  Far::PrimvarRefinerReal<double> primvar(*refiner);
  for (int k = 1; k <= levels; ++k) {
    std::vector<Point3> next(static_cast<size_t>(refiner->GetLevel(k).GetNumVertices()));
    const Point3* source = current.data();
    Point3* destination = next.data();  // OpenSubdiv takes the buffers by reference
    primvar.Interpolate(k, source, destination);
    current = std::move(next);
  }
  if (toLimit && levels > 0) {
    std::vector<Point3> limit(current.size());
    const Point3* source = current.data();
    Point3* destination = limit.data();
    primvar.Limit(source, destination);
    current = std::move(limit);
  }

  const Far::TopologyLevel& last = refiner->GetLevel(levels);
  SurfaceMesh refined;
  refined.positions.resize(static_cast<Eigen::Index>(current.size()), 3);
  for (size_t v = 0; v < current.size(); ++v)
    for (int d = 0; d < 3; ++d)
      refined.positions(static_cast<Eigen::Index>(v), d) = current[v].p[d];
  refined.faces.values.reserve(static_cast<size_t>(last.GetNumFaceVertices()));
  for (int f = 0; f < last.GetNumFaces(); ++f) {
    const Far::ConstIndexArray verts = last.GetFaceVertices(f);
    for (int i = 0; i < verts.size(); ++i) {
      SurfaceCorner corner;
      corner.position = static_cast<uint32_t>(verts[i]);
      refined.faces.values.push_back(corner);
    }
    refined.faces.closeRow();
  }
  return refined;
}

}  // namespace sculpt
