// TracePolicy::continuous (integrate/trace.hpp): the end of a trace is a continuous function of the
// field's phase, near the walls of the cube and the ball too. Measured as animate uses it: CNJ's lattice
// traced for CNJ's time along the bounded field at phases a fine step apart. A continuous (Lipschitz)
// map moves every point by about half as much when the step halves; a map with branch switches keeps its
// jumps. The guarded policy (CNJ's) is measured the same way, to show that the measure sees jumps.
#include "dfvn/integrate/trace.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "dfvn/sampling/curl_noise_jitter.hpp"

namespace dfvn {
namespace {

struct Scan {
  double largest_move = 0.0;  // over consecutive phases and the sites, in lattice spacings
};

// The sites of the K^N cell-centred lattice inside the domain, traced at phases first + j * step for
// j = 0..count, with CNJ's field and trace time; the largest move between consecutive phases.
template <int N>
Scan scan_phases(DomainKind domain, TracePolicy policy, int grid, double first, double step, int count) {
  CnjOptions cnj;
  cnj.domain = domain;
  const LatticeSpec lattice{N, grid, Protocol::fair};
  const std::vector<double> sites = cnj_start_sites(lattice, domain);
  const double spacing = lattice.spacing();
  const double time = cnj.step_scale * average_neighbour_distance(N) * spacing;
  TraceOptions trace = cnj_trace_options(cnj);
  trace.policy = policy;
  trace.max_step_length = cnj_transition_width(cnj, lattice);
  std::vector<Vec<N>> before;
  Scan scan;
  for (int j = 0; j <= count; ++j) {
    FieldOptions field_options = cnj_field_options(cnj, spacing);
    field_options.phase = first + j * step;
    const Tracer<N> tracer(DfvnField<N>(3, field_options), trace);
    std::vector<Vec<N>> ends;
    for (std::size_t i = 0; i < sites.size() / N; ++i) ends.push_back(tracer.trace(Eigen::Map<const Vec<N>>(sites.data() + i * N), time));
    for (std::size_t i = 0; j > 0 && i < ends.size(); ++i)
      scan.largest_move = std::max(scan.largest_move, (ends[i] - before[i]).norm() / spacing);
    before = std::move(ends);
  }
  return scan;
}

// Over the same phase range, the largest move at phase steps 2d and d: ~2 for a continuous map.
template <int N>
double halving_ratio(DomainKind domain, TracePolicy policy, int grid, double range) {
  constexpr int kSteps = 100;
  const double coarse = scan_phases<N>(domain, policy, grid, 0.4, 2.0 * range / kSteps, kSteps / 2).largest_move;
  const double fine = scan_phases<N>(domain, policy, grid, 0.4, range / kSteps, kSteps).largest_move;
  return coarse / fine;
}

TEST(TraceContinuous, EndsAreContinuousInThePhase) {
  // A range of 0.01 rad in steps of 1e-4 and 2e-4: every move far below a spacing, and halving the
  // step halves the largest one (within 20%: the largest move's particle may change).
  for (DomainKind domain : {DomainKind::cube, DomainKind::ball}) {
    const double r2 = halving_ratio<2>(domain, TracePolicy::continuous, 10, 0.01);
    const double r3 = halving_ratio<3>(domain, TracePolicy::continuous, 5, 0.01);
    EXPECT_NEAR(r2, 2.0, 0.4) << "2D " << to_string(domain);
    EXPECT_NEAR(r3, 2.0, 0.4) << "3D " << to_string(domain);
  }
}

TEST(TraceContinuous, GuardedPolicySwitchesBranch) {
  // CNJ's guarded traces over the same phases: somewhere a test flips and a site jumps, so halving the
  // step leaves the largest move as it was.
  const double r3 = halving_ratio<3>(DomainKind::cube, TracePolicy::guarded, 5, 0.01);
  EXPECT_LT(r3, 1.3) << "3D cube";
}

TEST(TraceContinuous, GuardedIsTheDefaultAndValidates) {
  TraceOptions o;
  EXPECT_EQ(o.policy, TracePolicy::guarded);
  EXPECT_EQ(to_string(TracePolicy::continuous), "continuous");
  o.max_step_length = 0.0;
  EXPECT_THROW(o.validate(), std::invalid_argument);
  o.max_step_length = std::nan("");
  EXPECT_THROW(o.validate(), std::invalid_argument);
}

// A trace of time 0 stays at its start, and a backward trace undoes a forward one (the steps are
// chosen along the way, so this holds to the integration's error, not exactly).
TEST(TraceContinuous, ZeroAndBackwardTime) {
  CnjOptions cnj;
  cnj.domain = DomainKind::cube;
  FieldOptions field_options = cnj_field_options(cnj, 0.1);
  field_options.phase = 0.3;
  TraceOptions trace;
  trace.policy = TracePolicy::continuous;
  trace.max_step_length = 0.01;
  trace.steps = 4;
  const Tracer<3> tracer(DfvnField<3>(5, field_options), trace);
  const Vec<3> x0(0.41, 0.52, 0.37);
  EXPECT_EQ(tracer.trace(x0, 0.0), x0);
  const Vec<3> forward = tracer.trace(x0, 0.05);
  EXPECT_GT((forward - x0).norm(), 1e-3);
  EXPECT_LT((tracer.trace(forward, -0.05) - x0).norm(), 1e-5);
}

}  // namespace
}  // namespace dfvn
