#include "field/dfvn_field.hpp"

#include <cassert>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>

#include "field/cross_product.hpp"
#include "noise/noise_domain.hpp"

namespace dfvn {

void FieldOptions::validate() const {
  check_noise_frequency(frequency);
  if ((constraint == FieldConstraint::inside_cube || constraint == FieldConstraint::inside_ball) &&
      !(transition_width > 0.0 && transition_width <= 0.25))
    throw std::invalid_argument(
        fmt::format("the boundary's transition width must be in (0, 1/4], got {:g}", transition_width));
}

template <int N>
DfvnField<N>::DfvnField(std::uint64_t seed, const FieldOptions& options)
    : noise_((options.validate(), make_noise_functions<N>(options.noise, seed))),
      options_(options),
      seed_(seed),
      scale_(2.0 * std::numbers::pi * options.frequency / noise_->wavenumber()),
      amplitude_(noise_->amplitude()) {
  if (options.constraint != FieldConstraint::none)
    constraint_ = std::make_shared<const ConstraintFunction<N>>(options.constraint, options.transition_width);
  // The noise domain bounds F x; each basis is safe for its own scale s = 2 pi F / k_eff there
  // (noise/noise_domain.hpp), which the checks of the tests assert.
  assert(scale_ > 0.0 && scale_ <= 2.0 * options.frequency);
}

template <int N>
bool DfvnField<N>::in_domain(const Vec<N>& x) const {
  return in_noise_domain(Vec<N>(options_.frequency * x));
}

template <int N>
void DfvnField<N>::check_in_domain(const Vec<N>& x, std::string_view what) const {
  for (int j = 0; j < N; ++j) check_noise_argument(x[j], options_.frequency, fmt::format("{}, column {}", what, j + 1));
}

template <int N>
FieldSample<N> DfvnField<N>::evaluate_functions(const Vec<N>& x) const {
  const NoiseSample<N, N - 1> noise = noise_->evaluate(scale_ * x);
  FieldSample<N> out;
  const double value_scale = amplitude_ / scale_;
  for (int i = 0; i < N - 1; ++i) {
    out.value[i] = value_scale * noise.value[i];
    out.gradient[i] = amplitude_ * noise.gradient[i];
  }
  if (constraint_) constraint_->replace(x, out.value[0], out.gradient[0]);
  out.velocity.setConstant(std::numeric_limits<double>::quiet_NaN());
  return out;
}

template <int N>
FieldSample<N> DfvnField<N>::evaluate(const Vec<N>& x) const {
  FieldSample<N> out = evaluate_functions(x);
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
