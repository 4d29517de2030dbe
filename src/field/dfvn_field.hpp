// The divergence-free vector noise field c(x) = cross(grad f_1, ..., grad f_{N-1}) (Eq. 8).
#pragma once

#include <array>
#include <cstdint>

#include "core/dimension.hpp"
#include "field/normalisation.hpp"
#include "noise/simplex_noise.hpp"

namespace dfvn {

template <int N>
struct FieldSample {
  Vec<N> velocity;                       // c(x)
  std::array<double, N - 1> value;       // f_i(x)
  std::array<Vec<N>, N - 1> gradient;    // grad f_i(x)
};

// f_i(x) = (A_N / F) n_i(F x), where n_i are the N-1 simplex noise functions of one seed, F is the
// frequency and A_N the per-dimension amplitude of normalisation.hpp. Then grad f_i(x) = A_N
// grad n_i(F x), so c = cross(grad f_i) has an RMS magnitude of 1 over space for every dimension and
// every frequency: the frequency changes how fast the field varies, never how fast points move.
// Scaling the f_i by constants does not change their iso-contours, so reprojection (Eq. 10-12)
// keeps working on exactly the curves that c is tangent to.
template <int N>
class DfvnField {
 public:
  static constexpr int kFunctions = N - 1;

  // Throws std::invalid_argument unless the frequency is in [kMinNoiseFrequency, kMaxNoiseFrequency]
  // (noise/noise_domain.hpp) and the amplitude is finite and positive. evaluate(x) needs frequency * x
  // inside the noise domain; callers check their points before evaluating.
  DfvnField(std::uint64_t seed, double frequency = 1.0, double amplitude = field_amplitude(N));

  FieldSample<N> evaluate(const Vec<N>& x) const;
  Vec<N> velocity(const Vec<N>& x) const { return evaluate(x).velocity; }

  double frequency() const { return frequency_; }
  double amplitude() const { return amplitude_; }
  std::uint64_t seed() const { return noise_.seed(); }

 private:
  SimplexNoise<N> noise_;
  double frequency_;
  double amplitude_;
};

extern template class DfvnField<2>;
extern template class DfvnField<3>;
extern template class DfvnField<4>;
extern template class DfvnField<5>;
extern template class DfvnField<6>;
extern template class DfvnField<7>;
extern template class DfvnField<8>;

}  // namespace dfvn
