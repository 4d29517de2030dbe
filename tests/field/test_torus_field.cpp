// The field on the torus [0,1)^N (FieldOptions::periodic): the diagnose targets on uniform random
// points, exact periodicity of the field and of its traces, and the options it refuses, in 2D-8D.
#include <cmath>
#include <cstdio>

#include "dfvn/field/diagnose.hpp"
#include "dfvn/field/dfvn_field.hpp"
#include "dfvn/integrate/trace.hpp"
#include "test_support.hpp"

namespace dfvn {
namespace {

template <typename T>
class TorusFieldTest : public ::testing::Test {
 protected:
  static constexpr int N = T::value;
};
TYPED_TEST_SUITE(TorusFieldTest, testing::AllDimensions);

constexpr std::uint64_t kSeed = 5;

FieldOptions torus(double frequency) {
  FieldOptions o{NoiseBasis::turning_bands, frequency};
  o.periodic = true;
  return o;
}

// The field targets on 10^5 uniform random points (median/RMS >= 0.4, <= 0.3% below 1% of the
// RMS, RMS within 3% of 1, divergence median <= 1e-8 and p95 <= 1e-6), at the main job's field frequency
// (0.2 cycles per spacing with K = 6: 1.2 cycles per unit length), and on 2 x 10^4 points at a higher
// one (the binomial standard error of a 0.2% fraction there is 0.03%). The points fill
// many periods: on the torus that is the same as filling one.
TYPED_TEST(TorusFieldTest, MeetsTheFieldTargetsOnUniformRandomPoints) {
  constexpr int N = TestFixture::N;
  for (const double frequency : {1.2, 4.0}) {
    DiagnosisOptions o;
    o.dimension = N;
    o.field = torus(frequency);
    o.seed = kSeed;
    o.points = frequency == 1.2 ? 100000 : 20000;
    const FieldDiagnosis d = diagnose_field(o);
    std::printf("torus N=%d F=%.1f: RMS |c| %.4f, median/RMS %.3f, below 1%% %.5f, |div c|/|Dc| median %.3g p95 %.3g, "
                "k_eff ratio %.3f\n",
                N, frequency, d.rms_speed, d.median_over_rms, d.fraction_below_1_percent, d.divergence_median,
                d.divergence_p95, d.wavenumber_measured / d.wavenumber_expected);
    EXPECT_GE(d.median_over_rms, 0.4);
    EXPECT_LE(d.fraction_below_1_percent, 0.003);
    EXPECT_NEAR(d.rms_speed, 1.0, 0.03);
    EXPECT_LE(d.divergence_median, 1e-8);
    EXPECT_LE(d.divergence_p95, 1e-6);
  }
}

// c(x + e_j) = c(x) and the f_i with it, to 1e-12 relative.
TYPED_TEST(TorusFieldTest, FieldRepeatsWithPeriodOne) {
  constexpr int N = TestFixture::N;
  const DfvnField<N> field(kSeed, torus(1.7));
  double worst = 0.0;
  for (std::uint64_t i = 0; i < 200; ++i) {
    const Vec<N> x = testing::random_point<N>(kSeed, i, 0.0, 1.0);
    const FieldSample<N> a = field.evaluate(x);
    for (int j = 0; j < N; ++j) {
      Vec<N> y = x;
      y[j] -= 1.0;
      const FieldSample<N> b = field.evaluate(y);
      worst = std::max(worst, (a.velocity - b.velocity).norm() / std::max(1.0, a.velocity.norm()));
      for (int f = 0; f < N - 1; ++f) worst = std::max(worst, std::abs(a.value[f] - b.value[f]));
    }
  }
  EXPECT_LT(worst, 1e-12);
}

// A trace from x0 + e_j ends at the trace from x0 plus e_j: traces can be wrapped at any time.
TYPED_TEST(TorusFieldTest, TracesCommuteWithThePeriod) {
  constexpr int N = TestFixture::N;
  const DfvnField<N> field(kSeed, torus(1.2));
  const Tracer<N> tracer(field, TraceOptions{.steps = 2});
  double worst = 0.0;
  for (std::uint64_t i = 0; i < 50; ++i) {
    const Vec<N> x0 = testing::random_point<N>(kSeed, i, 0.0, 1.0);
    const Vec<N> end = tracer.trace(x0, 0.3);
    const int j = static_cast<int>(i % N);
    Vec<N> shifted = x0;
    shifted[j] += 1.0;
    Vec<N> back = tracer.trace(shifted, 0.3);
    back[j] -= 1.0;
    worst = std::max(worst, (back - end).norm());
  }
  EXPECT_LT(worst, 1e-10);
}

TEST(TorusField, RefusesAConstraintAndBasesWithoutAPeriodicForm) {
  FieldOptions o = torus(1.0);
  o.constraint = FieldConstraint::inside_cube;
  o.transition_width = 0.1;
  EXPECT_THROW(DfvnField<3>(1, o), std::invalid_argument);
  o = torus(1.0);
  o.noise = NoiseBasis::simplex;
  EXPECT_THROW(DfvnField<3>(1, o), std::invalid_argument);
}

// The normalisation is measured per seed: RMS |c| = 1 over the torus for every seed, not on average.
TEST(TorusField, EverySeedIsNormalised) {
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    DiagnosisOptions o;
    o.dimension = 7;
    o.field = torus(1.2);
    o.seed = seed;
    o.points = 20000;
    EXPECT_NEAR(diagnose_field(o).rms_speed, 1.0, 0.03) << "seed " << seed;
  }
}

}  // namespace
}  // namespace dfvn
