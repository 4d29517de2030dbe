// --time T (FieldOptions::transform.time, noise/noise_transforms.hpp's SlicedNoise): the N-1 functions
// of the (N+1)D basis at (x, T). The field targets at several times (turning bands 2D-7D: RMS within 3%
// of 1, median/RMS >= 0.4, <= 0.3% below 1% of RMS, divergence median <= 1e-8 and p95 <= 1e-6; the
// lattice bases: divergence), continuity in T (the largest change of c halves with the time step), the
// phase acting on the (N+1)D basis, the torus's period kept, N = 8 and non-finite times refused.
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

#include "dfvn/field/diagnose.hpp"
#include "dfvn/field/dfvn_field.hpp"
#include "test_support.hpp"

namespace dfvn {
namespace {

template <typename T>
class FieldTimeTest : public ::testing::Test {};
using SliceableDimensions = ::testing::Types<testing::Dim<2>, testing::Dim<3>, testing::Dim<4>, testing::Dim<5>,
                                             testing::Dim<6>, testing::Dim<7>>;
TYPED_TEST_SUITE(FieldTimeTest, SliceableDimensions);

TYPED_TEST(FieldTimeTest, MeetsTheFieldTargetsAtSeveralTimes) {
  constexpr int N = TypeParam::value;
  for (const NoiseBasis basis : kAllNoiseBases)
    for (const double t : {-2.3, 0.0, 0.37, 5.0}) {
      // Simplex's (N+1)D field fails the divergence targets from 6D on (tests/field/test_dfvn_field.cpp).
      if (basis == NoiseBasis::simplex && N + 1 > 5) continue;
      // simplex-separate's field meets them up to 6D (data/simplex_collapse.md).
      if (basis == NoiseBasis::simplex_separate && N + 1 > 6) continue;
      if (basis != NoiseBasis::turning_bands && t != 0.37) continue;  // the time the suite takes
      DiagnosisOptions options;
      options.dimension = N;
      // The ASan + UBSan build measures the lattice bases (2^(N+1) corners: 7D-8D quintic gradient took
      // 130-390 s there) on 1/8 of the points: they are held to the divergence quantiles only here.
      options.points = basis == NoiseBasis::turning_bands ? 20000 : testing::sanitizer_scaled(20000, 8);
      options.field.noise = basis;
      options.field.transform.time = t;
      const FieldDiagnosis d = diagnose_field(options);
      std::printf("%s %dD t %.2f: RMS %.4f, median/RMS %.3f, below 1%% %.3f%%, div median %.2g, p95 %.2g, k_eff ratio %.4f\n",
                  std::string(to_string(basis)).c_str(), N, t, d.rms_speed, d.median_over_rms, 100.0 * d.fraction_below_1_percent,
                  d.divergence_median, d.divergence_p95, d.wavenumber_measured / d.wavenumber_expected);
      SCOPED_TRACE(::testing::Message() << to_string(basis) << " t " << t);
      EXPECT_LE(d.divergence_median, 1e-8);
      EXPECT_LE(d.divergence_p95, 1e-6);
      if (basis == NoiseBasis::turning_bands) {
        EXPECT_NEAR(d.rms_speed, 1.0, 0.03);
        EXPECT_GE(d.median_over_rms, 0.4);
        EXPECT_LE(d.fraction_below_1_percent, 0.003);
        EXPECT_NEAR(d.wavenumber_measured / d.wavenumber_expected, 1.0, 0.03);  // F cycles per unit length along x
      }
    }
}

TYPED_TEST(FieldTimeTest, ContinuousInTime) {
  constexpr int N = TypeParam::value;
  for (const NoiseBasis basis : kAllNoiseBases) {
    auto field_at = [&](double t) {
      FieldOptions o{basis, 1.0};
      o.transform.time = t;
      return DfvnField<N>(21, o);
    };
    const double t0 = 0.61, h = 1e-3;
    const DfvnField<N> f0 = field_at(t0), f1 = field_at(t0 + h), f2 = field_at(t0 + h / 2);
    double jump = 0.0, half = 0.0;
    for (std::uint64_t k = 0; k < 400; ++k) {
      const Vec<N> x = testing::random_point<N>(2, k, -10.0, 10.0);
      const Vec<N> c0 = f0.velocity(x);
      jump = std::max(jump, (f1.velocity(x) - c0).norm());
      half = std::max(half, (f2.velocity(x) - c0).norm());
    }
    std::printf("%s %dD: largest |c(t + h) - c(t)| %.3g, at h / 2 %.3g (ratio %.3f)\n", std::string(to_string(basis)).c_str(), N,
                jump, half, jump / half);
    EXPECT_GT(jump, 0.0) << to_string(basis);
    // simplex-separate's 8D amplitude is measured with a 23% standard error (data/simplex_collapse.md),
    // so only the linear shrinking is asserted for it there.
    if (basis != NoiseBasis::simplex_separate || N + 1 < 8) {
      EXPECT_LT(jump, 0.1) << to_string(basis);
    }
    EXPECT_NEAR(jump / half, 2.0, 0.2) << to_string(basis);
  }
}

TYPED_TEST(FieldTimeTest, PhaseTurnsTheSpaceTimeBasis) {
  constexpr int N = TypeParam::value;
  FieldOptions a{NoiseBasis::turning_bands, 1.0}, b = a, zero = a;
  a.transform.time = b.transform.time = zero.transform.time = 1.25;
  a.phase = 0.8;
  b.phase = 0.8 + 2.0 * std::numbers::pi;
  const DfvnField<N> fa(3, a), fb(3, b), f0(3, zero);
  double period = 0.0, moved = 0.0;
  for (std::uint64_t k = 0; k < 200; ++k) {
    const Vec<N> x = testing::random_point<N>(6, k, -5.0, 5.0);
    period = std::max(period, (fa.velocity(x) - fb.velocity(x)).cwiseAbs().maxCoeff());
    moved = std::max(moved, (fa.velocity(x) - f0.velocity(x)).cwiseAbs().maxCoeff());
  }
  EXPECT_LE(period, 1e-11);
  EXPECT_GT(moved, 1e-2);
}

TYPED_TEST(FieldTimeTest, TorusKeepsItsPeriodAlongX) {
  constexpr int N = TypeParam::value;
  FieldOptions o{NoiseBasis::turning_bands, 2.0};
  o.periodic = true;
  o.transform.time = 0.3;
  const DfvnField<N> field(5, o);
  double worst = 0.0;
  for (std::uint64_t k = 0; k < 100; ++k) {
    const Vec<N> x = testing::random_point<N>(4, k, 0.0, 1.0);
    for (int j = 0; j < N; ++j) worst = std::max(worst, (field.velocity(x + Vec<N>::Unit(j)) - field.velocity(x)).norm());
  }
  EXPECT_LE(worst, 1e-9);
}

TEST(FieldTime, EightDimensionsAndNonFiniteTimesAreRefused) {
  FieldOptions o;
  o.transform.time = 1.0;
  EXPECT_THROW(DfvnField<8>(1, o), std::invalid_argument);  // no 9D basis
  for (const double t : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    o.transform.time = t;
    EXPECT_THROW(DfvnField<3>(1, o), std::invalid_argument) << t;
  }
  o.transform.time = 0x1p60;  // F t outside the noise domain
  EXPECT_THROW(DfvnField<3>(1, o), std::invalid_argument);
}

}  // namespace
}  // namespace dfvn
