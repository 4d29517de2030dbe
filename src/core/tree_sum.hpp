// Sums of a few numbers in a fixed balanced tree, for small fixed-size kernels whose time is the
// latency of one long dependent chain (field/cross_product.hpp, integrate/min_norm_step.hpp).
#pragma once

namespace dfvn {

// p[0] + ... + p[n-1] as a balanced tree: ceil(log2 n) dependent additions instead of n - 1. The order
// is fixed by n, so for a given build the result depends only on p. (A build that lets the compiler
// fuse multiply-adds, e.g. DFVN_NATIVE on an FMA machine, may round the callers' products differently.)
template <int n>
[[gnu::always_inline]] inline double tree_sum(const double* p) {
  static_assert(n >= 1);
  if constexpr (n == 1) {
    return p[0];
  } else {
    return tree_sum<n / 2>(p) + tree_sum<n - n / 2>(p + n / 2);
  }
}

}  // namespace dfvn
