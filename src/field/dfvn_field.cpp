#include "field/dfvn_field.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>

#include "field/cross_product.hpp"

namespace dfvn {

void FieldOptions::validate() const {
  if (!std::isfinite(frequency) || !(frequency > 0.0))
    throw std::invalid_argument(fmt::format("frequency must be finite and positive, got {}", frequency));
}

template <int N>
DfvnField<N>::DfvnField(std::uint64_t seed, const FieldOptions& options)
    : noise_((options.validate(), make_noise_functions<N>(options.noise, seed))),
      options_(options),
      seed_(seed),
      scale_(2.0 * std::numbers::pi * options.frequency / noise_->wavenumber()),
      amplitude_(noise_->amplitude()) {
  if (!std::isfinite(scale_) || !(scale_ > 0.0))
    throw std::invalid_argument(fmt::format("frequency {} is outside the range the noise supports", options.frequency));
}

template <int N>
FieldSample<N> DfvnField<N>::evaluate(const Vec<N>& x) const {
  const NoiseSample<N, N - 1> noise = noise_->evaluate(scale_ * x);
  FieldSample<N> out;
  const double value_scale = amplitude_ / scale_;
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
