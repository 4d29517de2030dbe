// The one place where a runtime dimension becomes a compile-time one.
#pragma once

#include <Eigen/Core>
#include <stdexcept>
#include <string>
#include <utility>

namespace dfvn {

inline constexpr int kMinDimension = 2;
inline constexpr int kMaxDimension = 8;

template <int N>
using Vec = Eigen::Matrix<double, N, 1>;

// Calls f.template operator()<N>() for the runtime dimension n. Every dimension in
// [kMinDimension, kMaxDimension] is instantiated here, so each one is compiled.
template <typename F>
decltype(auto) dispatch_dimension(int n, F&& f) {
  switch (n) {
    case 2: return std::forward<F>(f).template operator()<2>();
    case 3: return std::forward<F>(f).template operator()<3>();
    case 4: return std::forward<F>(f).template operator()<4>();
    case 5: return std::forward<F>(f).template operator()<5>();
    case 6: return std::forward<F>(f).template operator()<6>();
    case 7: return std::forward<F>(f).template operator()<7>();
    case 8: return std::forward<F>(f).template operator()<8>();
    default:
      throw std::invalid_argument("dimension " + std::to_string(n) + " is not supported (allowed: " +
                                  std::to_string(kMinDimension) + ".." +
                                  std::to_string(kMaxDimension) + ")");
  }
}

}  // namespace dfvn
