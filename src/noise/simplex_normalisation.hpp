// Per-dimension amplitude A_N of the simplex noise functions, so that the RMS of |c| over space is 1
// (SimplexNoiseFunctions::amplitude). The shared traversal couples the functions, so there is no
// closed form (contrast turning_bands.hpp): the amplitudes are measured.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>

namespace dfvn {

// Produced by scripts/derive_normalisation (build/scripts/derive_normalisation 2000000 8): for each N,
// A_N = rms^(-1/(N-1)) where rms is the RMS of |cross(grad n_1, ..., grad n_{N-1})| of the raw simplex
// noise over 2 million uniform points of [0,1000]^N for each of 8 seeds.
//
// Why the error grows with N: with the C^2 kernel radius r^2 = 1/2 (simplex_noise.hpp) the kernels
// of the N+1 vertices cover less and less of the simplex as N grows (no vertex in range: 0% of
// space up to 5D, 1.8% in 6D, 18% in 7D, 41% in 8D), and each gradient near the edge of a kernel
// scales like t^4, so |c| behaves like t^(4(N-1)): most of space is nearly still and the RMS is
// carried by rare fast regions (median |c| / RMS: 0.90 in 2D, 0.07 in 4D, 1e-14 in 7D). A_N itself
// is accurate to (relative error of mean |c|^2) / (2 (N-1)): below 1% in every dimension. The third column is the relative
// standard error of the mean of |c|^2 that the derivation reported; tests/field/test_normalisation.cpp
// re-checks RMS |c| = 1 with other seeds and points.
struct AmplitudeEntry {
  int dimension;
  double amplitude;
  double relative_standard_error;
};

inline constexpr AmplitudeEntry kFieldAmplitudes[] = {
    {2, 27.2205, 0.0002},
    {3, 27.6827, 0.00063},
    {4, 26.7845, 0.0022},
    {5, 25.3173, 0.0065},
    {6, 24.0405, 0.019},
    {7, 23.0393, 0.081},
    {8, 22.311, 0.17},
};

// The same for the simplex-separate basis (noise/simplex_separate.hpp): build/scripts/derive_normalisation
// 2000000 8 separate, the same points and seeds. 2D is simplex's (one function: the same S). The
// separate functions' envelopes are independent-ish (shifted by o_i), so |c| is still wherever any one
// function is in a hole: the raw RMS falls faster with N than the fused one's, and from 7D on a few
// points carry it (relative standard errors 15% and 23%).
inline constexpr AmplitudeEntry kSeparateFieldAmplitudes[] = {
    {2, 27.2205, 0.0002},
    {3, 28.1032, 0.00034},
    {4, 33.5928, 0.00082},
    {5, 48.7473, 0.0021},
    {6, 74.4628, 0.014},
    {7, 138.341, 0.15},
    {8, 277.175, 0.23},
};

// The amplitude a table holds for a dimension; throws std::invalid_argument if it has none.
template <std::size_t Size>
double field_amplitude_in(const AmplitudeEntry (&table)[Size], int dimension) {
  for (const auto& entry : table)
    if (entry.dimension == dimension) return entry.amplitude;
  throw std::invalid_argument("no field amplitude for dimension " + std::to_string(dimension));
}

inline double simplex_separate_field_amplitude(int dimension) {
  return field_amplitude_in(kSeparateFieldAmplitudes, dimension);
}

inline double simplex_field_amplitude(int dimension) { return field_amplitude_in(kFieldAmplitudes, dimension); }

}  // namespace dfvn
