#pragma once
// Node vectors padded to four doubles per node (x, y, z, 0), and the transfers between them and
// the element kernels' coordinate-major element vectors. The padding turns the per-element
// gather and scatter (64 nodes for a tricubic element) into one 32-byte load or load-add-store
// per node plus a 4x4 transpose per four nodes, instead of three scalar accesses per node.

#include <Eigen/Core>
#include <cstdint>

#if defined(__AVX__)
#include <immintrin.h>
#endif

#include "mesh/cell_complex.h"

namespace sculpt {

using NodeRows = Eigen::Matrix<double, Eigen::Dynamic, 4, Eigen::RowMajor>;

/// element[c*count + n] = rows(ids[n], c) for c < 3; count is a multiple of 4.
inline void gatherNodeRows(const NodeRows& rows, const uint32_t* ids, int count, double* element) {
  const double* base = rows.data();
  for (int n = 0; n < count; n += 4) {
#if defined(__AVX__)
    const __m256d p0 = _mm256_loadu_pd(base + 4 * size_t(ids[n]));
    const __m256d p1 = _mm256_loadu_pd(base + 4 * size_t(ids[n + 1]));
    const __m256d p2 = _mm256_loadu_pd(base + 4 * size_t(ids[n + 2]));
    const __m256d p3 = _mm256_loadu_pd(base + 4 * size_t(ids[n + 3]));
    const __m256d xz01 = _mm256_unpacklo_pd(p0, p1), yw01 = _mm256_unpackhi_pd(p0, p1);
    const __m256d xz23 = _mm256_unpacklo_pd(p2, p3), yw23 = _mm256_unpackhi_pd(p2, p3);
    _mm256_storeu_pd(element + n, _mm256_permute2f128_pd(xz01, xz23, 0x20));
    _mm256_storeu_pd(element + count + n, _mm256_permute2f128_pd(yw01, yw23, 0x20));
    _mm256_storeu_pd(element + 2 * count + n, _mm256_permute2f128_pd(xz01, xz23, 0x31));
#else
    for (int k = n; k < n + 4; ++k)
      for (int c = 0; c < 3; ++c) element[c * count + k] = base[4 * size_t(ids[k]) + c];
#endif
  }
}

/// rows(ids[n], c) += element[c*count + n] for c < 3, one node after the other (an id may
/// repeat: a pyramid's apex); count is a multiple of 4.
inline void scatterAddNodeRows(const double* element, const uint32_t* ids, int count,
                               NodeRows& rows) {
  double* base = rows.data();
  for (int n = 0; n < count; n += 4) {
#if defined(__AVX__)
    const __m256d x = _mm256_loadu_pd(element + n);
    const __m256d y = _mm256_loadu_pd(element + count + n);
    const __m256d z = _mm256_loadu_pd(element + 2 * count + n);
    const __m256d zero = _mm256_setzero_pd();
    const __m256d xy02 = _mm256_unpacklo_pd(x, y), xy13 = _mm256_unpackhi_pd(x, y);
    const __m256d z02 = _mm256_unpacklo_pd(z, zero), z13 = _mm256_unpackhi_pd(z, zero);
    const __m256d node[4] = {_mm256_permute2f128_pd(xy02, z02, 0x20),
                             _mm256_permute2f128_pd(xy13, z13, 0x20),
                             _mm256_permute2f128_pd(xy02, z02, 0x31),
                             _mm256_permute2f128_pd(xy13, z13, 0x31)};
    for (int k = 0; k < 4; ++k) {
      double* row = base + 4 * size_t(ids[n + k]);
      _mm256_storeu_pd(row, _mm256_add_pd(_mm256_loadu_pd(row), node[k]));
    }
#else
    for (int k = n; k < n + 4; ++k)
      for (int c = 0; c < 3; ++c) base[4 * size_t(ids[k]) + c] += element[c * count + k];
#endif
  }
}

}  // namespace sculpt
