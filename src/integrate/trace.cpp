#include "dfvn/integrate/trace.hpp"

#include "dfvn/core/message_text.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace dfvn {

Integrator parse_integrator(std::string_view name) {
  if (name == "euler") return Integrator::euler;
  if (name == "rk4") return Integrator::rk4;
  throw std::invalid_argument("unknown integrator " + quote_for_message(name) + " (allowed: euler, rk4)");
}

Reprojection parse_reprojection(std::string_view name) {
  if (name == "none") return Reprojection::none;
  if (name == "newton") return Reprojection::newton;
  if (name == "gauss-newton") return Reprojection::gauss_newton;
  throw std::invalid_argument("unknown reprojection " + quote_for_message(name) + " (allowed: none, newton, gauss-newton)");
}

std::string_view to_string(Integrator integrator) {
  return integrator == Integrator::euler ? "euler" : "rk4";
}

std::string_view to_string(Reprojection reprojection) {
  switch (reprojection) {
    case Reprojection::none: return "none";
    case Reprojection::newton: return "newton";
    case Reprojection::gauss_newton: return "gauss-newton";
  }
  return "?";
}

std::string_view to_string(TracePolicy rule) { return rule == TracePolicy::guarded ? "guarded" : "continuous"; }

void TraceOptions::validate() const {
  if (steps < 1) throw std::invalid_argument("steps must be at least 1, got " + std::to_string(steps));
  if (reproject_iterations < 0)
    throw std::invalid_argument("reprojection iterations must be >= 0, got " +
                                std::to_string(reproject_iterations));
  if (!std::isfinite(residual_tolerance) || residual_tolerance < 0.0)
    throw std::invalid_argument("residual tolerance must be finite and >= 0");
  if (!std::isfinite(max_condition) || max_condition <= 1.0)
    throw std::invalid_argument("maximum condition number must be finite and > 1");
  if (!(max_update_ratio > 0.0)) throw std::invalid_argument("maximum update ratio must be > 0");
  if (policy != TracePolicy::guarded && policy != TracePolicy::continuous)
    throw std::invalid_argument("unknown trace policy");
  if (!(max_step_length > 0.0)) throw std::invalid_argument("maximum step length must be > 0");
  if (steps > std::numeric_limits<int>::max() / kMaxStepGrowth)
    throw std::invalid_argument("steps must be at most " + std::to_string(std::numeric_limits<int>::max() / kMaxStepGrowth));
}

}  // namespace dfvn
