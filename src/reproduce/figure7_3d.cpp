// Figure 7's two constructions (Section 5.4) side by side, in 2D and in 3D (reproduce/surface_figures.hpp):
//   eq13:  the library's, f_1 (f_2 in the paper's 3D wording) replaced by Eq. 13's blend of the signed distance
//          d and the noise, c = cross(grad f_i), traced with Gauss-Newton reprojection;
//   paper: the paper's own words, "the first vector is a 3D noise gradient ... the second vector is interpolated
//          from (0,0,1) inside to the normal of the contour" (2D) and "from another noise gradient inside to the
//          surface normal" (3D): c = grad F x v with v = (1 - alpha) n + alpha e_z (2D, on the plane z = 0, F
//          3D noise) or v = (1 - alpha) G n + alpha grad f_2 (3D), alpha = S(d / w) as Eq. 13's; v is not a
//          gradient in the transition zone, so c is not divergence-free there and no function holds the
//          streamlines: traced with RK4 alone.
// Both make c tangent to the circle (sphere) on it and to every circle (sphere) outside.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <numbers>
#include <random>

#include <Eigen/Geometry>
#include <omp.h>

#include "dfvn/core/parallel.hpp"
#include "dfvn/core/stopwatch.hpp"
#include "dfvn/field/constraint.hpp"
#include "dfvn/field/dfvn_field.hpp"
#include "dfvn/integrate/trace.hpp"
#include "dfvn/reproduce/surface_figures.hpp"

