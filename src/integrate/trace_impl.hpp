// The definitions of Tracer<N>, included by one small translation unit per dimension
// (trace_2.cpp .. trace_8.cpp), so that no single file compiles all seven instantiations: under
// ASan + UBSan the single-file version took over two minutes and dominated the build.
#pragma once

#include <cmath>
#include <limits>
#include <stdexcept>

#include "dfvn/field/cross_product.hpp"
#include "dfvn/integrate/min_norm_step.hpp"
#include "dfvn/integrate/trace.hpp"
#include "dfvn/noise/noise_domain.hpp"

namespace dfvn {

template <int N>
double iso_residual(const FieldSample<N>& sample, const std::array<double, N - 1>& tau) {
  double worst = 0.0;
  for (int i = 0; i < N - 1; ++i) worst = std::max(worst, std::abs(sample.value[i] - tau[i]));
  return worst;
}

// The noise is defined only where every |F x_j| < kMaxNoiseArgument (noise/noise_domain.hpp). Callers
// check that traces start inside; a trace that still reaches the edge (an extreme step) sees beyond it
// a zero field with NaN values: every reprojection update across the edge is rejected (a NaN residual
// never compares as an improvement), and a step with a stage or its end beyond the edge is not taken
// (trace_with). So the noise is never evaluated outside its domain, and a trace ends inside it.
// With Velocity::skip only the f_i and their gradients are computed (the reprojection's evaluations:
// the cross product was a third of their cost in 7D); the velocity is then NaN inside the domain.
enum class Velocity { compute, skip };

template <int N, Velocity V = Velocity::compute>
FieldSample<N> evaluate_counted(const DfvnField<N>& field, const Vec<N>& x, TraceStats& stats) {
  ++stats.field_evaluations;
  if (!field.in_domain(x)) [[unlikely]] {
    ++stats.outside_domain;
    FieldSample<N> outside;
    outside.velocity.setZero();
    outside.value.fill(std::numeric_limits<double>::quiet_NaN());
    for (Vec<N>& gradient : outside.gradient) gradient.setZero();
    return outside;
  }
  if constexpr (V == Velocity::skip) return field.evaluate_functions(x);
  return field.evaluate(x);
}

template <int N>
template <Reprojection R, TracePolicy P>
FieldSample<N> Tracer<N>::reproject_with(const Tracer& self, Vec<N>& x, const std::array<double, N - 1>& tau,
                                         double max_update, TraceStats& stats) {
  const TraceOptions& o = self.options_;
  FieldSample<N> sample = evaluate_counted<N, Velocity::skip>(self.field_, x, stats);
  double residual_now = iso_residual<N>(sample, tau);
  // guarded: takes x + step unless it is too long or raises the residual; false when it was not taken.
  // continuous: takes x + step shortened to max_update (false only for a non-finite step).
  auto try_update = [&](Vec<N> step) {
    if constexpr (P == TracePolicy::continuous) {
      const double length = step.norm();
      if (!std::isfinite(length)) {
        ++stats.skipped_updates;
        return false;
      }
      if (length > max_update) {
        step *= max_update / length;
        ++stats.shortened_updates;
      }
    } else if (!step.allFinite() || !(step.norm() <= max_update)) {
      ++stats.skipped_updates;
      return false;
    }
    const Vec<N> candidate = x + step;
    FieldSample<N> moved = evaluate_counted<N, Velocity::skip>(self.field_, candidate, stats);
    const double residual_moved = iso_residual<N>(moved, tau);
    if constexpr (P == TracePolicy::guarded) {
      if (!(residual_moved <= residual_now)) {
        ++stats.skipped_updates;
        return false;
      }
    } else if (!std::isfinite(residual_moved)) {  // beyond the noise domain's edge: stay inside it
      ++stats.skipped_updates;
      return false;
    }
    x = candidate;
    sample = std::move(moved);
    residual_now = residual_moved;
    ++stats.reprojection_updates;
    return true;
  };
  if constexpr (R == Reprojection::gauss_newton) {
    for (int iteration = 0; iteration < o.reproject_iterations; ++iteration) {
      if (residual_now <= o.residual_tolerance) break;
      std::array<double, N - 1> residual;
      for (int i = 0; i < N - 1; ++i) residual[i] = tau[i] - sample.value[i];
      // Eq. (10)-(11): the minimum-norm solution of J v = tau - f(x), J's rows the gradients.
      Vec<N> step;
      if (!min_norm_step<N>(sample.gradient, residual, o.max_condition, step)) {
        ++stats.skipped_updates;  // rank deficient or ill-conditioned: keep x as it is
        break;
      }
      if (!try_update(step)) break;
    }
  } else if constexpr (R == Reprojection::newton) {
    const double min_gradient2 = 1.0 / (o.max_condition * o.max_condition);
    for (int iteration = 0; iteration < o.reproject_iterations; ++iteration) {
      if (residual_now <= o.residual_tolerance) break;
      // Eq. (12), one function at a time, each with a fresh evaluation at the moved point. A projection
      // onto contour i may raise another function's residual (the sweep as a whole converges), so
      // each projection must lower its own |f_i - tau_i|, besides the length bound.
      for (int i = 0; i < N - 1; ++i) {
        const Vec<N>& gradient = sample.gradient[i];
        const double gradient2 = gradient.squaredNorm();
        const double error = sample.value[i] - tau[i];
        if (error == 0.0) continue;
        Vec<N> step = -gradient * (error / gradient2);
        if (!(gradient2 > min_gradient2) || !step.allFinite()) {
          ++stats.skipped_updates;
          continue;
        }
        if constexpr (P == TracePolicy::continuous) {
          const double length = step.norm();
          if (length > max_update) {
            step *= max_update / length;
            ++stats.shortened_updates;
          }
        } else if (!(step.norm() <= max_update)) {
          ++stats.skipped_updates;
          continue;
        }
        const Vec<N> candidate = x + step;
        FieldSample<N> moved = evaluate_counted<N, Velocity::skip>(self.field_, candidate, stats);
        const bool worse = P == TracePolicy::guarded ? !(std::abs(moved.value[i] - tau[i]) <= std::abs(error))
                                                    : !std::isfinite(moved.value[i]);
        if (worse) {
          ++stats.skipped_updates;
          continue;
        }
        x = candidate;
        sample = std::move(moved);
        ++stats.reprojection_updates;
      }
      residual_now = iso_residual<N>(sample, tau);
    }
  }
  return sample;  // its velocity is not computed: the callers that need it take cross<N>(gradient)
}

// One integration step from x over time h (negative: backwards), k1 the velocity at x: Euler's h k1
// (Eq. 9) or RK4's h (k1 + 2 k2 + 2 k3 + k4) / 6. `fastest` gets the largest speed of its stages.
template <int N, Integrator I>
Vec<N> step_increment(const DfvnField<N>& field, const Vec<N>& x, const Vec<N>& k1, double h, TraceStats& stats,
                      double& fastest) {
  if constexpr (I == Integrator::euler) {
    fastest = k1.norm();
    return h * k1;
  } else {
    const Vec<N> k2 = evaluate_counted(field, Vec<N>(x + 0.5 * h * k1), stats).velocity;
    const Vec<N> k3 = evaluate_counted(field, Vec<N>(x + 0.5 * h * k2), stats).velocity;
    const Vec<N> k4 = evaluate_counted(field, Vec<N>(x + h * k3), stats).velocity;
    fastest = std::max({k1.norm(), k2.norm(), k3.norm(), k4.norm()});
    return (h / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
  }
}

template <int N>
template <Integrator I, Reprojection R, TracePolicy P>
Vec<N> Tracer<N>::trace_with(const Tracer& self, const Vec<N>& x0, double time, TraceStats& stats) {
  const int steps = self.options_.steps;
  // guarded: `steps` steps of delta = time / steps (Algorithm 1). continuous: steps of at most that
  // time and at most max_step_length long at the step's first velocity, the last one taking the time
  // that is left (and at most kMaxStepGrowth times `steps` of them): the step lengths are continuous
  // in x, and where the count changes the extra step is of length 0, so the end stays continuous.
  const double delta = time / steps;
  const int max_steps = P == TracePolicy::continuous ? steps * TraceOptions::kMaxStepGrowth : steps;
  double remaining = std::abs(time);
  Vec<N> x = x0;
  // The evaluation at x0 gives both the iso-values tau = f(x0) and the first velocity.
  FieldSample<N> current = evaluate_counted(self.field_, x, stats);
  const std::array<double, N - 1> tau = current.value;
  for (int k = 0; k < max_steps; ++k) {
    const Vec<N> before_step = x;
    const std::int64_t outside_before = stats.outside_domain;
    bool last = (k + 1 == max_steps);
    if constexpr (P == TracePolicy::continuous) {
      // The step's time: at most what is left, delta, and the time that moves max_step_length at the
      // largest of its stages' speeds. The stages depend on the time, so it is found by fixed-point
      // updates h <- min(h, max_step_length / largest stage speed at h), at most kLengthUpdates of them;
      // each is a continuous function of h and x, and an update that changes nothing ends the search
      // (the next ones would not change it either).
      const double limit = self.options_.max_step_length;
      const auto by_length = [&](double speed, double otherwise) { return speed > 0.0 ? limit / speed : otherwise; };
      double length = std::min({remaining, std::abs(delta), by_length(current.velocity.norm(), remaining)});
      Vec<N> increment;
      for (int update = 0;; ++update) {
        double fastest = 0.0;
        increment = step_increment<N, I>(self.field_, x, current.velocity, std::copysign(length, time), stats, fastest);
        const double shorter = std::min(length, by_length(fastest, length));
        if (!(shorter < length) || update + 1 == TraceOptions::kLengthUpdates) break;
        length = shorter;
      }
      last = last || !(length < remaining);
      remaining = last ? 0.0 : remaining - length;
      x += increment;
    } else {
      double fastest = 0.0;
      x += step_increment<N, I>(self.field_, x, current.velocity, delta, stats, fastest);
    }
    // A step that reached beyond the edge of the noise domain (a stage evaluated there, or the step's
    // end) is not taken: the trace stops at the last point whose step stayed inside, rather than at a
    // point outside the domain computed from the zero field beyond it.
    if (stats.outside_domain != outside_before || !self.field_.in_domain(x)) [[unlikely]] {
      if (stats.outside_domain == outside_before) ++stats.outside_domain;
      ++stats.stopped_at_edge;
      return before_step;
    }
    if constexpr (R == Reprojection::none) {
      if (!last) current = evaluate_counted(self.field_, x, stats);
    } else {
      // The reprojection ends with an evaluation at the projected point: it is the next k1.
      const double max_update = self.options_.max_update_ratio * (x - before_step).norm();
      current = reproject_with<R, P>(self, x, tau, max_update, stats);
      // The velocity at the projected point is the next k1; after the last step nobody needs it.
      if (!last) current.velocity = cross<N>(current.gradient);
    }
    if (last) break;
  }
  return x;
}

template <int N>
Tracer<N>::Tracer(const DfvnField<N>& field, const TraceOptions& options)
    : field_(field), options_(options) {
  options_.validate();
  if (field.kind() == FieldKind::curl && options_.reprojection != Reprojection::none)
    throw std::invalid_argument(
        "curl noise has no reprojection (its streamlines are not intersections of iso-surfaces): "
        "use reprojection none with --field curl");
  auto select = [&]<Integrator I, TracePolicy P>() -> TraceFunction {
    switch (options_.reprojection) {
      case Reprojection::none: return &trace_with<I, Reprojection::none, P>;
      case Reprojection::newton: return &trace_with<I, Reprojection::newton, P>;
      case Reprojection::gauss_newton: return &trace_with<I, Reprojection::gauss_newton, P>;
    }
    throw std::invalid_argument("unknown reprojection policy");
  };
  auto select_rule = [&]<Integrator I>() -> TraceFunction {
    return options_.policy == TracePolicy::guarded ? select.template operator()<I, TracePolicy::guarded>()
                                                       : select.template operator()<I, TracePolicy::continuous>();
  };
  trace_ = options_.integrator == Integrator::euler ? select_rule.template operator()<Integrator::euler>()
                                                    : select_rule.template operator()<Integrator::rk4>();
  const bool guarded = options_.policy == TracePolicy::guarded;
  switch (options_.reprojection) {
    case Reprojection::none: reproject_ = &reproject_with<Reprojection::none, TracePolicy::guarded>; break;
    case Reprojection::newton:
      reproject_ = guarded ? &reproject_with<Reprojection::newton, TracePolicy::guarded>
                           : &reproject_with<Reprojection::newton, TracePolicy::continuous>;
      break;
    case Reprojection::gauss_newton:
      reproject_ = guarded ? &reproject_with<Reprojection::gauss_newton, TracePolicy::guarded>
                           : &reproject_with<Reprojection::gauss_newton, TracePolicy::continuous>;
      break;
  }
}

template <int N>
Vec<N> Tracer<N>::trace(const Vec<N>& x0, double time, TraceStats* stats) const {
  TraceStats local;
  const Vec<N> x = trace_(*this, x0, time, local);
  if (stats) *stats += local;
  return x;
}

template <int N>
FieldSample<N> Tracer<N>::reproject(Vec<N>& x, const std::array<double, N - 1>& tau, TraceStats* stats,
                                    double max_update) const {
  TraceStats local;
  FieldSample<N> sample = reproject_(*this, x, tau, max_update, local);
  if (field_.kind() == FieldKind::curl)  // (reprojection none) its velocity is no cross product
    sample.velocity = field_.in_domain(x) ? field_.velocity(x) : Vec<N>::Zero();
  else
    sample.velocity = cross<N>(sample.gradient);  // zero outside the noise domain, whose gradients are zero
  if (stats) *stats += local;
  return sample;
}

// Each trace_<N>.cpp instantiates one dimension.
#define DFVN_INSTANTIATE_TRACER(N) \
  template class Tracer<N>;        \
  template double iso_residual<N>(const FieldSample<N>&, const std::array<double, N - 1>&);

}  // namespace dfvn
