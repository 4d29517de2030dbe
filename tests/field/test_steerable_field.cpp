// The DFVN field of --noise steerable (field/dfvn_field.hpp with noise/steerable_noise.hpp), 2D-4D, a
// constant and the circular direction field: the divergence targets of every basis (|div c| / |Dc|
// median <= 1e-8, p95 <= 1e-6) and RMS |c| within 3% of 1 (the measured amplitude); c runs mostly along u;
// the refused combinations.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "dfvn/field/dfvn_field.hpp"
#include "dfvn/field/diagnose.hpp"

namespace dfvn {
namespace {

std::vector<double> skew_direction(int n) {
  std::vector<double> u(static_cast<std::size_t>(n));
  for (int j = 0; j < n; ++j) u[j] = (j % 2 == 0 ? 1.0 : -1.0) * (j + 1);
  return u;
}

FieldOptions steerable_options(int n, bool circular) {
  FieldOptions o;
  o.noise = NoiseBasis::steerable;
  if (circular) o.transform.steer.circular = true;
  else o.transform.steer.direction = skew_direction(n);
  return o;
}

class SteerableFieldTest : public ::testing::TestWithParam<std::tuple<int, bool>> {};

TEST_P(SteerableFieldTest, MeetsTheDivergenceAndSpeedTargets) {
  const auto [n, circular] = GetParam();
  DiagnosisOptions options;
  options.dimension = n;
  options.points = 20000;
  options.field = steerable_options(n, circular);
  // The circular field is centred on the origin: points in [-P/2, P/2]^N would need an offset; the default
  // box [0, 1000 / F]^N sees the quarter of the circle's directions, which covers every direction class of
  // the lattice in 2D (the cube's symmetries), and the field's statistics do not depend on the radius.
  const FieldDiagnosis d = diagnose_field(options);
  std::printf("steerable %dD %s: RMS %.4f, median/RMS %.3f, div median %.2g, p95 %.2g, k_eff measured/expected %.3f\n", n,
              circular ? "circular" : "constant", d.rms_speed, d.median_over_rms, d.divergence_median, d.divergence_p95,
              d.wavenumber_measured / d.wavenumber_expected);
  EXPECT_LE(d.divergence_median, 1e-8);
  EXPECT_LE(d.divergence_p95, 1e-6);
  EXPECT_NEAR(d.rms_speed, 1.0, 0.03);
}

INSTANTIATE_TEST_SUITE_P(Dimensions, SteerableFieldTest,
                         ::testing::Combine(::testing::Values(2, 3, 4), ::testing::Bool()));

// grad f_i is mostly across u (the noise varies slowly along u), so c = cross(grad f_i) runs mostly along
// u in 2D: E[(u . c)^2] / E|c|^2 above 1/2 (isotropic: 1/2).
TEST(SteerableField, FlowsMostlyAlongTheDirection) {
  FieldOptions o = steerable_options(2, false);
  o.transform.steer.direction = {1.0, 0.0};
  const DfvnField<2> field(5, o);
  double along = 0.0, total = 0.0;
  for (int p = 0; p < 20000; ++p) {
    const Vec<2> x(0.0137 * p, 0.00731 * (p % 997));
    const Vec<2> c = field.velocity(x);
    along += c[0] * c[0];
    total += c.squaredNorm();
  }
  std::printf("steerable 2D u = e1: E[c_1^2] / E|c|^2 = %.3f\n", along / total);
  EXPECT_GT(along / total, 0.7);
}

// The noise domain's margin (noise/noise_domain.hpp) assumes every basis's scale s = 2 pi F / k_eff <= 2.5 F,
// i.e. k_eff >= 2 pi / 2.5 (DfvnField asserts it in debug builds).
TEST(SteerableField, ScaleStaysInsideTheDomainMargin) {
  for (const bool circular : {false, true})
    for (const double k : {0.5, 0.05, 0.99}) {
      FieldOptions o2 = steerable_options(2, circular), o3 = steerable_options(3, circular), o4 = steerable_options(4, circular);
      o2.transform.steer.k = o3.transform.steer.k = k;
      o4.transform.steer.k = std::min(k, 0.9);
      const double s2 = DfvnField<2>(1, o2).scale(), s3 = DfvnField<3>(1, o3).scale(), s4 = DfvnField<4>(1, o4).scale();
      std::printf("steerable %s k %.2f: k_eff 2D %.3f, 3D %.3f, 4D %.3f\n", circular ? "circular" : "constant", k,
                  2.0 * M_PI / s2, 2.0 * M_PI / s3, 2.0 * M_PI / s4);
      EXPECT_LE(s2, 2.5);
      EXPECT_LE(s3, 2.5);
      EXPECT_LE(s4, 2.5);
    }
}

TEST(SteerableField, RefusesBadCombinations) {
  FieldOptions o = steerable_options(3, false);
  EXPECT_NO_THROW(DfvnField<3>(1, o));
  EXPECT_THROW(DfvnField<2>(1, o), std::invalid_argument);  // a 3-component direction in 2D
  FieldOptions high = steerable_options(5, false);
  EXPECT_THROW(DfvnField<5>(1, high), std::invalid_argument);  // N > 4
  FieldOptions none;
  none.noise = NoiseBasis::steerable;
  EXPECT_THROW(DfvnField<2>(1, none), std::invalid_argument);  // no direction
  FieldOptions other = steerable_options(2, false);
  other.noise = NoiseBasis::turning_bands;
  EXPECT_THROW(other.validate(), std::invalid_argument);  // steering another basis
  FieldOptions stretched = steerable_options(2, false);
  stretched.transform.stretch_direction = {1.0, 0.0};
  stretched.transform.stretch_factor = 2.0;
  EXPECT_THROW(stretched.validate(), std::invalid_argument);
  FieldOptions torus = steerable_options(2, false);
  torus.periodic = true;
  EXPECT_THROW(torus.validate(), std::invalid_argument);
}

}  // namespace
}  // namespace dfvn
