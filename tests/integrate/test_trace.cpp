#include "dfvn/integrate/trace.hpp"

#include <algorithm>
#include <cmath>

#include "test_support.hpp"

namespace dfvn {
namespace {

template <typename D>
class TraceTest : public ::testing::Test {};
TYPED_TEST_SUITE(TraceTest, testing::AllDimensions);

constexpr std::uint64_t kSeed = 2025;

// Starting points where |c| is of order one (the field's RMS), so that paths actually move.
template <int N>
std::vector<Vec<N>> moving_points(const DfvnField<N>& field, int count) {
  std::vector<Vec<N>> points;
  for (std::uint64_t i = 0; points.size() < static_cast<std::size_t>(count) && i < 5000000; ++i) {
    const Vec<N> x = testing::random_point<N>(kSeed, i);
    const double speed = field.velocity(x).norm();
    if (speed > 0.3 && speed < 3.0) points.push_back(x);
  }
  return points;
}

template <int N>
Vec<N> trace_plain(const DfvnField<N>& field, Integrator integrator, int steps, const Vec<N>& x0, double time) {
  TraceOptions o;
  o.integrator = integrator;
  o.reprojection = Reprojection::none;
  o.steps = steps;
  return Tracer<N>(field, o).trace(x0, time);
}

// Median over starting points of log2(e(M) / e(2M)) for M = 16: ~4 for RK4, ~1 for Euler.
template <int N>
double convergence_order(Integrator integrator) {
  const DfvnField<N> field(kSeed, FieldOptions{NoiseBasis::simplex, 1.0});
  const auto points = moving_points<N>(field, 9);
  EXPECT_EQ(points.size(), 9u);
  // In 7D-8D |c| varies like t^(4(N-1)) near kernel edges (noise/simplex_normalisation.hpp), so the asymptotic
  // regime of the step needs a shorter path there.
  const double time = N <= 6 ? 0.25 : 0.05;
  std::vector<double> orders;
  for (const auto& x0 : points) {
    const Vec<N> reference = trace_plain<N>(field, Integrator::rk4, 4096, x0, time);
    const double coarse = (trace_plain<N>(field, integrator, 16, x0, time) - reference).norm();
    const double fine = (trace_plain<N>(field, integrator, 32, x0, time) - reference).norm();
    orders.push_back(std::log2(coarse / fine));
  }
  std::nth_element(orders.begin(), orders.begin() + 4, orders.end());
  return orders[4];
}

TYPED_TEST(TraceTest, Rk4ErrorShrinksLikeHToTheFourth) {
  constexpr int N = TypeParam::value;
  const double order = convergence_order<N>(Integrator::rk4);
  std::printf("N=%d RK4 observed order %.2f\n", N, order);
  EXPECT_NEAR(order, 4.0, 0.6);
}

TYPED_TEST(TraceTest, EulerErrorShrinksLikeH) {
  constexpr int N = TypeParam::value;
  const double order = convergence_order<N>(Integrator::euler);
  std::printf("N=%d Euler observed order %.2f\n", N, order);
  EXPECT_NEAR(order, 1.0, 0.3);
}

// Streamlines of c are intersections of iso-contours (Section 4): with Gauss-Newton reprojection
// the trace stays on f(x) = f(x0) to round-off; without it, it drifts.
TYPED_TEST(TraceTest, GaussNewtonReprojectionKeepsTheIsoValues) {
  constexpr int N = TypeParam::value;
  const DfvnField<N> field(kSeed, FieldOptions{NoiseBasis::simplex, 1.0});
  // From 6D on the speed along one streamline ranges over 0.3..300 and there are regions where every
  // gradient vanishes (noise/simplex_normalisation.hpp): too long a step overshoots into one, which no reprojection
  // can undo (8D with 500 steps: drift 0.3 with or without reprojection; with 1000 steps: 8e-14 vs
  // 0.17; 6D with 50 steps: 0.21 vs 0.22 for one path).
  TraceOptions with;
  with.steps = N <= 5 ? 50 : (N <= 7 ? 500 : 2000);
  TraceOptions without = with;
  without.reprojection = Reprojection::none;
  const Tracer<N> projecting(field, with), plain(field, without);
  double worst_with = 0.0, worst_without = 0.0;
  TraceStats stats;
  for (const auto& x0 : moving_points<N>(field, 20)) {
    const auto tau = field.evaluate(x0).value;
    worst_with = std::max(worst_with, iso_residual<N>(field.evaluate(projecting.trace(x0, 0.5, &stats)), tau));
    worst_without = std::max(worst_without, iso_residual<N>(field.evaluate(plain.trace(x0, 0.5)), tau));
  }
  std::printf("N=%d iso-value drift: gauss-newton %.3g, none %.3g (%lld updates, %lld skipped)\n", N,
              worst_with, worst_without, static_cast<long long>(stats.reprojection_updates),
              static_cast<long long>(stats.skipped_updates));
  EXPECT_LT(worst_with, 1e-10);
  EXPECT_GT(worst_without, 1000.0 * std::max(worst_with, 1e-14));
}

TYPED_TEST(TraceTest, NewtonReprojectionReducesTheResidual) {
  constexpr int N = TypeParam::value;
  const DfvnField<N> field(kSeed, FieldOptions{NoiseBasis::simplex, 1.0});
  TraceOptions o;
  o.reprojection = Reprojection::newton;
  o.reproject_iterations = 10;
  o.residual_tolerance = 0.0;
  const Tracer<N> tracer(field, o);
  // Eq. (12) projects onto one contour at a time, so it converges linearly (about tenfold a
  // sweep in 3D, 1.5-fold in 8D), unlike Gauss-Newton: it must never increase the residual, and
  // reduce it substantially at a typical point.
  std::vector<double> ratios;
  for (const auto& x0 : moving_points<N>(field, 11)) {
    const auto tau = field.evaluate(x0).value;
    Vec<N> x = x0 + 0.01 * field.velocity(x0) + 1e-4 * Vec<N>::Ones();  // off the contours
    const double before = iso_residual<N>(field.evaluate(x), tau);
    const double after = iso_residual<N>(tracer.reproject(x, tau), tau);
    EXPECT_LT(after, before);
    ratios.push_back(after / before);
  }
  std::nth_element(ratios.begin(), ratios.begin() + 5, ratios.end());
  std::printf("N=%d Newton, 10 sweeps: median residual ratio %.3g\n", N, ratios[5]);
  EXPECT_LT(ratios[5], 0.1);
}

// In 6D-8D the noise has regions with no simplex vertex inside the kernel radius, where every
// gradient is zero and the Jacobian has rank 0: the update must be skipped and counted, never NaN.
TYPED_TEST(TraceTest, RankDeficientJacobianSkipsTheUpdate) {
  constexpr int N = TypeParam::value;
  const DfvnField<N> field(kSeed, FieldOptions{NoiseBasis::simplex, 1.0});
  Vec<N> hole;
  bool found = false;
  for (std::uint64_t i = 0; i < 200000 && !found; ++i) {
    hole = testing::random_point<N>(kSeed + 9, i);
    found = field.evaluate(hole).gradient[0].isZero(0.0);
  }
  if (N >= 7) {
    ASSERT_TRUE(found);
  }
  if (!found) GTEST_SKIP() << "no zero-gradient region found in " << N << "D (expected below 6D)";
  for (Reprojection r : {Reprojection::gauss_newton, Reprojection::newton}) {
    TraceOptions o;
    o.reprojection = r;
    const Tracer<N> tracer(field, o);
    std::array<double, N - 1> tau;
    tau.fill(0.5);  // unreachable iso-values
    Vec<N> x = hole;
    TraceStats stats;
    tracer.reproject(x, tau, &stats);
    EXPECT_TRUE(x.allFinite());
    EXPECT_EQ(x, hole);
    EXPECT_GT(stats.skipped_updates, 0);
  }
}

// Regression: an ill-conditioned Gauss-Newton linearisation used to throw points to distant parts of
// their contours (5D paper lattice, one RK4 step: up to 5.5e7 step lengths away from the unprojected
// result). Updates are now bounded by the step length and must lower the residual.
TEST(Trace, ReprojectionNeverJumpsFarFromTheStep) {
  constexpr int N = 5;
  const DfvnField<N> field(1, FieldOptions{NoiseBasis::simplex, 5.0});
  TraceOptions projected;  // one RK4 step, Gauss-Newton, as curl noise jittering uses it
  TraceOptions plain = projected;
  plain.reprojection = Reprojection::none;
  const Tracer<N> with(field, projected), without(field, plain);
  const double time = 0.09;
  double worst = 0.0;
  for (std::uint64_t i = 0; i < 100000; ++i) {
    Vec<N> x0;
    std::uint64_t k = i;
    for (int j = 0; j < N; ++j, k /= 10) x0[j] = 0.05 + 0.1 * static_cast<double>(k % 10);
    const Vec<N> a = with.trace(x0, time), b = without.trace(x0, time);
    const double step = (b - x0).norm();
    worst = std::max(worst, (a - b).norm() / std::max(step, 1e-300));
  }
  std::printf("max |projected - unprojected| / step = %.3g\n", worst);
  EXPECT_LT(worst, 10.0);
}

TEST(TraceOptions, Validation) {
  TraceOptions o;
  o.steps = 0;
  EXPECT_THROW(o.validate(), std::invalid_argument);
  o = {};
  o.reproject_iterations = -1;
  EXPECT_THROW(o.validate(), std::invalid_argument);
  o = {};
  o.residual_tolerance = std::nan("");
  EXPECT_THROW(o.validate(), std::invalid_argument);
  EXPECT_THROW(parse_integrator("rk5"), std::invalid_argument);
  EXPECT_THROW(parse_reprojection("gauss"), std::invalid_argument);
  EXPECT_EQ(parse_reprojection("gauss-newton"), Reprojection::gauss_newton);
}

}  // namespace
}  // namespace dfvn
