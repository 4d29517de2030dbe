// Bridson's curl noise (FieldKind::curl, field/dfvn_field.hpp) in 2D and 3D with every basis: its
// divergence and RMS speed on 10^5 uniform random points, its analytic velocity against central
// differences of its potential, and what it refuses.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "dfvn/field/dfvn_field.hpp"
#include "dfvn/integrate/trace.hpp"
#include "test_support.hpp"

namespace dfvn {
namespace {

template <typename T>
class CurlFieldTest : public ::testing::Test {
 protected:
  static constexpr int N = T::dimension;
  static FieldOptions options(double frequency) {
    FieldOptions o{T::basis, frequency};
    o.kind = FieldKind::curl;
    return o;
  }
};
using CurlBasesAndDimensions =
    ::testing::Types<testing::BasisDim<NoiseBasis::simplex, 2>, testing::BasisDim<NoiseBasis::simplex, 3>,
                     testing::BasisDim<NoiseBasis::turning_bands, 2>, testing::BasisDim<NoiseBasis::turning_bands, 3>,
                     testing::BasisDim<NoiseBasis::quintic_gradient, 2>,
                     testing::BasisDim<NoiseBasis::quintic_gradient, 3>>;
TYPED_TEST_SUITE(CurlFieldTest, CurlBasesAndDimensions, testing::BasisDimName);

constexpr std::uint64_t kSeed = 7;
constexpr double kFrequency = 1.3;
constexpr int kPoints = 100000;

double quantile(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  return v[static_cast<std::size_t>(q * static_cast<double>(v.size() - 1))];
}

// |div c| / |Dc| by central differences (h = 1e-5 cycles) and |c|^2 on 10^5 uniform random points in
// [0, 1000 / F]^N: median <= 1e-8, p95 <= 1e-6, RMS |c| within 3% of 1.
TYPED_TEST(CurlFieldTest, DivergenceFreeWithUnitRmsOnUniformRandomPoints) {
  constexpr int N = TestFixture::N;
  const DfvnField<N> field(kSeed, TestFixture::options(kFrequency));
  const double h = 1e-5 / kFrequency;
  std::vector<double> ratios;
  ratios.reserve(kPoints);
  double speed2 = 0.0;
  for (int i = 0; i < kPoints; ++i) {
    const Vec<N> x = testing::random_point<N>(kSeed, static_cast<std::uint64_t>(i), 0.0, 1000.0 / kFrequency);
    speed2 += field.velocity(x).squaredNorm();
    double divergence = 0.0, jacobian2 = 0.0;
    for (int j = 0; j < N; ++j) {
      Vec<N> xp = x, xm = x;
      xp[j] += h;
      xm[j] -= h;
      const Vec<N> column = (field.velocity(xp) - field.velocity(xm)) / (2.0 * h);
      divergence += column[j];
      jacobian2 += column.squaredNorm();
    }
    if (jacobian2 > 0.0) ratios.push_back(std::abs(divergence) / std::sqrt(jacobian2));
  }
  ASSERT_GT(ratios.size(), kPoints * 0.99);
  const double median = quantile(ratios, 0.5), p95 = quantile(ratios, 0.95);
  const double rms = std::sqrt(speed2 / kPoints);
  this->RecordProperty("divergence_median", std::to_string(median));
  this->RecordProperty("rms", std::to_string(rms));
  EXPECT_LE(median, 1e-8);
  EXPECT_LE(p95, 1e-6);
  EXPECT_NEAR(rms, 1.0, 0.03);
}

// c = curl psi: each component against central differences of the potential's components.
TYPED_TEST(CurlFieldTest, VelocityIsTheCurlOfThePotential) {
  constexpr int N = TestFixture::N;
  const DfvnField<N> field(kSeed, TestFixture::options(kFrequency));
  const double h = 1e-5 / kFrequency;
  for (std::uint64_t i = 0; i < 500; ++i) {
    const Vec<N> x = testing::random_point<N>(kSeed + 1, i);
    // d psi_k / d x_j
    double d[3][3] = {};
    for (int j = 0; j < N; ++j) {
      Vec<N> xp = x, xm = x;
      xp[j] += h;
      xm[j] -= h;
      const auto pp = field.curl_potential(xp), pm = field.curl_potential(xm);
      for (int k = 0; k < 3; ++k) d[k][j] = (pp[k] - pm[k]) / (2.0 * h);
    }
    Vec<N> expected;
    if constexpr (N == 2) {
      expected << d[0][1], -d[0][0];
    } else {
      expected << d[2][1] - d[1][2], d[0][2] - d[2][0], d[1][0] - d[0][1];
    }
    const FieldSample<N> s = field.evaluate(x);
    ASSERT_LE((s.velocity - expected).norm(), 1e-6) << "point " << i;
    // The functions the field reports are psi_1..psi_{N-1}.
    const auto psi = field.curl_potential(x);
    for (int k = 0; k < N - 1; ++k) ASSERT_EQ(s.value[k], psi[k]);
  }
}

// The three potentials of 3D are independent: psi_3 comes from another seed's functions.
TEST(CurlField, ThirdPotentialIsUncorrelatedWithTheOthers) {
  for (NoiseBasis basis : kAllNoiseBases) {
    FieldOptions o{basis, 1.0};
    o.kind = FieldKind::curl;
    const DfvnField<3> field(kSeed, o);
    double s13 = 0.0, s23 = 0.0, s11 = 0.0, s22 = 0.0, s33 = 0.0;
    for (std::uint64_t i = 0; i < 20000; ++i) {
      const auto p = field.curl_potential(testing::random_point<3>(kSeed, i, 0.0, 500.0));
      s13 += p[0] * p[2], s23 += p[1] * p[2], s11 += p[0] * p[0], s22 += p[1] * p[1], s33 += p[2] * p[2];
    }
    EXPECT_LT(std::abs(s13) / std::sqrt(s11 * s33), 0.05) << to_string(basis);
    EXPECT_LT(std::abs(s23) / std::sqrt(s22 * s33), 0.05) << to_string(basis);
  }
}

// In 2D, (d psi/dy, -d psi/dx) is the 2D generalised cross product of grad psi: the dfvn field.
TEST(CurlField, TwoDimensionalCurlNoiseIsTheTwoDimensionalDfvnField) {
  for (NoiseBasis basis : kAllNoiseBases) {
    FieldOptions o{basis, 0.7};
    const DfvnField<2> dfvn(kSeed, o);
    o.kind = FieldKind::curl;
    const DfvnField<2> curl(kSeed, o);
    for (std::uint64_t i = 0; i < 1000; ++i) {
      const Vec<2> x = testing::random_point<2>(kSeed, i);
      ASSERT_EQ(curl.velocity(x), dfvn.velocity(x));
    }
  }
}

TEST(CurlField, TorusIsPeriodicWithUnitRms) {
  FieldOptions o{NoiseBasis::turning_bands, 2.0};
  o.kind = FieldKind::curl;
  o.periodic = true;
  const DfvnField<3> field(kSeed, o);
  double speed2 = 0.0;
  for (std::uint64_t i = 0; i < kPoints; ++i) {
    const Vec<3> x = testing::random_point<3>(kSeed, i, 0.0, 1.0);
    const Vec<3> c = field.velocity(x);
    speed2 += c.squaredNorm();
    if (i < 100) {
      const Vec<3> shifted = x + Vec<3>(1.0, -2.0, 3.0);
      ASSERT_LE((field.velocity(shifted) - c).norm(), 1e-9);
    }
  }
  EXPECT_NEAR(std::sqrt(speed2 / kPoints), 1.0, 0.03);
}

TEST(CurlField, RefusesWhatItHasNot) {
  FieldOptions o{NoiseBasis::turning_bands, 1.0};
  o.kind = FieldKind::curl;
  EXPECT_THROW(DfvnField<4>(kSeed, o), std::invalid_argument);
  EXPECT_THROW(DfvnField<8>(kSeed, o), std::invalid_argument);
  FieldOptions bounded = o;
  bounded.constraint = FieldConstraint::inside_cube;
  bounded.transition_width = 0.1;
  EXPECT_THROW(DfvnField<3>(kSeed, bounded), std::invalid_argument);
  const DfvnField<3> field(kSeed, o);
  for (Reprojection r : {Reprojection::newton, Reprojection::gauss_newton})
    EXPECT_THROW(Tracer<3>(field, TraceOptions{.reprojection = r}), std::invalid_argument);
  const Tracer<3> tracer(field, TraceOptions{.reprojection = Reprojection::none, .steps = 8});
  const Vec<3> start(0.3, 0.2, 0.1);
  const Vec<3> end = tracer.trace(start, 0.5);
  EXPECT_TRUE(end.allFinite());
  EXPECT_GT((end - start).norm(), 0.0);
  const DfvnField<3> dfvn(kSeed, FieldOptions{NoiseBasis::turning_bands, 1.0});
  EXPECT_THROW(dfvn.curl_potential(start), std::logic_error);
  EXPECT_EQ(parse_field_kind("curl"), FieldKind::curl);
  EXPECT_EQ(parse_field_kind("dfvn"), FieldKind::dfvn);
  EXPECT_THROW(parse_field_kind("bitangent"), std::invalid_argument);
}

}  // namespace
}  // namespace dfvn
