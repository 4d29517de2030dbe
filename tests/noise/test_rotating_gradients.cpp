// Seed 001's rotation methods (noise/rotating_gradients.hpp) for 3D simplex noise: unit vectors, q orthogonal to
// p, the well-behaved method at alpha = 0 giving the no-rotation gradients bit for bit over all 289 hashes (so its
// noise at phase 0 is the Fibonacci gradients' noise), the fast one not; period 2 pi and the sign flip at pi; the
// correlation of the noise at alpha with the noise at 0 against cos alpha; RMS |c| = 1 and divergence of their
// DFVN fields; the refusals outside 3D simplex noise.
#include "dfvn/noise/rotating_gradients.hpp"

#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>

#include "dfvn/field/dfvn_field.hpp"
#include "dfvn/noise/simplex_noise.hpp"
#include "test_support.hpp"

namespace dfvn {
namespace {

double dot(const std::array<double, 3>& a, const std::array<double, 3>& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

TEST(RotatingGradients, UnitOrthogonalAndWellBehavedAtZeroIsStatic) {
  int fast_static = 0;
  for (int k = 0; k < kFibonacciPoints; ++k) {
    const FibonacciAngles a = fibonacci_angles(k);
    const auto p = fibonacci_gradient(a), q = well_behaved_second_vector(a);
    EXPECT_NEAR(dot(p, p), 1.0, 1e-15) << k;
    EXPECT_NEAR(dot(q, q), 1.0, 1e-14) << k;
    EXPECT_NEAR(dot(p, q), 0.0, 1e-15) << k;
    // Bit for bit: the full formula at alpha = 0 is the no-rotation gradient (the noise's shortcut).
    const auto g0 = well_behaved_rotating_gradient(a, std::cos(0.0), std::sin(0.0));
    for (int j = 0; j < 3; ++j) EXPECT_EQ(g0[j], p[j]) << k;
    const auto f0 = fast_rotating_gradient(a, 1.0, 0.0);
    fast_static += std::abs(dot(f0, p) - 1.0) < 1e-9;
    for (double alpha : {0.3, 1.7, 4.0}) {
      const auto f = fast_rotating_gradient(a, std::cos(alpha), std::sin(alpha));
      EXPECT_NEAR(dot(f, f), 1.0, 1e-14);
      EXPECT_NEAR(dot(f, p), 0.0, 1e-14);  // the fast method turns in the plane normal to its axis fib(k)
      EXPECT_NEAR(dot(f, f0), std::cos(alpha), 1e-14);
      EXPECT_NEAR(dot(well_behaved_rotating_gradient(a, std::cos(alpha), std::sin(alpha)), p), std::cos(alpha), 1e-14);
    }
  }
  EXPECT_EQ(fast_static, 0);  // no alpha gives the static gradients back (Section 3's second point)
  // The equal-area mapping: the mean of fib(k) is near 0 and its second moment near I / 3.
  double mean[3] = {0, 0, 0}, second[3] = {0, 0, 0};
  for (int k = 0; k < kFibonacciPoints; ++k) {
    const auto p = fibonacci_gradient(fibonacci_angles(k));
    for (int j = 0; j < 3; ++j) mean[j] += p[j] / kFibonacciPoints, second[j] += p[j] * p[j] / kFibonacciPoints;
  }
  for (int j = 0; j < 3; ++j) {
    EXPECT_LT(std::abs(mean[j]), 0.01);
    EXPECT_NEAR(second[j], 1.0 / 3.0, 0.005);
  }
  EXPECT_EQ(parse_gradient_rotation("well-behaved"), GradientRotation::well_behaved);
  EXPECT_THROW(parse_gradient_rotation("slow"), std::invalid_argument);
}

TEST(RotatingGradients, TwoVectorIsTheDefault) {
  const SimplexNoise<3> a(7, 0.8), b(7, 0.8, GradientRotation::two_vector);
  const Vec<3> x(0.3, -1.2, 2.5);
  EXPECT_EQ(a.evaluate_all(x).value, b.evaluate_all(x).value);
}

TEST(RotatingGradients, PeriodSignAndCorrelation) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-50.0, 50.0);
  const int points = static_cast<int>(testing::sanitizer_scaled(20000, 4));
  for (GradientRotation r : kAllGradientRotations) {
    const SimplexNoise<3> zero(9, 0.0, r), half(9, std::numbers::pi, r), alpha(9, 1.0, r), turned(9, 1.0 + 2.0 * std::numbers::pi, r);
    double s00 = 0.0, saa = 0.0, s0a = 0.0, worst_sign = 0.0, worst_period = 0.0;
    for (int p = 0; p < points; ++p) {
      const Vec<3> x(u(rng), u(rng), u(rng));
      const auto f0 = zero.evaluate_all(x), fa = alpha.evaluate_all(x);
      worst_sign = std::max(worst_sign, std::abs(half.evaluate_all(x).value[0] + f0.value[0]));
      worst_period = std::max(worst_period, std::abs(turned.evaluate_all(x).value[1] - fa.value[1]));
      s00 += f0.value[0] * f0.value[0], saa += fa.value[0] * fa.value[0], s0a += f0.value[0] * fa.value[0];
    }
    SCOPED_TRACE(std::string(to_string(r)));
    EXPECT_LT(worst_sign, 1e-12);
    EXPECT_LT(worst_period, 1e-12);
    EXPECT_NEAR(s0a / std::sqrt(s00 * saa), std::cos(1.0), 0.03);
  }
}

TEST(RotatingGradients, FieldsKeepRmsOneAndNoDivergence) {
  for (GradientRotation r : {GradientRotation::fast, GradientRotation::well_behaved}) {
    for (double phase : {0.0, 1.3}) {
      FieldOptions o{NoiseBasis::simplex, 1.0};
      o.phase = phase;
      o.transform.rotation = r;
      const DfvnField<3> field(4, o);
      std::mt19937_64 rng(5);
      std::uniform_real_distribution<double> u(0.0, 40.0);
      const int points = static_cast<int>(testing::sanitizer_scaled(20000, 4));
      double sum = 0.0, worst_div = 0.0;
      for (int p = 0; p < points; ++p) {
        const Vec<3> x(u(rng), u(rng), u(rng));
        const Vec<3> c = field.velocity(x);
        sum += c.squaredNorm();
        if (p < 200) {
          constexpr double h = 1e-5;
          double d = 0.0;
          for (int j = 0; j < 3; ++j) {
            Vec<3> step = Vec<3>::Zero();
            step[j] = h;
            d += (field.velocity(Vec<3>(x + step))[j] - field.velocity(Vec<3>(x - step))[j]) / (2 * h);
          }
          worst_div = std::max(worst_div, std::abs(d));
        }
      }
      SCOPED_TRACE(std::string(to_string(r)) + " phase " + std::to_string(phase));
      EXPECT_NEAR(std::sqrt(sum / points), 1.0, 0.05);
      EXPECT_LT(worst_div, 1e-6);
    }
  }
  FieldOptions bad{NoiseBasis::simplex, 1.0};
  bad.transform.rotation = GradientRotation::fast;
  EXPECT_THROW(DfvnField<2>(4, bad), std::invalid_argument);
  EXPECT_THROW(DfvnField<4>(4, bad), std::invalid_argument);
  bad.noise = NoiseBasis::turning_bands;
  EXPECT_THROW(DfvnField<3>(4, bad), std::invalid_argument);
}

}  // namespace
}  // namespace dfvn
