// The supported domain of the noise (noise/noise_domain.hpp): finite values and gradients everywhere
// inside it, a clear exception at every entry point outside it.
#include "dfvn/noise/noise_domain.hpp"

#include <cmath>
#include <numbers>
#include <functional>
#include <string>
#include <vector>

#include "dfvn/field/dfvn_field.hpp"
#include "dfvn/field/evaluate_points.hpp"
#include "dfvn/io/csv.hpp"
#include "dfvn/integrate/trace.hpp"
#include "dfvn/noise/simplex_noise.hpp"
#include "test_support.hpp"

namespace dfvn {
namespace {

using testing::AllDimensions;

template <typename D>
class NoiseDomainTest : public ::testing::Test {};
TYPED_TEST_SUITE(NoiseDomainTest, AllDimensions);

constexpr std::uint64_t kSeed = 20260109;
const double kLargestArgument = std::nextafter(kMaxNoiseArgument, 0.0);

// Every noise basis (kAllNoiseBases), as a function evaluating its N-1 functions at the domain
// argument u = F x the way the field does: at s x = (2 pi / k_eff) u.
template <int N>
struct NamedBasis {
  std::string name;
  std::function<NoiseSample<N, N - 1>(const Vec<N>&)> evaluate;
};
template <int N>
std::vector<NamedBasis<N>> every_basis(std::uint64_t seed) {
  std::vector<NamedBasis<N>> bases;
  for (NoiseBasis b : kAllNoiseBases) {
    const auto noise = make_noise_functions<N>(b, seed);
    const double scale = 2.0 * std::numbers::pi / noise->wavenumber();
    bases.push_back({std::string(to_string(b)), [noise, scale](const Vec<N>& u) { return noise->evaluate(Vec<N>(scale * u)); }});
  }
  return bases;
}

// A point spread over the whole domain: each coordinate has a random sign and a magnitude 2^e with e
// uniform in [-40, 50), so every scale up to the bound is sampled equally often; the first 64 points
// put every coordinate at the largest argument inside the bound, with random signs.
template <int N>
Vec<N> point_across_domain(std::uint64_t seed, std::uint64_t index) {
  Vec<N> u;
  for (int j = 0; j < N; ++j) {
    const double sign = random_unit(seed, Stream::test, index, 2 * j) < 0.5 ? -1.0 : 1.0;
    const double exponent = -40.0 + 90.0 * random_unit(seed, Stream::test, index, 2 * j + 1);
    u[j] = sign * (index < 64 ? kLargestArgument : std::min(std::exp2(exponent), kLargestArgument));
  }
  return u;
}

TYPED_TEST(NoiseDomainTest, EveryBasisIsFiniteAcrossTheWholeDomain) {
  constexpr int N = TypeParam::value;
  for (const NamedBasis<N>& basis : every_basis<N>(kSeed)) {
    int failures = 0;
    for (std::uint64_t i = 0; i < 20000 && failures < 5; ++i) {
      const Vec<N> u = point_across_domain<N>(kSeed, i);
      ASSERT_TRUE(in_noise_domain(u));
      const NoiseSample<N, N - 1> s = basis.evaluate(u);
      for (int m = 0; m < N - 1; ++m) {
        // Inside the domain the kernel sum is bounded as anywhere else: N+1 vertices, each at most
        // (1/2)^4 |g| |d| in value and (1/2)^4 |g| + 8 (1/2)^3 |g| |d|^2 in gradient, |g| <= sqrt(N).
        const bool ok = std::isfinite(s.value[m]) && s.gradient[m].allFinite() && std::abs(s.value[m]) < 10.0 &&
                        s.gradient[m].norm() < 100.0;
        if (!ok) {
          ++failures;
          ADD_FAILURE() << basis.name << " noise, function " << m << " at u = " << u.transpose()
                        << ": value " << s.value[m] << ", gradient " << s.gradient[m].transpose() << " (seed "
                        << kSeed << ")";
        }
      }
    }
  }
}

TYPED_TEST(NoiseDomainTest, FieldIsFiniteAcrossTheDomainAtEveryFrequency) {
  constexpr int N = TypeParam::value;
  for (NoiseBasis basis : kAllNoiseBases)
  for (const double frequency : {kMinNoiseFrequency, 1.0, kMaxNoiseFrequency}) {
    const DfvnField<N> field(kSeed, FieldOptions{basis, frequency});
    for (std::uint64_t i = 0; i < 2000; ++i) {
      const Vec<N> x = point_across_domain<N>(kSeed + 1, i) / frequency;
      const FieldSample<N> s = field.evaluate(x);
      ASSERT_TRUE(s.velocity.allFinite()) << "F = " << frequency << ", x = " << x.transpose();
      for (int m = 0; m < N - 1; ++m) {
        ASSERT_TRUE(std::isfinite(s.value[m])) << "F = " << frequency << ", x = " << x.transpose();
        ASSERT_TRUE(s.gradient[m].allFinite()) << "F = " << frequency << ", x = " << x.transpose();
      }
    }
  }
}

// A trace that runs into the edge of the domain stops before it: finite, inside, and counted.
TYPED_TEST(NoiseDomainTest, TraceStopsAtTheEdgeOfTheDomain) {
  constexpr int N = TypeParam::value;
  const DfvnField<N> field(kSeed, FieldOptions{kDefaultNoiseBasis, kMaxNoiseFrequency});  // the domain is |x_j| < 1
  TraceOptions options;
  options.steps = 8;
  const Tracer<N> tracer(field, options);
  int reached_edge = 0;
  for (std::uint64_t i = 0; i < 200; ++i) {
    // Start within 2^-20 of a random corner of the domain and trace for a time of 16 / |c(x0)|: the
    // first RK4 stage already moves a unit length along c(x0), past the edge unless c(x0) points
    // inwards along every axis (probability 2^-N).
    Vec<N> x0 = testing::random_point<N>(kSeed + 2, i, -1.0, 1.0);
    for (int j = 0; j < N; ++j) x0[j] = std::copysign(1.0 - std::exp2(-20.0), x0[j]);
    const double speed = field.velocity(x0).norm();
    if (!(speed > 0.0)) continue;
    TraceStats stats;
    const Vec<N> x = tracer.trace(x0, 16.0 / speed, &stats);
    EXPECT_TRUE(x.allFinite()) << "x0 = " << x0.transpose();
    EXPECT_TRUE(field.in_domain(x)) << "x0 = " << x0.transpose() << ", x = " << x.transpose();  // issue 23
    reached_edge += stats.outside_domain > 0;
  }
  EXPECT_GT(reached_edge, 100) << "too few traces reached the edge to test anything";
}

TEST(NoiseDomain, ArgumentsOutsideTheBoundAreRefusedWithTheValue) {
  EXPECT_NO_THROW(check_noise_argument(kLargestArgument, 1.0, "x"));
  EXPECT_NO_THROW(check_noise_argument(-kLargestArgument, 1.0, "x"));
  for (const double bad : {kMaxNoiseArgument, -kMaxNoiseArgument, 1e308, std::numeric_limits<double>::infinity(),
                           std::numeric_limits<double>::quiet_NaN()}) {
    try {
      check_noise_argument(bad, 1.0, "line 7, column 2");
      ADD_FAILURE() << bad << " was accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("line 7, column 2"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("noise domain"), std::string::npos) << e.what();
    }
  }
  // The product counts: a small coordinate at a high frequency is outside too.
  EXPECT_THROW(check_noise_argument(2.0, kMaxNoiseFrequency, "x"), std::invalid_argument);
}

TEST(NoiseDomain, FrequenciesOutsideTheRangeAreRefused) {
  for (const double bad : {0.0, -1.0, 1e-320, 0.5 * kMinNoiseFrequency, 2.0 * kMaxNoiseFrequency, 1e308,
                           std::numeric_limits<double>::quiet_NaN()}) {
    EXPECT_THROW(check_noise_frequency(bad), std::invalid_argument) << bad;
    EXPECT_THROW(DfvnField<3>(kSeed, FieldOptions{kDefaultNoiseBasis, bad}), std::invalid_argument) << bad;
  }
  EXPECT_NO_THROW(DfvnField<3>(kSeed, FieldOptions{kDefaultNoiseBasis, kMinNoiseFrequency}));
  EXPECT_NO_THROW(DfvnField<3>(kSeed, FieldOptions{kDefaultNoiseBasis, kMaxNoiseFrequency}));
}

TEST(NoiseDomain, FieldOfAPointTableRefusesAPointOutsideTheDomain) {
  PointTable points;
  points.dimension = 2;
  points.coordinates = {0.5, 0.5, 1e308, 0.25};
  FieldQuery query;
  query.dimension = 2;
  std::vector<double> velocity(4), values(2);
  try {
    evaluate_field(query, points.coordinates.data(), points.rows(), velocity.data(), values.data());
    ADD_FAILURE() << "1e308 was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("point 2, column 1"), std::string::npos) << e.what();
  }
  points.coordinates[2] = 0.75;
  EXPECT_NO_THROW(evaluate_field(query, points.coordinates.data(), points.rows(), velocity.data(), values.data()));
}

}  // namespace
}  // namespace dfvn
