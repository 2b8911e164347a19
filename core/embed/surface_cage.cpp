#include "embed/surface_cage.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <deque>
#include <numbers>
#include <stdexcept>
#include <string>

namespace sculpt {
namespace {

using Vec3 = Eigen::Vector3d;
using Triangle = std::array<Vec3, 3>;

constexpr uint32_t kNone = 0xffffffffu;

// The regular grid: voxel (i, j, k) spans origin + h * [i, i+1] x [j, j+1] x [k, k+1].
struct Grid {
  Vec3 origin;
  double h = 0.0;
  int64_t n[3] = {0, 0, 0};

  int64_t count() const { return n[0] * n[1] * n[2]; }
  int64_t voxel(int64_t i, int64_t j, int64_t k) const { return i + n[0] * (j + n[1] * k); }
  bool inside(int64_t i, int64_t j, int64_t k) const {
    return i >= 0 && j >= 0 && k >= 0 && i < n[0] && j < n[1] && k < n[2];
  }
  Vec3 centre(int64_t i, int64_t j, int64_t k) const {
    return origin + h * Vec3(double(i) + 0.5, double(j) + 0.5, double(k) + 0.5);
  }
};

// Checks the input and fans every polygon into triangles.
std::vector<Triangle> surfaceTriangles(const SurfaceMesh& surface) {
  if (surface.numVertices() == 0 || surface.numFaces() == 0)
    throw std::invalid_argument("buildSurfaceCage: the surface is empty (" +
                                std::to_string(surface.numVertices()) + " vertices, " +
                                std::to_string(surface.numFaces()) + " faces)");
  if (!surface.positions.allFinite())
    throw std::invalid_argument("buildSurfaceCage: the surface has a non-finite coordinate");
  std::vector<Triangle> triangles;
  for (uint32_t f = 0; f < surface.numFaces(); ++f) {
    const auto corners = surface.faces.row(f);
    for (const SurfaceCorner& corner : corners)
      if (corner.position >= surface.numVertices())
        throw std::invalid_argument("buildSurfaceCage: face " + std::to_string(f) +
                                    " uses vertex " + std::to_string(corner.position) +
                                    ", out of range");
    const auto point = [&](size_t c) -> Vec3 {
      return surface.positions.row(corners[c].position).transpose();
    };
    for (size_t c = 1; c + 1 < corners.size(); ++c)
      triangles.push_back({point(0), point(c), point(c + 1)});
  }
  return triangles;
}

// Akenine-Möller's separating-axis test of a triangle against an axis-aligned box.
bool triangleOverlapsBox(const Triangle& triangle, const Vec3& centre, double half) {
  const Vec3 v0 = triangle[0] - centre, v1 = triangle[1] - centre, v2 = triangle[2] - centre;
  const Vec3 edges[3] = {v1 - v0, v2 - v1, v0 - v2};
  // Nine axes: box axis x triangle edge
  for (int a = 0; a < 3; ++a)
    for (const Vec3& e : edges) {
      Vec3 axis = Vec3::Zero();
      axis[(a + 1) % 3] = -e[(a + 2) % 3];
      axis[(a + 2) % 3] = e[(a + 1) % 3];
      const double p0 = axis.dot(v0), p1 = axis.dot(v1), p2 = axis.dot(v2);
      const double r = half * axis.cwiseAbs().sum();
      if (std::min({p0, p1, p2}) > r || std::max({p0, p1, p2}) < -r) return false;
    }
  // Box face normals
  for (int a = 0; a < 3; ++a)
    if (std::min({v0[a], v1[a], v2[a]}) > half || std::max({v0[a], v1[a], v2[a]}) < -half)
      return false;
  // Triangle normal
  const Vec3 normal = edges[0].cross(edges[1]);
  const double r = half * normal.cwiseAbs().sum();
  return std::abs(normal.dot(v0)) <= r;
}

// Generalized winding number (Jacobson et al. 2013): the solid angles of the triangles seen from
// p over 4 pi (Van Oosterom–Strackee). About +-1 inside a closed surface, 0 outside.
double windingNumber(const std::vector<Triangle>& triangles, const Vec3& p) {
  double sum = 0.0;
  for (const Triangle& t : triangles) {
    const Vec3 a = t[0] - p, b = t[1] - p, c = t[2] - p;
    const double la = a.norm(), lb = b.norm(), lc = c.norm();
    const double numerator = a.dot(b.cross(c));
    const double denominator = la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb;
    sum += 2.0 * std::atan2(numerator, denominator);
  }
  return sum / (4.0 * std::numbers::pi);
}

Grid makeGrid(const SurfaceMesh& surface, const CageSettings& settings) {
  if (settings.marginCells < 0)
    throw std::invalid_argument("buildSurfaceCage: marginCells must be >= 0 (got " +
                                std::to_string(settings.marginCells) + ")");
  const Vec3 lo = surface.positions.colwise().minCoeff().transpose();
  const Vec3 hi = surface.positions.colwise().maxCoeff().transpose();
  const Vec3 extent = hi - lo;
  Grid grid;
  grid.h = settings.cellSize == 0.0 ? extent.maxCoeff() / 12.0 : settings.cellSize;
  if (settings.cellSize == 0.0 && !(grid.h > 0.0))
    throw std::invalid_argument(
        "buildSurfaceCage: the surface has zero extent; give a cell size explicitly");
  if (!(grid.h > 0.0) || !std::isfinite(grid.h))
    throw std::invalid_argument(
        "buildSurfaceCage: the cell size must be positive and finite (got " +
        std::to_string(settings.cellSize) + ")");
  // The bounding box in whole cells, then the margin plus one empty layer on each side
  const double pad = double(settings.marginCells) + 1.0;
  double counts[3], total = 1.0;
  for (int a = 0; a < 3; ++a) {
    counts[a] = std::max(1.0, std::ceil(extent[a] / grid.h)) + 2.0 * pad;
    total *= counts[a];
  }
  if (!(total <= double(settings.maxCells)))
    throw std::invalid_argument(
        "buildSurfaceCage: too many cells: a cell size of " + std::to_string(grid.h) +
        " needs a grid of " + std::to_string(counts[0]) + " x " + std::to_string(counts[1]) +
        " x " + std::to_string(counts[2]) + " voxels, more than the limit of " +
        std::to_string(settings.maxCells) + "; choose a larger cell size");
  for (int a = 0; a < 3; ++a) grid.n[a] = int64_t(counts[a]);
  const Vec3 centre = 0.5 * (lo + hi);
  grid.origin = centre - 0.5 * grid.h * Vec3(counts[0], counts[1], counts[2]);
  return grid;
}

// Marks voxels that overlap some triangle (box enlarged by a hair, so that this is conservative).
void markSurfaceVoxels(const Grid& grid, const std::vector<Triangle>& triangles,
                       std::vector<uint8_t>& marked) {
  const double half = 0.5 * grid.h * (1.0 + 1e-6);
  for (const Triangle& t : triangles) {
    int64_t lo[3], hi[3];
    for (int a = 0; a < 3; ++a) {
      const double tMin = std::min({t[0][a], t[1][a], t[2][a]});
      const double tMax = std::max({t[0][a], t[1][a], t[2][a]});
      lo[a] = std::clamp(int64_t(std::floor((tMin - grid.origin[a]) / grid.h - 1e-6)), int64_t(0),
                         grid.n[a] - 1);
      hi[a] = std::clamp(int64_t(std::floor((tMax - grid.origin[a]) / grid.h + 1e-6)), int64_t(0),
                         grid.n[a] - 1);
    }
    for (int64_t k = lo[2]; k <= hi[2]; ++k)
      for (int64_t j = lo[1]; j <= hi[1]; ++j)
        for (int64_t i = lo[0]; i <= hi[0]; ++i) {
          const int64_t v = grid.voxel(i, j, k);
          if (!marked[size_t(v)] && triangleOverlapsBox(t, grid.centre(i, j, k), half))
            marked[size_t(v)] = 1;
        }
  }
}

// Marks the unmarked voxels that lie inside: per face-connected region of unmarked voxels,
// sampled winding numbers; regions whose samples disagree are decided voxel by voxel.
void markInteriorVoxels(const Grid& grid, const std::vector<Triangle>& triangles,
                        std::vector<uint8_t>& marked) {
  constexpr size_t kSamples = 16;
  std::vector<uint8_t> visited(marked);
  std::vector<int64_t> region;
  const auto position = [&](int64_t v, int64_t& i, int64_t& j, int64_t& k) {
    i = v % grid.n[0];
    j = (v / grid.n[0]) % grid.n[1];
    k = v / (grid.n[0] * grid.n[1]);
  };
  const auto isInside = [&](int64_t v) {
    int64_t i, j, k;
    position(v, i, j, k);
    return std::abs(windingNumber(triangles, grid.centre(i, j, k))) > 0.5;
  };
  for (int64_t seed = 0; seed < grid.count(); ++seed) {
    if (visited[size_t(seed)]) continue;
    // Collect the region (breadth first, face neighbours)
    region.clear();
    region.push_back(seed);
    visited[size_t(seed)] = 1;
    for (size_t r = 0; r < region.size(); ++r) {
      int64_t i, j, k;
      position(region[r], i, j, k);
      const int64_t neighbours[6][3] = {{i - 1, j, k}, {i + 1, j, k}, {i, j - 1, k},
                                        {i, j + 1, k}, {i, j, k - 1}, {i, j, k + 1}};
      for (const auto& n : neighbours) {
        if (!grid.inside(n[0], n[1], n[2])) continue;
        const int64_t w = grid.voxel(n[0], n[1], n[2]);
        if (visited[size_t(w)]) continue;
        visited[size_t(w)] = 1;
        region.push_back(w);
      }
    }
    // Sample the region evenly
    const size_t samples = std::min(kSamples, region.size());
    size_t insideSamples = 0;
    for (size_t s = 0; s < samples; ++s)
      insideSamples += isInside(region[s * region.size() / samples]);
    if (insideSamples == 0) continue;
    if (insideSamples == samples) {
      for (int64_t v : region) marked[size_t(v)] = 1;
      continue;
    }
    for (int64_t v : region)
      if (isInside(v)) marked[size_t(v)] = 1;
  }
}

// Chebyshev dilation by `radius` voxels (the 26-neighbourhood applied radius times), one axis at
// a time.
void dilate(const Grid& grid, int radius, std::vector<uint8_t>& marked) {
  if (radius <= 0) return;
  std::vector<uint8_t> source;
  const int64_t stride[3] = {1, grid.n[0], grid.n[0] * grid.n[1]};
  for (int a = 0; a < 3; ++a) {
    source = marked;
    for (int64_t v = 0; v < grid.count(); ++v) {
      if (!source[size_t(v)]) continue;
      const int64_t coordinate = (v / stride[a]) % grid.n[a];
      const int64_t from = std::max<int64_t>(0, coordinate - radius);
      const int64_t to = std::min<int64_t>(grid.n[a] - 1, coordinate + radius);
      for (int64_t c = from; c <= to; ++c) marked[size_t(v + (c - coordinate) * stride[a])] = 1;
    }
  }
}

// For each 8-bit occupancy of the voxels around a lattice vertex (bit = dx + 2 dy + 4 dz), whether
// the union is a manifold there: the occupied and the empty octants each face-connected.
std::array<bool, 256> manifoldVertexTable() {
  const auto connected = [](unsigned set) {
    if (set == 0) return true;
    unsigned reached = set & (~set + 1u), previous = 0;
    while (reached != previous) {
      previous = reached;
      for (unsigned o = 0; o < 8; ++o)
        if (reached & (1u << o))
          for (unsigned axis = 1; axis < 8; axis <<= 1)
            if (set & (1u << (o ^ axis))) reached |= 1u << (o ^ axis);
    }
    return reached == set;
  };
  std::array<bool, 256> table{};
  for (unsigned mask = 0; mask < 256; ++mask)
    table[mask] = connected(mask) && connected(~mask & 0xffu);
  return table;
}

// Fills the 2x2x2 voxel block around every lattice vertex where the voxel set is not a manifold,
// until none is left (validate() rejects edges and vertices where the boundary pinches).
void makeManifold(const Grid& grid, std::vector<uint8_t>& marked) {
  static const std::array<bool, 256> manifold = manifoldVertexTable();
  const int64_t m[3] = {grid.n[0] + 1, grid.n[1] + 1, grid.n[2] + 1};
  const auto octant = [&](int64_t i, int64_t j, int64_t k, unsigned o, int64_t& vi, int64_t& vj,
                          int64_t& vk) {
    vi = i - 1 + (o & 1u);
    vj = j - 1 + ((o >> 1) & 1u);
    vk = k - 1 + ((o >> 2) & 1u);
    return grid.inside(vi, vj, vk);
  };
  std::deque<std::array<int64_t, 3>> work;
  std::vector<uint8_t> queued(size_t(m[0] * m[1] * m[2]), 1);
  for (int64_t k = 0; k < m[2]; ++k)
    for (int64_t j = 0; j < m[1]; ++j)
      for (int64_t i = 0; i < m[0]; ++i) work.push_back({i, j, k});
  while (!work.empty()) {
    const auto [i, j, k] = work.front();
    work.pop_front();
    queued[size_t(i + m[0] * (j + m[1] * k))] = 0;
    unsigned mask = 0;
    for (unsigned o = 0; o < 8; ++o) {
      int64_t vi, vj, vk;
      if (octant(i, j, k, o, vi, vj, vk) && marked[size_t(grid.voxel(vi, vj, vk))]) mask |= 1u << o;
    }
    if (manifold[mask]) continue;
    // Fill the block (out-of-grid octants stay empty: the in-grid ones then form a face-connected
    // slab, so the vertex is fixed) and look again at the lattice vertices around it
    for (unsigned o = 0; o < 8; ++o) {
      int64_t vi, vj, vk;
      if (octant(i, j, k, o, vi, vj, vk)) marked[size_t(grid.voxel(vi, vj, vk))] = 1;
    }
    for (int64_t dk = -1; dk <= 1; ++dk)
      for (int64_t dj = -1; dj <= 1; ++dj)
        for (int64_t di = -1; di <= 1; ++di) {
          const int64_t a = i + di, b = j + dj, c = k + dk;
          if (a < 0 || b < 0 || c < 0 || a >= m[0] || b >= m[1] || c >= m[2]) continue;
          uint8_t& q = queued[size_t(a + m[0] * (b + m[1] * c))];
          if (!q) {
            q = 1;
            work.push_back({a, b, c});
          }
        }
  }
}

}  // namespace

Cage buildSurfaceCage(const SurfaceMesh& surface, const CageSettings& settings) {
  const std::vector<Triangle> triangles = surfaceTriangles(surface);
  const Grid grid = makeGrid(surface, settings);

  // Voxels that hold the surface, then those inside it, then the margin
  std::vector<uint8_t> marked(size_t(grid.count()), 0);
  markSurfaceVoxels(grid, triangles, marked);
  markInteriorVoxels(grid, triangles, marked);
  dilate(grid, settings.marginCells, marked);
  makeManifold(grid, marked);

  // One hexahedron per voxel; vertices only for used lattice points
  Cage cage;
  cage.cellSize = grid.h;
  cage.origin = grid.origin;
  for (int a = 0; a < 3; ++a) cage.gridSize[size_t(a)] = uint32_t(grid.n[a]);
  const int64_t m0 = grid.n[0] + 1, m1 = grid.n[1] + 1;
  std::vector<uint32_t> vertexOf(size_t(m0 * m1 * (grid.n[2] + 1)), kNone);
  std::vector<std::array<int64_t, 3>> lattice;
  static constexpr uint32_t kHexLoops[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                               {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  static constexpr int kCorner[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                        {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  CellComplex& control = cage.control;
  for (int64_t k = 0; k < grid.n[2]; ++k)
    for (int64_t j = 0; j < grid.n[1]; ++j)
      for (int64_t i = 0; i < grid.n[0]; ++i) {
        if (!marked[size_t(grid.voxel(i, j, k))]) continue;
        std::array<uint32_t, 8> hex;
        for (int c = 0; c < 8; ++c) {
          const int64_t a = i + kCorner[c][0], b = j + kCorner[c][1], d = k + kCorner[c][2];
          uint32_t& id = vertexOf[size_t(a + m0 * (b + m1 * d))];
          if (id == kNone) {
            id = uint32_t(lattice.size());
            lattice.push_back({a, b, d});
          }
          hex[size_t(c)] = id;
        }
        for (const auto& loop : kHexLoops) {
          const std::array<uint32_t, 4> ids{hex[loop[0]], hex[loop[1]], hex[loop[2]], hex[loop[3]]};
          control.addLoop(ids);
        }
        control.finishCell();
      }
  control.positions.resize(Eigen::Index(lattice.size()), 3);
  for (size_t v = 0; v < lattice.size(); ++v)
    control.positions.row(Eigen::Index(v)) =
        (grid.origin +
         grid.h * Vec3(double(lattice[v][0]), double(lattice[v][1]), double(lattice[v][2])))
            .transpose();
  return cage;
}

}  // namespace sculpt
