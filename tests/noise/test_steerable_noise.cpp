// Steerable noise (seed 002, noise/steerable_noise.hpp), 2D-4D: the anisotropy of E[grad n grad n^T] on
// 10^5 random points against the construction's prediction (a quadrature, below), the weight sum > 0 on
// 10^5 random points, u and -u bit for bit, analytic gradients against central differences (constant and
// circular direction fields, i.e. with the dG/dy terms), the metric's remapping and the refused specs.
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "dfvn/noise/quintic_fade.hpp"
#include "dfvn/noise/steerable_noise.hpp"

namespace dfvn {
namespace {

template <int N>
Vec<N> skew_unit() {  // (1, -2, 3, -4) / |.|: on no axis and no diagonal
  Vec<N> u;
  for (int j = 0; j < N; ++j) u[j] = (j % 2 == 0 ? 1.0 : -1.0) * (j + 1);
  return u / u.norm();
}

template <int N>
SteerSpec constant_spec(const Vec<N>& u, double k = kDefaultSteerK) {
  SteerSpec spec;
  spec.direction.assign(u.data(), u.data() + N);
  spec.k = k;
  return spec;
}

SteerSpec circular_spec(double k = kDefaultSteerK) {
  SteerSpec spec;
  spec.circular = true;
  spec.k = k;
  return spec;
}

// Gauss-Legendre nodes and weights on [0, 1] (Newton's iteration on P_n).
void gauss_legendre(int n, std::vector<double>& nodes, std::vector<double>& weights) {
  nodes.resize(n);
  weights.resize(n);
  for (int i = 0; i < n; ++i) {
    double x = std::cos(M_PI * (i + 0.75) / (n + 0.5)), dp = 0.0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1.0, p1 = x;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (x * p1 - p0) / (x * x - 1.0);
      const double step = p1 / dp;
      x -= step;
      if (std::abs(step) < 1e-16) break;
    }
    nodes[i] = 0.5 * (1.0 - x);
    weights[i] = 1.0 / ((1.0 - x * x) * dp * dp);  // (2 / ((1 - x^2) P'^2)) / 2
  }
}

double phi(double t) { return t < 1.0 ? 1.0 - quintic_fade(t) : 0.0; }
double dphi(double t) { return t < 1.0 ? -quintic_fade_slope(t) : 0.0; }

// The construction's prediction of E[grad n grad n^T] in the lattice frame for a constant metric G:
// n = sum_b g_b^T G v_b w(v_b) with independent g_b of covariance I / 3, and averaging over the cell turns
// the sum over corners into an integral over v in [-1, 1]^N:
//   E[grad n grad n^T] = (1/3) int B B^T dv,   B = w G + grad w (G v)^T,   w = P(v) phi(v^T G v).
// Gauss-Legendre with 12 nodes on each half-axis (the integrand is C2 at v_j = 0 and on v^T G v = 1).
template <int N>
Eigen::Matrix<double, N, N> predicted_covariance(const Eigen::Matrix<double, N, N>& g) {
  std::vector<double> x, w;
  gauss_legendre(12, x, w);
  const int per_axis = 24, total = static_cast<int>(std::pow(per_axis, N));
  Eigen::Matrix<double, N, N> m = Eigen::Matrix<double, N, N>::Zero();
  for (int index = 0; index < total; ++index) {
    Vec<N> v;
    double weight = 1.0;
    for (int d = 0, rest = index; d < N; ++d, rest /= per_axis) {
      const int k = rest % per_axis;
      v[d] = k < 12 ? -x[k] : x[k - 12];
      weight *= w[k % 12];
    }
    const Vec<N> gv = g * v;
    const double q = v.dot(gv);
    if (q >= 1.0) continue;
    double p = 1.0;
    for (int d = 0; d < N; ++d) p *= phi(std::abs(v[d]));
    Vec<N> dp;
    for (int d = 0; d < N; ++d) {
      double others = 1.0;
      for (int e = 0; e < N; ++e)
        if (e != d) others *= phi(std::abs(v[e]));
      dp[d] = (v[d] < 0.0 ? -1.0 : 1.0) * dphi(std::abs(v[d])) * others;
    }
    const Vec<N> dw = dp * phi(q) + (p * dphi(q) * 2.0) * gv;
    const Eigen::Matrix<double, N, N> b = (p * phi(q)) * g + dw * gv.transpose();
    m += (weight / 3.0) * (b * b.transpose());
  }
  return m;
}

// (mean eigenvalue across u) / (u^T M u): how much faster the noise varies across u than along it.
template <int N>
double anisotropy_ratio(const Eigen::Matrix<double, N, N>& m, const Vec<N>& u) {
  const double along = u.dot(m * u);
  return (m.trace() - along) / ((N - 1) * along);
}

template <typename T>
class SteerableTest : public ::testing::Test {};
using SteerableDimensions = ::testing::Types<std::integral_constant<int, 2>, std::integral_constant<int, 3>,
                                             std::integral_constant<int, 4>>;
TYPED_TEST_SUITE(SteerableTest, SteerableDimensions);

TYPED_TEST(SteerableTest, MetricIsTheDocumentsRemapping) {
  constexpr int N = TypeParam::value;
  const Vec<N> u = skew_unit<N>();
  for (const double k : {0.25, 0.5, 0.9}) {
    const auto g = steer_metric<N>(u, k);
    const double a = (4.0 - k) / (N - 1) - kSteerEpsilon;
    EXPECT_NEAR(u.dot(g * u), k, 1e-14);
    Vec<N> across = Vec<N>::Zero();
    across[0] = u[1];
    across[1] = -u[0];
    across.normalize();
    EXPECT_NEAR(across.dot(g * across), a, 1e-14);
    EXPECT_NEAR(g.trace(), 4.0 - (N - 1) * kSteerEpsilon, 1e-13);
    EXPECT_LT(g.trace(), 4.0);
  }
}

// The construction's E[grad n grad n^T] (measured on 10^5 random points of the noise) against its
// prediction (the quadrature above) within 10%, for the first function (lattice axes = world axes) and
// the last (a rotated lattice), an axis direction and a skew one. The document's eigenvalue ratio
// (4 - k) / ((N - 1) k) is printed beside: data/steerable_notes.md compares them.
TYPED_TEST(SteerableTest, AnisotropyFollowsThePrediction) {
  constexpr int N = TypeParam::value;
  Vec<N> axis = Vec<N>::Zero();
  axis[0] = 1.0;
  for (const Vec<N>& u : {axis, skew_unit<N>()})
    for (const double k : {0.5, 0.25}) {
      const SteerableNoise<N> noise(7, 0.0, constant_spec<N>(u, k));
      std::mt19937_64 rng(11);
      std::uniform_real_distribution<double> uniform(0.0, 1000.0);
      constexpr int kPoints = 100000;
      std::array<Eigen::Matrix<double, N, N>, N - 1> measured;
      for (auto& m : measured) m.setZero();
      for (int p = 0; p < kPoints; ++p) {
        Vec<N> y;
        for (int j = 0; j < N; ++j) y[j] = uniform(rng);
        const auto s = noise.evaluate(y);
        for (int i = 0; i < N - 1; ++i) measured[i] += s.gradient[i] * s.gradient[i].transpose() / kPoints;
      }
      for (const int i : N > 2 ? std::vector<int>{0, N - 2} : std::vector<int>{0}) {
        const auto& r = noise.lattice().rotation(i);
        const Eigen::Matrix<double, N, N> g_lattice = r * steer_metric<N>(u, k) * r.transpose();
        const Eigen::Matrix<double, N, N> predicted = r.transpose() * predicted_covariance<N>(g_lattice) * r;
        const double ratio = anisotropy_ratio<N>(measured[i], u), expected = anisotropy_ratio<N>(predicted, u);
        std::printf("steerable %dD k %.2f u %s function %d: measured ratio %.4f, predicted %.4f, document's eigenvalue ratio "
                    "%.4f; E|grad n|^2 measured %.5f predicted %.5f\n",
                    N, k, u == axis ? "axis" : "skew", i, ratio, expected, (4.0 - k) / ((N - 1) * k), measured[i].trace(),
                    predicted.trace());
        EXPECT_NEAR(ratio / expected, 1.0, 0.10);
        EXPECT_GT(ratio, 1.0);  // the noise varies slower along u
        EXPECT_NEAR(measured[i].trace() / predicted.trace(), 1.0, 0.05);
      }
    }
}

TYPED_TEST(SteerableTest, WeightSumStaysPositive) {
  constexpr int N = TypeParam::value;
  for (const SteerSpec& spec : {constant_spec<N>(skew_unit<N>()), constant_spec<N>(skew_unit<N>(), 0.05), circular_spec()}) {
    const SteerableNoise<N> noise(3, 0.0, spec);
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> uniform(-50.0, 50.0);
    double lowest = 1e300;
    for (int p = 0; p < 100000; ++p) {
      Vec<N> y;
      for (int j = 0; j < N; ++j) y[j] = uniform(rng);
      for (int i = 0; i < N - 1; ++i) lowest = std::min(lowest, noise.weight_sum(i, y));
    }
    std::printf("steerable %dD k %.2f %s: lowest weight sum on 10^5 points %.4g\n", N, spec.k,
                spec.circular ? "circular" : "constant", lowest);
    EXPECT_GT(lowest, 0.0);
  }
}

TYPED_TEST(SteerableTest, OppositeDirectionsGiveIdenticalOutput) {
  constexpr int N = TypeParam::value;
  const Vec<N> u = skew_unit<N>() * 3.7;  // any length
  const SteerableNoise<N> plus(9, 0.3, constant_spec<N>(u)), minus(9, 0.3, constant_spec<N>(Vec<N>(-u)));
  EXPECT_EQ(plus.amplitude(), minus.amplitude());
  EXPECT_EQ(plus.wavenumber(), minus.wavenumber());
  std::mt19937_64 rng(2);
  std::uniform_real_distribution<double> uniform(-20.0, 20.0);
  for (int p = 0; p < 2000; ++p) {
    Vec<N> y;
    for (int j = 0; j < N; ++j) y[j] = uniform(rng);
    const auto a = plus.evaluate(y), b = minus.evaluate(y);
    for (int i = 0; i < N - 1; ++i) {
      ASSERT_EQ(a.value[i], b.value[i]);
      for (int j = 0; j < N; ++j) ASSERT_EQ(a.gradient[i][j], b.gradient[i][j]);
    }
  }
}

// Central differences with step 1e-5 against the analytic gradient, both direction fields (the circular
// one exercises the dG/dy terms; without them the error is of the size of the gradient), with a phase.
TYPED_TEST(SteerableTest, GradientMatchesCentralDifferences) {
  constexpr int N = TypeParam::value;
  for (const SteerSpec& spec : {constant_spec<N>(skew_unit<N>()), circular_spec(), circular_spec(0.2)}) {
    const SteerableNoise<N> noise(4, 1.1, spec);
    std::mt19937_64 rng(8);
    std::uniform_real_distribution<double> uniform(-4.0, 4.0);  // near the circular field's axis too
    double worst = 0.0;
    for (int p = 0; p < 3000; ++p) {
      Vec<N> y;
      for (int j = 0; j < N; ++j) y[j] = uniform(rng);
      const auto s = noise.evaluate(y);
      for (int j = 0; j < N; ++j) {
        constexpr double h = 1e-5;
        Vec<N> a = y, b = y;
        a[j] += h;
        b[j] -= h;
        const auto sa = noise.evaluate(a), sb = noise.evaluate(b);
        for (int i = 0; i < N - 1; ++i) {
          const double fd = (sa.value[i] - sb.value[i]) / (2.0 * h);
          worst = std::max(worst, std::abs(fd - s.gradient[i][j]) / (1.0 + std::abs(s.gradient[i][j])));
        }
      }
    }
    std::printf("steerable %dD %s k %.2f: worst |analytic - central difference| / (1 + |analytic|) %.3g\n", N,
                spec.circular ? "circular" : "constant", spec.k, worst);
    EXPECT_LT(worst, 1e-6);
  }
}

TYPED_TEST(SteerableTest, CircularMetricDerivativesMatchDifferences) {
  constexpr int N = TypeParam::value;
  const SteerableNoise<N> noise(1, 0.0, circular_spec());
  Vec<N> y;
  for (int j = 0; j < N; ++j) y[j] = 0.3 + 0.7 * j;
  std::array<Eigen::Matrix<double, N, N>, N> dg;
  const auto g = noise.metric(y, &dg);
  EXPECT_NEAR(g.trace(), 4.0 - (N - 1) * kSteerEpsilon, 1e-13);
  for (int j = 0; j < N; ++j) {
    Vec<N> a = y, b = y;
    a[j] += 1e-6;
    b[j] -= 1e-6;
    const Eigen::Matrix<double, N, N> fd = (noise.metric(a) - noise.metric(b)) / 2e-6;
    EXPECT_LT((fd - dg[j]).norm(), 1e-8);
  }
  // Far from the axis the metric is the document's for the circle's tangent.
  Vec<N> far = Vec<N>::Zero();
  far[0] = 1e6;
  Vec<N> tangent = Vec<N>::Zero();
  tangent[1] = 1.0;
  EXPECT_LT((noise.metric(far) - steer_metric<N>(tangent, kDefaultSteerK)).norm(), 1e-9);
}

// The phase turns the quintic basis's gradients (noise/noise_functions.hpp): every term is linear in g, so
// n(alpha + pi) = -n(alpha) and n(alpha + 2 pi) = n(alpha) up to the rounding of cos and sin; phase 0 is
// the phase-free noise.
TYPED_TEST(SteerableTest, PhaseHasPeriodTwoPiAndFlipsAtPi) {
  constexpr int N = TypeParam::value;
  for (const SteerSpec& spec : {constant_spec<N>(skew_unit<N>()), circular_spec()}) {
    const SteerableNoise<N> a(6, 0.7, spec), flipped(6, 0.7 + M_PI, spec), turned(6, 0.7 + 2.0 * M_PI, spec), other(6, 1.2, spec);
    Vec<N> y;
    for (int j = 0; j < N; ++j) y[j] = 1.37 * (j + 1) - 2.0;
    const auto s = a.evaluate(y), f = flipped.evaluate(y), t = turned.evaluate(y), o = other.evaluate(y);
    for (int i = 0; i < N - 1; ++i) {
      EXPECT_NEAR(f.value[i], -s.value[i], 1e-12);
      EXPECT_NEAR(t.value[i], s.value[i], 1e-12);
      EXPECT_GT(std::abs(o.value[i] - s.value[i]), 1e-6);
      EXPECT_LT((f.gradient[i] + s.gradient[i]).norm(), 1e-11);
    }
  }
}

TEST(SteerableSpec, RefusesBadInput) {
  SteerSpec ok;
  ok.direction = {1.0, 2.0};
  EXPECT_NO_THROW(check_steer_spec(ok, 2));
  EXPECT_THROW(check_steer_spec(ok, 3), std::invalid_argument);  // wrong length
  SteerSpec zero;
  zero.direction = {0.0, 0.0};
  EXPECT_THROW(check_steer_spec(zero, 2), std::invalid_argument);
  SteerSpec nan = ok;
  nan.direction[0] = std::nan("");
  EXPECT_THROW(check_steer_spec(nan, 2), std::invalid_argument);
  for (const double k : {0.0, -0.5, 1.5, std::nan("")}) {
    SteerSpec bad = ok;
    bad.k = k;
    EXPECT_THROW(check_steer_spec(bad, 2), std::invalid_argument) << k;
  }
  SteerSpec four;
  four.direction = {1.0, 0.0, 0.0, 0.0};
  four.k = 1.0;  // (4 - 3e-4) / 4 < 1: u's eigenvalue would not be the smallest
  EXPECT_THROW(check_steer_spec(four, 4), std::invalid_argument);
  SteerSpec none;
  EXPECT_THROW(check_steer_spec(none, 2), std::invalid_argument);
  SteerSpec both = ok;
  both.circular = true;
  EXPECT_THROW(check_steer_spec(both, 2), std::invalid_argument);
  SteerSpec circle;
  circle.circular = true;
  EXPECT_THROW(check_steer_spec(circle, 5), std::invalid_argument);
  EXPECT_THROW((void)make_steerable_noise<5>(1, 0.0, circle), std::invalid_argument);
  EXPECT_NO_THROW((void)make_steerable_noise<4>(1, 0.0, circle));
  EXPECT_THROW((void)make_noise_functions<2>(NoiseBasis::steerable, 1), std::invalid_argument);
  EXPECT_EQ(parse_noise_basis("steerable"), NoiseBasis::steerable);
}

}  // namespace
}  // namespace dfvn
