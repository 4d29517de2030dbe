// --stretch U:S (FieldOptions::transform, noise/noise_transforms.hpp): f_i(A x) with A = I + (S-1) u u^T.
// For every basis and dimension: the field's divergence targets (|div c| / |Dc| median <= 1e-8, p95 <=
// 1e-6) and RMS |c| within 3% of 1 after the renormalisation (simplex where its unstretched field meets
// them: divergence N <= 5, RMS N <= 4); on 10^5 random points E[grad f grad f^T]
// has an eigenvector along u within 2 degrees whose eigenvalue is S^2 times the mean of the others
// within 3%; S = 1 is the unstretched field bit for bit; bad stretches refused.
#include <cmath>
#include <cstdio>
#include <numbers>

#include <Eigen/Eigenvalues>

#include "dfvn/field/diagnose.hpp"
#include "dfvn/field/dfvn_field.hpp"
#include "test_support.hpp"

namespace dfvn {
namespace {

// A direction that is on no axis and no diagonal: (1, -2, 3, -4, ...).
std::vector<double> skew_direction(int n) {
  std::vector<double> u(static_cast<std::size_t>(n));
  for (int j = 0; j < n; ++j) u[j] = (j % 2 == 0 ? 1.0 : -1.0) * (j + 1);
  return u;
}

// The eigenvector of the gradient covariance closest to the stretch direction u = skew_direction(N):
// its angle to u in degrees and its eigenvalue over the mean of the others. One dynamic-size solver for
// every dimension (the fixed-size ones, instantiated per dimension, made this file the slowest to build).
struct StretchAxis {
  double angle = 0.0, ratio = 0.0;
};
StretchAxis stretch_axis(const Eigen::MatrixXd& covariance) {
  const int n = static_cast<int>(covariance.rows());
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(covariance);
  Eigen::VectorXd u(n);
  for (int j = 0; j < n; ++j) u[j] = skew_direction(n)[j];
  u.normalize();
  int along = 0;
  for (int j = 1; j < n; ++j)
    if (std::abs(eig.eigenvectors().col(j).dot(u)) > std::abs(eig.eigenvectors().col(along).dot(u))) along = j;
  const double angle = std::acos(std::min(1.0, std::abs(eig.eigenvectors().col(along).dot(u)))) * 180.0 / std::numbers::pi;
  double others = 0.0;
  for (int j = 0; j < n; ++j)
    if (j != along) others += eig.eigenvalues()[j];
  others /= n - 1;
  return {angle, eig.eigenvalues()[along] / others};
}

template <typename T>
class FieldStretchTest : public ::testing::Test {};
TYPED_TEST_SUITE(FieldStretchTest, testing::AllDimensions);

TYPED_TEST(FieldStretchTest, MeetsTheDivergenceTargetsForEveryBasis) {
  constexpr int N = TypeParam::value;
  for (const NoiseBasis basis : kAllNoiseBases)
    for (const double s : {3.0, 0.4}) {
      if (N >= 6 && s < 1.0 && basis != NoiseBasis::turning_bands) continue;  // the time the suite takes
      DiagnosisOptions options;
      options.dimension = N;
      // The ASan + UBSan build measures the lattice bases (2^N corners: 7D-8D took 140 s and more there)
      // on 1/8 of the points and holds them to the divergence quantiles only; the RMS needs all 20000.
      const bool reduced = basis != NoiseBasis::turning_bands && testing::kSanitized;
      options.points = reduced ? testing::sanitizer_scaled(20000, 8) : 20000;
      options.field.noise = basis;
      options.field.transform.stretch_direction = skew_direction(N);
      options.field.transform.stretch_factor = s;
      const FieldDiagnosis d = diagnose_field(options);
      std::printf("%s %dD S %.1f: RMS %.4f, median/RMS %.3f, div median %.2g, p95 %.2g\n", std::string(to_string(basis)).c_str(),
                  N, s, d.rms_speed, d.median_over_rms, d.divergence_median, d.divergence_p95);
      SCOPED_TRACE(::testing::Message() << to_string(basis) << " S " << s);
      // The simplex field fails the targets from 6D on without a stretch too (tests/field/
      // test_dfvn_field.cpp: |Dc| is tiny in most of space); it is held to them where it meets them.
      // Its RMS |c| from 5D on, a mean over a field that is nearly still in most of space, is off by 6%
      // without a stretch too (1.058 on these 20000 points, 0.957 for seed 2).
      // simplex-separate (data/simplex_collapse.md) is held where its own unstretched field is: divergence
      // up to 6D; its measured amplitude has a 4-23% standard error from 5D on, so RMS up to 4D.
      const bool separate = basis == NoiseBasis::simplex_separate;
      if ((basis != NoiseBasis::simplex || N <= 5) && (!separate || N <= 6)) {
        EXPECT_LE(d.divergence_median, 1e-8);
        EXPECT_LE(d.divergence_p95, 1e-6);
      }
      if (((basis != NoiseBasis::simplex && !separate) || N <= 4) && !reduced) {
        EXPECT_NEAR(d.rms_speed, 1.0, 0.03);
      }
    }
}

TYPED_TEST(FieldStretchTest, GradientCovarianceHasTheStretchAlongU) {
  constexpr int N = TypeParam::value;
  constexpr int kPoints = 100000;
  for (const NoiseBasis basis : kAllNoiseBases)
    for (const double s : {3.0, 0.5}) {
      if (s < 1.0 && basis != NoiseBasis::turning_bands) continue;  // the time the suite takes
      FieldOptions options{basis, 1.0};
      options.transform.stretch_direction = skew_direction(N);
      options.transform.stretch_factor = s;
      const DfvnField<N> field(17, options);
      Eigen::Matrix<double, N, N> moment = Eigen::Matrix<double, N, N>::Zero();
      for (int k = 0; k < kPoints; ++k) {
        const Vec<N> x = testing::random_point<N>(5, static_cast<std::uint64_t>(k), -200.0, 200.0);
        const FieldSample<N> f = field.evaluate_functions(x);
        for (const Vec<N>& g : f.gradient) moment += g * g.transpose();
      }
      const auto [angle, ratio] = stretch_axis(moment / (kPoints * (N - 1.0)));
      std::printf("%s %dD S %.1f: angle %.3f deg, eigenvalue ratio %.4f (S^2 = %.4f)\n", std::string(to_string(basis)).c_str(), N,
                  s, angle, ratio, s * s);
      SCOPED_TRACE(::testing::Message() << to_string(basis) << " S " << s);
      EXPECT_LE(angle, 2.0);
      EXPECT_NEAR(ratio / (s * s), 1.0, 0.03);
    }
}

TYPED_TEST(FieldStretchTest, FactorOneIsTheUnstretchedFieldBitForBit) {
  constexpr int N = TypeParam::value;
  for (const NoiseBasis basis : kAllNoiseBases) {
    FieldOptions stretched{basis, 1.3};
    stretched.transform.stretch_direction = skew_direction(N);
    stretched.transform.stretch_factor = 1.0;
    const DfvnField<N> a(4, FieldOptions{basis, 1.3}), b(4, stretched);
    for (std::uint64_t k = 0; k < 100; ++k) {
      const Vec<N> x = testing::random_point<N>(8, k);
      const FieldSample<N> fa = a.evaluate(x), fb = b.evaluate(x);
      ASSERT_EQ(fa.velocity, fb.velocity) << to_string(basis);
      for (int i = 0; i < N - 1; ++i) ASSERT_EQ(fa.value[i], fb.value[i]);
    }
  }
}

TEST(FieldStretch, BadStretchesAreRefused) {
  FieldOptions o;
  o.transform.stretch_direction = {0.0, 0.0, 0.0};
  EXPECT_THROW(DfvnField<3>(1, o), std::invalid_argument);  // zero direction
  o.transform.stretch_direction = {1.0, 0.0, 0.0};
  for (const double s : {0.0, -1.0, std::nan(""), 1e7}) {
    o.transform.stretch_factor = s;
    EXPECT_THROW(DfvnField<3>(1, o), std::invalid_argument) << s;
  }
  o.transform.stretch_factor = 2.0;
  o.transform.stretch_direction = {1.0, 0.0};  // two components in 3D
  EXPECT_THROW(DfvnField<3>(1, o), std::invalid_argument);
  o.transform.stretch_direction = {1.0, 0.0, 0.0};
  o.periodic = true;  // the torus's period
  EXPECT_THROW(DfvnField<3>(1, o), std::invalid_argument);
  NoiseTransform t;
  EXPECT_THROW(parse_stretch("1,0", t), std::invalid_argument);
  EXPECT_THROW(parse_stretch("1,x:2", t), std::invalid_argument);
  EXPECT_THROW(parse_stretch("1,0:", t), std::invalid_argument);
  EXPECT_THROW(parse_stretch("0,0:2", t), std::invalid_argument);
  EXPECT_THROW(parse_stretch("1,0:0", t), std::invalid_argument);
  EXPECT_THROW(parse_stretch("1,0:2,3", t), std::invalid_argument);
  parse_stretch("3,4:2.5", t);
  EXPECT_EQ(t.stretch_direction, (std::vector<double>{3.0, 4.0}));
  EXPECT_EQ(t.stretch_factor, 2.5);
}

}  // namespace
}  // namespace dfvn
