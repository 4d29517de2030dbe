#include "dfvn/field/constraint.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "dfvn/core/message_text.hpp"

namespace dfvn {

std::string_view to_string(FieldConstraint constraint) {
  switch (constraint) {
    case FieldConstraint::none: return "none";
    case FieldConstraint::inside_cube: return "cube";
    case FieldConstraint::inside_ball: return "ball";
    case FieldConstraint::on_sphere: return "sphere";
  }
  return "?";
}

Bound parse_bound(std::string_view name) {
  for (Bound bound : kAllBounds)
    if (name == to_string(bound)) return bound;
  throw std::invalid_argument("unknown bound " + quote_for_message(name) + " (allowed: " + bound_names() + ")");
}

std::string_view to_string(Bound bound) { return bound == Bound::eq13 ? "eq13" : "ramp"; }

std::string bound_names() {
  std::string names;
  for (Bound bound : kAllBounds) names += (names.empty() ? "" : ", ") + std::string(to_string(bound));
  return names;
}

double noise_gradient_rms(int dimension) {
  const double n = dimension;
  return std::sqrt(n / std::pow(std::tgamma(n + 1.0), 1.0 / (n - 1.0)));
}

double smoothstep_c2(double u, double* derivative) {
  if (u <= 0.0 || u >= 1.0) {
    if (derivative) *derivative = 0.0;
    return u <= 0.0 ? 0.0 : 1.0;
  }
  if (derivative) *derivative = 30.0 * u * u * (1.0 - u) * (1.0 - u);
  return u * u * u * (10.0 + u * (-15.0 + 6.0 * u));
}

double bridson_ramp(double r, double* derivative) {
  const double a = std::abs(r);
  if (a >= 1.0) {
    if (derivative) *derivative = 0.0;
    return r > 0.0 ? 1.0 : -1.0;
  }
  const double r2 = r * r;
  if (derivative) *derivative = (15.0 - 30.0 * r2 + 15.0 * r2 * r2) / 8.0;
  return r * (15.0 - 10.0 * r2 + 3.0 * r2 * r2) / 8.0;
}

template <int N>
double cube_boundary_function(const Vec<N>& x, Vec<N>& gradient) {
  // The nearest face, and whether x is inside at all.
  double nearest = x[0];
  int nearest_axis = 0;
  double nearest_sign = 1.0;
  for (int j = 0; j < N; ++j) {
    if (x[j] < nearest) nearest = x[j], nearest_axis = j, nearest_sign = 1.0;
    if (1.0 - x[j] < nearest) nearest = 1.0 - x[j], nearest_axis = j, nearest_sign = -1.0;
  }
  if (!(nearest > 0.0)) {  // on or outside the boundary: the most negative face distance
    gradient.setZero();
    gradient[nearest_axis] = nearest_sign;
    return nearest;
  }
  // Scaled by the nearest distance m so that nothing overflows: H = m / sqrt(sum_k (m / t_k)^2) and
  // dH/dt_k = (H / t_k)^3, with dt_k/dx_j = +1 (face x_j = 0) or -1 (face x_j = 1).
  double sum = 0.0;
  for (int j = 0; j < N; ++j) {
    const double a = nearest / x[j], b = nearest / (1.0 - x[j]);
    sum += a * a + b * b;
  }
  const double h = nearest / std::sqrt(sum);
  for (int j = 0; j < N; ++j) {
    const double a = h / x[j], b = h / (1.0 - x[j]);
    gradient[j] = a * a * a - b * b * b;
  }
  return h;
}

template <int N>
double ball_boundary_function(const Vec<N>& x, Vec<N>& gradient) {
  const Vec<N> from_centre = (x.array() - 0.5).matrix();
  const double r = from_centre.norm();
  if (r > 0.0)
    gradient = -from_centre / r;
  else
    gradient.setZero();  // the centre: the medial axis, where alpha = 1 and d is not used
  return 0.5 - r;
}

template <int N>
bool satisfies_constraint(FieldConstraint constraint, const Vec<N>& x, double sphere_tolerance) {
  if (!x.allFinite()) return false;
  switch (constraint) {
    case FieldConstraint::none: return true;
    case FieldConstraint::inside_cube: return (x.array() >= 0.0).all() && (x.array() <= 1.0).all();
    case FieldConstraint::inside_ball: return (x.array() - 0.5).matrix().norm() <= 0.5;
    case FieldConstraint::on_sphere: return std::abs(x.norm() - 1.0) <= sphere_tolerance;
  }
  return false;
}

namespace {

// Eq. (13) given d, grad d, alpha and grad alpha: f_1 = (1 - alpha) G d + alpha f~ and
// grad f_1 = (1 - alpha) G grad d + alpha grad f~ + (f~ - G d) grad alpha.
template <int N>
void blend(double g, double d, const Vec<N>& grad_d, double alpha, const Vec<N>& grad_alpha, double& value,
           Vec<N>& gradient) {
  const double noise = value;
  value = (1.0 - alpha) * g * d + alpha * noise;
  gradient = (1.0 - alpha) * g * grad_d + alpha * gradient + (noise - g * d) * grad_alpha;
}

// The ramp bound: f_1 = ramp(d / w) f~ and grad f_1 = ramp grad f~ + f~ ramp'(d / w) / w grad d.
template <int N>
void ramp(double w, double d, const Vec<N>& grad_d, double& value, Vec<N>& gradient) {
  double slope = 0.0;
  const double scale = bridson_ramp(d / w, &slope);
  gradient = scale * gradient + (value * slope / w) * grad_d;
  value *= scale;
}

// The ramp where the boundary function d (the cube's H or the ball's signed distance) is below w. For the
// cube H <= min_k t_k: deeper than w from every face H may still be below w (near an edge or a corner),
// so H decides.
template <int N, double (*kBoundaryFunction)(const Vec<N>&, Vec<N>&)>
void ramp_inside(double w, const Vec<N>& x, double& value, Vec<N>& gradient) {
  Vec<N> grad_d;
  const double d = kBoundaryFunction(x, grad_d);
  if (d >= w) return;
  ramp<N>(w, d, grad_d, value, gradient);
}

template <int N>
void replace_inside_cube(double g, double w, const Vec<N>& x, double& value, Vec<N>& gradient) {
  // alpha = prod_j a_j with a_j = S(x_j / w) S((1 - x_j) / w), and d alpha / d x_j = a_j' prod_{i != j} a_i.
  double a[N], da[N];
  bool core = true;
  for (int j = 0; j < N; ++j) {
    double d_low = 0.0, d_high = 0.0;
    const double low = smoothstep_c2(x[j] / w, &d_low);
    const double high = smoothstep_c2((1.0 - x[j]) / w, &d_high);
    a[j] = low * high;
    da[j] = (d_low * high - low * d_high) / w;
    core = core && a[j] == 1.0;
  }
  if (core) return;  // alpha = 1, grad alpha = 0: f_1 is the noise
  double alpha = 1.0;
  Vec<N> grad_alpha;
  for (int j = 0; j < N; ++j) {
    alpha *= a[j];
    double others = da[j];
    for (int i = 0; i < N; ++i)
      if (i != j) others *= a[i];
    grad_alpha[j] = others;
  }
  Vec<N> grad_d;
  const double d = cube_boundary_function<N>(x, grad_d);
  blend<N>(g, d, grad_d, alpha, grad_alpha, value, gradient);
}

template <int N>
void replace_inside_ball(double g, double w, const Vec<N>& x, double& value, Vec<N>& gradient) {
  Vec<N> grad_d;
  const double d = ball_boundary_function<N>(x, grad_d);
  double d_alpha = 0.0;
  const double alpha = smoothstep_c2(d / w, &d_alpha);
  if (alpha == 1.0) return;
  blend<N>(g, d, grad_d, alpha, Vec<N>(grad_d * (d_alpha / w)), value, gradient);
}

template <int N>
void replace_on_sphere(double g, const Vec<N>& x, double& value, Vec<N>& gradient) {
  value = 0.5 * g * x.squaredNorm();
  gradient = g * x;
}

}  // namespace

template <int N>
ConstraintFunction<N>::ConstraintFunction(FieldConstraint constraint, double transition_width, Bound bound)
    : constraint_(constraint), width_(transition_width), bound_(bound), gradient_rms_(noise_gradient_rms(N)) {
  parse_bound(to_string(bound));  // an unknown enum value throws
  switch (constraint) {
    case FieldConstraint::none:
      throw std::invalid_argument("a constraint function needs a constraint (cube, ball or sphere)");
    case FieldConstraint::inside_cube:
    case FieldConstraint::inside_ball:
      if (!(transition_width > 0.0 && transition_width <= 0.25))
        throw std::invalid_argument(
            fmt::format("the boundary's transition width must be in (0, 1/4], got {:g}", transition_width));
      break;
    case FieldConstraint::on_sphere:
      if (N < 3) throw std::invalid_argument("a field on the sphere needs N >= 3 (in 2D no noise function is left)");
      break;
  }
  replace_ = choose_replacement(constraint, bound);
}

template <int N>
auto ConstraintFunction<N>::choose_replacement(FieldConstraint constraint, Bound bound) -> Replacement {
  const bool ramped = bound == Bound::ramp;
  switch (constraint) {
    case FieldConstraint::inside_cube:
      if (ramped)
        return [](const ConstraintFunction& f, const Vec<N>& x, double& v, Vec<N>& g) {
          ramp_inside<N, cube_boundary_function<N>>(f.width_, x, v, g);
        };
      return [](const ConstraintFunction& f, const Vec<N>& x, double& v, Vec<N>& g) {
        replace_inside_cube<N>(f.gradient_rms_, f.width_, x, v, g);
      };
    case FieldConstraint::inside_ball:
      if (ramped)
        return [](const ConstraintFunction& f, const Vec<N>& x, double& v, Vec<N>& g) {
          ramp_inside<N, ball_boundary_function<N>>(f.width_, x, v, g);
        };
      return [](const ConstraintFunction& f, const Vec<N>& x, double& v, Vec<N>& g) {
        replace_inside_ball<N>(f.gradient_rms_, f.width_, x, v, g);
      };
    case FieldConstraint::on_sphere:
      return [](const ConstraintFunction& f, const Vec<N>& x, double& v, Vec<N>& g) {
        replace_on_sphere<N>(f.gradient_rms_, x, v, g);
      };
    case FieldConstraint::none: break;
  }
  throw std::invalid_argument("a constraint function needs a constraint (cube, ball or sphere)");
}

template <int N>
void ConstraintFunction<N>::replace(const Vec<N>& x, double& value, Vec<N>& gradient) const {
  replace_(*this, x, value, gradient);
}

#define DFVN_INSTANTIATE_CONSTRAINT(N)                                                   \
  template double cube_boundary_function<N>(const Vec<N>&, Vec<N>&);                     \
  template double ball_boundary_function<N>(const Vec<N>&, Vec<N>&);                     \
  template bool satisfies_constraint<N>(FieldConstraint, const Vec<N>&, double);         \
  template class ConstraintFunction<N>;
DFVN_INSTANTIATE_CONSTRAINT(2)
DFVN_INSTANTIATE_CONSTRAINT(3)
DFVN_INSTANTIATE_CONSTRAINT(4)
DFVN_INSTANTIATE_CONSTRAINT(5)
DFVN_INSTANTIATE_CONSTRAINT(6)
DFVN_INSTANTIATE_CONSTRAINT(7)
DFVN_INSTANTIATE_CONSTRAINT(8)

}  // namespace dfvn
