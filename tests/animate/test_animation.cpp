// Animated CNJ (animate/animation.hpp): conformant frames keep every particle inside, drop mode pops,
// moves shrink linearly with the phase step, the result does not depend on the thread count; cnj mode's
// frames are CNJ at their phase and keep CNJ's packing, advect mode's mix it away; the packing columns
// and the move summary against brute force; what reprojection holds while alpha changes (advect).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>

#include "dfvn/animate/animation.hpp"
#include "dfvn/core/quantile.hpp"
#include "dfvn/field/dfvn_field.hpp"
#include "dfvn/sampling/curl_noise_jitter.hpp"

namespace dfvn {
namespace {

AnimationOptions options_for(int dimension, int grid, DomainMode mode, int frames = 300, double step = 0.05,
                             AnimationMode animation = AnimationMode::cnj) {
  AnimationOptions o;
  o.mode = animation;
  o.dimension = dimension;
  o.grid = grid;
  o.frames = frames;
  o.phase_step = step;
  o.cnj.domain_mode = mode;
  return o;
}

double largest_jump(const AnimationResult& a) {
  double j = 0.0;
  for (const FrameStats& s : a.frames) j = std::max(j, s.largest_jump);
  return j;
}

// Every frame of a conformant run: every particle inside (checked on the positions themselves, not
// only on the counters), none entered or left, and the particles do move.
void expect_conformant(int dimension, int grid, DomainKind domain = DomainKind::cube,
                       AnimationMode animation = AnimationMode::cnj) {
  AnimationOptions o = options_for(dimension, grid, DomainMode::conformant, 300, 0.05, animation);
  o.cnj.domain = domain;
  const AnimationResult a = animate(o, 7, 0);
  ASSERT_EQ(a.frames.size(), 300u);
  const Domain box = Domain::unit(domain);
  std::uint64_t kept = 0;
  for (int k = 0; k < o.frames; ++k) {
    const FrameStats& s = a.frames[static_cast<std::size_t>(k)];
    EXPECT_EQ(s.inside, a.particles) << dimension << "D frame " << k;
    EXPECT_EQ(s.entered, 0u) << dimension << "D frame " << k;
    EXPECT_EQ(s.left, 0u) << dimension << "D frame " << k;
    for (std::uint64_t i = 0; i < a.particles; ++i)
      ASSERT_TRUE(box.contains(a.frame(k) + i * dimension, dimension)) << dimension << "D frame " << k << " particle " << i;
    if (k > 0) EXPECT_GT(s.rms_move, 0.1 * a.frame_time) << dimension << "D frame " << k;
    kept += s.kept_at_start;
  }
  // Retraced steps that no refinement kept inside (advect), ends moved into the domain (cnj) are rare.
  std::uint64_t projected = 0;
  for (const FrameStats& s : a.frames) projected += s.projected;
  EXPECT_LE(kept, a.particles * o.frames / 1000) << dimension << "D";
  EXPECT_LE(projected, a.particles * o.frames / 1000) << dimension << "D";
}

TEST(Animation, ConformantKeepsEveryParticleInside2D) { expect_conformant(2, 10); }
TEST(Animation, ConformantKeepsEveryParticleInside3D) { expect_conformant(3, 5); }
TEST(Animation, ConformantKeepsEveryParticleInside5D) { expect_conformant(5, 3); }
TEST(Animation, ConformantKeepsEveryParticleInsideTheBall3D) { expect_conformant(3, 6, DomainKind::ball); }
TEST(Animation, ConformantKeepsEveryParticleInsideTheBall2D) { expect_conformant(2, 10, DomainKind::ball); }
TEST(Animation, AdvectKeepsEveryParticleInside) {
  expect_conformant(2, 10, DomainKind::cube, AnimationMode::advect);
  expect_conformant(3, 5, DomainKind::ball, AnimationMode::advect);
}

TEST(Animation, DropModePops) {
  for (int dimension : {2, 3}) {
    AnimationOptions o = options_for(dimension, dimension == 2 ? 10 : 5, DomainMode::drop);
    const AnimationResult a = animate(o, 7, 0);
    std::uint64_t events = 0;
    for (int k = 0; k < o.frames; ++k) {
      const FrameStats& s = a.frames[static_cast<std::size_t>(k)];
      events += s.entered + s.left;
      std::uint64_t nan_rows = 0;
      for (std::uint64_t i = 0; i < a.particles; ++i) nan_rows += std::isnan(a.frame(k)[i * dimension]);
      EXPECT_EQ(nan_rows, a.particles - s.inside) << "NaN rows are the particles outside";
      if (k > 0) {  // the counters agree with the positions
        std::uint64_t entered = 0, left = 0;
        for (std::uint64_t i = 0; i < a.particles; ++i) {
          const bool before = !std::isnan(a.frame(k - 1)[i * dimension]), now = !std::isnan(a.frame(k)[i * dimension]);
          entered += now && !before;
          left += before && !now;
        }
        EXPECT_EQ(entered, s.entered);
        EXPECT_EQ(left, s.left);
      }
    }
    EXPECT_GT(events, 0u) << dimension << "D drop mode should pop";
    EXPECT_GT(a.popping_per_100_frames(), 1.0);
  }
}

// Continuity: over the same phase range, half the phase step gives half the largest per-frame jump.
// advect: the frame time halves. cnj, drop mode: the trace map along the free field is continuous in
// alpha, so its moves are the derivative times DA. (Not cnj conformant: in Eq. (13)'s transition layer
// some one-step traces' reprojection does not converge, and their ends, continuous but erratic, move by
// a few thousandths of a spacing at any phase step: data/animation_continuity.md.)
TEST(Animation, LargestJumpIsLinearInThePhaseStep) {
  struct Case { int dimension, grid; DomainMode mode; AnimationMode animation; double step; };
  for (const Case& c : {Case{2, 10, DomainMode::conformant, AnimationMode::advect, 0.04},
                        Case{2, 10, DomainMode::drop, AnimationMode::advect, 0.04},
                        Case{3, 5, DomainMode::conformant, AnimationMode::advect, 0.04},
                        Case{3, 5, DomainMode::drop, AnimationMode::advect, 0.04},
                        Case{2, 10, DomainMode::drop, AnimationMode::cnj, 0.04},
                        Case{3, 5, DomainMode::drop, AnimationMode::cnj, 0.04}}) {
    const double coarse = largest_jump(animate(options_for(c.dimension, c.grid, c.mode, 61, c.step, c.animation), 3, 0));
    const double fine = largest_jump(animate(options_for(c.dimension, c.grid, c.mode, 121, c.step / 2, c.animation), 3, 0));
    EXPECT_NEAR(coarse / fine, 2.0, 0.3) << c.dimension << "D " << to_string(c.mode) << " " << to_string(c.animation)
                                         << ": " << coarse << " vs " << fine;
  }
}

// cnj mode: every frame is CNJ of the start lattice at its phase, traced with the continuous policy
// (animation_trace_options), bit for bit except the ends moved into the domain (CNJ retraces those).
TEST(Animation, EveryFrameIsCnjAtItsPhase) {
  for (DomainKind domain : {DomainKind::cube, DomainKind::ball}) {
    AnimationOptions o = options_for(3, 6, DomainMode::conformant, 4, 0.3);
    o.cnj.domain = domain;
    o.start_phase = 0.7;
    const AnimationResult a = animate(o, 5, 0);
    for (int k = 0; k < o.frames; ++k) {
      CnjOptions cnj = o.cnj;
      cnj.phase = o.start_phase + k * o.phase_step;
      cnj.trace = animation_trace_options(o);
      const CnjResult c = curl_noise_jitter(LatticeSpec{3, 6, Protocol::fair}, cnj, 5, 0);
      ASSERT_EQ(c.points.coordinates.size(), a.particles * 3);
      std::uint64_t differ = 0;
      for (std::uint64_t i = 0; i < a.particles; ++i)
        differ += std::memcmp(c.points.point(i), a.frame(k) + 3 * i, 3 * sizeof(double)) != 0;
      EXPECT_EQ(differ, a.frames[k].projected) << to_string(domain) << " frame " << k;
      EXPECT_EQ(c.retraced, a.frames[k].projected) << to_string(domain) << " frame " << k;
    }
  }
}

// The issue that made cnj mode the default: along the flow (advect) the packing decays towards uniform
// random points; as CNJ at every phase it stays (2D 10^2 over 200 frames: cnj's median keeps 0.95-1.14 of
// frame 0's, advect's falls to 0.64, mean 0.75; 3D 5^3: cnj 0.91-1.14, advect mean 0.83).
TEST(Animation, CnjModeKeepsThePackingAdvectMixesItAway) {
  for (int dimension : {2, 3}) {
    const int grid = dimension == 2 ? 10 : 5, frames = dimension == 2 ? 200 : 150;
    const AnimationResult cnj = animate(options_for(dimension, grid, DomainMode::conformant, frames), 7, 0);
    const AnimationResult advect =
        animate(options_for(dimension, grid, DomainMode::conformant, frames, 0.05, AnimationMode::advect), 7, 0);
    const PackingSummary kept = summarise_packing(cnj), mixed = summarise_packing(advect);
    EXPECT_GT(kept.median_min, 0.85) << dimension << "D";
    EXPECT_NEAR(kept.median_mean, 1.0, 0.08) << dimension << "D";
    EXPECT_LT(mixed.median_mean, 0.9) << dimension << "D";
    EXPECT_LT(mixed.median_min, 0.8) << dimension << "D";
  }
}

// frames.csv's packing columns and the move summary against brute force over the positions.
TEST(Animation, PackingColumnsAndMovesAgainstBruteForce) {
  for (DomainMode mode : {DomainMode::conformant, DomainMode::drop}) {
    AnimationOptions o = options_for(2, 6, mode, 12, 0.2);
    o.cnj.domain = DomainKind::ball;
    o.drop_margin = 1;
    const AnimationResult a = animate(o, 13, 0);
    const Domain ball = Domain::unit(DomainKind::ball);
    std::vector<double> moves;
    for (int k = 0; k < o.frames; ++k) {
      const double* x = a.frame(k);
      std::vector<double> nearest;
      for (std::uint64_t i = 0; i < a.particles; ++i) {
        if (std::isnan(x[2 * i])) continue;
        double best = INFINITY;
        for (std::uint64_t j = 0; j < a.particles; ++j)
          if (j != i && !std::isnan(x[2 * j])) best = std::min(best, std::hypot(x[2 * i] - x[2 * j], x[2 * i + 1] - x[2 * j + 1]));
        nearest.push_back(best);
        if (k > 0 && !std::isnan(a.frame(k - 1)[2 * i]))
          moves.push_back(std::hypot(x[2 * i] - a.frame(k - 1)[2 * i], x[2 * i + 1] - a.frame(k - 1)[2 * i + 1]));
      }
      std::sort(nearest.begin(), nearest.end());
      const FrameStats& s = a.frames[static_cast<std::size_t>(k)];
      ASSERT_EQ(nearest.size(), s.inside);
      EXPECT_DOUBLE_EQ(s.nn_min, nearest.front()) << k;
      EXPECT_DOUBLE_EQ(s.nn_q01, quantile_of_sorted(nearest, 0.01)) << k;
      EXPECT_DOUBLE_EQ(s.nn_median, median_of_sorted(nearest)) << k;
      const double mean_spacing = std::sqrt(ball.measure(2) / static_cast<double>(nearest.size()));
      EXPECT_NEAR(s.nn_median_scaled, s.nn_median / mean_spacing, 1e-12) << k;
    }
    std::sort(moves.begin(), moves.end());
    const double unit = std::sqrt(ball.measure(2) / static_cast<double>(a.frames[0].inside));
    EXPECT_NEAR(a.mean_spacing(), unit, 1e-15);
    EXPECT_EQ(a.moves.moves, moves.size());
    EXPECT_NEAR(a.moves.median, median_of_sorted(moves) / unit, 1e-12);
    EXPECT_NEAR(a.moves.p99, quantile_of_sorted(moves, 0.99) / unit, 1e-12);
    EXPECT_NEAR(a.moves.largest, moves.back() / unit, 1e-12);
  }
}

TEST(Animation, ThreadCountDoesNotChangeTheResult) {
  for (DomainMode mode : {DomainMode::conformant, DomainMode::drop}) {
    AnimationOptions o = options_for(3, 5, mode, 40);
    o.lattice = StartLattice::bcc;
    const AnimationResult one = animate(o, 11, 1), two = animate(o, 11, 2), four = animate(o, 11, 4);
    ASSERT_EQ(one.positions.size(), two.positions.size());
    EXPECT_EQ(std::memcmp(one.positions.data(), two.positions.data(), one.positions.size() * sizeof(double)), 0);
    EXPECT_EQ(std::memcmp(one.positions.data(), four.positions.data(), one.positions.size() * sizeof(double)), 0);
    for (std::size_t k = 0; k < one.frames.size(); ++k) {
      EXPECT_EQ(one.frames[k].inside, four.frames[k].inside);
      EXPECT_EQ(one.frames[k].rms_move, four.frames[k].rms_move);
      EXPECT_EQ(one.frames[k].largest_jump, four.frames[k].largest_jump);
    }
  }
}

// Frame 0 of a conformant cubic advect run is CNJ's set (sample's, the guarded policy) of the
// unit-protocol lattice at phase alpha_0.
TEST(Animation, AdvectFrameZeroIsCnj) {
  AnimationOptions o = options_for(3, 6, DomainMode::conformant, 2, 0.05, AnimationMode::advect);
  o.start_phase = 0.7;
  const AnimationResult a = animate(o, 5, 0);
  CnjOptions cnj = o.cnj;
  cnj.phase = 0.7;
  const CnjResult c = curl_noise_jitter(LatticeSpec{3, 6, Protocol::fair}, cnj, 5, 0);
  ASSERT_EQ(c.points.coordinates.size(), a.particles * 3);
  EXPECT_EQ(std::memcmp(c.points.coordinates.data(), a.frame(0), c.points.coordinates.size() * sizeof(double)), 0);
}

TEST(Animation, StartSites) {
  AnimationOptions o = options_for(3, 5, DomainMode::conformant);
  EXPECT_EQ(animation_start_sites(o).size(), 125u * 3);
  o.lattice = StartLattice::bcc;
  const std::vector<double> bcc = animation_start_sites(o);
  ASSERT_EQ(bcc.size(), (125u + 64u) * 3);
  EXPECT_DOUBLE_EQ(bcc[125 * 3], 0.2);  // the first body centre: the corner (1/K, 1/K, 1/K)
  // The BCC lattice's nearest neighbours are sqrt(3)/2 spacings apart (8 of them), closer than the cubic 1.
  const double d = std::sqrt(3.0 * 0.1 * 0.1);  // (0.1, 0.1, 0.1) to (0.2, 0.2, 0.2)
  EXPECT_NEAR(std::hypot(bcc[0] - bcc[125 * 3], bcc[1] - bcc[125 * 3 + 1], bcc[2] - bcc[125 * 3 + 2]), d, 1e-15);
  o.cnj.domain_mode = DomainMode::drop;
  o.drop_margin = 2;
  EXPECT_EQ(animation_start_sites(o).size(), (9u * 9 * 9 + 8u * 8 * 8) * 3);
  o.lattice = StartLattice::cubic;
  o.cnj.domain = DomainKind::ball;
  o.cnj.domain_mode = DomainMode::conformant;
  const std::vector<double> ball = animation_start_sites(o);
  for (std::size_t i = 0; i < ball.size(); i += 3)
    EXPECT_LE(std::hypot(ball[i] - 0.5, ball[i + 1] - 0.5, ball[i + 2] - 0.5), 0.5);
  EXPECT_LT(ball.size(), 125u * 3);
}

// What reprojection holds while alpha changes: within frame k a trace holds the f_i of the field at
// alpha_k at the values they had at its start (x_{k-1}); those values are not the ones x_{k-1} had at
// alpha_{k-1}: the iso-values move with alpha. The boundary function does not: on the cube's boundary
// f_1 = 0 and grad f_1 is normal to it at every alpha.
TEST(Animation, ReprojectionWhileAlphaChanges) {
  AnimationOptions o = options_for(3, 5, DomainMode::conformant, 6, 0.1, AnimationMode::advect);
  const AnimationResult a = animate(o, 9, 0);
  const double h = 1.0 / o.grid;
  const auto field_at = [&](double phase) {
    return DfvnField<3>(9, FieldOptions{o.cnj.noise, o.cnj.frequency / h, FieldConstraint::inside_cube,
                                        std::min(o.cnj.boundary_width * h, 0.25), o.cnj.bound, false, FieldKind::dfvn, phase});
  };
  double held = 0.0, moved = 0.0;
  for (int k = 1; k < o.frames; ++k) {
    const DfvnField<3> now = field_at(a.frames[k].phase), before = field_at(a.frames[k - 1].phase);
    for (std::uint64_t i = 0; i < a.particles; ++i) {
      const Vec<3> start = Eigen::Map<const Vec<3>>(a.frame(k - 1) + 3 * i);
      const Vec<3> end = Eigen::Map<const Vec<3>>(a.frame(k) + 3 * i);
      const FieldSample<3> s0 = now.evaluate(start), s1 = now.evaluate(end), sb = before.evaluate(start);
      for (int f = 0; f < 2; ++f) {
        held = std::max(held, std::abs(s1.value[f] - s0.value[f]));
        moved = std::max(moved, std::abs(s0.value[f] - sb.value[f]));
      }
    }
  }
  EXPECT_LT(held, 1e-10) << "reprojection holds the iso-values of alpha_k within a frame";
  EXPECT_GT(moved, 1e-3) << "the iso-values move with alpha from frame to frame";
  // The boundary: a point on the face x0 = 0 at several phases.
  for (double phase : {0.0, 0.5, 1.7, 3.0}) {
    const FieldSample<3> s = field_at(phase).evaluate(Vec<3>(0.0, 0.37, 0.61));
    EXPECT_NEAR(s.value[0], 0.0, 1e-15) << phase;
    EXPECT_NEAR(s.gradient[0].y(), 0.0, 1e-12) << phase;
    EXPECT_NEAR(s.gradient[0].z(), 0.0, 1e-12) << phase;
    EXPECT_GT(s.gradient[0].x(), 0.0) << phase;
    EXPECT_NEAR(s.velocity.x(), 0.0, 1e-12) << "c is tangent to the boundary at phase " << phase;
  }
}

TEST(Animation, BadOptions) {
  const auto refuses = [](const std::function<void(AnimationOptions&)>& change) {
    AnimationOptions o;
    change(o);
    EXPECT_THROW(o.validate(), std::invalid_argument);
  };
  refuses([](AnimationOptions& o) { o.phase_step = std::nan(""); });
  refuses([](AnimationOptions& o) { o.phase_step = INFINITY; });
  refuses([](AnimationOptions& o) { o.phase_step = 0.0; });
  refuses([](AnimationOptions& o) { o.phase_step = 7.0; });
  refuses([](AnimationOptions& o) { o.start_phase = std::nan(""); });
  refuses([](AnimationOptions& o) { o.frames = 0; });
  refuses([](AnimationOptions& o) { o.frames = AnimationOptions::kMaxFrames + 1; });
  refuses([](AnimationOptions& o) { o.dimension = 6; o.grid = 20; });  // 64 Mi particles x 300 frames
  refuses([](AnimationOptions& o) { o.cnj.domain = DomainKind::torus; });
  refuses([](AnimationOptions& o) { o.drop_margin = -1; });
  refuses([](AnimationOptions& o) { o.mode = static_cast<AnimationMode>(7); });
  EXPECT_THROW(parse_animation_mode("flow"), std::invalid_argument);
  EXPECT_EQ(parse_animation_mode(to_string(AnimationMode::advect)), AnimationMode::advect);
  AnimationOptions fine;
  EXPECT_NO_THROW(fine.validate());
}

}  // namespace
}  // namespace dfvn
