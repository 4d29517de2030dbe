// Animated CNJ (animate/animation.hpp): conformant frames keep every particle inside, drop mode pops,
// moves shrink linearly with the phase step, the result does not depend on the thread count, and
// what reprojection holds while alpha changes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>

#include "dfvn/animate/animation.hpp"
#include "dfvn/field/dfvn_field.hpp"
#include "dfvn/sampling/curl_noise_jitter.hpp"

namespace dfvn {
namespace {

AnimationOptions options_for(int dimension, int grid, DomainMode mode, int frames = 300, double step = 0.05) {
  AnimationOptions o;
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
void expect_conformant(int dimension, int grid, DomainKind domain = DomainKind::cube) {
  AnimationOptions o = options_for(dimension, grid, DomainMode::conformant);
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
  // Retraced steps that no refinement kept inside are rare (they stay at their start for one frame).
  EXPECT_LE(kept, a.particles * o.frames / 1000) << dimension << "D";
}

TEST(Animation, ConformantKeepsEveryParticleInside2D) { expect_conformant(2, 10); }
TEST(Animation, ConformantKeepsEveryParticleInside3D) { expect_conformant(3, 5); }
TEST(Animation, ConformantKeepsEveryParticleInside5D) { expect_conformant(5, 3); }
TEST(Animation, ConformantKeepsEveryParticleInsideTheBall3D) { expect_conformant(3, 6, DomainKind::ball); }

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
TEST(Animation, LargestJumpIsLinearInThePhaseStep) {
  struct Case { int dimension, grid; DomainMode mode; };
  for (const Case& c : {Case{2, 10, DomainMode::conformant}, Case{2, 10, DomainMode::drop}, Case{3, 5, DomainMode::conformant},
                        Case{3, 5, DomainMode::drop}}) {
    const double coarse = largest_jump(animate(options_for(c.dimension, c.grid, c.mode, 61, 0.04), 3, 0));
    const double fine = largest_jump(animate(options_for(c.dimension, c.grid, c.mode, 121, 0.02), 3, 0));
    EXPECT_NEAR(coarse / fine, 2.0, 0.2) << c.dimension << "D " << to_string(c.mode) << ": " << coarse << " vs " << fine;
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

// Frame 0 of a conformant cubic run is CNJ's set of the unit-protocol lattice at phase alpha_0.
TEST(Animation, FrameZeroIsCnj) {
  AnimationOptions o = options_for(3, 6, DomainMode::conformant, 2);
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
  AnimationOptions o = options_for(3, 5, DomainMode::conformant, 6, 0.1);
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
  AnimationOptions fine;
  EXPECT_NO_THROW(fine.validate());
}

}  // namespace
}  // namespace dfvn
