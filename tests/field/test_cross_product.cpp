#include "dfvn/field/cross_product.hpp"

#include <Eigen/Geometry>
#include <Eigen/LU>

#include "test_support.hpp"

namespace dfvn {
namespace {

template <typename D>
class CrossProductTest : public ::testing::Test {};
TYPED_TEST_SUITE(CrossProductTest, testing::AllDimensions);

template <int N>
std::array<Vec<N>, N - 1> random_vectors(std::uint64_t index) {
  std::array<Vec<N>, N - 1> v;
  for (int k = 0; k < N - 1; ++k) v[k] = testing::random_point<N>(7, index * 16 + k, -1.0, 1.0);
  return v;
}

// Eq. (1): cross(v_1..v_{N-1}) . v = det[v | v_1 | ... | v_{N-1}], checked against Eigen's determinant.
TYPED_TEST(CrossProductTest, SatisfiesTheDeterminantDefinition) {
  constexpr int N = TypeParam::value;
  for (std::uint64_t i = 0; i < 200; ++i) {
    const auto v = random_vectors<N>(i);
    const Vec<N> c = cross<N>(v);
    const Vec<N> probe = testing::random_point<N>(8, i, -1.0, 1.0);
    Eigen::Matrix<double, N, N> m;
    m.col(0) = probe;
    for (int k = 0; k < N - 1; ++k) m.col(k + 1) = v[k];
    EXPECT_NEAR(c.dot(probe), m.determinant(), 1e-12);
  }
}

TYPED_TEST(CrossProductTest, IsOrthogonalToEveryArgument) {
  constexpr int N = TypeParam::value;
  for (std::uint64_t i = 0; i < 200; ++i) {
    const auto v = random_vectors<N>(i);
    const Vec<N> c = cross<N>(v);
    for (int k = 0; k < N - 1; ++k) EXPECT_NEAR(c.dot(v[k]), 0.0, 1e-13 * (1.0 + c.norm() * v[k].norm()));
  }
}

TYPED_TEST(CrossProductTest, RankDeficientInputGivesZero) {
  constexpr int N = TypeParam::value;
  if constexpr (N >= 3) {
    auto v = random_vectors<N>(3);
    v[N - 2] = 2.0 * v[0];
    EXPECT_LT(cross<N>(v).norm(), 1e-14);
  }
  std::array<Vec<N>, N - 1> zeros;
  for (auto& z : zeros) z.setZero();
  EXPECT_EQ(cross<N>(zeros), Vec<N>::Zero());
}

// Issue 40: vectors of subnormal size (the gradients at the centre of an obstacle of radius 1e-310) gave
// Inf and NaN (the pivot's reciprocal overflowed). cross is linear in each vector: scaling v_k by 2^-e_k
// scales the product by 2^-(sum e_k), exactly while nothing underflows, so each scaled product must be the
// unscaled one times that power (to rounding), and products below the smallest double must be finite.
TYPED_TEST(CrossProductTest, VectorsOfSubnormalSizeGiveTheScaledProduct) {
  constexpr int N = TypeParam::value;
  for (std::uint64_t i = 0; i < 50; ++i) {
    const auto v = random_vectors<N>(i);
    const Vec<N> c = cross<N>(v);
    auto tiny = v;
    tiny[0] *= 0x1p-1030;  // subnormal components: the first pivot's reciprocal is not finite
    const Vec<N> scaled = cross<N>(tiny);
    ASSERT_TRUE(scaled.allFinite()) << "N = " << N << ", i = " << i;
    // 44 bits are left at 2^-1030: the rounding is below 2^-44 of c
    const Vec<N> expected = scaled * 0x1p515 * 0x1p515;
    EXPECT_LT((expected - c).norm(), 1e-12 * (1.0 + c.norm())) << "N = " << N << ", i = " << i;
    for (auto& w : tiny) w *= 0x1p-1000;  // every vector tiny: the product underflows to zero, not NaN
    EXPECT_TRUE(cross<N>(tiny).allFinite());
    auto huge = v;
    huge[0] *= 0x1p1000;  // large but representable: the product is the scaled one
    EXPECT_LT((cross<N>(huge) * 0x1p-1000 - c).norm(), 1e-12 * (1.0 + c.norm()));
  }
}

TEST(CrossProduct, ThreeDimensionsEqualsEigenCross) {
  for (std::uint64_t i = 0; i < 200; ++i) {
    const auto v = random_vectors<3>(i);
    EXPECT_LT((cross<3>(v) - v[0].cross(v[1])).norm(), 1e-15);
  }
}

TEST(CrossProduct, TwoDimensionsRotatesClockwise) {
  // Section 3.2: grad f x [0,0,1] = [f_y, -f_x].
  const Vec<2> c = cross<2>({Vec<2>(3.0, 5.0)});
  EXPECT_DOUBLE_EQ(c[0], 5.0);
  EXPECT_DOUBLE_EQ(c[1], -3.0);
}

TEST(CrossProduct, FourDimensionsMatchesTheBasisExample) {
  // cross(e1, e2, e3) in 4D: det[v | e1 | e2 | e3] = -v4, so the result is -e4.
  const Vec<4> c = cross<4>({Vec<4>::Unit(0), Vec<4>::Unit(1), Vec<4>::Unit(2)});
  EXPECT_EQ(c, Vec<4>(0, 0, 0, -1));
}

}  // namespace
}  // namespace dfvn
