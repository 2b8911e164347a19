#include "project/project.h"

#include <algorithm>
#include <cstring>
#include <numeric>

#include "fem/fem_mesh.h"

namespace sculpt {
namespace {

// A k-d tree over sample positions for nearest-sample queries. Nodes are stored implicitly in a
// permutation of the sample indices: the median of each range splits it on the widest axis.
class KdTree {
 public:
  explicit KdTree(const std::vector<Eigen::Vector3d>& points) : points_(points) {
    order_.resize(points.size());
    std::iota(order_.begin(), order_.end(), uint32_t{0});
    axes_.assign(points.size(), 0);
    build(0, order_.size());
  }

  /// Index of the nearest point; ties go to the lowest index.
  uint32_t nearest(const Eigen::Vector3d& query) const {
    Best best;
    search(0, order_.size(), query, best);
    return best.index;
  }

 private:
  struct Best {
    double distance2 = std::numeric_limits<double>::infinity();
    uint32_t index = std::numeric_limits<uint32_t>::max();
  };

  void build(size_t begin, size_t end) {
    if (end - begin <= 1) return;
    Eigen::Vector3d lo = points_[order_[begin]], hi = lo;
    for (size_t i = begin; i < end; ++i) {
      lo = lo.cwiseMin(points_[order_[i]]);
      hi = hi.cwiseMax(points_[order_[i]]);
    }
    int axis = 0;
    (hi - lo).maxCoeff(&axis);
    const size_t mid = begin + (end - begin) / 2;
    std::nth_element(order_.begin() + static_cast<std::ptrdiff_t>(begin),
                     order_.begin() + static_cast<std::ptrdiff_t>(mid),
                     order_.begin() + static_cast<std::ptrdiff_t>(end),
                     [&](uint32_t a, uint32_t b) {
                       const double pa = points_[a][axis], pb = points_[b][axis];
                       return pa < pb || (pa == pb && a < b);
                     });
    axes_[mid] = static_cast<uint8_t>(axis);
    build(begin, mid);
    build(mid + 1, end);
  }

  void search(size_t begin, size_t end, const Eigen::Vector3d& query, Best& best) const {
    if (begin >= end) return;
    const size_t mid = begin + (end - begin) / 2;
    const uint32_t index = order_[mid];
    const double d2 = (points_[index] - query).squaredNorm();
    if (d2 < best.distance2 || (d2 == best.distance2 && index < best.index)) best = {d2, index};
    if (end - begin == 1) return;
    const int axis = axes_[mid];
    const double delta = query[axis] - points_[index][axis];
    // Visit the side of the query first; the other only if the splitting plane is close enough
    // (<= so that equidistant points with lower indices are still found).
    if (delta < 0) {
      search(begin, mid, query, best);
      if (delta * delta <= best.distance2) search(mid + 1, end, query, best);
    } else {
      search(mid + 1, end, query, best);
      if (delta * delta <= best.distance2) search(begin, mid, query, best);
    }
  }

  const std::vector<Eigen::Vector3d>& points_;
  std::vector<uint32_t> order_;
  std::vector<uint8_t> axes_;
};

}  // namespace

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

bool sameBits(const Material& a, const Material& b) {
  return sameBits(a.density, b.density) && sameBits(a.damping, b.damping) &&
         sameBits(a.youngs, b.youngs) && sameBits(a.poisson, b.poisson);
}

bool sameControlMesh(const CellComplex& a, const CellComplex& b) {
  if (a.positions.rows() != b.positions.rows()) return false;
  for (Eigen::Index i = 0; i < a.positions.size(); ++i) {
    if (!sameBits(a.positions.data()[i], b.positions.data()[i])) return false;
  }
  return a.cellFaceBegin == b.cellFaceBegin && a.loopBegin == b.loopBegin &&
         a.loopVertices == b.loopVertices && a.creases == b.creases && a.corners == b.corners;
}

bool sameMaterialSamples(const MaterialSamples& a, const MaterialSamples& b) {
  if (a.level != b.level || a.materials.size() != b.materials.size() ||
      a.restPositions.size() != b.restPositions.size()) {
    return false;
  }
  for (size_t i = 0; i < a.materials.size(); ++i) {
    if (!sameBits(a.materials[i], b.materials[i])) return false;
  }
  for (size_t i = 0; i < a.restPositions.size(); ++i) {
    for (int k = 0; k < 3; ++k) {
      if (!sameBits(a.restPositions[i][k], b.restPositions[i][k])) return false;
    }
  }
  return true;
}

MaterialSamples captureMaterials(const FemMesh& mesh, int level) {
  MaterialSamples samples;
  samples.level = level;
  samples.restPositions = mesh.gaussRestPosition;
  samples.materials = mesh.gaussMaterial;
  return samples;
}

std::vector<Material> resampleMaterials(const MaterialSamples& from,
                                        std::span<const Eigen::Vector3d> positions,
                                        const Material& fallback) {
  std::vector<Material> result(positions.size(), fallback);
  if (from.materials.empty() || from.restPositions.size() != from.materials.size()) return result;
  const KdTree tree(from.restPositions);
  for (size_t i = 0; i < positions.size(); ++i)
    result[i] = from.materials[tree.nearest(positions[i])];
  return result;
}

std::string contentHash(std::string_view bytes) {
  uint64_t hash = 0xcbf29ce484222325ull;
  for (const char ch : bytes) {
    hash ^= static_cast<unsigned char>(ch);
    hash *= 0x100000001b3ull;
  }
  static constexpr char kHex[] = "0123456789abcdef";
  std::string text = "fnv1a64:";
  for (int shift = 60; shift >= 0; shift -= 4) text.push_back(kHex[(hash >> shift) & 0xf]);
  return text;
}

void normalisePins(std::vector<uint32_t>& pins) {
  std::sort(pins.begin(), pins.end());
  pins.erase(std::unique(pins.begin(), pins.end()), pins.end());
}

}  // namespace sculpt
