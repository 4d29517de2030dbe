// warp/warp_lanes.hpp against Tracer<2>: every build this CPU runs gives the tracer's end points to the bit and
// its count of field evaluations, for Euler and RK4, with and without Newton reprojection, on the shader's
// field (Table 2) and on seeds and frequencies of other fields; lanes that reach the edge of the noise domain
// are reported untraced.
#include <cstdint>
#include <cstring>
#include <vector>

#include <gtest/gtest.h>

#include "dfvn/core/hash.hpp"
#include "dfvn/integrate/trace.hpp"
#include "dfvn/warp/image_warp.hpp"
#include "dfvn/warp/warp_lanes.hpp"

namespace dfvn {
namespace {

std::uint64_t bits_of(double v) {
  std::uint64_t b;
  std::memcpy(&b, &v, sizeof b);
  return b;
}

std::vector<Simd> builds() {
  std::vector<Simd> b{Simd::baseline};
  if (cpu_has_avx2() || cpu_has_avx512()) b.push_back(Simd::best);
  return b;
}

struct Case {
  Integrator integrator;
  int steps;
  int newton;
};

void expect_same_as_tracer(const DfvnField<2>& field, double time, const std::vector<double>& xs, const std::vector<double>& ys) {
  for (const Case c : {Case{Integrator::euler, 64, 0}, Case{Integrator::rk4, 64, 0}, Case{Integrator::euler, 17, 1},
                       Case{Integrator::rk4, 9, 1}, Case{Integrator::rk4, 13, 10}, Case{Integrator::euler, 5, 10},
                       Case{Integrator::rk4, 1, 3}}) {
    TraceOptions options;
    options.integrator = c.integrator;
    options.steps = c.steps;
    options.reprojection = c.newton > 0 ? Reprojection::newton : Reprojection::none;
    options.reproject_iterations = c.newton;
    const Tracer<2> tracer(field, options);
    const auto lanes = warp_lanes::quintic_field_2d(field, tracer.options());
    ASSERT_TRUE(lanes.has_value());
    const std::size_t n = xs.size();
    for (const Simd simd : builds()) {
      std::vector<double> end_x(n), end_y(n);
      std::vector<std::int64_t> evaluations(n);
      std::vector<std::uint8_t> traced(n);
      warp_lanes::trace(*lanes, tracer.options(), time, n, xs.data(), ys.data(), end_x.data(), end_y.data(),
                        evaluations.data(), traced.data(), simd);
      for (std::size_t i = 0; i < n; ++i) {
        SCOPED_TRACE(::testing::Message() << to_string(c.integrator) << " " << c.steps << " steps, newton " << c.newton
                                          << ", build " << (simd == Simd::best ? "best" : "baseline") << ", point " << i);
        ASSERT_TRUE(traced[i]);
        TraceStats stats;
        const Vec<2> end = tracer.trace(Vec<2>(xs[i], ys[i]), time, &stats);
        EXPECT_EQ(bits_of(end_x[i]), bits_of(end[0]));
        EXPECT_EQ(bits_of(end_y[i]), bits_of(end[1]));
        EXPECT_EQ(evaluations[i], stats.field_evaluations);
      }
    }
  }
}

// Points spread over [-1.5, 1.5]^2 from a fixed hash (seed 7), an odd count so that the last vector is partial.
void points(std::vector<double>& xs, std::vector<double>& ys, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) {
    xs.push_back(3.0 * (static_cast<double>(mix64(7 + 2 * i) >> 11) * 0x1p-53) - 1.5);
    ys.push_back(3.0 * (static_cast<double>(mix64(8 + 2 * i) >> 11) * 0x1p-53) - 1.5);
  }
}

TEST(WarpLanes, ShaderFieldEqualsTheTracer) {
  const WarpConfig shader = shader_warp_config();
  const DfvnField<2> field(shader.seed, FieldOptions{shader.noise, shader.frequency});
  std::vector<double> xs, ys;
  points(xs, ys, 37);
  xs.push_back(0.0), ys.push_back(0.0);  // a lattice point of the unrotated noise
  expect_same_as_tracer(field, shader.time * shader.field_magnitude, xs, ys);
}

TEST(WarpLanes, OtherSeedsAndFrequenciesEqualTheTracer) {
  for (const std::uint64_t seed : {2u, 99u})
    for (const double frequency : {0.7, 11.0}) {
      SCOPED_TRACE(::testing::Message() << "seed " << seed << ", frequency " << frequency);
      const DfvnField<2> field(seed, FieldOptions{NoiseBasis::quintic_gradient, frequency});
      std::vector<double> xs, ys;
      points(xs, ys, 11);
      expect_same_as_tracer(field, -0.8, xs, ys);  // backwards too
    }
}

TEST(WarpLanes, OnlyThePlainQuinticFieldWithoutGaussNewton) {
  const DfvnField<2> quintic(1, FieldOptions{NoiseBasis::quintic_gradient, 3.0});
  TraceOptions options;
  options.reprojection = Reprojection::gauss_newton;
  EXPECT_FALSE(warp_lanes::quintic_field_2d(quintic, options).has_value());
  options.reprojection = Reprojection::newton;
  EXPECT_TRUE(warp_lanes::quintic_field_2d(quintic, options).has_value());
  const DfvnField<2> simplex(1, FieldOptions{NoiseBasis::simplex, 3.0});
  EXPECT_FALSE(warp_lanes::quintic_field_2d(simplex, options).has_value());
  FieldOptions phased{NoiseBasis::quintic_gradient, 3.0};
  phased.phase = 0.5;
  EXPECT_FALSE(warp_lanes::quintic_field_2d(DfvnField<2>(1, phased), options).has_value());
}

TEST(WarpLanes, TracesThatLeaveTheNoiseDomainAreLeftToTheTracer) {
  // Frequency 2^40: the domain ends at |x_j| = 2^10. Starts just inside it on either side, where about half
  // the traces step out, and starts in the middle, which stay in: a lane is untraced exactly where the
  // tracer's run met the edge, and the others are the tracer's bits.
  const DfvnField<2> field(3, FieldOptions{NoiseBasis::quintic_gradient, 0x1p40});
  TraceOptions options;
  options.steps = 8;
  options.reprojection = Reprojection::none;
  const auto lanes = warp_lanes::quintic_field_2d(field, options);
  ASSERT_TRUE(lanes.has_value());
  const double edge = 0x1p10 * (1.0 - 0x1p-45);
  std::vector<double> xs, ys;
  for (int i = 0; i < 24; ++i) {
    xs.push_back(i < 16 ? (i % 2 == 1 ? edge : -edge) : 0.01 * i);
    ys.push_back(0.1 * i - 0.4);
  }
  const std::size_t n = xs.size();
  const Tracer<2> tracer(field, options);
  for (const Simd simd : builds()) {
    std::vector<double> end_x(n), end_y(n);
    std::vector<std::int64_t> evaluations(n);
    std::vector<std::uint8_t> traced(n);
    warp_lanes::trace(*lanes, options, 1.0, n, xs.data(), ys.data(), end_x.data(), end_y.data(), evaluations.data(),
                      traced.data(), simd);
    int met_edge = 0;
    for (std::size_t i = 0; i < n; ++i) {
      TraceStats stats;
      const Vec<2> end = tracer.trace(Vec<2>(xs[i], ys[i]), 1.0, &stats);
      met_edge += stats.outside_domain > 0;
      EXPECT_EQ(traced[i] != 0, stats.outside_domain == 0) << "point " << i;
      if (!traced[i]) continue;
      EXPECT_EQ(bits_of(end_x[i]), bits_of(end[0])) << "point " << i;
      EXPECT_EQ(bits_of(end_y[i]), bits_of(end[1])) << "point " << i;
      EXPECT_EQ(evaluations[i], stats.field_evaluations) << "point " << i;
    }
    EXPECT_GT(met_edge, 0);       // the case is exercised
    EXPECT_LT(met_edge, 24);
  }
}

}  // namespace
}  // namespace dfvn
