#include "dfvn/noise/noise_functions.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>

#include "dfvn/noise/gradient_noise.hpp"
#include "dfvn/noise/simplex_noise.hpp"
#include "dfvn/noise/simplex_separate.hpp"
#include "dfvn/noise/turning_bands.hpp"

namespace dfvn {

NoiseBasis parse_noise_basis(std::string_view name) {
  for (NoiseBasis basis : kNamedNoiseBases)
    if (name == to_string(basis)) return basis;
  throw std::invalid_argument("unknown noise basis '" + std::string(name) + "' (allowed: " + noise_basis_names() + ")");
}

std::string_view to_string(NoiseBasis basis) {
  switch (basis) {
    case NoiseBasis::simplex: return "simplex";
    case NoiseBasis::turning_bands: return "turning-bands";
    case NoiseBasis::quintic_gradient: return "quintic-gradient";
    case NoiseBasis::simplex_separate: return "simplex-separate";
    case NoiseBasis::steerable: return "steerable";
  }
  return "?";
}

std::string noise_basis_names() {
  std::string names;
  for (NoiseBasis basis : kNamedNoiseBases) names += (names.empty() ? "" : ", ") + std::string(to_string(basis));
  return names;
}

void check_noise_phase(double phase) {
  if (!std::isfinite(phase)) throw std::invalid_argument(fmt::format("the phase must be a finite number of radians, got {}", phase));
}

double reduced_phase(double phase) {
  check_noise_phase(phase);
  if (std::abs(phase) <= std::numbers::pi) return phase;
  return std::atan2(std::sin(phase), std::cos(phase));
}

template <int N>
std::shared_ptr<const NoiseFunctions<N>> make_noise_functions(NoiseBasis basis, std::uint64_t seed, double phase) {
  check_noise_phase(phase);
  switch (basis) {
    case NoiseBasis::simplex: return std::make_shared<const SimplexNoiseFunctions<N>>(seed, phase);
    case NoiseBasis::turning_bands: return std::make_shared<const TurningBandsNoise<N>>(seed, Simd::best, phase);
    case NoiseBasis::quintic_gradient: return std::make_shared<const QuinticGradientNoise<N>>(seed, phase);
    case NoiseBasis::simplex_separate: return std::make_shared<const SimplexSeparateNoiseFunctions<N>>(seed, phase);
    case NoiseBasis::steerable:
      throw std::invalid_argument("steerable noise needs its direction field (--steer-dir or --steer-field circular)");
  }
  throw std::invalid_argument("unknown noise basis");
}

template <int N>
std::shared_ptr<const NoiseFunctions<N>> make_periodic_noise_functions(NoiseBasis basis, std::uint64_t seed,
                                                                       double frequency, double phase) {
  check_noise_phase(phase);
  if (basis != NoiseBasis::turning_bands)
    throw std::invalid_argument("the torus needs a periodic noise basis: turning-bands (not " + std::string(to_string(basis)) +
                                ")");
  return std::make_shared<const TurningBandsNoise<N>>(seed, typename TurningBandsNoise<N>::Periodic{frequency}, Simd::best, phase);
}

template std::shared_ptr<const NoiseFunctions<2>> make_noise_functions<2>(NoiseBasis, std::uint64_t, double);
template std::shared_ptr<const NoiseFunctions<2>> make_periodic_noise_functions<2>(NoiseBasis, std::uint64_t, double, double);
template std::shared_ptr<const NoiseFunctions<3>> make_noise_functions<3>(NoiseBasis, std::uint64_t, double);
template std::shared_ptr<const NoiseFunctions<3>> make_periodic_noise_functions<3>(NoiseBasis, std::uint64_t, double, double);
template std::shared_ptr<const NoiseFunctions<4>> make_noise_functions<4>(NoiseBasis, std::uint64_t, double);
template std::shared_ptr<const NoiseFunctions<4>> make_periodic_noise_functions<4>(NoiseBasis, std::uint64_t, double, double);
template std::shared_ptr<const NoiseFunctions<5>> make_noise_functions<5>(NoiseBasis, std::uint64_t, double);
template std::shared_ptr<const NoiseFunctions<5>> make_periodic_noise_functions<5>(NoiseBasis, std::uint64_t, double, double);
template std::shared_ptr<const NoiseFunctions<6>> make_noise_functions<6>(NoiseBasis, std::uint64_t, double);
template std::shared_ptr<const NoiseFunctions<6>> make_periodic_noise_functions<6>(NoiseBasis, std::uint64_t, double, double);
template std::shared_ptr<const NoiseFunctions<7>> make_noise_functions<7>(NoiseBasis, std::uint64_t, double);
template std::shared_ptr<const NoiseFunctions<7>> make_periodic_noise_functions<7>(NoiseBasis, std::uint64_t, double, double);
template std::shared_ptr<const NoiseFunctions<8>> make_noise_functions<8>(NoiseBasis, std::uint64_t, double);
template std::shared_ptr<const NoiseFunctions<8>> make_periodic_noise_functions<8>(NoiseBasis, std::uint64_t, double, double);

}  // namespace dfvn
