#include "dfvn/field/bridson_flow.hpp"

#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include <Eigen/Geometry>
#include <fmt/format.h>

#include "dfvn/core/message_text.hpp"

namespace dfvn {

namespace {

// "KIND:a,b,c" -> the numbers after `prefix` (which the caller matched); every one finite.
std::vector<double> parse_numbers(std::string_view spec, std::string_view prefix, std::string_view what) {
  const std::string quoted = quote_for_message(spec);
  std::vector<double> numbers;
  std::string_view rest = spec.substr(prefix.size());
  while (true) {
    const std::size_t comma = rest.find(',');
    const std::string item(rest.substr(0, comma));
    char* end = nullptr;
    const double value = item.empty() ? NAN : std::strtod(item.c_str(), &end);
    if (item.empty() || end != item.c_str() + item.size())
      throw std::invalid_argument(fmt::format("{} {}: {} is not a number", what, quoted, quote_for_message(item)));
    if (!std::isfinite(value)) throw std::invalid_argument(fmt::format("{} {}: every number must be finite", what, quoted));
    numbers.push_back(value);
    if (comma == std::string_view::npos) break;
    rest = rest.substr(comma + 1);
  }
  return numbers;
}

Vec<3> vec3(const std::vector<double>& v, std::size_t first) { return Vec<3>(v[first], v[first + 1], v[first + 2]); }

std::string join(std::initializer_list<double> values) {
  std::string text;
  for (double v : values) text += (text.empty() ? "" : ",") + fmt::format("{:g}", v);
  return text;
}

}  // namespace

RigidBody parse_body(std::string_view spec) {
  constexpr std::string_view kPrefix = "sphere:";
  const std::string quoted = quote_for_message(spec);
  constexpr std::string_view kForm = "sphere:CX,CY,CZ,R,VX,VY,VZ,WX,WY,WZ";
  if (!spec.starts_with(kPrefix)) throw std::invalid_argument(fmt::format("body {}: expected {}", quoted, kForm));
  const std::vector<double> n = parse_numbers(spec, kPrefix, "body");
  if (n.size() != 10)
    throw std::invalid_argument(fmt::format("body {}: expected {} (10 numbers), got {}", quoted, kForm, n.size()));
  RigidBody b;
  b.centre = vec3(n, 0);
  b.radius = n[3];
  b.velocity = vec3(n, 4);
  b.angular = vec3(n, 7);
  if (!(b.radius > 0.0)) throw std::invalid_argument(fmt::format("body {}: the radius must be positive, got {:g}", quoted, b.radius));
  return b;
}

std::string to_string(const RigidBody& b) {
  return "sphere:" + join({b.centre[0], b.centre[1], b.centre[2], b.radius, b.velocity[0], b.velocity[1], b.velocity[2],
                           b.angular[0], b.angular[1], b.angular[2]});
}

Vortex parse_vortex(std::string_view spec) {
  const std::string quoted = quote_for_message(spec);
  constexpr std::string_view kForms = "particle:CX,CY,CZ,WX,WY,WZ,R or ring:CX,CY,CZ,NX,NY,NZ,RR,W,R";
  Vortex v;
  if (spec.starts_with("particle:")) {
    const std::vector<double> n = parse_numbers(spec, "particle:", "vortex");
    if (n.size() != 7) throw std::invalid_argument(fmt::format("vortex {}: expected particle:CX,CY,CZ,WX,WY,WZ,R (7 numbers)", quoted));
    v.kind = Vortex::Kind::particle;
    v.centre = vec3(n, 0);
    v.omega = vec3(n, 3);
    v.core_radius = n[6];
  } else if (spec.starts_with("ring:")) {
    const std::vector<double> n = parse_numbers(spec, "ring:", "vortex");
    if (n.size() != 9) throw std::invalid_argument(fmt::format("vortex {}: expected ring:CX,CY,CZ,NX,NY,NZ,RR,W,R (9 numbers)", quoted));
    v.kind = Vortex::Kind::ring;
    v.centre = vec3(n, 0);
    v.normal = vec3(n, 3);
    v.ring_radius = n[6];
    v.strength = n[7];
    v.core_radius = n[8];
    const double length = v.normal.norm();
    if (!(length > 0.0) || !std::isfinite(length))
      throw std::invalid_argument(fmt::format("vortex {}: the normal N must be a non-zero direction", quoted));
    v.normal /= length;
    if (!(v.core_radius < v.ring_radius))
      throw std::invalid_argument(fmt::format("vortex {}: the core radius R must be below the ring radius RR (the tube "
                                              "would reach the ring's axis, where its tangent jumps)", quoted));
  } else {
    throw std::invalid_argument(fmt::format("vortex {}: expected {}", quoted, kForms));
  }
  if (!(v.core_radius > 0.0))
    throw std::invalid_argument(fmt::format("vortex {}: the core radius R must be positive, got {:g}", quoted, v.core_radius));
  return v;
}

std::string to_string(const Vortex& v) {
  if (v.kind == Vortex::Kind::particle)
    return "particle:" + join({v.centre[0], v.centre[1], v.centre[2], v.omega[0], v.omega[1], v.omega[2], v.core_radius});
  return "ring:" + join({v.centre[0], v.centre[1], v.centre[2], v.normal[0], v.normal[1], v.normal[2], v.ring_radius,
                         v.strength, v.core_radius});
}

AmplitudeShape parse_amplitude(std::string_view spec) {
  const std::string quoted = quote_for_message(spec);
  AmplitudeShape a;
  if (spec.starts_with("constant:")) {
    a.kind = AmplitudeShape::Kind::constant;
    a.parameters = parse_numbers(spec, "constant:", "amplitude");
    if (a.parameters.size() != 1) throw std::invalid_argument(fmt::format("amplitude {}: expected constant:A", quoted));
  } else if (spec.starts_with("height:")) {
    a.kind = AmplitudeShape::Kind::height;
    a.parameters = parse_numbers(spec, "height:", "amplitude");
    if (a.parameters.size() != 2) throw std::invalid_argument(fmt::format("amplitude {}: expected height:Z0,Z1", quoted));
    if (a.parameters[0] == a.parameters[1])
      throw std::invalid_argument(fmt::format("amplitude {}: Z0 and Z1 must differ (the ramp runs from Z0 to Z1)", quoted));
  } else if (spec.starts_with("obstacles:")) {
    a.kind = AmplitudeShape::Kind::obstacles;
    a.parameters = parse_numbers(spec, "obstacles:", "amplitude");
    if (a.parameters.size() != 1 || !(a.parameters[0] > 0.0))
      throw std::invalid_argument(fmt::format("amplitude {}: expected obstacles:D with D > 0", quoted));
  } else {
    throw std::invalid_argument(fmt::format("amplitude {}: expected constant:A, height:Z0,Z1 or obstacles:D", quoted));
  }
  return a;
}

std::string to_string(const AmplitudeShape& a) {
  std::string text = a.kind == AmplitudeShape::Kind::constant ? "constant:"
                     : a.kind == AmplitudeShape::Kind::height ? "height:"
                                                              : "obstacles:";
  for (std::size_t i = 0; i < a.parameters.size(); ++i) text += (i ? "," : "") + fmt::format("{:g}", a.parameters[i]);
  return text;
}

void FlowOptions::validate() const {
  if (octaves < 1 || octaves > kMaxOctaves)
    throw std::invalid_argument(fmt::format("--octaves must be in [1, {}], got {}", kMaxOctaves, octaves));
  if (!(octave_gain > 0.0) || !std::isfinite(octave_gain))
    throw std::invalid_argument(fmt::format("--octave-gain must be a finite number > 0, got {:g}", octave_gain));
}

std::vector<double> octave_weights(int octaves, double gain) {
  std::vector<double> w(static_cast<std::size_t>(octaves));
  double sum = 0.0, power = 1.0;
  for (int o = 0; o < octaves; ++o, power *= gain) {
    w[o] = power;
    sum += power * power;
  }
  const double norm = std::sqrt(sum);
  for (double& a : w) a /= norm;
  return w;
}

std::vector<Obstacle> body_obstacles(const std::vector<RigidBody>& bodies) {
  std::vector<Obstacle> out;
  for (const RigidBody& b : bodies) out.push_back(Obstacle{{b.centre[0], b.centre[1], b.centre[2]}, b.radius});
  return out;
}

void check_flow(const FlowOptions& flow, int dimension, bool curl, FieldConstraint domain,
                const std::vector<Obstacle>& obstacles, double width) {
  flow.validate();
  const bool bounded = domain == FieldConstraint::inside_cube || domain == FieldConstraint::inside_ball;
  if ((!flow.bodies.empty() || !flow.vortices.empty()) && !(curl && dimension == 3))
    throw std::invalid_argument(
        "--body and --vortex are Bridson's vector potentials (Eqs. 6-8): they need --field curl in 3D (a DFVN field is a "
        "cross product of gradients, which an added potential is not)");
  if (!flow.bodies.empty() && !bounded)
    throw std::invalid_argument("--body moves inside a domain: it needs --domain cube or ball");
  if (flow.viscous && !bounded) throw std::invalid_argument("--viscous makes the walls no-slip: it needs --domain cube or ball");
  if (domain == FieldConstraint::on_sphere && (flow.viscous || !flow.amplitude.empty()))
    throw std::invalid_argument("on the sphere f_1 is the surface's function: --amplitude and --viscous need another domain");
  for (const AmplitudeShape& a : flow.amplitude)
    if (a.kind == AmplitudeShape::Kind::obstacles && obstacles.empty() && flow.bodies.empty())
      throw std::invalid_argument("--amplitude obstacles:D needs an --obstacle or a --body");
  if (flow.bodies.empty()) return;
  // Each body's blend region as an obstacle of radius R_b: inside the domain, clear of the wall's zone and of
  // every other solid's zone, so no other boundary sees the body's rigid potential.
  std::vector<Obstacle> regions = obstacles;
  for (const RigidBody& b : flow.bodies) regions.push_back(Obstacle{{b.centre[0], b.centre[1], b.centre[2]}, b.blend_radius()});
  try {
    check_obstacles(dimension, domain, regions, width);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(fmt::format(
        "every --body's blend region (radius {:g} R about its centre) must lie clear of the walls and of the other solids as an "
        "obstacle does: {}",
        RigidBody::kBlendRadii, e.what()));
  }
}

template <int N>
double flow_amplitude(const std::vector<AmplitudeShape>& shapes, const std::vector<Obstacle>& solids, const Vec<N>& x,
                      Vec<N>& gradient) {
  double value = 1.0;
  gradient.setZero();
  for (const AmplitudeShape& a : shapes) {
    double v = 0.0;
    Vec<N> g = Vec<N>::Zero();
    switch (a.kind) {
      case AmplitudeShape::Kind::constant: v = a.parameters[0]; break;
      case AmplitudeShape::Kind::height: {
        const double span = a.parameters[1] - a.parameters[0];
        double slope = 0.0;
        v = smoothstep_c2((x[N - 1] - a.parameters[0]) / span, &slope);
        g[N - 1] = slope / span;
        break;
      }
      case AmplitudeShape::Kind::obstacles: {
        // 1 - prod_b S(d_b / D): the product and its gradient by the product rule.
        const double reach = a.parameters[0];
        double product = 1.0;
        Vec<N> grad_product = Vec<N>::Zero();
        for (const Obstacle& o : solids) {
          Vec<N> n;
          const double d = obstacle_distance<N>(o, x, n);
          double slope = 0.0;
          const double s = smoothstep_c2(d / reach, &slope);
          grad_product = s * grad_product + (product * slope / reach) * n;
          product *= s;
        }
        v = 1.0 - product;
        g = -grad_product;
        break;
      }
    }
    gradient = v * gradient + value * g;
    value *= v;
  }
  return value;
}

template <int N>
double viscous_factor(FieldConstraint domain, const std::vector<Obstacle>& solids, double width, const Vec<N>& x,
                      Vec<N>& gradient) {
  double value = 1.0;
  gradient.setZero();
  auto multiply = [&](double d, const Vec<N>& n) {
    double slope = 0.0;
    const double s = smoothstep_c2(d / width, &slope);
    gradient = s * gradient + (value * slope / width) * n;
    value *= s;
  };
  Vec<N> n;
  if (domain == FieldConstraint::inside_cube) multiply(cube_boundary_function<N>(x, n), n);
  if (domain == FieldConstraint::inside_ball) multiply(ball_boundary_function<N>(x, n), n);
  for (const Obstacle& o : solids) {
    const double d = obstacle_distance<N>(o, x, n);
    multiply(d, n);
  }
  return value;
}

namespace {

// The cross-product matrix [v]_x, [v]_x r = v x r.
Eigen::Matrix3d cross_matrix(const Vec<3>& v) {
  Eigen::Matrix3d m;
  m << 0.0, -v[2], v[1], v[2], 0.0, -v[0], -v[1], v[0], 0.0;
  return m;
}

// The fall-off's g(rho) = f(rho / R) (R^2 - rho^2) / 2 with f = 1 - S, and g'(rho) / rho, which stays smooth
// at rho = 0: f'(s) = -30 s^2 (1 - s)^2, so g'/rho = -15 s (1 - s)^2 (R^2 - rho^2) / R^2 - f(s).
void falloff(double rho, double core, double& g, double& slope_over_rho) {
  const double s = rho / core;
  const double f = 1.0 - smoothstep_c2(s, nullptr);
  const double room = core * core - rho * rho;
  g = 0.5 * f * room;
  slope_over_rho = -15.0 * s * (1.0 - s) * (1.0 - s) * room / (core * core) - f;
}

void add(const Vec<3>& value, const Eigen::Matrix3d& jacobian, std::array<double, 3>& psi, std::array<Vec<3>, 3>& rows) {
  for (int i = 0; i < 3; ++i) {
    psi[i] += value[i];
    rows[i] += jacobian.row(i).transpose();
  }
}

}  // namespace

void add_body_potential(const RigidBody& body, const Vec<3>& x, std::array<double, 3>& psi,
                        std::array<Vec<3>, 3>& jacobian) {
  const Vec<3> r = x - body.centre;
  const double distance = r.norm();
  const double blend_width = body.blend_radius() - body.radius;
  double slope = 0.0;
  const double blend = 1.0 - smoothstep_c2((distance - body.radius) / blend_width, &slope);
  if (blend == 0.0) return;  // beyond the blend region: A_b = 0 with zero slope
  const double rb2 = body.blend_radius() * body.blend_radius();
  // psi_rigid = V x r / 2 + w (R_b^2 - |r|^2) / 2, d psi_rigid / dx = [V]_x / 2 - w r^T.
  const Vec<3> rigid = 0.5 * body.velocity.cross(r) + 0.5 * (rb2 - distance * distance) * body.angular;
  const Eigen::Matrix3d rigid_jacobian = 0.5 * cross_matrix(body.velocity) - body.angular * r.transpose();
  Vec<3> grad_blend = Vec<3>::Zero();
  if (distance > 0.0) grad_blend = (-slope / blend_width / distance) * r;
  add(blend * rigid, blend * rigid_jacobian + rigid * grad_blend.transpose(), psi, jacobian);
}

void add_vortex_potential(const Vortex& v, const Vec<3>& x, std::array<double, 3>& psi, std::array<Vec<3>, 3>& jacobian) {
  const double core = v.core_radius;
  if (v.kind == Vortex::Kind::particle) {
    const Vec<3> r = x - v.centre;
    const double rho = r.norm();
    if (rho >= core) return;
    double g = 0.0, slope_over_rho = 0.0;
    falloff(rho, core, g, slope_over_rho);
    // psi = g w, d psi / dx = w (grad g)^T with grad g = (g' / rho) r.
    add(g * v.omega, v.omega * (slope_over_rho * r).transpose(), psi, jacobian);
    return;
  }
  const Vec<3> u = x - v.centre;
  const double h = u.dot(v.normal);
  const Vec<3> p = u - h * v.normal;
  const double rho_p = p.norm();
  const double q = rho_p - v.ring_radius;
  const double rho = std::sqrt(q * q + h * h);
  if (rho >= core) return;  // rho < core < RR also keeps rho_p > 0
  const Vec<3> p_hat = p / rho_p;
  const Vec<3> tangent = v.normal.cross(p_hat);
  double g = 0.0, slope_over_rho = 0.0;
  falloff(rho, core, g, slope_over_rho);
  // x - x_C = q p_hat + h n, so grad g = (g' / rho) (q p_hat + h n); d t / dx = ([n]_x - t p_hat^T) / rho_p.
  const Vec<3> grad_g = slope_over_rho * (q * p_hat + h * v.normal);
  const Eigen::Matrix3d d_tangent = (cross_matrix(v.normal) - tangent * p_hat.transpose()) / rho_p;
  add(v.strength * g * tangent, v.strength * (tangent * grad_g.transpose() + g * d_tangent), psi, jacobian);
}

#define DFVN_INSTANTIATE_FLOW(N)                                                                                       \
  template double flow_amplitude<N>(const std::vector<AmplitudeShape>&, const std::vector<Obstacle>&, const Vec<N>&,   \
                                    Vec<N>&);                                                                          \
  template double viscous_factor<N>(FieldConstraint, const std::vector<Obstacle>&, double, const Vec<N>&, Vec<N>&);
DFVN_INSTANTIATE_FLOW(2)
DFVN_INSTANTIATE_FLOW(3)
DFVN_INSTANTIATE_FLOW(4)
DFVN_INSTANTIATE_FLOW(5)
DFVN_INSTANTIATE_FLOW(6)
DFVN_INSTANTIATE_FLOW(7)
DFVN_INSTANTIATE_FLOW(8)
#undef DFVN_INSTANTIATE_FLOW

}  // namespace dfvn
