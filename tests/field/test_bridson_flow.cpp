// Bridson's toolbox on the field (field/bridson_flow.hpp): the parsers and refusals; the analytic
// Jacobians of the body and vortex potentials, the amplitude and the viscous factor against central
// differences; the divergence of every flow field (DFVN in 2D-6D, 2D and 3D curl noise with octaves,
// amplitude, bodies, vortices and viscous solids); the boundary conditions (c . n = 0 on static walls and
// obstacles, the rigid motion's normal component on a moving body, c = 0 on viscous walls and c = the
// rigid motion on a viscous body); RMS |c| = 1 with octaves; the octaves' energies (nested fields of
// curl noise differ by exactly the added octave, energy a_o^2); one octave and no flow is the old field.
#include "dfvn/field/bridson_flow.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>
#include <stdexcept>
#include <vector>

#include <Eigen/Geometry>

#include "dfvn/field/dfvn_field.hpp"
#include "test_support.hpp"

namespace dfvn {
namespace {

constexpr std::uint64_t kSeed = 5;
constexpr double kWidth = 0.05;

TEST(BridsonFlow, ParseAndRefuse) {
  const RigidBody b = parse_body("sphere:0.5,0.5,0.5,0.1,1,0,0,0,0,2");
  EXPECT_EQ(b.radius, 0.1);
  EXPECT_EQ(b.velocity, Vec<3>(1, 0, 0));
  EXPECT_EQ(b.angular, Vec<3>(0, 0, 2));
  EXPECT_EQ(to_string(b), "sphere:0.5,0.5,0.5,0.1,1,0,0,0,0,2");
  for (const char* bad : {"sphere:0.5,0.5,0.5,0.1,1,0,0,0,0", "box:0.5,0.5,0.5,0.1,1,0,0,0,0,2",
                          "sphere:0.5,0.5,0.5,0,1,0,0,0,0,2", "sphere:0.5,0.5,0.5,0.1,nan,0,0,0,0,2", "sphere:"})
    EXPECT_THROW(parse_body(bad), std::invalid_argument) << bad;
  const Vortex ring = parse_vortex("ring:0.5,0.5,0.2,0,0,2,0.15,3,0.05");
  EXPECT_EQ(ring.kind, Vortex::Kind::ring);
  EXPECT_EQ(ring.normal, Vec<3>(0, 0, 1));  // normalised
  EXPECT_EQ(parse_vortex("particle:0.5,0.5,0.5,0,1,0,0.1").kind, Vortex::Kind::particle);
  for (const char* bad : {"ring:0.5,0.5,0.2,0,0,0,0.15,3,0.05", "ring:0.5,0.5,0.2,0,0,1,0.05,3,0.05",
                          "particle:0.5,0.5,0.5,0,1,0,0", "particle:0.5,0.5,0.5,0,1,0", "line:0,0,0,1,1,1,0.1"})
    EXPECT_THROW(parse_vortex(bad), std::invalid_argument) << bad;
  EXPECT_EQ(parse_amplitude("height:0.2,0.8").kind, AmplitudeShape::Kind::height);
  for (const char* bad : {"height:0.2,0.2", "obstacles:0", "obstacles:-1", "constant:", "constant:1,2", "wake:1"})
    EXPECT_THROW(parse_amplitude(bad), std::invalid_argument) << bad;

  FieldOptions dfvn{NoiseBasis::turning_bands, 2.0, FieldConstraint::inside_cube, kWidth, Bound::ramp};
  dfvn.flow.bodies = {b};
  EXPECT_THROW(DfvnField<3>(kSeed, dfvn), std::invalid_argument);  // bodies need curl noise
  FieldOptions curl = dfvn;
  curl.kind = FieldKind::curl;
  EXPECT_NO_THROW(DfvnField<3>(kSeed, curl));
  curl.flow.bodies = {parse_body("sphere:0.5,0.5,0.25,0.1,1,0,0,0,0,2")};  // blend region in the wall's zone
  EXPECT_THROW(DfvnField<3>(kSeed, curl), std::invalid_argument);
  FieldOptions free_viscous{NoiseBasis::turning_bands, 2.0};
  free_viscous.flow.viscous = true;
  EXPECT_THROW(DfvnField<2>(kSeed, free_viscous), std::invalid_argument);
  FieldOptions torus{NoiseBasis::turning_bands, 2.0};
  torus.periodic = true;
  torus.flow.amplitude = {parse_amplitude("constant:2")};
  EXPECT_THROW(DfvnField<2>(kSeed, torus), std::invalid_argument);
  torus.flow.amplitude = {};
  torus.flow.octaves = 3;
  EXPECT_NO_THROW(DfvnField<2>(kSeed, torus));
  torus.flow.octaves = kMaxOctaves + 1;
  EXPECT_THROW(DfvnField<2>(kSeed, torus), std::invalid_argument);
  FieldOptions lonely{NoiseBasis::turning_bands, 2.0, FieldConstraint::inside_cube, kWidth, Bound::ramp};
  lonely.flow.amplitude = {parse_amplitude("obstacles:0.2")};  // no obstacle to measure from
  EXPECT_THROW(DfvnField<2>(kSeed, lonely), std::invalid_argument);
}

TEST(BridsonFlow, OctaveWeights) {
  const std::vector<double> w = octave_weights(4, kKolmogorovOctaveGain);
  double sum = 0.0;
  for (double a : w) sum += a * a;
  EXPECT_NEAR(sum, 1.0, 1e-15);
  for (int o = 1; o < 4; ++o) EXPECT_NEAR(w[o] / w[o - 1], std::pow(2.0, -1.0 / 3.0), 1e-15);
  EXPECT_EQ(octave_weights(1, 0.5), std::vector<double>{1.0});
}

// The Jacobian rows of a 3D potential against central differences of its values.
template <typename Potential>
void expect_jacobian(const Potential& potential, const Vec<3>& x, double tolerance) {
  std::array<double, 3> psi{0, 0, 0};
  std::array<Vec<3>, 3> rows{Vec<3>::Zero(), Vec<3>::Zero(), Vec<3>::Zero()};
  potential(x, psi, rows);
  constexpr double h = 1e-6;
  for (int j = 0; j < 3; ++j) {
    Vec<3> step = Vec<3>::Zero();
    step[j] = h;
    std::array<double, 3> plus{0, 0, 0}, minus{0, 0, 0};
    std::array<Vec<3>, 3> unused{Vec<3>::Zero(), Vec<3>::Zero(), Vec<3>::Zero()};
    potential(Vec<3>(x + step), plus, unused);
    potential(Vec<3>(x - step), minus, unused);
    for (int i = 0; i < 3; ++i)
      EXPECT_NEAR(rows[i][j], (plus[i] - minus[i]) / (2 * h), tolerance) << "row " << i << " column " << j << " at " << x.transpose();
  }
}

TEST(BridsonFlow, PotentialJacobians) {
  const RigidBody body = parse_body("sphere:0.5,0.5,0.5,0.1,0.3,-0.2,0.5,1,0,2");
  const Vortex particle = parse_vortex("particle:0.4,0.5,0.6,0,1,0.5,0.2");
  const Vortex ring = parse_vortex("ring:0.5,0.5,0.2,0.2,0,1,0.25,3,0.1");
  std::mt19937_64 rng(kSeed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int k = 0; k < 400; ++k) {
    const Vec<3> x(u(rng), u(rng), u(rng));
    expect_jacobian([&](const Vec<3>& y, auto& p, auto& j) { add_body_potential(body, y, p, j); }, x, 1e-7);
    expect_jacobian([&](const Vec<3>& y, auto& p, auto& j) { add_vortex_potential(particle, y, p, j); }, x, 1e-7);
    expect_jacobian([&](const Vec<3>& y, auto& p, auto& j) { add_vortex_potential(ring, y, p, j); }, x, 1e-6);
  }
  // Near the particle's centre c -> w x r; inside the ring the flow runs along +N for W > 0.
  std::array<double, 3> psi{0, 0, 0};
  std::array<Vec<3>, 3> rows{Vec<3>::Zero(), Vec<3>::Zero(), Vec<3>::Zero()};
  const Vec<3> r(1e-4, -2e-4, 1e-4);
  add_vortex_potential(particle, Vec<3>(particle.centre + r), psi, rows);
  const Vec<3> curl(rows[2][1] - rows[1][2], rows[0][2] - rows[2][0], rows[1][0] - rows[0][1]);
  // g'/rho = -1 - 15 s + O(s^2) at s = |r| / R (the fall-off's S starts as 10 s^3): c = w x r (1 + 15 s + ...).
  const double s = r.norm() / particle.core_radius;
  EXPECT_LT((curl - particle.omega.cross(r)).norm(), 16.0 * s * particle.omega.cross(r).norm());
  psi = {0, 0, 0};
  rows = {Vec<3>::Zero(), Vec<3>::Zero(), Vec<3>::Zero()};
  const Vortex flat = parse_vortex("ring:0.5,0.5,0.2,0,0,1,0.25,3,0.1");
  add_vortex_potential(flat, Vec<3>(0.5 + 0.2, 0.5, 0.2), psi, rows);  // 0.05 inside the core line
  EXPECT_GT(rows[1][0] - rows[0][1], 0.05);  // c_z > 0
}

template <int N>
void expect_gradient(const std::function<double(const Vec<N>&, Vec<N>&)>& f, const Vec<N>& x, double tolerance) {
  Vec<N> g;
  f(x, g);
  constexpr double h = 1e-6;
  for (int j = 0; j < N; ++j) {
    Vec<N> step = Vec<N>::Zero();
    step[j] = h;
    Vec<N> unused;
    EXPECT_NEAR(g[j], (f(x + step, unused) - f(x - step, unused)) / (2 * h), tolerance) << j << " at " << x.transpose();
  }
}

TEST(BridsonFlow, AmplitudeAndViscousGradients) {
  const std::vector<Obstacle> solids{parse_obstacle("sphere:0.3,0.4,0.6,0.1"), parse_obstacle("sphere:0.7,0.6,0.4,0.12")};
  const std::vector<AmplitudeShape> shapes{parse_amplitude("constant:1.5"), parse_amplitude("height:0.7,0.2"),
                                           parse_amplitude("obstacles:0.3")};
  std::mt19937_64 rng(kSeed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int k = 0; k < 300; ++k) {
    const Vec<3> x(u(rng), u(rng), u(rng));
    expect_gradient<3>([&](const Vec<3>& y, Vec<3>& g) { return flow_amplitude<3>(shapes, solids, y, g); }, x, 1e-7);
    for (FieldConstraint domain : {FieldConstraint::inside_cube, FieldConstraint::inside_ball})
      expect_gradient<3>([&](const Vec<3>& y, Vec<3>& g) { return viscous_factor<3>(domain, solids, 0.1, y, g); }, x, 1e-6);
  }
}

// Median |div c| / RMS |c| by central differences on random points of the unit cube, and RMS |c|.
template <int N>
void divergence(const DfvnField<N>& field, int points, double& median_ratio, double& rms) {
  std::mt19937_64 rng(kSeed + N);
  std::uniform_real_distribution<double> u(0.01, 0.99);
  std::vector<double> div;
  double sum2 = 0.0;
  constexpr double h = 1e-5;
  for (int k = 0; k < points; ++k) {
    Vec<N> x;
    for (int j = 0; j < N; ++j) x[j] = u(rng);
    sum2 += field.velocity(x).squaredNorm();
    double d = 0.0;
    for (int j = 0; j < N; ++j) {
      Vec<N> step = Vec<N>::Zero();
      step[j] = h;
      d += (field.velocity(x + step)[j] - field.velocity(x - step)[j]) / (2 * h);
    }
    div.push_back(std::abs(d));
  }
  rms = std::sqrt(sum2 / points);
  std::nth_element(div.begin(), div.begin() + points / 2, div.end());
  median_ratio = div[points / 2] / rms;
}

template <int N>
FieldOptions dfvn_flow(Bound bound, bool viscous) {
  FieldOptions o{NoiseBasis::turning_bands, 1.5, FieldConstraint::inside_cube, kWidth, bound};
  o.flow.octaves = 3;
  o.flow.viscous = viscous;
  std::vector<double> centre(N, 0.5);
  o.obstacles = {Obstacle{centre, 0.15}};
  o.flow.amplitude = {parse_amplitude("obstacles:0.6"), parse_amplitude("height:-0.5,1")};
  return o;
}

template <typename T>
class FlowDivergence : public ::testing::Test {};
using FlowDimensions = ::testing::Types<testing::Dim<2>, testing::Dim<3>, testing::Dim<4>, testing::Dim<6>>;
TYPED_TEST_SUITE(FlowDivergence, FlowDimensions);

TYPED_TEST(FlowDivergence, DfvnWithEveryTermIsDivergenceFree) {
  constexpr int N = TypeParam::value;
  for (Bound bound : {Bound::eq13, Bound::ramp})
    for (bool viscous : {false, true}) {
      const DfvnField<N> field(kSeed, dfvn_flow<N>(bound, viscous));
      double median = 0.0, rms = 0.0;
      divergence<N>(field, static_cast<int>(testing::sanitizer_scaled(400, 4)), median, rms);
      EXPECT_GT(rms, 0.05);
      EXPECT_LT(median, 1e-6) << to_string(bound) << (viscous ? " viscous" : "");
    }
}

FieldOptions curl_flow(bool viscous) {
  FieldOptions o{NoiseBasis::turning_bands, 1.5, FieldConstraint::inside_cube, kWidth, Bound::ramp};
  o.kind = FieldKind::curl;
  o.flow.octaves = 3;
  o.flow.viscous = viscous;
  o.obstacles = {parse_obstacle("sphere:0.25,0.75,0.5,0.08")};
  o.flow.bodies = {parse_body("sphere:0.55,0.45,0.55,0.1,0.3,0,0.5,0,0,2")};
  o.flow.vortices = {parse_vortex("ring:0.5,0.5,0.2,0,0,1,0.15,3,0.05"), parse_vortex("particle:0.8,0.2,0.8,0,1,0,0.1")};
  o.flow.amplitude = {parse_amplitude("obstacles:0.4")};
  return o;
}

TEST(BridsonFlow, CurlWithEveryTermIsDivergenceFree) {
  for (bool viscous : {false, true}) {
    const DfvnField<3> field(kSeed, curl_flow(viscous));
    double median = 0.0, rms = 0.0;
    divergence<3>(field, static_cast<int>(testing::sanitizer_scaled(1000, 4)), median, rms);
    EXPECT_GT(rms, 0.05);
    EXPECT_LT(median, 1e-7) << (viscous ? "viscous" : "inviscid");
  }
}

// Random unit vectors.
std::vector<Vec<3>> directions(int count) {
  std::mt19937_64 rng(kSeed);
  std::normal_distribution<double> g;
  std::vector<Vec<3>> out;
  for (int k = 0; k < count; ++k) {
    const Vec<3> v(g(rng), g(rng), g(rng));
    out.push_back(v / v.norm());
  }
  return out;
}

TEST(BridsonFlow, BoundaryConditions) {
  for (bool viscous : {false, true}) {
    FieldOptions options = curl_flow(viscous);
    options.flow.amplitude = {};  // the noise at full strength on every solid
    const DfvnField<3> field(kSeed, options);
    const RigidBody& body = options.flow.bodies[0];
    const Obstacle& obstacle = options.obstacles[0];
    const Vec<3> obstacle_centre(obstacle.centre[0], obstacle.centre[1], obstacle.centre[2]);
    double body_normal = 0.0, body_slip = 0.0, obstacle_normal = 0.0, obstacle_speed = 0.0, wall_normal = 0.0,
           wall_speed = 0.0, speed = 0.0;
    for (const Vec<3>& n : directions(500)) {
      const Vec<3> x = body.centre + body.radius * n;
      const Vec<3> relative = field.velocity(x) - body.velocity - body.angular.cross(x - body.centre);
      body_normal = std::max(body_normal, std::abs(relative.dot(n)));
      body_slip = std::max(body_slip, relative.norm());
      const Vec<3> on_obstacle = field.velocity(Vec<3>(obstacle_centre + obstacle.radius * n));
      obstacle_normal = std::max(obstacle_normal, std::abs(on_obstacle.dot(n)));
      obstacle_speed = std::max(obstacle_speed, on_obstacle.norm());
      // A point of the face x = 0 (y, z from the direction, inside the face).
      const Vec<3> on_wall = field.velocity(Vec<3>(0.0, 0.5 + 0.45 * n[1], 0.5 + 0.45 * n[2]));
      wall_normal = std::max(wall_normal, std::abs(on_wall[0]));
      wall_speed = std::max(wall_speed, on_wall.norm());
      speed = std::max(speed, field.velocity(Vec<3>(0.5 + 0.3 * n[0], 0.5 + 0.3 * n[1], 0.5 + 0.3 * n[2])).norm());
    }
    SCOPED_TRACE(viscous ? "viscous" : "inviscid");
    EXPECT_LT(body_normal, 1e-8);
    EXPECT_LT(obstacle_normal, 1e-8);
    EXPECT_LT(wall_normal, 1e-12);
    EXPECT_GT(speed, 0.1);
    if (viscous) {  // no-slip: c is the body's rigid motion on it, and 0 on every static solid
      EXPECT_LT(body_slip, 1e-10);
      EXPECT_LT(obstacle_speed, 1e-12);
      EXPECT_LT(wall_speed, 1e-12);
    } else {  // slip: tangential motion remains
      EXPECT_GT(body_slip, 0.01);
      EXPECT_GT(obstacle_speed, 0.01);
      EXPECT_GT(wall_speed, 0.01);
    }
  }
  // DFVN with viscous walls: c = 0 on the cube's faces and the obstacle.
  const DfvnField<3> dfvn(kSeed, dfvn_flow<3>(Bound::eq13, true));
  for (const Vec<3>& n : directions(200)) {
    EXPECT_LT(dfvn.velocity(Vec<3>(0.5 + 0.45 * n[0], 1.0, 0.5 + 0.45 * n[2])).norm(), 1e-12);
    EXPECT_LT(dfvn.velocity(Vec<3>(Vec<3>::Constant(0.5) + 0.15 * n)).norm(), 1e-10);
  }
}

// RMS |c| over 2 10^4 random points of a box of 20 cycles, free field.
template <int N>
double free_rms(const FieldOptions& options) {
  const DfvnField<N> field(kSeed, options);
  std::mt19937_64 rng(kSeed);
  std::uniform_real_distribution<double> u(0.0, 20.0);
  const int points = static_cast<int>(testing::sanitizer_scaled(20000, 4));
  double sum = 0.0;
  for (int k = 0; k < points; ++k) {
    Vec<N> x;
    for (int j = 0; j < N; ++j) x[j] = u(rng);
    sum += field.velocity(x).squaredNorm();
  }
  return std::sqrt(sum / points);
}

TEST(BridsonFlow, OctavesKeepRmsOne) {
  for (FieldKind kind : {FieldKind::dfvn, FieldKind::curl}) {
    FieldOptions o{NoiseBasis::turning_bands, 1.0};
    o.kind = kind;
    o.flow.octaves = 4;
    EXPECT_NEAR(free_rms<2>(o), 1.0, 0.05) << to_string(kind);
    EXPECT_NEAR(free_rms<3>(o), 1.0, 0.06) << to_string(kind);
  }
  FieldOptions o{NoiseBasis::turning_bands, 1.0};
  o.flow.octaves = 3;
  o.flow.octave_gain = 0.5;
  EXPECT_NEAR(free_rms<5>(o), 1.0, 0.06);
}

// Curl noise is linear in its octaves: with K octaves (weights a_o^(K) = g^o / n_K) the fields of K and K+1
// octaves satisfy n_{K+1} c_{K+1} - n_K c_K = g^K c^(K), octave K's own field (RMS 1): its energy, measured
// from the two fields alone, is g^(2K) / n_{K+1}^2 of the K+1-octave field's, the weight a_K squared.
TEST(BridsonFlow, CurlOctaveEnergiesFollowTheGain) {
  const double gain = kKolmogorovOctaveGain;
  std::vector<DfvnField<3>> fields;
  for (int k = 1; k <= 4; ++k) {
    FieldOptions o{NoiseBasis::turning_bands, 1.0};
    o.kind = FieldKind::curl;
    o.flow.octaves = k;
    fields.emplace_back(kSeed, o);
  }
  auto norm = [&](int k) {
    double s = 0.0;
    for (int o = 0; o < k; ++o) s += std::pow(gain, 2 * o);
    return std::sqrt(s);
  };
  std::mt19937_64 rng(kSeed);
  std::uniform_real_distribution<double> u(0.0, 20.0);
  const int points = static_cast<int>(testing::sanitizer_scaled(20000, 4));
  std::vector<double> energy(4, 0.0);
  for (int p = 0; p < points; ++p) {
    const Vec<3> x(u(rng), u(rng), u(rng));
    Vec<3> previous = Vec<3>::Zero();
    for (int k = 1; k <= 4; ++k) {
      const Vec<3> scaled = norm(k) * fields[k - 1].velocity(x);
      energy[k - 1] += (scaled - previous).squaredNorm();
      previous = scaled;
    }
  }
  for (int o = 0; o < 4; ++o) EXPECT_NEAR(energy[o] / points / std::pow(gain, 2 * o), 1.0, 0.08) << "octave " << o;
}

TEST(BridsonFlow, OneOctaveWithoutFlowIsTheOldField) {
  FieldOptions o{NoiseBasis::turning_bands, 1.5, FieldConstraint::inside_cube, kWidth, Bound::ramp};
  o.kind = FieldKind::curl;
  FieldOptions same = o;
  same.flow.octave_gain = 0.3;  // the gain of a single octave is unused: no flow
  EXPECT_FALSE(same.flow.active());
  const DfvnField<3> a(kSeed, o), b(kSeed, same);
  const Vec<3> x(0.3, 0.6, 0.2);
  EXPECT_EQ(a.velocity(x), b.velocity(x));
  // One octave through the flow path (a constant amplitude of 1) gives the same field up to rounding.
  FieldOptions unit = o;
  unit.flow.amplitude = {parse_amplitude("constant:1")};
  const DfvnField<3> c(kSeed, unit);
  EXPECT_LT((a.velocity(x) - c.velocity(x)).norm(), 1e-14 * (1.0 + a.velocity(x).norm()));
}

}  // namespace
}  // namespace dfvn
