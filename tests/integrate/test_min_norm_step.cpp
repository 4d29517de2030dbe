#include "dfvn/integrate/min_norm_step.hpp"

#include <limits>

#include <Eigen/Dense>

#include "test_support.hpp"

namespace dfvn {
namespace {

template <typename D>
class MinNormStep : public ::testing::Test {};
TYPED_TEST_SUITE(MinNormStep, testing::AllDimensions);

constexpr std::uint64_t kSeed = 77;

template <int N>
std::array<Vec<N>, N - 1> random_rows(std::uint64_t index) {
  std::array<Vec<N>, N - 1> rows;
  for (int i = 0; i < N - 1; ++i) rows[i] = testing::random_point<N>(kSeed, index * 16 + i, -1.0, 1.0);
  return rows;
}

// Against an independent minimum-norm solution: Eigen's complete orthogonal decomposition, v = J^+ r. The
// reference uses dynamic-size matrices: one instantiation of the decomposition serves every dimension (seven
// fixed-size ones made this file the slowest of the build to compile).
TYPED_TEST(MinNormStep, EqualsThePseudoInverseSolution) {
  constexpr int N = TypeParam::value;
  for (std::uint64_t k = 0; k < 200; ++k) {
    const auto rows = random_rows<N>(k);
    std::array<double, N - 1> r;
    Eigen::MatrixXd jacobian(N - 1, N);
    Eigen::VectorXd rhs(N - 1);
    for (int i = 0; i < N - 1; ++i) {
      r[i] = testing::random_point<2>(kSeed + 1, k * 16 + i, -1.0, 1.0)[0];
      jacobian.row(i) = rows[i].transpose();
      rhs[i] = r[i];
    }
    Vec<N> step;
    ASSERT_TRUE(min_norm_step<N>(rows, r, 1e8, step));
    const Eigen::VectorXd expected = jacobian.completeOrthogonalDecomposition().solve(rhs);
    EXPECT_LT((step - expected).norm(), 1e-10 * (1.0 + expected.norm())) << "N = " << N << ", case " << k;
    // It solves the system and is orthogonal to the null space (it lies in the row space).
    EXPECT_LT((jacobian * step - rhs).norm(), 1e-10 * (1.0 + rhs.norm()));
  }
}

TYPED_TEST(MinNormStep, RefusesRankDeficientAndIllConditionedSystems) {
  constexpr int N = TypeParam::value;
  std::array<double, N - 1> r;
  r.fill(1.0);
  Vec<N> step = Vec<N>::Constant(42.0);
  auto rows = random_rows<N>(1);
  rows[N - 2] = Vec<N>::Zero();  // a zero gradient
  EXPECT_FALSE(min_norm_step<N>(rows, r, 1e8, step));
  if constexpr (N > 2) {
    rows = random_rows<N>(2);
    rows[N - 2] = rows[0] * 3.0;  // two parallel gradients
    EXPECT_FALSE(min_norm_step<N>(rows, r, 1e8, step));
    rows[N - 2] = rows[0] + Vec<N>::Constant(1e-10);  // nearly parallel: condition ~1e10
    EXPECT_FALSE(min_norm_step<N>(rows, r, 1e8, step));
    EXPECT_TRUE(min_norm_step<N>(rows, r, 1e12, step));
  }
  rows = random_rows<N>(3);
  EXPECT_TRUE(min_norm_step<N>(rows, r, 1e8, step));
  EXPECT_NE(step[0], 42.0);
}

// A NaN or infinite entry in any gradient, or in the residual, never gives a finite step the caller
// would take: the solve refuses, or its step is not finite (Tracer checks step.allFinite()).
TYPED_TEST(MinNormStep, NonFiniteInputNeverGivesAFiniteStep) {
  constexpr int N = TypeParam::value;
  const double bad[] = {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                        -std::numeric_limits<double>::infinity()};
  std::array<double, N - 1> r;
  r.fill(0.5);
  for (const double value : bad)
    for (int row = 0; row < N - 1; ++row)
      for (int i = 0; i < N; ++i) {
        auto rows = random_rows<N>(5);
        rows[row][i] = value;
        Vec<N> step = Vec<N>::Zero();
        const bool taken = min_norm_step<N>(rows, r, 1e8, step);
        EXPECT_FALSE(taken && step.allFinite()) << "gradient " << row << ", entry " << i << " = " << value;
      }
  for (const double value : bad)
    for (int row = 0; row < N - 1; ++row) {
      std::array<double, N - 1> bad_r = r;
      bad_r[row] = value;
      Vec<N> step = Vec<N>::Zero();
      const bool taken = min_norm_step<N>(random_rows<N>(6), bad_r, 1e8, step);
      EXPECT_FALSE(taken && step.allFinite()) << "residual " << row << " = " << value;
    }
}

}  // namespace
}  // namespace dfvn