namespace dfvn {

namespace {

constexpr double kRadius = 0.5;  // the disc's and the ball's radius, centre (1/2, ...)

// The paper's 2D construction on the plane z = 0: F the first function of the free 3D field (gradient RMS G_3
// per function, G_3^2 = 3 / sqrt(6)), scaled by 1 / sqrt(2/3 G_3^2) so that its in-plane part, the field inside
// the disc, has RMS 1 as every field of the library.
Vec<2> paper_velocity_2d(const DfvnField<3>& noise, double width, const Vec<2>& p) {
  static const double kScale = 1.0 / std::sqrt(2.0 / 3.0 * std::pow(noise_gradient_rms(3), 2));
  const Vec<3> gradient = noise.evaluate_functions(Vec<3>(p[0], p[1], 0.0)).gradient[0];
  Vec<2> n;
  const double d = ball_boundary_function<2>(p, n);
  const double alpha = smoothstep_c2(d / width, nullptr);
  const Vec<3> v((1.0 - alpha) * n[0], (1.0 - alpha) * n[1], alpha);
  const Vec<3> c = gradient.cross(v);
  return kScale * Vec<2>(c[0], c[1]);
}

// The paper's 3D construction: grad f_1 x ((1 - alpha) G n + alpha grad f_2) of the free 3D field.
Vec<3> paper_velocity_3d(const DfvnField<3>& noise, double width, const Vec<3>& x) {
  const FieldSample<3> s = noise.evaluate_functions(x);
  Vec<3> n;
  const double d = ball_boundary_function<3>(x, n);
  const double alpha = smoothstep_c2(d / width, nullptr);
  return s.gradient[0].cross(Vec<3>((1.0 - alpha) * noise_gradient_rms(3) * n + alpha * s.gradient[1]));
}

template <int N, typename Velocity>
Vec<N> rk4(const Velocity& velocity, Vec<N> x, double time, int steps) {
  const double h = time / steps;
  for (int k = 0; k < steps; ++k) {
    const Vec<N> k1 = velocity(x), k2 = velocity(Vec<N>(x + 0.5 * h * k1)), k3 = velocity(Vec<N>(x + 0.5 * h * k2)),
                 k4 = velocity(Vec<N>(x + h * k3));
    x += (h / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
  }
  return x;
}

// |div c| / RMS |c| over random points of the transition zone d in (0, w) (central differences, h = 1e-5):
// the median and the 95th percentile.
template <int N, typename Velocity>
void zone_divergence(const Velocity& velocity, double width, std::uint64_t seed, double& median, double& p95) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g;
  std::uniform_real_distribution<double> u(0.0, 1.0);
  constexpr int kPoints = 2000;
  constexpr double h = 1e-5;
  std::vector<double> div;
  double sum2 = 0.0;
  for (int k = 0; k < kPoints; ++k) {
    Vec<N> dir;
    for (int j = 0; j < N; ++j) dir[j] = g(rng);
    dir.normalize();
    const Vec<N> x = Vec<N>::Constant(0.5) + (kRadius - width * u(rng)) * dir;
    sum2 += velocity(x).squaredNorm();
    double d = 0.0;
    for (int j = 0; j < N; ++j) {
      Vec<N> step = Vec<N>::Zero();
      step[j] = h;
      d += (velocity(Vec<N>(x + step))[j] - velocity(Vec<N>(x - step))[j]) / (2.0 * h);
    }
    div.push_back(std::abs(d));
  }
  const double rms = std::sqrt(sum2 / kPoints);
  std::sort(div.begin(), div.end());
  median = div[kPoints / 2] / rms;
  p95 = div[kPoints * 95 / 100] / rms;
}

// The 3D texture: a checker of cosines, 3 cycles per unit length along each axis, with a dark shell of 0.03 inside
// the sphere (the paper's blue outline).
double texture_3d(const Vec<3>& x) {
  const double r = (x - Vec<3>::Constant(0.5)).norm();
  if (r >= kRadius - 0.03 && r <= kRadius) return 0.0;
  const double k = 2.0 * std::numbers::pi * 3.0;
  return 0.5 + 0.45 * std::cos(k * x[0]) * std::cos(k * x[1]) * std::cos(k * x[2]);
}

// The start point of pixel (col, row) of central slice `plane` (0: z = 1/2, 1: y = 1/2, 2: x = 1/2); row 0 at the top.
Vec<3> slice_point(int plane, int col, int row, int side) {
  const double a = (col + 0.5) / side, b = 1.0 - (row + 0.5) / side;
  if (plane == 0) return {a, b, 0.5};
  if (plane == 1) return {a, 0.5, b};
  return {0.5, a, b};
}

// Statistics of traces from starts to ends about the centre: inside/left, largest end radius of an inside start,
// largest radius drift of an outside start.
template <int N>
void confinement(const std::vector<Vec<N>>& starts, const std::vector<Vec<N>>& ends, Figure7ConstructionRow& row) {
  const Vec<N> centre = Vec<N>::Constant(0.5);
  for (std::size_t i = 0; i < starts.size(); ++i) {
    const double r0 = (starts[i] - centre).norm(), r1 = (ends[i] - centre).norm();
    if (r0 <= kRadius) {
      ++row.inside;
      row.left += r1 > kRadius;
      row.max_end_radius_inside = std::max(row.max_end_radius_inside, r1);
    } else {
      row.max_radius_drift_outside = std::max(row.max_radius_drift_outside, std::abs(r1 - r0));
    }
  }
}

}  // namespace

void run_figure7_constructions(const Figure7Config& config, Figure7Result& result, const FractionProgress& progress) {
  const int threads = resolve_threads(config.threads);
  const double w = config.transition_width;
  const DfvnField<3> free3(config.seed, FieldOptions{config.noise, config.frequency});
  FieldOptions ball{config.noise, config.frequency};
  ball.constraint = FieldConstraint::inside_ball;
  ball.transition_width = w;
  ball.bound = Bound::eq13;
  const DfvnField<3> eq13_3d(config.seed, ball);
  FieldOptions disc = ball;
  disc.constraint = FieldConstraint::inside_ball;
  const DfvnField<2> eq13_2d(config.seed, disc);
  TraceOptions trace;
  trace.integrator = Integrator::rk4;
  trace.steps = config.steps;
  trace.reprojection = Reprojection::gauss_newton;
  const Tracer<3> tracer3(eq13_3d, trace);
  auto paper2 = [&](const Vec<2>& p) { return paper_velocity_2d(free3, w, p); };
  auto paper3 = [&](const Vec<3>& x) { return paper_velocity_3d(free3, w, x); };

  // 2D: the paper's construction over the same pixels as the Eq. 13 run above (whose rows come from its result).
  {
    Stopwatch watch;
    const int side = config.width;
    const std::size_t pixels = static_cast<std::size_t>(side) * side;
    std::vector<Vec<2>> starts(pixels), ends(pixels);
    result.warped_paper = FloatImage{side, side, std::vector<float>(pixels)};
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
    for (int row = 0; row < side; ++row)
      for (int col = 0; col < side; ++col) {
        const std::size_t i = static_cast<std::size_t>(row) * side + col;
        starts[i] = Vec<2>((col + 0.5) / side, (row + 0.5) / side);
        ends[i] = rk4<2>(paper2, starts[i], config.time, config.steps);
        const double r = (ends[i] - Vec<2>(0.5, 0.5)).norm();
        result.warped_paper.values[i] = static_cast<float>(0.5 + 0.5 * std::cos(2.0 * std::numbers::pi * config.rings * r / kRadius));
      }
    Figure7ConstructionRow eq13{2, "eq13"}, paper{2, "paper"};
    eq13.inside = result.inside, eq13.left = result.left, eq13.max_end_radius_inside = result.max_radius_inside_end;
    eq13.max_radius_drift_outside = result.max_radius_drift_outside;
    eq13.field_evaluations = result.field_evaluations;
    eq13.seconds = result.seconds;
    zone_divergence<2>([&](const Vec<2>& p) { return eq13_2d.velocity(p); }, w, config.seed, eq13.zone_divergence_median,
                       eq13.zone_divergence_p95);
    confinement<2>(starts, ends, paper);
    paper.field_evaluations = static_cast<std::int64_t>(pixels) * 4 * config.steps;
    paper.seconds = watch.seconds();
    zone_divergence<2>(paper2, w, config.seed, paper.zone_divergence_median, paper.zone_divergence_p95);
    result.constructions = {eq13, paper};
  }
  if (progress) progress(0.2);

  // 3D: three central slices of the ball, the source texture and each construction's warp.
  const int side = config.width3d;
  const std::size_t per_slice = static_cast<std::size_t>(side) * side;
  result.slices_3d.assign(9, FloatImage{side, side, std::vector<float>(per_slice)});
  std::vector<Vec<3>> starts(3 * per_slice);
  for (int plane = 0; plane < 3; ++plane)
    for (int row = 0; row < side; ++row)
      for (int col = 0; col < side; ++col) {
        const std::size_t i = plane * per_slice + static_cast<std::size_t>(row) * side + col;
        starts[i] = slice_point(plane, col, row, side);
        result.slices_3d[plane].values[i - plane * per_slice] = static_cast<float>(texture_3d(starts[i]));
      }
  for (int c = 0; c < 2; ++c) {
    Stopwatch watch;
    std::vector<Vec<3>> ends(starts.size());
    std::vector<TraceStats> stats(static_cast<std::size_t>(threads));
    std::atomic<int> done{0};
    const int total = static_cast<int>(starts.size());
#pragma omp parallel for schedule(dynamic, 64) num_threads(threads)
    for (int i = 0; i < total; ++i) {
      const int d = done.fetch_add(1, std::memory_order_relaxed);
      if (progress && omp_get_thread_num() == 0) progress(0.2 + 0.4 * c + 0.4 * d / total);
      ends[i] = c == 0 ? tracer3.trace(starts[i], config.time, &stats[static_cast<std::size_t>(omp_get_thread_num())])
                       : rk4<3>(paper3, starts[i], config.time, config.steps);
      const std::size_t plane = static_cast<std::size_t>(i) / per_slice;
      result.slices_3d[3 * (c + 1) + plane].values[static_cast<std::size_t>(i) - plane * per_slice] =
          static_cast<float>(texture_3d(ends[i]));
    }
    Figure7ConstructionRow row{3, c == 0 ? "eq13" : "paper"};
    confinement<3>(starts, ends, row);
    for (const TraceStats& s : stats) row.field_evaluations += s.field_evaluations;
    if (c == 1) row.field_evaluations = static_cast<std::int64_t>(total) * 4 * config.steps;
    row.seconds = watch.seconds();
    if (c == 0)
      zone_divergence<3>([&](const Vec<3>& x) { return eq13_3d.velocity(x); }, w, config.seed, row.zone_divergence_median,
                         row.zone_divergence_p95);
    else
      zone_divergence<3>(paper3, w, config.seed, row.zone_divergence_median, row.zone_divergence_p95);
    result.constructions.push_back(row);
  }
  if (progress) progress(1.0);
}

}  // namespace dfvn
