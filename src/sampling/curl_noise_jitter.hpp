// Curl noise jittering (CNJ, Section 5.1): every lattice point is traced along the DFVN field for a
// short time (Algorithm 1). The field has no sources or sinks, so points move without clustering.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "integrate/trace.hpp"
#include "sampling/lattice.hpp"
#include "sampling/point_set.hpp"

namespace dfvn {

struct CnjOptions {
  TraceOptions trace;  // default: one RK4 step with Gauss-Newton reprojection
  // Trace time t = step_scale * dbar(N) * spacing (Section 5.1: proportional to the average
  // neighbour distance). |c| has RMS 1, so t is also the RMS length of a one-step move.
  // Noise frequency in cycles per lattice spacing (FieldOptions::frequency): the field's frequency is
  // frequency / spacing.
  // Defaults: the choice of choose_cnj_defaults (reproduce/cnj_study.hpp) on `reproduce cnj-study
  // --seeds 5`, recorded in data/cnj_defaults.md.
  NoiseBasis noise = kDefaultNoiseBasis;
  double step_scale = 0.5;
  double frequency = 0.2;
  // A move of 2^20 lattice spacings is far past any useful jitter (a point moved more than K
  // spacings has left the unit cube unless its streamline loops); the bound keeps every
  // displacement, and the sum of their squares, far from overflow.
  static constexpr double kMaxStepScale = 0x1p20;

  void validate() const;  // throws std::invalid_argument naming the option
};

struct CnjResult {
  PointSet points;                  // domain [0,1]^N; points that left it are dropped
  std::uint64_t dropped = 0;
  double trace_time = 0.0;          // t
  double field_frequency = 0.0;     // frequency / spacing
  double rms_displacement = 0.0;    // over all traced points, dropped ones included
  // x - x0 of every traced point (dropped ones included), K^N x N row-major in lattice order.
  std::vector<double> displacements;
  TraceStats trace_stats;
};

// Progress callback: fraction done in [0, 1]; called from one thread only.
using ProgressCallback = std::function<void(double)>;

template <int N>
CnjResult curl_noise_jitter(const LatticeSpec& lattice, const CnjOptions& options, std::uint64_t seed, int threads,
                            const ProgressCallback& progress = {});

// Runtime-dimension entry point (the lattice's dimension).
CnjResult curl_noise_jitter(const LatticeSpec& lattice, const CnjOptions& options, std::uint64_t seed, int threads,
                            const ProgressCallback& progress = {});

}  // namespace dfvn
