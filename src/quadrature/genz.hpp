// Genz's six test families for integration over [0,1]^N (Genz 1984, "Testing multidimensional
// integration routines"), with their exact integrals in closed form. Parameters: shifts u in [0,1)^N
// and positive widths a, scaled so that sum_i a_i = b_F, the family's difficulty; b = 9.0, 7.25,
// 1.85, 7.03, 20.4, 4.3 (Genz 1987, as used by Barthelmann, Novak and Ritter 2000), the same in every
// dimension.
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

namespace dfvn {

enum class GenzFamily { oscillatory, product_peak, corner_peak, gaussian, continuous, discontinuous };
inline constexpr GenzFamily kGenzFamilies[] = {GenzFamily::oscillatory, GenzFamily::product_peak,
                                               GenzFamily::corner_peak, GenzFamily::gaussian,
                                               GenzFamily::continuous, GenzFamily::discontinuous};
std::string_view to_string(GenzFamily family);
double genz_difficulty(GenzFamily family);  // b_F

struct GenzIntegrand {
  GenzFamily family = GenzFamily::oscillatory;
  std::vector<double> a;  // widths, a_i > 0
  std::vector<double> u;  // shifts in [0,1)
  int dimension() const { return static_cast<int>(a.size()); }

  // f(x), x in [0,1]^N:
  //   oscillatory    cos(2 pi u_1 + sum a_i x_i)
  //   product peak   prod 1 / (a_i^-2 + (x_i - u_i)^2)
  //   corner peak    (1 + sum a_i x_i)^-(N+1)
  //   gaussian       exp(-sum a_i^2 (x_i - u_i)^2)
  //   continuous     exp(-sum a_i |x_i - u_i|)
  //   discontinuous  0 if x_1 > u_1 or x_2 > u_2 (x_1 only in 1D), else exp(sum a_i x_i)
  double operator()(const double* x) const;
  // The integral over [0,1]^N in closed form (derivations in genz.cpp).
  double exact_integral() const;
};

// Random parameters of one realization: u_i and the raw widths uniform in [0,1) from (seed, family,
// axis), the widths then scaled to sum b_F.
GenzIntegrand random_genz_integrand(GenzFamily family, int dimension, std::uint64_t seed);

}  // namespace dfvn
