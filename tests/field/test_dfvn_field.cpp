#include "field/dfvn_field.hpp"

#include <cmath>

#include "test_support.hpp"

namespace dfvn {
namespace {

template <typename D>
class FieldTest : public ::testing::Test {};
TYPED_TEST_SUITE(FieldTest, testing::AllDimensions);

constexpr std::uint64_t kSeed = 42;

// Divergence by central differences and the Frobenius norm of the Jacobian at x.
template <int N, typename F>
std::pair<double, double> divergence_and_jacobian(const F& vector_field, const Vec<N>& x, double h) {
  double divergence = 0.0, jacobian2 = 0.0;
  for (int j = 0; j < N; ++j) {
    Vec<N> xp = x, xm = x;
    xp[j] += h;
    xm[j] -= h;
    const Vec<N> column = (vector_field(xp) - vector_field(xm)) / (2.0 * h);
    divergence += column[j];
    jacobian2 += column.squaredNorm();
  }
  return {divergence, std::sqrt(jacobian2)};
}

// Points where the field is active: the noise has large empty regions in high dimensions
// (no simplex vertex within the kernel radius), where both c and its Jacobian vanish.
template <int N>
std::vector<Vec<N>> active_points(const DfvnField<N>& field, int count) {
  std::vector<Vec<N>> points;
  for (std::uint64_t i = 0; points.size() < static_cast<std::size_t>(count) && i < 2000000; ++i) {
    const Vec<N> x = testing::random_point<N>(kSeed, i);
    if (field.velocity(x).norm() > 0.05) points.push_back(x);
  }
  return points;
}

TYPED_TEST(FieldTest, DivergenceIsZeroRelativeToTheJacobian) {
  constexpr int N = TypeParam::value;
  const DfvnField<N> field(kSeed, FieldOptions{NoiseBasis::simplex, 1.3});
  const auto points = active_points<N>(field, 200);
  ASSERT_EQ(points.size(), 200u);
  double worst_field = 0.0, median_gradient_field = 0.0;
  std::vector<double> gradient_ratios;
  for (const auto& x : points) {
    const auto [div, jac] = divergence_and_jacobian<N>([&](const Vec<N>& p) { return field.velocity(p); }, x, 1e-5);
    worst_field = std::max(worst_field, std::abs(div) / jac);
    // Control: the gradient field grad f_1 is not divergence-free (its divergence is the Laplacian);
    // the same measurement must see that, or the test could not fail.
    const auto [div_g, jac_g] =
        divergence_and_jacobian<N>([&](const Vec<N>& p) { return field.evaluate(p).gradient[0]; }, x, 1e-5);
    gradient_ratios.push_back(std::abs(div_g) / jac_g);
  }
  std::nth_element(gradient_ratios.begin(), gradient_ratios.begin() + 100, gradient_ratios.end());
  median_gradient_field = gradient_ratios[100];
  this->RecordProperty("max_relative_divergence", std::to_string(worst_field));
  std::printf("N=%d max |div c| / |Dc| = %.3g (control grad f_1: median %.3g)\n", N, worst_field,
              median_gradient_field);
  EXPECT_LT(worst_field, 1e-6);
  EXPECT_GT(median_gradient_field, 1e-2);
}

TYPED_TEST(FieldTest, VelocityIsOrthogonalToEveryGradient) {
  constexpr int N = TypeParam::value;
  const DfvnField<N> field(kSeed, FieldOptions{NoiseBasis::simplex, 0.7});
  for (std::uint64_t i = 0; i < 500; ++i) {
    const auto s = field.evaluate(testing::random_point<N>(kSeed + 1, i));
    for (int k = 0; k < N - 1; ++k)
      EXPECT_LE(std::abs(s.velocity.dot(s.gradient[k])), 1e-13 * (1.0 + s.velocity.norm() * s.gradient[k].norm()));
  }
}

TYPED_TEST(FieldTest, FrequencyScalesSpaceButNotSpeed) {
  constexpr int N = TypeParam::value;
  const DfvnField<N> base(kSeed, FieldOptions{NoiseBasis::simplex, 1.0}), fast(kSeed, FieldOptions{NoiseBasis::simplex, 4.0});
  for (std::uint64_t i = 0; i < 50; ++i) {
    const Vec<N> x = testing::random_point<N>(kSeed + 2, i);
    const auto a = base.evaluate(4.0 * x);
    const auto b = fast.evaluate(x);
    EXPECT_LT((a.velocity - b.velocity).norm(), 1e-12 * (1.0 + a.velocity.norm()));
    EXPECT_NEAR(a.value[0], 4.0 * b.value[0], 1e-12 * (1.0 + std::abs(a.value[0])));
  }
}

TEST(Field, RejectsBadFrequency) {
  EXPECT_THROW(DfvnField<3>(1, FieldOptions{NoiseBasis::simplex, 0.0}), std::invalid_argument);
  EXPECT_THROW(DfvnField<3>(1, FieldOptions{NoiseBasis::simplex, -1.0}), std::invalid_argument);
  EXPECT_THROW(DfvnField<3>(1, FieldOptions{NoiseBasis::simplex, std::nan("")}), std::invalid_argument);
}

}  // namespace
}  // namespace dfvn
