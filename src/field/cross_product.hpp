// The generalised cross product of N-1 vectors in R^N (Shaw 1987; the paper's Eq. 1).
#pragma once

#include <array>
#include <cmath>
#include <limits>
#include <utility>

#include "dfvn/core/dimension.hpp"
#include "dfvn/core/tree_sum.hpp"

namespace dfvn {

// cross(v_1, ..., v_{N-1}) is the vector c with c . v = det[v | v_1 | ... | v_{N-1}] for every v
// (Eq. 1). In 2D that is (v_y, -v_x), the vector rotated clockwise by 90 degrees (Section 3.2); in 3D
// the usual cross product.
//
// Instead of N cofactors of size N-1 (O(N^4)) we factor A = [v_1 | ... | v_{N-1}] once, O(N^3):
// Gaussian elimination with partial pivoting gives P A = L U with L unit lower triangular (N x N,
// last column e_N) and U upper triangular (N x (N-1), last row zero). Then
//   P [A | v] = L [U | L^{-1} P v]  =>  det[A | v] = sign(P) prod(U_kk) (e_N^T L^{-1} P v),
// so with l = L^{-T} e_N: det[A | v] = sign(P) prod(U_kk) sum_i l_i v_{perm(i)}, and
// det[v | A] = (-1)^(N-1) det[A | v] (moving a column across N-1 others).
// A rank-deficient A yields an exact zero pivot and the zero vector, which is the correct answer.
// The time is the latency of one dependent chain, so the pivot search and the row exchange do not
// branch (a row is exchanged with itself when it is its own pivot) and l's sums are balanced trees.
// A pivot below 2^-1024 (vectors of subnormal size: the gradients near the centre of an obstacle of
// radius 1e-310) has no finite reciprocal: then cross_rescaled computes the same product exactly scaled.
template <int N>
Vec<N> cross_rescaled(const std::array<Vec<N>, N - 1>& v);

template <int N>
Vec<N> cross(const std::array<Vec<N>, N - 1>& v) {
  double a[N][N - 1];
  int perm[N];
  for (int i = 0; i < N; ++i) {
    perm[i] = i;
    for (int k = 0; k < N - 1; ++k) a[i][k] = v[k][i];
  }
  double scale = (N % 2 == 1) ? 1.0 : -1.0;  // (-1)^(N-1)
  for (int k = 0; k < N - 1; ++k) {
    int pivot = k;
    double largest = std::abs(a[k][k]);
    for (int i = k + 1; i < N; ++i) {
      const double candidate = std::abs(a[i][k]);
      const bool larger = candidate > largest;
      pivot = larger ? i : pivot;
      largest = larger ? candidate : largest;
    }
    if (largest == 0.0) return Vec<N>::Zero();
    for (int j = 0; j < N - 1; ++j) std::swap(a[k][j], a[pivot][j]);
    std::swap(perm[k], perm[pivot]);
    scale = pivot != k ? -scale : scale;
    scale *= a[k][k];
    const double inverse_pivot = 1.0 / a[k][k];
    if (std::abs(inverse_pivot) > std::numeric_limits<double>::max()) [[unlikely]]
      return cross_rescaled<N>(v);
    for (int i = k + 1; i < N; ++i) {
      const double factor = a[i][k] * inverse_pivot;
      a[i][k] = factor;  // L(i, k)
      for (int j = k + 1; j < N - 1; ++j) a[i][j] -= factor * a[k][j];
    }
  }
  // Solve L^T l = e_N by back substitution (L^T is unit upper triangular).
  double l[N] = {};
  l[N - 1] = 1.0;
  for (int i = N - 2; i >= 0; --i) {
    double terms[N];
    for (int j = 0; j < N; ++j) terms[j] = j > i ? a[j][i] * l[j] : 0.0;
    l[i] = -tree_sum<N>(terms);
  }
  Vec<N> c;
  for (int i = 0; i < N; ++i) c[perm[i]] = scale * l[i];
  return c;
}

// cross(v) for vectors of any finite size: cross is linear in each v_k, so each is scaled by a power of
// two (exact) to a largest component in [1, 2), the product of those is taken by elimination that divides
// by each pivot (|L(i, k)| <= 1 under partial pivoting, so nothing overflows), and the result is scaled
// back (to a subnormal number or zero when that is its size). Rarely used: slower than cross's reciprocals.
template <int N>
Vec<N> cross_rescaled(const std::array<Vec<N>, N - 1>& v) {
  double a[N][N - 1];
  int perm[N];
  int exponent = 0;
  for (int k = 0; k < N - 1; ++k) {
    const double largest = v[k].cwiseAbs().maxCoeff();
    if (largest == 0.0) return Vec<N>::Zero();
    const int e = std::ilogb(largest);
    exponent += e;
    for (int i = 0; i < N; ++i) a[i][k] = std::ldexp(v[k][i], -e);
  }
  for (int i = 0; i < N; ++i) perm[i] = i;
  double scale = (N % 2 == 1) ? 1.0 : -1.0;
  for (int k = 0; k < N - 1; ++k) {
    int pivot = k;
    for (int i = k + 1; i < N; ++i)
      if (std::abs(a[i][k]) > std::abs(a[pivot][k])) pivot = i;
    if (a[pivot][k] == 0.0) return Vec<N>::Zero();
    for (int j = 0; j < N - 1; ++j) std::swap(a[k][j], a[pivot][j]);
    std::swap(perm[k], perm[pivot]);
    if (pivot != k) scale = -scale;
    // The pivot's own exponent moves to `exponent`, so that `scale` stays near 1 whatever the pivots.
    const int e = std::ilogb(a[k][k]);
    exponent += e;
    scale *= std::ldexp(a[k][k], -e);
    for (int i = k + 1; i < N; ++i) {
      const double factor = a[i][k] / a[k][k];
      a[i][k] = factor;
      for (int j = k + 1; j < N - 1; ++j) a[i][j] -= factor * a[k][j];
    }
  }
  double l[N] = {};
  l[N - 1] = 1.0;
  for (int i = N - 2; i >= 0; --i) {
    double sum = 0.0;
    for (int j = i + 1; j < N; ++j) sum += a[j][i] * l[j];
    l[i] = -sum;
  }
  Vec<N> c;
  for (int i = 0; i < N; ++i) c[perm[i]] = std::ldexp(scale * l[i], exponent);
  return c;
}

}  // namespace dfvn
