#pragma once
// The MacCracken–Joy oracle of docs/design/mj-subdivision.md §5.4, §7.4: the boundary of the
// MJ-refined lattice at levels 1..K equals OpenSubdiv's Catmull–Clark refinement of the level-0
// boundary (Sdc::SCHEME_CATMARK, creases as infinitely sharp edges, corners as infinitely sharp
// vertices), point for point, to 1e-12 of the bounding-box diagonal. Test binaries that include
// this link OpenSubdiv::osdCPU.

#include <gtest/gtest.h>
#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefinerFactory.h>
#include <opensubdiv/sdc/crease.h>
#include <opensubdiv/sdc/options.h>
#include <opensubdiv/sdc/types.h>

#include <algorithm>
#include <iomanip>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "mesh/topology.h"
#include "mesh/validation.h"
#include "subdiv/mj_refiner.h"
#include "support/mesh_builders.h"

namespace sculpt::test {

namespace osd_oracle {
namespace Far = OpenSubdiv::Far;
namespace Sdc = OpenSubdiv::Sdc;

/// Primvar buffer element for Far::PrimvarRefinerReal<double>.
struct OsdPoint {
  double p[3] = {0, 0, 0};
  void Clear(void* = nullptr) { p[0] = p[1] = p[2] = 0.0; }
  void AddWithWeight(const OsdPoint& src, double weight) {
    p[0] += weight * src.p[0];
    p[1] += weight * src.p[1];
    p[2] += weight * src.p[2];
  }
  Eigen::Vector3d vec() const { return {p[0], p[1], p[2]}; }
};

inline std::string scientific(double x) {
  std::ostringstream s;
  s << std::scientific << std::setprecision(3) << x;
  return s.str();
}

inline std::vector<int> sortedKey(std::vector<int> v) {
  std::sort(v.begin(), v.end());
  return v;
}

/// True when b is a cyclic rotation of a.
inline bool sameCycle(const std::vector<int>& a, const std::vector<int>& b) {
  if (a.size() != b.size()) return false;
  for (size_t s = 0; s < a.size(); ++s) {
    bool ok = true;
    for (size_t i = 0; i < a.size() && ok; ++i) ok = a[(i + s) % a.size()] == b[i];
    if (ok) return true;
  }
  return false;
}

/// Runs MJ and OpenSubdiv side by side and compares every boundary vertex at levels 1..kLevels
/// (fails the current test with the first difference).
}  // namespace osd_oracle

inline void compareWithOpenSubdiv(const CellComplex& control, int levels = 3) {
  using namespace osd_oracle;
  const int kLevels = levels;
  const auto issues = validate(control);
  ASSERT_TRUE(isValid(issues));
  const auto s = subdivide(control, kLevels);
  ASSERT_TRUE(s.has_value());
  const Topology& t0 = s->topologies[0];

  // 1. Level-0 boundary faces, outward, over compacted vertex ids.
  std::vector<int> osdOf(t0.numVertices, -1);
  std::vector<OsdPoint> base;
  std::vector<int> faceSizes, faceVerts;
  for (uint32_t f = 0; f < t0.numFaces(); ++f) {
    if (!t0.faceIsBoundary[f]) continue;
    ASSERT_EQ(t0.faceCells[f][1], kNoCell);
    const auto c = static_cast<uint32_t>(t0.faceCells[f][0]);
    const auto cellFaces = t0.cellFaces.row(c);
    const auto slot = std::find(cellFaces.begin(), cellFaces.end(), f) - cellFaces.begin();
    ASSERT_LT(slot, static_cast<std::ptrdiff_t>(cellFaces.size()));
    const auto loop = t0.outwardLoop(c, static_cast<uint32_t>(slot));
    faceSizes.push_back(static_cast<int>(loop.size()));
    for (uint32_t v : loop) {
      if (osdOf[v] < 0) {
        osdOf[v] = static_cast<int>(base.size());
        OsdPoint q;
        for (int d = 0; d < 3; ++d) q.p[d] = control.positions(static_cast<Eigen::Index>(v), d);
        base.push_back(q);
      }
      faceVerts.push_back(osdOf[v]);
    }
  }
  std::vector<int> creasePairs;
  std::vector<float> creaseWeights;
  for (const auto& [a, b] : control.creases) {
    ASSERT_GE(osdOf[a], 0);
    ASSERT_GE(osdOf[b], 0);
    creasePairs.push_back(osdOf[a]);
    creasePairs.push_back(osdOf[b]);
    creaseWeights.push_back(Sdc::Crease::SHARPNESS_INFINITE);
  }
  std::vector<int> cornerIds;
  std::vector<float> cornerWeights;
  for (uint32_t v : control.corners) {
    ASSERT_GE(osdOf[v], 0);
    cornerIds.push_back(osdOf[v]);
    cornerWeights.push_back(Sdc::Crease::SHARPNESS_INFINITE);
  }

  // 2. OpenSubdiv topology refiner, Catmull–Clark with default options.
  Far::TopologyDescriptor desc;
  desc.numVertices = static_cast<int>(base.size());
  desc.numFaces = static_cast<int>(faceSizes.size());
  desc.numVertsPerFace = faceSizes.data();
  desc.vertIndicesPerFace = faceVerts.data();
  desc.numCreases = static_cast<int>(creaseWeights.size());
  desc.creaseVertexIndexPairs = creasePairs.data();
  desc.creaseWeights = creaseWeights.data();
  desc.numCorners = static_cast<int>(cornerIds.size());
  desc.cornerVertexIndices = cornerIds.data();
  desc.cornerWeights = cornerWeights.data();
  using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
  std::unique_ptr<Far::TopologyRefiner> refiner(
      Factory::Create(desc, Factory::Options(Sdc::SCHEME_CATMARK, Sdc::Options())));
  ASSERT_NE(refiner, nullptr);
  Far::TopologyRefiner::UniformOptions uniform(kLevels);
  uniform.fullTopologyInLastLevel = 1;
  refiner->RefineUniform(uniform);
  ASSERT_EQ(refiner->GetMaxLevel(), kLevels);

  // 3. Interpolate level by level (in double precision).
  std::vector<std::vector<OsdPoint>> osd(kLevels + 1);
  osd[0] = base;
  Far::PrimvarRefinerReal<double> primvar(*refiner);
  for (int k = 1; k <= kLevels; ++k) {
    osd[static_cast<size_t>(k)].resize(static_cast<size_t>(refiner->GetLevel(k).GetNumVertices()));
    const OsdPoint* src = osd[static_cast<size_t>(k - 1)].data();
    OsdPoint* dst = osd[static_cast<size_t>(k)].data();
    primvar.Interpolate(k, src, dst);
  }

  const Eigen::Vector3d lo = control.positions.colwise().minCoeff().transpose();
  const Eigen::Vector3d hi = control.positions.colwise().maxCoeff().transpose();
  const double tolerance = 1e-12 * (hi - lo).norm();

  // 4. Map MJ boundary vertices to OpenSubdiv vertices level by level and compare.
  std::vector<int> map = osdOf;
  for (int k = 0; k <= kLevels; ++k) {
    SCOPED_TRACE("level " + std::to_string(k));
    const Topology& t = s->topologies[static_cast<size_t>(k)];
    const Far::TopologyLevel& level = refiner->GetLevel(k);
    const Points& mj = s->levels[static_cast<size_t>(k)].positions;

    // Counts and the vertex map: boundary vertices map one-to-one onto OSD's vertices.
    uint32_t boundaryVertices = 0, boundaryFaces = 0;
    std::vector<uint8_t> hit(static_cast<size_t>(level.GetNumVertices()), 0);
    for (uint32_t v = 0; v < t.numVertices; ++v) {
      ASSERT_EQ(t.vertexIsBoundary[v] != 0, map[v] >= 0) << "vertex " << v;
      if (!t.vertexIsBoundary[v]) continue;
      ++boundaryVertices;
      ASSERT_LT(map[v], level.GetNumVertices());
      ASSERT_EQ(hit[static_cast<size_t>(map[v])], 0) << "two MJ vertices map to OSD " << map[v];
      hit[static_cast<size_t>(map[v])] = 1;
    }
    for (uint32_t f = 0; f < t.numFaces(); ++f) boundaryFaces += t.faceIsBoundary[f] ? 1u : 0u;
    EXPECT_EQ(boundaryVertices, static_cast<uint32_t>(level.GetNumVertices()));
    EXPECT_EQ(boundaryFaces, static_cast<uint32_t>(level.GetNumFaces()));

    // Positions.
    double maxError = 0.0;
    for (uint32_t v = 0; v < t.numVertices; ++v) {
      if (map[v] < 0) continue;
      const double err =
          (test::pos(mj, v) - osd[static_cast<size_t>(k)][static_cast<size_t>(map[v])].vec())
              .norm();
      maxError = std::max(maxError, err);
      EXPECT_LE(err, tolerance) << "MJ vertex " << v << " / OSD vertex " << map[v];
    }
    ::testing::Test::RecordProperty("max_error_level_" + std::to_string(k), scientific(maxError));

    // Faces: every MJ boundary face is an OSD face with the same (outward) orientation.
    std::map<std::vector<int>, int> osdFaces;
    for (int f = 0; f < level.GetNumFaces(); ++f) {
      const auto fv = level.GetFaceVertices(f);
      osdFaces[sortedKey(std::vector<int>(fv.begin(), fv.end()))] = f;
    }
    std::vector<int> faceOf(t.numFaces(), -1);
    for (uint32_t f = 0; f < t.numFaces(); ++f) {
      if (!t.faceIsBoundary[f]) continue;
      std::vector<int> loop;
      for (uint32_t v : t.faceVertices.row(f)) loop.push_back(map[v]);
      const auto it = osdFaces.find(sortedKey(loop));
      ASSERT_NE(it, osdFaces.end()) << "MJ boundary face " << f << " has no OSD counterpart";
      faceOf[f] = it->second;
      const auto fv = level.GetFaceVertices(it->second);
      EXPECT_TRUE(sameCycle(std::vector<int>(fv.begin(), fv.end()), loop))
          << "MJ boundary face " << f << " is not oriented like OSD's";
    }
    if (k == kLevels) break;

    // Child map for level k+1 (numbering of mj_refiner.h).
    const Topology& next = s->topologies[static_cast<size_t>(k + 1)];
    std::vector<int> childMap(next.numVertices, -1);
    for (uint32_t v = 0; v < t.numVertices; ++v)
      if (map[v] >= 0) childMap[v] = level.GetVertexChildVertex(map[v]);
    for (uint32_t e = 0; e < t.numEdges(); ++e) {
      if (!t.edgeIsBoundary[e]) continue;
      const auto [a, b] = t.edgeVertices[e];
      const int osdEdge = level.FindEdge(map[a], map[b]);
      ASSERT_NE(osdEdge, Far::INDEX_INVALID) << "MJ boundary edge " << e;
      childMap[t.numVertices + e] = level.GetEdgeChildVertex(osdEdge);
      // Crease tags agree with OSD's sharpness.
      EXPECT_EQ(t.edgeIsCrease[e] != 0, Sdc::Crease::IsInfinite(level.GetEdgeSharpness(osdEdge)))
          << "edge " << e;
    }
    for (uint32_t f = 0; f < t.numFaces(); ++f)
      if (faceOf[f] >= 0)
        childMap[t.numVertices + t.numEdges() + f] = level.GetFaceChildVertex(faceOf[f]);
    map = std::move(childMap);
  }
}

}  // namespace sculpt::test
