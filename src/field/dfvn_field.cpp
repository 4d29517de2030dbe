#include "field/dfvn_field.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "field/cross_product.hpp"
#include "noise/noise_domain.hpp"

namespace dfvn {

template <int N>
DfvnField<N>::DfvnField(std::uint64_t seed, double frequency, double amplitude)
    : noise_(seed), frequency_(frequency), amplitude_(amplitude) {
  check_noise_frequency(frequency);
  if (!std::isfinite(amplitude) || amplitude <= 0.0)
    throw std::invalid_argument("amplitude must be finite and positive, got " + std::to_string(amplitude));
}

template <int N>
FieldSample<N> DfvnField<N>::evaluate(const Vec<N>& x) const {
  const NoiseSample<N, N - 1> noise = noise_.evaluate_all(frequency_ * x);
  FieldSample<N> out;
  const double value_scale = amplitude_ / frequency_;
  for (int i = 0; i < N - 1; ++i) {
    out.value[i] = value_scale * noise.value[i];
    out.gradient[i] = amplitude_ * noise.gradient[i];
  }
  out.velocity = cross<N>(out.gradient);  // Eq. (8)
  return out;
}

template class DfvnField<2>;
template class DfvnField<3>;
template class DfvnField<4>;
template class DfvnField<5>;
template class DfvnField<6>;
template class DfvnField<7>;
template class DfvnField<8>;

}  // namespace dfvn
