#include "sim/sparse_cholesky.h"

#include "sim/single_precision_factor.h"

#include <Eigen/CholmodSupport>
#include <Eigen/SparseCholesky>
#include <dlfcn.h>

#include <cstdlib>
#include <cstring>
#include <mutex>
#include <vector>

namespace sculpt {

using SparseMatrix = Eigen::SparseMatrix<double>;

// From this many rows on, the ordering is METIS's alone (see factor()).
constexpr Eigen::Index kNestedDissectionRows = 3000;

namespace {

// Eigen's wrapper keeps CHOLMOD's factor to itself; the single-precision copy reads it.
class SupernodalLLT : public Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower> {
 public:
  const cholmod_factor* factor() const { return m_cholmodFactor; }
};

}  // namespace

struct SparseCholesky::Impl {
  SupernodalLLT supernodal;
  SinglePrecisionFactor single;
  Eigen::SimplicialLLT<SparseMatrix, Eigen::Lower> simplicial;
  // The pattern the analysis belongs to (empty: none yet).
  std::vector<int> outer, inner;
  Eigen::Index rows = -1;

  bool samePattern(const SparseMatrix& S) const {
    if (S.rows() != rows || outer.size() != size_t(S.outerSize() + 1) ||
        inner.size() != size_t(S.nonZeros()))
      return false;
    return std::equal(outer.begin(), outer.end(), S.outerIndexPtr()) &&
           std::equal(inner.begin(), inner.end(), S.innerIndexPtr());
  }
  void keepPattern(const SparseMatrix& S) {
    rows = S.rows();
    outer.assign(S.outerIndexPtr(), S.outerIndexPtr() + S.outerSize() + 1);
    inner.assign(S.innerIndexPtr(), S.innerIndexPtr() + S.nonZeros());
  }
};

namespace {

// OpenBLAS (the usual libblas.so.3 on Debian) starts one thread per core, and they spin between
// calls: the haptic servo and the simulation's own workers lost their cores to them (the stylus
// window test's force faded between probes). The blocks factored here are small; one thread.
void useOneBlasThread() {
  static std::once_flag once;
  std::call_once(once, [] {
    using SetThreads = void (*)(int);
    if (auto set = reinterpret_cast<SetThreads>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads")))
      set(1);
  });
}

}  // namespace

SparseCholesky::Method SparseCholesky::defaultMethod() {
  const char* text = std::getenv("SCULPT_CHOLESKY");
  return text && std::strcmp(text, "simplicial") == 0 ? Method::Simplicial : Method::Supernodal;
}

SparseCholesky::SparseCholesky(Method method) : method_(method), impl_(std::make_unique<Impl>()) {
  useOneBlasThread();
}
SparseCholesky::~SparseCholesky() = default;
SparseCholesky::SparseCholesky(SparseCholesky&&) noexcept = default;
SparseCholesky& SparseCholesky::operator=(SparseCholesky&&) noexcept = default;

void SparseCholesky::analyse(const SparseMatrix& S) {
  if (!S.isCompressed()) {
    SparseMatrix compressed = S;
    compressed.makeCompressed();
    analyse(compressed);
    return;
  }
  valid_ = false;
  size_ = S.rows();
  if (impl_->samePattern(S)) return;
  if (method_ == Method::Supernodal) {
    // CHOLMOD's default orders with AMD and, when the fill is high, also with METIS, keeping
    // the sparser factor. Past a few thousand rows our systems (3D lattices of control points)
    // always kept METIS's nested dissection: the AMD analysis is skipped there (block10 at
    // K = 1: 3.0 M nonzeros in L against AMD's 3.5 M).
    auto& llt = impl_->supernodal;
    cholmod_common& common = llt.cholmod();
    if (S.rows() >= kNestedDissectionRows) {
      common.nmethods = 1;
      common.method[0].ordering = CHOLMOD_METIS;
    } else {
      common.nmethods = 0;
    }
    llt.analyzePattern(S);
  } else {
    impl_->simplicial.analyzePattern(S);
  }
  impl_->keepPattern(S);
}

bool SparseCholesky::factor(const SparseMatrix& S) {
  if (!S.isCompressed()) {
    SparseMatrix compressed = S;
    compressed.makeCompressed();
    return factor(compressed);
  }
  analyse(S);  // nothing to do while the pattern stays
  if (method_ == Method::Supernodal) {
    auto& llt = impl_->supernodal;
    llt.factorize(S);
    valid_ = llt.info() == Eigen::Success;
    if (valid_) impl_->single.copy(*llt.factor());  // reuses the copy's storage
    else impl_->single = {};
  } else {
    auto& llt = impl_->simplicial;
    llt.factorize(S);
    valid_ = llt.info() == Eigen::Success;
  }
  return valid_;
}

void SparseCholesky::solve(const Eigen::VectorXd& r, Eigen::VectorXd& z) const {
  if (method_ == Method::Simplicial) {
    z = impl_->simplicial.solve(r);
    return;
  }
  // In single precision, unless a value leaves its range.
  if (impl_->single.empty() || !impl_->single.solve(r, z)) z = impl_->supernodal.solve(r);
}

void SparseCholesky::solve(const Eigen::MatrixXd& R, Eigen::MatrixXd& Z,
                           Precision precision) const {
  if (method_ == Method::Simplicial) {
    Z = impl_->simplicial.solve(R);
    return;
  }
  if (precision == Precision::Double || impl_->single.empty() || !impl_->single.solve(R, Z))
    Z = impl_->supernodal.solve(R);
}

long long SparseCholesky::factorNonZeros() const {
  if (!valid_) return 0;
  if (method_ == Method::Supernodal)
    return static_cast<long long>(const_cast<Impl&>(*impl_).supernodal.cholmod().lnz);
  return impl_->simplicial.matrixL().nestedExpression().nonZeros();
}

}  // namespace sculpt
