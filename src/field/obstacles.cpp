#include "dfvn/field/obstacles.hpp"

#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include <fmt/format.h>

#include "dfvn/core/message_text.hpp"

namespace dfvn {

Obstacle parse_obstacle(std::string_view spec) {
  const std::string quoted = quote_for_message(spec);
  constexpr std::string_view kPrefix = "sphere:";
  if (spec.substr(0, kPrefix.size()) != kPrefix)
    throw std::invalid_argument(fmt::format("obstacle {}: expected sphere:CX,CY[,CZ...],R", quoted));
  std::vector<double> numbers;
  std::string_view rest = spec.substr(kPrefix.size());
  while (true) {
    const std::size_t comma = rest.find(',');
    const std::string item(rest.substr(0, comma));
    char* end = nullptr;
    const double value = item.empty() ? NAN : std::strtod(item.c_str(), &end);
    if (item.empty() || end != item.c_str() + item.size())
      throw std::invalid_argument(fmt::format("obstacle {}: {} is not a number", quoted, quote_for_message(item)));
    if (!std::isfinite(value))
      throw std::invalid_argument(fmt::format("obstacle {}: every centre coordinate and the radius must be finite", quoted));
    numbers.push_back(value);
    if (comma == std::string_view::npos) break;
    rest = rest.substr(comma + 1);
  }
  if (numbers.size() < 3)
    throw std::invalid_argument(fmt::format("obstacle {}: expected sphere:CX,CY[,CZ...],R (a centre of 2 or more coordinates and a radius)", quoted));
  Obstacle o;
  o.radius = numbers.back();
  numbers.pop_back();
  o.centre = numbers;
  if (!(o.radius > 0.0)) throw std::invalid_argument(fmt::format("obstacle {}: the radius must be positive, got {:g}", quoted, o.radius));
  return o;
}

std::string to_string(const Obstacle& obstacle) {
  std::string text = "sphere:";
  for (double c : obstacle.centre) text += fmt::format("{:g},", c);
  return text + fmt::format("{:g}", obstacle.radius);
}

void check_obstacles(int dimension, FieldConstraint domain, const std::vector<Obstacle>& obstacles, double width) {
  if (obstacles.empty()) return;
  if (domain != FieldConstraint::inside_cube && domain != FieldConstraint::inside_ball)
    throw std::invalid_argument("obstacles lie inside a domain: --obstacle needs --domain cube or ball");
  const double n = dimension;
  for (std::size_t a = 0; a < obstacles.size(); ++a) {
    const Obstacle& o = obstacles[a];
    const std::string name = to_string(o);
    if (static_cast<int>(o.centre.size()) != dimension)
      throw std::invalid_argument(fmt::format("obstacle {}: {} centre coordinates for a {}D field (sphere:CX,CY[,CZ...],R)", name,
                                              o.centre.size(), dimension));
    if (!(o.radius > 0.0) || !std::isfinite(o.radius))
      throw std::invalid_argument(fmt::format("obstacle {}: the radius must be positive", name));
    for (double c : o.centre)
      if (!std::isfinite(c)) throw std::invalid_argument(fmt::format("obstacle {}: the centre must be finite", name));
    if (domain == FieldConstraint::inside_cube) {
      double nearest = 1.0;
      for (double c : o.centre) nearest = std::min({nearest, c, 1.0 - c});
      const double needed = o.radius + std::sqrt(2.0 * n) * width;
      if (nearest < needed)
        throw std::invalid_argument(fmt::format(
            "obstacle {} must lie inside the cube clear of its boundary zone: each face at least R + sqrt(2N) w = {:g} "
            "from the centre (w = --boundary-width {:g}), the nearest is {:g}",
            name, needed, width, nearest));
    } else {
      double r2 = 0.0;
      for (double c : o.centre) r2 += (c - 0.5) * (c - 0.5);
      const double reach = std::sqrt(r2) + o.radius + 2.0 * width;
      if (reach > 0.5)
        throw std::invalid_argument(fmt::format(
            "obstacle {} must lie inside the ball clear of its boundary zone: |c - centre| + R + 2 w = {:g} exceeds 1/2 "
            "(w = --boundary-width {:g})",
            name, reach, width));
    }
    for (std::size_t b = 0; b < a; ++b) {
      const Obstacle& p = obstacles[b];
      double d2 = 0.0;
      for (int j = 0; j < dimension; ++j) d2 += (o.centre[j] - p.centre[j]) * (o.centre[j] - p.centre[j]);
      if (std::sqrt(d2) < o.radius + p.radius + 2.0 * width)
        throw std::invalid_argument(fmt::format("obstacles {} and {} are closer than R_a + R_b + 2 w (w = --boundary-width {:g})",
                                                to_string(p), name, width));
    }
  }
}

template <int N>
double obstacle_distance(const Obstacle& obstacle, const Vec<N>& x, Vec<N>& gradient) {
  Vec<N> from_centre;
  for (int j = 0; j < N; ++j) from_centre[j] = x[j] - obstacle.centre[j];
  const double r = from_centre.norm();
  if (r > 0.0)
    gradient = from_centre / r;
  else
    gradient.setZero();
  return r - obstacle.radius;
}

template <int N>
bool outside_obstacles(const std::vector<Obstacle>& obstacles, const Vec<N>& x) {
  Vec<N> unused;
  for (const Obstacle& o : obstacles)
    if (!(obstacle_distance<N>(o, x, unused) >= 0.0)) return false;
  return true;
}

template <int N>
void ramp_obstacles(const std::vector<Obstacle>& obstacles, double width, const Vec<N>& x, double& value, Vec<N>& gradient) {
  for (const Obstacle& o : obstacles) {
    Vec<N> n;
    const double d = obstacle_distance<N>(o, x, n);
    if (d >= width) continue;
    double slope = 0.0;
    const double scale = bridson_ramp(d / width, &slope);
    gradient = scale * gradient + (value * slope / width) * n;
    value *= scale;
  }
}

namespace {

// psi_c = alpha psi + (1 - alpha) n (n . psi) with alpha = |ramp(d / w)|, given d, n = grad d and its
// Hessian; J[i] = grad psi_i on entry and grad psi_c,i on return:
//   d psi_c,i / dx_j = alpha_j (psi_i - n_i s) + alpha J_ij + (1 - alpha) (dn_i/dx_j s + n_i s_j),
//   s = n . psi, s_j = sum_k (dn_k/dx_j psi_k + n_k J_kj), alpha_j = sign(d) ramp'(d / w) n_j / w.
void bridson_term(double w, double d, const Vec<3>& n, const Eigen::Matrix3d& hessian, std::array<double, 3>& psi,
                  std::array<Vec<3>, 3>& jacobian) {
  if (d >= w) return;
  double slope = 0.0;
  const double ramp = bridson_ramp(d / w, &slope);
  const double alpha = std::abs(ramp);
  const Vec<3> grad_alpha = (ramp < 0.0 ? -slope : slope) / w * n;
  Eigen::Matrix3d j;  // j(i, k) = d psi_i / dx_k
  for (int i = 0; i < 3; ++i) j.row(i) = jacobian[i].transpose();
  const Vec<3> p(psi[0], psi[1], psi[2]);
  const double s = n.dot(p);
  const Vec<3> grad_s = hessian * p + j.transpose() * n;  // hessian is symmetric
  const Vec<3> pc = alpha * p + (1.0 - alpha) * s * n;
  const Eigen::Matrix3d jc = (p - s * n) * grad_alpha.transpose() + alpha * j + (1.0 - alpha) * (hessian * s + n * grad_s.transpose());
  for (int i = 0; i < 3; ++i) {
    psi[i] = pc[i];
    jacobian[i] = jc.row(i).transpose();
  }
}

}  // namespace

void bridson_boundary_3d(FieldConstraint domain, const std::vector<Obstacle>& obstacles, double width, const Vec<3>& x,
                         std::array<double, 3>& psi, std::array<Vec<3>, 3>& jacobian) {
  if (domain == FieldConstraint::inside_cube) {
    Vec<3> n;
    const double h = cube_boundary_function<3>(x, n);
    if (h > 0.0 && h < width) {
      // grad H_j = (H / x_j)^3 - (H / (1 - x_j))^3, so dn_j/dx_i = 3 n_i n_j / H - delta_ij 3 H^3 (x_j^-4 + (1 - x_j)^-4).
      Eigen::Matrix3d hessian = 3.0 * n * n.transpose() / h;
      for (int k = 0; k < 3; ++k) hessian(k, k) -= 3.0 * h * h * h * (std::pow(x[k], -4) + std::pow(1.0 - x[k], -4));
      bridson_term(width, h, n, hessian, psi, jacobian);
    } else if (h <= 0.0) {
      bridson_term(width, h, n, Eigen::Matrix3d::Zero(), psi, jacobian);  // outside: the continuation (planar)
    }
  } else if (domain == FieldConstraint::inside_ball) {
    const Vec<3> u = (x.array() - 0.5).matrix();
    const double r = u.norm();
    if (r > 0.0) {
      const Vec<3> n = -u / r;
      const Eigen::Matrix3d hessian = -(Eigen::Matrix3d::Identity() - n * n.transpose()) / r;
      bridson_term(width, 0.5 - r, n, hessian, psi, jacobian);
    }
  }
  for (const Obstacle& o : obstacles) {
    Vec<3> n;
    const double d = obstacle_distance<3>(o, x, n);
    const double r = d + o.radius;
    if (r > 0.0) bridson_term(width, d, n, (Eigen::Matrix3d::Identity() - n * n.transpose()) / r, psi, jacobian);
  }
}

#define DFVN_INSTANTIATE_OBSTACLES(N)                                                                   \
  template double obstacle_distance<N>(const Obstacle&, const Vec<N>&, Vec<N>&);                        \
  template bool outside_obstacles<N>(const std::vector<Obstacle>&, const Vec<N>&);                      \
  template void ramp_obstacles<N>(const std::vector<Obstacle>&, double, const Vec<N>&, double&, Vec<N>&);
DFVN_INSTANTIATE_OBSTACLES(2)
DFVN_INSTANTIATE_OBSTACLES(3)
DFVN_INSTANTIATE_OBSTACLES(4)
DFVN_INSTANTIATE_OBSTACLES(5)
DFVN_INSTANTIATE_OBSTACLES(6)
DFVN_INSTANTIATE_OBSTACLES(7)
DFVN_INSTANTIATE_OBSTACLES(8)
#undef DFVN_INSTANTIATE_OBSTACLES

}  // namespace dfvn
