#include "sim/rest_stiffness.h"

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include "fem/tricubic_kernel.h"
#include "sim/node_block_rows.h"

namespace sculpt {
namespace {

using Block = Eigen::Matrix3d;

// A tricubic element's rest stiffness, as the kernel computes it (its Hessian products with the
// unit vectors at rotation I: tricubicRestStiffness). An affine element of uniform material is
// lambda K_lambda + mu K_mu, with the two parts shared by every element of the same inverse
// Jacobian and volume (all the cells of a block, most of a cage's), kept as 64 x 64 blocks
// (a * 64 + b).
class TricubicStiffness {
 public:
  // Either an element's own matrix (192 x 192, coordinate c of node a at row c * 64 + a) or a
  // pair of shared parts and their weights.
  struct Element {
    const Eigen::MatrixXd* own = nullptr;
    const Block* lambdaPart = nullptr;
    const Block* muPart = nullptr;
    double lambda = 0, mu = 0;
  };

  TricubicStiffness(const FemMesh& mesh, std::span<const LameParameters> lame)
      : mesh_(mesh), lame_(lame), own_(192, 192) {}

  Element operator()(uint32_t e) {
    const Eigen::Matrix3d* J = mesh_.tricubicInverseJacobian.data() + size_t(e) * 64;
    const double* volume = mesh_.gaussVolume.data() + mesh_.gaussBegin(e);
    const LameParameters* lame = lame_.data() + mesh_.gaussBegin(e);
    const bool affine = affineInverseJacobians(J);
    bool uniform = true;
    for (int q = 1; q < kTricubicGaussPoints && uniform; ++q)
      uniform = lame[q].lambda == lame[0].lambda && lame[q].mu == lame[0].mu;
    if (!affine || !uniform) {
      stiffness(J, affine, volume, lame, own_);
      return {&own_};
    }
    // Elements of one shape agree to rounding only (their Jacobians come from their own
    // corners): the key keeps 30 bits of the volume, of the largest entry and of each entry
    // relative to it (a zero comes out as rounding noise).
    const double scale = J[0].cwiseAbs().maxCoeff();
    std::array<double, 11> key;
    for (int rc = 0; rc < 9; ++rc)
      key[size_t(rc)] = std::round(J[0](rc / 3, rc % 3) / scale * 0x1p30);
    key[9] = roundedTo30Bits(scale);
    key[10] = roundedTo30Bits(volume[0]);
    auto found = shared_.find(key);
    if (found == shared_.end()) {
      Parts parts;
      std::vector<LameParameters> unit(kTricubicGaussPoints);
      for (LameParameters& p : unit) p = {1.0, 0.0};
      stiffness(J, true, volume, unit.data(), own_);
      parts.lambda = blocksOf(own_);
      for (LameParameters& p : unit) p = {0.0, 1.0};
      stiffness(J, true, volume, unit.data(), own_);
      parts.mu = blocksOf(own_);
      found = shared_.emplace(key, std::move(parts)).first;
    }
    return {nullptr, found->second.lambda.data(), found->second.mu.data(), lame[0].lambda,
            lame[0].mu};
  }

  // Block (a, b) of an element's own matrix.
  static Block blockOf(const Eigen::MatrixXd& K, int a, int b) {
    Block block;
    for (int c = 0; c < 3; ++c)
      for (int r = 0; r < 3; ++r) block(r, c) = K(r * 64 + a, c * 64 + b);
    return block;
  }

