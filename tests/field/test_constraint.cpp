// The constrained fields of Section 4 (field/constraint.hpp): bounded by the cube or the ball (Eq. 13)
// and on the sphere, swept over dimensions 2..8 (the sphere 3..8).
#include "dfvn/field/constraint.hpp"

#include <cmath>
#include <cstdio>

#include "dfvn/field/dfvn_field.hpp"
#include "test_support.hpp"

namespace dfvn {
namespace {

template <typename T>
class ConstraintTest : public ::testing::Test {
 protected:
  static constexpr int N = T::value;
};
TYPED_TEST_SUITE(ConstraintTest, testing::AllDimensions);

constexpr std::uint64_t kSeed = 7;
constexpr double kFrequency = 1.5;  // cycles per unit length: ~ CNJ's 0.2 cycles per spacing 0.13
constexpr double kWidth = 0.2;      // the transition width w

template <int N>
DfvnField<N> constrained_field(FieldConstraint constraint, Bound bound = Bound::eq13) {
  return DfvnField<N>(kSeed, FieldOptions{kDefaultNoiseBasis, kFrequency, constraint, kWidth, bound});
}

// A point in the cube whose first coordinate lies within the transition (where Eq. 13 blends) and the
// others anywhere inside: most of these points have alpha strictly between 0 and 1.
template <int N>
Vec<N> point_in_cube_transition(std::uint64_t i) {
  Vec<N> x = testing::random_point<N>(kSeed, i, 0.02, 0.98);
  x[0] = 0.01 + (kWidth - 0.02) * random_unit(kSeed, Stream::test, i, 99);
  return x;
}

// A point in the ball at a distance 0.01..w from its sphere (the transition).
template <int N>
Vec<N> point_in_ball_transition(std::uint64_t i) {
  const double r = 0.5 - (0.01 + (kWidth - 0.02) * random_unit(kSeed, Stream::test, i, 98));
  return Vec<N>(Vec<N>::Constant(0.5) + r * testing::random_direction<N>(kSeed, i));
}

template <int N, typename F>
double central_difference_error(const F& value_and_gradient, const Vec<N>& x, double h) {
  Vec<N> gradient;
  value_and_gradient(x, gradient);
  Vec<N> numeric, unused;
  for (int j = 0; j < N; ++j) {
    Vec<N> xp = x, xm = x;
    xp[j] += h;
    xm[j] -= h;
    numeric[j] = (value_and_gradient(xp, unused) - value_and_gradient(xm, unused)) / (2.0 * h);
  }
  return (numeric - gradient).norm() / std::max(1.0, gradient.norm());
}

TYPED_TEST(ConstraintTest, BoundaryFunctionGradientsMatchCentralDifferences) {
  constexpr int N = TestFixture::N;
  double worst_cube = 0.0, worst_ball = 0.0;
  for (std::uint64_t i = 0; i < 300; ++i) {
    worst_cube = std::max(worst_cube, central_difference_error<N>(
                                          [](const Vec<N>& x, Vec<N>& g) { return cube_boundary_function<N>(x, g); },
                                          point_in_cube_transition<N>(i), 1e-6));
    worst_ball = std::max(worst_ball, central_difference_error<N>(
                                          [](const Vec<N>& x, Vec<N>& g) { return ball_boundary_function<N>(x, g); },
                                          point_in_ball_transition<N>(i), 1e-6));
  }
  EXPECT_LT(worst_cube, 1e-6);
  EXPECT_LT(worst_ball, 1e-6);
}

TYPED_TEST(ConstraintTest, CubeBoundaryFunctionIsPositiveInsideZeroOnTheBoundaryAndBelowTheFaceDistance) {
  constexpr int N = TestFixture::N;
  Vec<N> g;
  for (std::uint64_t i = 0; i < 500; ++i) {
    const Vec<N> x = testing::random_point<N>(kSeed, i, 0.0, 1.0);
    const double nearest = std::min(x.minCoeff(), 1.0 - x.maxCoeff());
    const double h = cube_boundary_function<N>(x, g);
    EXPECT_GT(h, 0.0);
    EXPECT_LE(h, nearest);
    EXPECT_GE(h, nearest / std::sqrt(2.0 * N));  // at most 2N faces as near as the nearest
  }
  Vec<N> on_face = Vec<N>::Constant(0.5);
  on_face[N - 1] = 1.0;
  EXPECT_EQ(cube_boundary_function<N>(on_face, g), 0.0);
  Vec<N> outside = on_face;
  outside[N - 1] = 1.25;
  EXPECT_DOUBLE_EQ(cube_boundary_function<N>(outside, g), -0.25);
  // Near a face (far from the others) the gradient is the inward normal.
  Vec<N> near_face = Vec<N>::Constant(0.5);
  near_face[0] = 1e-6;
  cube_boundary_function<N>(near_face, g);
  EXPECT_NEAR(g[0], 1.0, 1e-9);
  // Near k faces at equal distance t: H = t / sqrt(k) and |grad H| = 1/k (the comment's claim).
  Vec<N> corner = Vec<N>::Constant(0.5);
  const int k = std::min(N, 3);
  for (int j = 0; j < k; ++j) corner[j] = 1e-4;
  const double h = cube_boundary_function<N>(corner, g);
  EXPECT_NEAR(h, 1e-4 / std::sqrt(double(k)), 1e-9);
  EXPECT_NEAR(g.norm(), 1.0 / k, 1e-6);
}

TYPED_TEST(ConstraintTest, BoundedFieldFirstFunctionGradientMatchesCentralDifferences) {
  constexpr int N = TestFixture::N;
  for (Bound bound : kAllBounds)
  for (FieldConstraint c : {FieldConstraint::inside_cube, FieldConstraint::inside_ball}) {
    const DfvnField<N> field = constrained_field<N>(c, bound);
    double worst = 0.0;
    for (std::uint64_t i = 0; i < 200; ++i) {
      const Vec<N> x = c == FieldConstraint::inside_cube ? point_in_cube_transition<N>(i) : point_in_ball_transition<N>(i);
      worst = std::max(worst, central_difference_error<N>(
                                  [&](const Vec<N>& p, Vec<N>& g) {
                                    const FieldSample<N> s = field.evaluate(p);
                                    g = s.gradient[0];
                                    return s.value[0];
                                  },
                                  x, 1e-6));
    }
    EXPECT_LT(worst, 1e-6) << to_string(c) << " " << to_string(bound);
  }
}

// Divergence by central differences relative to the Jacobian's Frobenius norm, as for the free field
// (tests/field/test_dfvn_field.cpp), on points in the transition where f_1 blends d and the noise.
// The noise is C2, not C3: within a step h of one of its seams (turning bands: the 1D lattice points
// of its quintic gradient noises) the third derivative jumps and the central difference of c is off
// by O(h) for the free field as well (measured: 4e-4 at h = 1e-4 at such a point). Points where the
// free field's own central-difference divergence exceeds 1e-7 are therefore set aside, and counted.
TYPED_TEST(ConstraintTest, BoundedFieldIsDivergenceFree) {
  constexpr int N = TestFixture::N;
  const DfvnField<N> free(kSeed, FieldOptions{kDefaultNoiseBasis, kFrequency});
  for (Bound bound : kAllBounds)
  for (FieldConstraint c : {FieldConstraint::inside_cube, FieldConstraint::inside_ball}) {
    const DfvnField<N> field = constrained_field<N>(c, bound);
    double worst = 0.0, control = 0.0;
    int counted = 0, at_seams = 0;
    for (std::uint64_t i = 0; i < 200; ++i) {
      const Vec<N> x = c == FieldConstraint::inside_cube ? point_in_cube_transition<N>(i) : point_in_ball_transition<N>(i);
      double divergence = 0.0, jacobian2 = 0.0, divergence_g = 0.0, divergence_free = 0.0, jacobian2_free = 0.0;
      // The cube's level sets are rounded over ~ the distance t to the boundary, so the field's
      // derivatives grow like 1/t there: the step shrinks with t to keep the truncation error small.
      const double t = c == FieldConstraint::inside_cube ? std::min(x.minCoeff(), 1.0 - x.maxCoeff())
                                                         : 0.5 - (x.array() - 0.5).matrix().norm();
      const double h = std::min(1e-5, 1e-3 * t);
      for (int j = 0; j < N; ++j) {
        Vec<N> xp = x, xm = x;
        xp[j] += h;
        xm[j] -= h;
        const FieldSample<N> sp = field.evaluate(xp), sm = field.evaluate(xm);
        const Vec<N> column = (sp.velocity - sm.velocity) / (2.0 * h);
        divergence += column[j];
        jacobian2 += column.squaredNorm();
        divergence_g += (sp.gradient[0][j] - sm.gradient[0][j]) / (2.0 * h);
        const Vec<N> column_free = (free.velocity(xp) - free.velocity(xm)) / (2.0 * h);
        divergence_free += column_free[j];
        jacobian2_free += column_free.squaredNorm();
      }
      if (jacobian2 < 1e-6) continue;
      if (std::abs(divergence_free) > 1e-7 * std::sqrt(jacobian2_free)) {
        ++at_seams;
        continue;
      }
      ++counted;
      worst = std::max(worst, std::abs(divergence) / std::sqrt(jacobian2));
      control = std::max(control, std::abs(divergence_g));  // the Laplacian of f_1: not zero
    }
    std::printf("N=%d %s %s: max |div c| / |Dc| = %.3g over %d points, %d near a seam of the noise (control |lap f_1| "
                "up to %.3g)\n",
                N, std::string(to_string(c)).c_str(), std::string(to_string(bound)).c_str(), worst, counted, at_seams,
                control);
    EXPECT_GT(counted, 180);
    EXPECT_LT(worst, 1e-6) << to_string(c) << " " << to_string(bound);
    EXPECT_GT(control, 1e-2);
  }
}

// On the boundary grad f_1 is normal (Eq. 13: alpha = 0 and grad alpha = 0; the ramp: f_1 = 0), so c
// is tangent, for every bound.
TYPED_TEST(ConstraintTest, NormalComponentVanishesOnTheBoundary) {
  constexpr int N = TestFixture::N;
  for (Bound bound : kAllBounds) {
  SCOPED_TRACE(std::string(to_string(bound)));
  const DfvnField<N> cube = constrained_field<N>(FieldConstraint::inside_cube, bound);
  const DfvnField<N> ball = constrained_field<N>(FieldConstraint::inside_ball, bound);
  double worst_cube = 0.0, worst_ball = 0.0, rms_cube = 0.0, rms_ball = 0.0;
  const int count = 500;
  for (std::uint64_t i = 0; i < count; ++i) {
    Vec<N> x = testing::random_point<N>(kSeed, i, 0.0, 1.0);
    const int axis = static_cast<int>(i % N);
    const bool high = (i / N) % 2 == 1;
    x[axis] = high ? 1.0 : 0.0;
    const Vec<N> c = cube.velocity(x);
    worst_cube = std::max(worst_cube, std::abs(c[axis]));
    rms_cube += c.squaredNorm() / count;
    const Vec<N> n = testing::random_direction<N>(kSeed, i);
    const Vec<N> b = ball.velocity(Vec<N>(Vec<N>::Constant(0.5) + 0.5 * n));
    worst_ball = std::max(worst_ball, std::abs(b.dot(n)));
    rms_ball += b.squaredNorm() / count;
  }
  rms_cube = std::sqrt(rms_cube);
  rms_ball = std::sqrt(rms_ball);
  std::printf("N=%d %s on the boundary: max |c.n| cube %.3g (RMS |c| %.3g), ball %.3g (RMS |c| %.3g)\n", N,
              std::string(to_string(bound)).c_str(), worst_cube, rms_cube, worst_ball, rms_ball);
  EXPECT_LT(worst_cube, 1e-10 * rms_cube);
  EXPECT_LT(worst_ball, 1e-10 * rms_ball);
  // The tangential field is alive on the boundary: points there still move.
  EXPECT_GT(rms_cube, 0.1);
  EXPECT_GT(rms_ball, 0.1);
  }
}

TYPED_TEST(ConstraintTest, DeepInsideTheBoundedFieldIsTheFreeField) {
  constexpr int N = TestFixture::N;
  const DfvnField<N> free(kSeed, FieldOptions{kDefaultNoiseBasis, kFrequency});
  const DfvnField<N> cube = constrained_field<N>(FieldConstraint::inside_cube);
  const DfvnField<N> ramp = constrained_field<N>(FieldConstraint::inside_cube, Bound::ramp);
  int ramp_free = 0;
  for (std::uint64_t i = 0; i < 100; ++i) {
    const Vec<N> x = testing::random_point<N>(kSeed, i, kWidth, 1.0 - kWidth);
    EXPECT_EQ(cube.velocity(x), free.velocity(x));
    // The ramp acts where the cube's boundary function H < w, which reaches deeper near edges.
    Vec<N> unused;
    if (cube_boundary_function<N>(x, unused) >= kWidth) {
      EXPECT_EQ(ramp.velocity(x), free.velocity(x));
      ++ramp_free;
    }
  }
  if (N <= 3) EXPECT_GT(ramp_free, 0);
}

TYPED_TEST(ConstraintTest, SphereFieldIsTangentToEverySphere) {
  constexpr int N = TestFixture::N;
  if constexpr (N >= 3) {
    const DfvnField<N> field = constrained_field<N>(FieldConstraint::on_sphere);
    double worst = 0.0, rms = 0.0;
    for (std::uint64_t i = 0; i < 300; ++i) {
      const Vec<N> x = testing::random_point<N>(kSeed, i, -2.0, 2.0);
      const Vec<N> c = field.velocity(x);
      worst = std::max(worst, std::abs(c.dot(x)) / x.norm());
      rms += c.squaredNorm() / 300;
    }
    EXPECT_LT(worst, 1e-12 * std::max(1.0, std::sqrt(rms)));
    EXPECT_GT(std::sqrt(rms), 0.1);
  } else {
    EXPECT_THROW(constrained_field<N>(FieldConstraint::on_sphere), std::invalid_argument);
  }
}

// G^2 = N / (N!)^(1/(N-1)) assumes independent isotropic gradients; measured on the noise it should
// hold to the accuracy of that assumption.
TYPED_TEST(ConstraintTest, NoiseGradientRmsMatchesTheMeasuredOne) {
  constexpr int N = TestFixture::N;
  const DfvnField<N> field(kSeed, FieldOptions{kDefaultNoiseBasis, kFrequency});
  double sum2 = 0.0;
  const int count = 4000;
  for (std::uint64_t i = 0; i < count; ++i) {
    const FieldSample<N> s = field.evaluate(testing::random_point<N>(kSeed, i, 0.0, 200.0));
    for (const Vec<N>& g : s.gradient) sum2 += g.squaredNorm();
  }
  const double measured = std::sqrt(sum2 / (count * (N - 1)));
  std::printf("N=%d RMS |grad f_i| measured %.4f, derived %.4f\n", N, measured, noise_gradient_rms(N));
  EXPECT_NEAR(measured / noise_gradient_rms(N), 1.0, 0.1);
}

TEST(Constraint, RefusesBadTransitionWidths) {
  for (double w : {0.0, -0.1, 0.3, std::nan("")})
    EXPECT_THROW((DfvnField<3>(1, FieldOptions{kDefaultNoiseBasis, 1.0, FieldConstraint::inside_cube, w})),
                 std::invalid_argument)
        << w;
  EXPECT_THROW((ConstraintFunction<3>(FieldConstraint::none, 0.1)), std::invalid_argument);
}

TEST(Constraint, BoundNamesRoundTrip) {
  for (Bound bound : kAllBounds) EXPECT_EQ(parse_bound(to_string(bound)), bound);
  EXPECT_EQ(bound_names(), "eq13, ramp");
  EXPECT_THROW(parse_bound("mirror"), std::invalid_argument);
}

// Bridson's ramp: odd, C2 at |r| = 1 (first and second derivatives 0 there), slope 15/8 at 0.
TEST(Constraint, BridsonRampIsC2) {
  double d = 0.0;
  EXPECT_EQ(bridson_ramp(0.0, &d), 0.0);
  EXPECT_DOUBLE_EQ(d, 15.0 / 8.0);
  EXPECT_DOUBLE_EQ(bridson_ramp(1.0, &d), 1.0);
  EXPECT_EQ(d, 0.0);
  EXPECT_EQ(bridson_ramp(3.0, &d), 1.0);
  EXPECT_DOUBLE_EQ(bridson_ramp(-0.4, nullptr), -bridson_ramp(0.4, nullptr));
  double d_near = 0.0;
  bridson_ramp(1.0 - 1e-4, &d_near);
  EXPECT_LT(d_near / 1e-4, 1e-2);  // ramp'' -> 0 at 1
  for (double r : {-0.9, -0.3, 0.2, 0.7}) {
    double slope = 0.0;
    bridson_ramp(r, &slope);
    EXPECT_NEAR(slope, (bridson_ramp(r + 1e-6, nullptr) - bridson_ramp(r - 1e-6, nullptr)) / 2e-6, 1e-8) << r;
  }
}

TEST(Constraint, SmoothstepIsC2AtBothEnds) {
  double d = 0.0;
  EXPECT_EQ(smoothstep_c2(0.0, &d), 0.0);
  EXPECT_EQ(d, 0.0);
  EXPECT_EQ(smoothstep_c2(1.0, &d), 1.0);
  EXPECT_EQ(d, 0.0);
  EXPECT_DOUBLE_EQ(smoothstep_c2(0.5, &d), 0.5);
  EXPECT_DOUBLE_EQ(d, 1.875);
  // Second derivative 60u - 180u^2 + 120u^3 -> 0 at both ends: the one-sided difference quotient of S'.
  double d_near = 0.0;
  smoothstep_c2(1e-4, &d_near);
  EXPECT_LT(d_near / 1e-4, 1e-2);
  smoothstep_c2(1.0 - 1e-4, &d_near);
  EXPECT_LT(d_near / 1e-4, 1e-2);
}

}  // namespace
}  // namespace dfvn
