// --lift (2D; FieldOptions::transform.lift, noise/noise_transforms.hpp's LiftedNoise): f(x) = F(x, h(x))
// for the first function F of the 3D basis. Checked here:
// - the derivation of issue 27: the xy-projection of grad F x grad(z - h) at (x, h(x)) equals
//   (df/dy, -df/dx), the lifted field's c (computed from the 3D basis directly, to 1e-12 relative);
// - the 2D divergence on 10^5 random points: median <= 1e-8 and p95 <= 1e-6 relative, every basis, a
//   plane, a bump and a bump with the vertical ramp;
// - a plane is the stretch along grad h by sqrt(1 + |grad h|^2): E[grad f grad f^T] has eigenvalue ratio
//   1 + |grad h|^2 along grad h (3%, 2 degrees);
// - the ramp adds ramp * perp(grad h) = ramp (h_y, -h_x) to c (the mean velocity on a plane);
// - plane:0,0 is --time 0 bit for bit; bad lifts refused.
#include <cmath>
#include <cstdio>
#include <numbers>

#include <Eigen/Eigenvalues>

#include "dfvn/field/diagnose.hpp"
#include "dfvn/field/dfvn_field.hpp"
#include "lift_projection.hpp"
#include "test_support.hpp"

namespace dfvn {
namespace {

FieldOptions lifted(NoiseBasis basis, std::string_view spec, double ramp = 0.0) {
  FieldOptions o{basis, 1.0};
  o.transform.lift = parse_lift(spec);
  o.transform.lift.ramp = ramp;
  return o;
}

TEST(FieldLift, ProjectedThreeDimensionalFieldIsTheLiftedTwoDimensionalOne) {
  for (const NoiseBasis basis : kAllNoiseBases)
    for (const char* spec : {"plane:0.7,-1.3", "bump:1.5,2,0.3,-0.2"}) {
      const double worst = testing::largest_lift_projection_error(basis, lifted(basis, spec), -3.0, 3.0);
      std::printf("%s %s: largest relative |P(grad F x grad(z - h)) - c| %.3g\n", std::string(to_string(basis)).c_str(), spec, worst);
      EXPECT_LE(worst, 1e-12) << to_string(basis) << " " << spec;
    }
}

TEST(FieldLift, TwoDimensionalDivergenceOnRandomPoints) {
  for (const NoiseBasis basis : kAllNoiseBases)
    for (const auto& [spec, ramp] : {std::pair{"plane:1,0.5", 0.0}, std::pair{"bump:1,2", 0.0}, std::pair{"bump:2,1.5", 0.8}}) {
      DiagnosisOptions options;
      options.dimension = 2;
      options.points = 100000;
      options.periods = 4.0;  // the bump (radius 1.5-2 around the origin) covers a good share of the points
      options.field = lifted(basis, spec, ramp);
      const FieldDiagnosis d = diagnose_field(options);
      std::printf("%s %s ramp %.1f: RMS %.4f, div median %.2g, p95 %.2g, max %.2g\n", std::string(to_string(basis)).c_str(), spec, ramp,
                  d.rms_speed, d.divergence_median, d.divergence_p95, d.divergence_max);
      EXPECT_LE(d.divergence_median, 1e-8) << to_string(basis) << " " << spec;
      EXPECT_LE(d.divergence_p95, 1e-6) << to_string(basis) << " " << spec;
    }
}

TEST(FieldLift, PlaneStretchesAlongTheSlope) {
  constexpr int kPoints = 100000;
  const Vec<2> slope(1.2, -0.5);
  const DfvnField<2> field(13, lifted(NoiseBasis::turning_bands, "plane:1.2,-0.5"));
  Eigen::Matrix2d moment = Eigen::Matrix2d::Zero();
  for (int k = 0; k < kPoints; ++k) {
    const Vec<2> g = field.evaluate_functions(testing::random_point<2>(5, static_cast<std::uint64_t>(k), -300.0, 300.0)).gradient[0];
    moment += g * g.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(moment / kPoints);
  const Vec<2> along = eig.eigenvectors().col(1);  // the larger eigenvalue
  const double angle = std::acos(std::min(1.0, std::abs(along.dot(slope.normalized())))) * 180.0 / std::numbers::pi;
  const double ratio = eig.eigenvalues()[1] / eig.eigenvalues()[0];
  std::printf("plane 1.2,-0.5: angle %.3f deg, ratio %.4f (1 + |grad h|^2 = %.4f)\n", angle, ratio, 1.0 + slope.squaredNorm());
  EXPECT_LE(angle, 2.0);
  EXPECT_NEAR(ratio / (1.0 + slope.squaredNorm()), 1.0, 0.03);
}

TEST(FieldLift, RampAddsMotionAlongTheContours) {
  constexpr int kPoints = 100000;
  const double ramp = 0.6;
  const Vec<2> slope(0.8, 0.3);
  const DfvnField<2> with(13, lifted(NoiseBasis::turning_bands, "plane:0.8,0.3", ramp)),
      without(13, lifted(NoiseBasis::turning_bands, "plane:0.8,0.3"));
  Vec<2> mean_with = Vec<2>::Zero(), mean_difference = Vec<2>::Zero();
  double worst = 0.0;
  for (int k = 0; k < kPoints; ++k) {
    const Vec<2> x = testing::random_point<2>(7, static_cast<std::uint64_t>(k), -500.0, 500.0);
    const Vec<2> c = with.velocity(x), d = c - without.velocity(x);
    mean_with += c / kPoints;
    mean_difference += d / kPoints;
    worst = std::max(worst, (d - ramp * Vec<2>(slope[1], -slope[0])).norm());
  }
  std::printf("ramp %.1f on plane 0.8,0.3: mean c (%.4f, %.4f), expected (%.4f, %.4f); largest |c - c_0 - ramp perp| %.3g\n", ramp,
              mean_with[0], mean_with[1], ramp * slope[1], -ramp * slope[0], worst);
  EXPECT_LE(worst, 1e-12);  // exactly ramp (h_y, -h_x) everywhere
  EXPECT_NEAR(mean_with[0], ramp * slope[1], 0.03);
  EXPECT_NEAR(mean_with[1], -ramp * slope[0], 0.03);
}

TEST(FieldLift, FlatPlaneIsTimeZeroBitForBit) {
  for (const NoiseBasis basis : kAllNoiseBases) {
    FieldOptions time{basis, 1.0};
    time.transform.time = 0.0;
    const DfvnField<2> a(3, lifted(basis, "plane:0,0")), b(3, time);
    for (std::uint64_t k = 0; k < 200; ++k) {
      const Vec<2> x = testing::random_point<2>(1, k);
      ASSERT_EQ(a.velocity(x), b.velocity(x)) << to_string(basis);
    }
  }
}

TEST(FieldLift, BadLiftsAreRefused) {
  for (const char* spec : {"", "plane", "plane:", "plane:1", "plane:1,2,3", "plane:1,x", "bump:1", "bump:1,0", "bump:1,-2",
                           "bump:1,2,3", "cone:1,2", "plane:nan,1", "plane:1,inf"})
    EXPECT_THROW(parse_lift(spec), std::invalid_argument) << spec;
  FieldOptions o = lifted(NoiseBasis::turning_bands, "plane:1,0");
  EXPECT_THROW(DfvnField<3>(1, o), std::invalid_argument);  // 2D only
  o.periodic = true;
  EXPECT_THROW(DfvnField<2>(1, o), std::invalid_argument);  // no torus
  o.periodic = false;
  o.transform.time = 1.0;
  EXPECT_THROW(DfvnField<2>(1, o), std::invalid_argument);  // both read z
}

}  // namespace
}  // namespace dfvn