 private:
  struct Parts {
    std::vector<Block> lambda, mu;
  };
  static std::vector<Block> blocksOf(const Eigen::MatrixXd& K) {
    std::vector<Block> blocks(size_t(kTricubicNodes) * kTricubicNodes);
    for (int a = 0; a < kTricubicNodes; ++a)
      for (int b = 0; b < kTricubicNodes; ++b) blocks[size_t(a * 64 + b)] = blockOf(K, a, b);
    return blocks;
  }
  static double roundedTo30Bits(double value) {
    int exponent = 0;
    const double mantissa = std::frexp(value, &exponent);
    return std::ldexp(std::round(std::ldexp(mantissa, 30)), exponent - 30);
  }
  static void stiffness(const Eigen::Matrix3d* J, bool affine, const double* volume,
                        const LameParameters* lame, Eigen::MatrixXd& K) {
    std::vector<double> block(size_t(tricubicRestSize(affine)));
    packTricubicInverseJacobians(J, affine, block.data());
    packTricubicMaterial(volume, lame, affine, block.data());
    tricubicRestStiffness(tricubicPackedView(block.data(), affine, block.data(), 0), K.data());
  }

  const FemMesh& mesh_;
  std::span<const LameParameters> lame_;
  Eigen::MatrixXd own_;
  std::map<std::array<double, 11>, Parts> shared_;
};

}  // namespace

SparseMatrix reducedRestStiffness(const FemMesh& mesh, std::span<const LameParameters> lame,
                                  const SparseMatrix& A, const std::atomic<bool>* stop,
                                  std::span<const uint8_t> skip) {
  const auto skipped = [&](uint32_t e) { return !skip.empty() && skip[e]; };
  SymmetricNodeBlocks nodes = symmetricNodePattern(
      mesh.numNodes(), mesh.numElements(), [&](uint32_t e) { return mesh.elementNodes(e); },
      skip);
  NodeBlockRows& K = nodes.K;
  TricubicStiffness tricubic(mesh, lame);
  std::vector<uint32_t> where(mesh.numNodes());
  // Elements with a matrix of their own add it at once; those of a shared shape are added row
  // by row below, so that a row's blocks stay in cache while every element around its node adds
  // to them (element by element, each element's 2,080 blocks went to 64 rows of K, 62 MB on the
  // bunny, at 24 ns a block). The shared parts' pointers mark them.
  std::vector<TricubicStiffness::Element> shared(mesh.numTricubic());
  for (uint32_t e = 0; e < mesh.numTricubic(); ++e) {
    if (stop && e % 64 == 0 && *stop) return {};
    if (skipped(e)) continue;
    const TricubicStiffness::Element Ke = tricubic(e);
    if (!Ke.own) {
      shared[e] = Ke;
      continue;
    }
    const auto own = [&](int a, int b) { return TricubicStiffness::blockOf(*Ke.own, a, b); };
    addUpperBlocks(nodes, mesh.tricubicNodes[e], own, where);
  }
  const NodeSlots& around = nodes.around;
  for (uint32_t n = 0; n < mesh.numNodes(); ++n) {
    if (stop && n % 256 == 0 && *stop) return {};
    placeUpperRow(nodes, n, where);
    for (uint32_t s = around.begin[n]; s < around.begin[n + 1]; ++s) {
      const auto [e, a] = around.slots[s];
      if (e >= mesh.numTricubic() || !shared[e].lambdaPart) continue;
      const TricubicStiffness::Element& Ke = shared[e];
      const auto& ids = mesh.tricubicNodes[e];
      const size_t row = size_t(a) * kTricubicNodes;
      for (int b = 0; b < kTricubicNodes; ++b)  // the blocks on and above the diagonal
        if (ids[size_t(b)] >= n)
          K.block[where[ids[size_t(b)]]] +=
              Ke.lambda * Ke.lambdaPart[row + size_t(b)] + Ke.mu * Ke.muPart[row + size_t(b)];
    }
  }
  for (uint32_t e = mesh.numTricubic(); e < mesh.numElements(); ++e) {
    if (skipped(e)) continue;
    const Eigen::Matrix<double, 24, 24> Ke = linearElementStiffness(mesh, lame, e);
    addUpperBlocks(nodes, mesh.elementNodes(e),
                   [&](int a, int b) -> Block { return Ke.block<3, 3>(3 * a, 3 * b); }, where);
  }
  if (stop && *stop) return {};
  return reduceSymmetricNodeBlocks(nodes, A);
}

}  // namespace sculpt
