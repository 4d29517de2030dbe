// The Gauss-Newton step of the reprojection (Eq. 10-11): the minimum-norm v with J v = r, where the
// rows of J are the N-1 gradients.
#pragma once

#include <array>
#include <cmath>
#include <utility>

#include "dfvn/core/dimension.hpp"
#include "dfvn/core/tree_sum.hpp"

namespace dfvn {

// Householder QR with column pivoting of A = J^T (N x (N-1)): A P = Q [R1; 0]. The minimum-norm
// solution lies in range(A) = range(Q1): v = Q1 w with R1^T w = P^T r.
//
// Written out for the fixed sizes (Eigen's ColPivHouseholderQR handles its reflectors through
// dynamic-size blocks: for a 7 x 6 matrix that was 15% of a CNJ point's instructions). The column of
// largest remaining norm comes first, so |R_00| is the largest and |R_{N-2,N-2}| the smallest pivot.
// A solve is one long chain of small dependent steps with little arithmetic in each, so every sum runs
// over all N entries as a balanced tree (core/tree_sum.hpp): the entries outside a column's active
// part are selected away (norms, forward substitution) or meet the reflector's zeros (reflections),
// and the reflector's v^T v comes from its closed form rather than another sum.
//
// Returns false, leaving `step` untouched, when A is rank deficient or |R_00| > max_condition
// |R_{N-2,N-2}|: the update is skipped rather than taken along a direction the rounding chose.
template <int N>
bool min_norm_step(const std::array<Vec<N>, N - 1>& gradients, const std::array<double, N - 1>& r,
                   double max_condition, Vec<N>& step) {
  constexpr int M = N - 1;
  double a[M][N];  // a[j] is column j of A, that is gradient j; reflectors act on every column
  int perm[M];
  for (int j = 0; j < M; ++j) {
    perm[j] = j;
    for (int i = 0; i < N; ++i) a[j][i] = gradients[j][i];
  }
  double reflector[M][N];  // v_k, zero above entry k
  double beta[M];          // H_k = I - beta_k v_k v_k^T
  double diagonal[M];      // R_kk
  for (int k = 0; k < M; ++k) {
    int pivot = k;
    double pivot_norm2 = -1.0;
    for (int j = k; j < M; ++j) {
      double terms[N];
      for (int i = 0; i < N; ++i) terms[i] = i >= k ? a[j][i] * a[j][i] : 0.0;
      const double norm2 = tree_sum<N>(terms);
      const bool larger = norm2 > pivot_norm2;
      pivot = larger ? j : pivot;
      pivot_norm2 = larger ? norm2 : pivot_norm2;
    }
    std::swap(a[k], a[pivot]);
    std::swap(perm[k], perm[pivot]);
    // The reflector that maps a[k][k..] onto alpha e_k, alpha of the opposite sign to a[k][k] so that
    // v_k = x - alpha e_k does not cancel; v^T v = 2 (|x|^2 + |x_k| |x|).
    const double norm = std::sqrt(pivot_norm2);
    const double alpha = a[k][k] >= 0.0 ? -norm : norm;
    for (int i = 0; i < N; ++i) reflector[k][i] = i > k ? a[k][i] : 0.0;
    reflector[k][k] = a[k][k] - alpha;
    const double vtv = 2.0 * (pivot_norm2 + std::abs(a[k][k]) * norm);
    beta[k] = vtv > 0.0 ? 2.0 / vtv : 0.0;
    diagonal[k] = alpha;
    for (int j = k + 1; j < M; ++j) {
      double terms[N];
      for (int i = 0; i < N; ++i) terms[i] = reflector[k][i] * a[j][i];
      const double f = beta[k] * tree_sum<N>(terms);
      for (int i = 0; i < N; ++i) a[j][i] -= f * reflector[k][i];
    }
  }
  const double largest = std::abs(diagonal[0]);
  const double smallest = std::abs(diagonal[M - 1]);
  if (!(smallest > 0.0) || largest > max_condition * smallest) return false;
  // R1^T w = P^T r: forward substitution; R_ik (i < k) is a[k][i] after the reflections.
  double y[N] = {};
  for (int k = 0; k < M; ++k) {
    double terms[N];
    for (int i = 0; i < N; ++i) terms[i] = i < k ? a[k][i] * y[i] : 0.0;
    y[k] = (r[perm[k]] - tree_sum<N>(terms)) / diagonal[k];
  }
  // v = Q [w; 0] = H_0 H_1 ... H_{M-1} [w; 0].
  for (int k = M - 1; k >= 0; --k) {
    double terms[N];
    for (int i = 0; i < N; ++i) terms[i] = reflector[k][i] * y[i];
    const double f = beta[k] * tree_sum<N>(terms);
    for (int i = 0; i < N; ++i) y[i] -= f * reflector[k][i];
  }
  for (int i = 0; i < N; ++i) step[i] = y[i];
  return true;
}

}  // namespace dfvn
