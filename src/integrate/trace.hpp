// Tracing points along a DFVN field: Algorithm 1 with Euler (Eq. 9) or RK4 steps and a reprojection
// onto the iso-contours of the noise functions after every step (Eq. 10-12).
#pragma once

#include <cstdint>
#include <limits>
#include <string_view>

#include "dfvn/core/dimension.hpp"
#include "dfvn/field/dfvn_field.hpp"

namespace dfvn {

enum class Integrator { euler, rk4 };
enum class Reprojection { none, newton, gauss_newton };
// How a trace steps and reprojects, a policy chosen once:
//   guarded (CNJ's, every subcommand's but animate's): `steps` steps of time / steps; a reprojection
//     update is taken only if it is at most max_update long and does not raise the residual, otherwise
//     the reprojection stops there. The end point is a discontinuous function of the start and of the
//     field (its phase): where a test flips, the trace switches branch.
//   continuous (animate's frames, issue 46): every step at most time / steps and max_step_length long
//     (at its first velocity), the last one taking the time that is left; every reprojection update
//     taken, shortened to max_update where it is longer. Step lengths and updates are continuous
//     functions of the position, so the end point is a continuous function of the start point and of
//     the field: a lattice traced at neighbouring phases moves by little. Left discontinuous, and rare:
//     a Jacobian above max_condition (its update is skipped in both policies) and the stop below
//     residual_tolerance (a jump of at most that residual over the gradient, ~1e-13 lengths).
enum class TracePolicy { guarded, continuous };

Integrator parse_integrator(std::string_view name);      // "euler" | "rk4"
Reprojection parse_reprojection(std::string_view name);  // "none" | "newton" | "gauss-newton"
std::string_view to_string(Integrator integrator);
std::string_view to_string(Reprojection reprojection);
std::string_view to_string(TracePolicy rule);

struct TraceOptions {
  Integrator integrator = Integrator::rk4;
  Reprojection reprojection = Reprojection::gauss_newton;
  int steps = 1;                     // M in Algorithm 1; the step length is time / steps
  int reproject_iterations = 10;     // R: at most this many updates after each step
  double residual_tolerance = 1e-13; // stop when max_i |f_i(x) - tau_i| is below this
  // Gauss-Newton skips an update whose Jacobian has a condition number (largest / smallest
  // singular value, estimated from the pivoted QR) above this; Newton skips a function whose
  // gradient is below max_condition^-1 times the field's RMS gradient (which is 1 by construction).
  double max_condition = 1e8;
  // An update longer than this times the length of the integration step it corrects is rejected,
  // and so is one that raises the residual. A correction longer than the step itself means the
  // linearisation is wrong and would jump to a distant part of the contour: without this bound a
  // single RK4 step + Gauss-Newton on the 5D paper lattice moved points up to 5.5e7 step lengths.
  // The authors' code uses 0.1, but in fast regions of the 5D-8D field an RK4 step's error is
  // comparable to the step, and 0.1 then rejects the corrections that keep traces on their contours
  // (tests/integrate/test_trace.cpp: drift 0.08-0.16 with 0.1, below 1e-13 with 1).
  double max_update_ratio = 1.0;
  TracePolicy policy = TracePolicy::guarded;
  // continuous: the longest step, in length units (at the step's first velocity); infinity: no limit.
  double max_step_length = std::numeric_limits<double>::infinity();
  // continuous: at most this many times `steps` steps per trace (the last takes the time left).
  static constexpr int kMaxStepGrowth = 64;
  // continuous: how many times a step's time may be shortened to its stages' speeds.
  static constexpr int kLengthUpdates = 3;

  // Throws std::invalid_argument with a message naming the offending option.
  void validate() const;
};

// Counters over one or many traces (they add up; reset by assigning {}).
struct TraceStats {
  std::int64_t field_evaluations = 0;
  std::int64_t reprojection_updates = 0;
  // Updates not taken: rank-deficient or ill-conditioned Jacobian, non-finite, longer than
  // max_update_ratio x step, or raising the residual.
  std::int64_t skipped_updates = 0;
  // TracePolicy::continuous: updates taken shortened to max_update_ratio x step.
  std::int64_t shortened_updates = 0;
  // Steps that reached beyond the edge of the noise domain (noise/noise_domain.hpp), and evaluations
  // there: a trace stops before such a step, at the last point whose step stayed inside.
  std::int64_t outside_domain = 0;
  // Traces that stopped so: their end is not where the trace would have gone (trace_table does not
  // accept it as an end: a bounded run retraces or keeps the point at its start, a dropping run drops it).
  std::int64_t stopped_at_edge = 0;

  TraceStats& operator+=(const TraceStats& other) {
    field_evaluations += other.field_evaluations;
    reprojection_updates += other.reprojection_updates;
    skipped_updates += other.skipped_updates;
    shortened_updates += other.shortened_updates;
    outside_domain += other.outside_domain;
    stopped_at_edge += other.stopped_at_edge;
    return *this;
  }
};

// A tracer binds a field to one (integrator, reprojection) policy, chosen once here so that the
// step loop contains no strategy switches.
template <int N>
class Tracer {
 public:
  // Throws std::invalid_argument if the options are invalid.
  Tracer(const DfvnField<N>& field, const TraceOptions& options);

  // Algorithm 1: trace x0 for time t (t may be negative: backwards) in options.steps steps. A trace
  // whose next step would reach beyond the edge of the noise domain (noise/noise_domain.hpp) stops
  // before it, counted in TraceStats::outside_domain, so the result is always inside; x0 itself must
  // be inside.
  Vec<N> trace(const Vec<N>& x0, double time, TraceStats* stats = nullptr) const;

  // Moves x back onto the iso-contours f(x) = tau with the configured policy, taking no update
  // longer than max_update; returns the field evaluation at the returned point.
  FieldSample<N> reproject(Vec<N>& x, const std::array<double, N - 1>& tau, TraceStats* stats = nullptr,
                           double max_update = std::numeric_limits<double>::infinity()) const;

  const TraceOptions& options() const { return options_; }
  const DfvnField<N>& field() const { return field_; }

 private:
  using TraceFunction = Vec<N> (*)(const Tracer&, const Vec<N>&, double, TraceStats&);
  using ReprojectFunction = FieldSample<N> (*)(const Tracer&, Vec<N>&, const std::array<double, N - 1>&, double,
                                               TraceStats&);
  DfvnField<N> field_;  // a copy: three words, and no dangling reference
  TraceOptions options_;
  TraceFunction trace_;
  ReprojectFunction reproject_;

  template <Integrator I, Reprojection R, TracePolicy P>
  static Vec<N> trace_with(const Tracer&, const Vec<N>&, double, TraceStats&);
  template <Reprojection R, TracePolicy P>
  static FieldSample<N> reproject_with(const Tracer&, Vec<N>&, const std::array<double, N - 1>&, double,
                                       TraceStats&);
};

// Max over i of |f_i(sample) - tau_i|.
template <int N>
double iso_residual(const FieldSample<N>& sample, const std::array<double, N - 1>& tau);

extern template class Tracer<2>;
extern template class Tracer<3>;
extern template class Tracer<4>;
extern template class Tracer<5>;
extern template class Tracer<6>;
extern template class Tracer<7>;
extern template class Tracer<8>;

}  // namespace dfvn
