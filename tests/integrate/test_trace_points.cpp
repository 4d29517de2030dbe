#include "dfvn/integrate/trace_points.hpp"

#include <vector>

#include "dfvn/core/hash.hpp"
#include "test_support.hpp"

namespace dfvn {
namespace {

template <typename T>
class TracePointsTest : public ::testing::Test {};
TYPED_TEST_SUITE(TracePointsTest, testing::AllDimensions);

// trace_points moves every row exactly as Tracer::trace moves it alone, and sums its counters, for 1
// and for 3 threads.
TYPED_TEST(TracePointsTest, TracesEveryRowAsTheTracerDoesForAnyThreadCount) {
  constexpr int N = TypeParam::value;
  constexpr std::size_t rows = 97;
  std::vector<double> points(rows * N);
  for (std::size_t i = 0; i < points.size(); ++i) points[i] = 4.0 * random_unit(3, Stream::test, i) - 2.0;
  TracePointsQuery query;
  query.dimension = N;
  query.seed = 9;
  query.field = {NoiseBasis::turning_bands, 0.6};
  query.trace.steps = 3;
  query.time = 0.2;
  const Tracer<N> tracer(DfvnField<N>(query.seed, query.field), query.trace);
  TraceStats expected_stats;
  std::vector<double> expected(rows * N);
  for (std::size_t i = 0; i < rows; ++i)
    Eigen::Map<Vec<N>>(expected.data() + i * N) =
        tracer.trace(Eigen::Map<const Vec<N>>(points.data() + i * N), query.time, &expected_stats);
  for (int threads : {1, 3}) {
    query.threads = threads;
    std::vector<double> out(rows * N);
    const TraceStats stats = trace_points(query, points.data(), rows, out.data());
    EXPECT_EQ(out, expected) << threads << " threads";
    EXPECT_EQ(stats.field_evaluations, expected_stats.field_evaluations);
    EXPECT_EQ(stats.reprojection_updates, expected_stats.reprojection_updates);
    EXPECT_EQ(stats.skipped_updates, expected_stats.skipped_updates);
  }
  std::vector<double> in_place = points;  // out may be the input
  trace_points(query, in_place.data(), rows, in_place.data());
  EXPECT_EQ(in_place, expected);
}

TEST(TracePoints, RefusesBadInputBeforeWritingAnything) {
  std::vector<double> points = {0.1, 0.2, 1e300, 0.4}, out(4, -7.0);
  TracePointsQuery query;
  query.dimension = 2;
  query.time = 0.1;
  EXPECT_THROW(trace_points(query, points.data(), 2, out.data()), std::invalid_argument);  // point 2 outside
  query.time = std::nan("");
  EXPECT_THROW(trace_points(query, points.data(), 1, out.data()), std::invalid_argument);
  query.time = 0.1;
  query.trace.steps = 0;
  EXPECT_THROW(trace_points(query, points.data(), 1, out.data()), std::invalid_argument);
  for (double v : out) EXPECT_EQ(v, -7.0);
}

}  // namespace
}  // namespace dfvn
