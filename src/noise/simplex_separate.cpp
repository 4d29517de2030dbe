#include "dfvn/noise/simplex_separate.hpp"

#include "dfvn/noise/simplex_normalisation.hpp"

namespace dfvn {
namespace {

// seeds/004's offsets (its 3D and 4D vectors share the first three), then four chosen here.
constexpr double kOffsetAxes[kMaxDimension] = {31.416, 47.853, 12.679, 113.408, 71.927, 23.114, 89.246, 57.381};

Vec<3> cross3(const Vec<3>& a, const Vec<3>& b) {
  return Vec<3>(a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]);
}

}  // namespace

template <int N>
Vec<N> simplex_separate_offset(int function) {
  Vec<N> o;
  for (int j = 0; j < N; ++j) o[j] = function * kOffsetAxes[j];
  return o;
}

template <int N>
SimplexSeparateNoiseFunctions<N>::SimplexSeparateNoiseFunctions(std::uint64_t seed, double phase)
    : noise_(seed, phase), wavenumber_(simplex_wavenumber(N)), amplitude_(simplex_separate_field_amplitude(N)) {
  for (int i = 0; i < N - 1; ++i) offsets_[i] = simplex_separate_offset<N>(i);
}

template <int N>
NoiseSample<N, N - 1> SimplexSeparateNoiseFunctions<N>::evaluate(const Vec<N>& x) const {
  NoiseSample<N, N - 1> out;
  for (int i = 0; i < N - 1; ++i) {
    // one traversal per function, always of S (function 0 of the seeded noise)
    const NoiseSample<N, 1> s = noise_.template evaluate<1>(i == 0 ? x : Vec<N>(x + offsets_[i]), 0);
    out.value[i] = s.value[0];
    out.gradient[i] = s.gradient[0];
  }
  return out;
}

Vec<3> bitangent_noise_3d(const SimplexNoise<3>& noise, const Vec<3>& p) {
  const Vec<3> da = noise.evaluate<1>(p, 0).gradient[0];
  const Vec<3> db = noise.evaluate<1>(Vec<3>(p + Vec<3>(31.416, 47.853, 12.679)), 0).gradient[0];
  return cross3(da, db);
}

Vec<3> bitangent_noise_4d(const SimplexNoise<4>& noise, const Vec<4>& p) {
  const Vec<4> da = noise.evaluate<1>(p, 0).gradient[0];
  const Vec<4> db = noise.evaluate<1>(Vec<4>(p + Vec<4>(31.416, 47.853, 12.679, 113.408)), 0).gradient[0];
  return cross3(Vec<3>(da.head<3>()), Vec<3>(db.head<3>()));
}

Vec<3> bitangent_noise_3d_fused(const SimplexNoise<3>& noise, const Vec<3>& p) {
  const NoiseSample<3, 2> s = noise.evaluate<2>(p, 0);
  return cross3(s.gradient[0], s.gradient[1]);
}

Vec<3> bitangent_noise_4d_fused(const SimplexNoise<4>& noise, const Vec<4>& p) {
  const NoiseSample<4, 2> s = noise.evaluate<2>(p, 0);
  return cross3(Vec<3>(s.gradient[0].head<3>()), Vec<3>(s.gradient[1].head<3>()));
}

#define DFVN_INSTANTIATE_SEPARATE(N)                      \
  template Vec<N> simplex_separate_offset<N>(int);        \
  template class SimplexSeparateNoiseFunctions<N>;
DFVN_INSTANTIATE_SEPARATE(2)
DFVN_INSTANTIATE_SEPARATE(3)
DFVN_INSTANTIATE_SEPARATE(4)
DFVN_INSTANTIATE_SEPARATE(5)
DFVN_INSTANTIATE_SEPARATE(6)
DFVN_INSTANTIATE_SEPARATE(7)
DFVN_INSTANTIATE_SEPARATE(8)
#undef DFVN_INSTANTIATE_SEPARATE

}  // namespace dfvn
