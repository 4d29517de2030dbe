#include "dfvn/field/evaluate_points.hpp"

#include <vector>

#include "dfvn/core/hash.hpp"
#include "test_support.hpp"

namespace dfvn {
namespace {

template <typename T>
class EvaluatePointsTest : public ::testing::Test {};
TYPED_TEST_SUITE(EvaluatePointsTest, testing::AllDimensions);

// A table of random points: rows x N, row-major, in [-3, 3]^N.
template <int N>
std::vector<double> random_table(std::size_t rows, std::uint64_t seed) {
  std::vector<double> points(rows * N);
  for (std::size_t i = 0; i < points.size(); ++i) points[i] = 6.0 * random_unit(seed, Stream::test, i) - 3.0;
  return points;
}

// evaluate_field writes exactly DfvnField::evaluate's numbers, for 1 and for 3 threads.
TYPED_TEST(EvaluatePointsTest, WritesTheFieldOfEveryRowForAnyThreadCount) {
  constexpr int N = TypeParam::value;
  constexpr std::size_t rows = 301;
  const std::vector<double> points = random_table<N>(rows, 17);
  FieldQuery query;
  query.dimension = N;
  query.seed = 5;
  query.field = {NoiseBasis::turning_bands, 0.8};
  const DfvnField<N> field(query.seed, query.field);
  for (int threads : {1, 3}) {
    query.threads = threads;
    std::vector<double> velocity(rows * N), values(rows * (N - 1));
    evaluate_field(query, points.data(), rows, velocity.data(), values.data());
    for (std::size_t i = 0; i < rows; ++i) {
      const FieldSample<N> s = field.evaluate(Eigen::Map<const Vec<N>>(points.data() + i * N));
      for (int j = 0; j < N; ++j) ASSERT_EQ(velocity[i * N + j], s.velocity[j]) << "row " << i << " threads " << threads;
      for (int j = 0; j < N - 1; ++j) ASSERT_EQ(values[i * (N - 1) + j], s.value[j]) << "row " << i;
    }
  }
}

TEST(EvaluatePoints, RefusesAPointOutsideTheNoiseDomainNamingItAndWritesNothing) {
  std::vector<double> points = {0.1, 0.2, 0.3, std::nan(""), 0.0, 0.0};
  std::vector<double> velocity(6, -7.0), values(4, -7.0);
  FieldQuery query;
  query.dimension = 3;
  try {
    evaluate_field(query, points.data(), 2, velocity.data(), values.data());
    FAIL() << "a NaN coordinate was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("point 2"), std::string::npos) << e.what();
  }
  for (double v : velocity) EXPECT_EQ(v, -7.0);
}

}  // namespace
}  // namespace dfvn
