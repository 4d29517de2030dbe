// Image warping by advecting pixel coordinates along 2D DFVN (Section 5.2, Table 2, Figure 5).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "integrate/trace.hpp"

namespace dfvn {

// An 8-bit grey image, row-major, row 0 at the top.
struct GrayImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> pixels;
};

struct WarpConfig {
  int width = 384;
  int height = 216;
  double time = 0.5;        // integration time t (the paper's t = 0.5)
  // Noise cycles across the image width. The shader's noise_scale is 7, but its field magnitude is
  // not ours: with RMS |c| = 1, frequency 7 moves points ~3.5 noise features in t = 0.5 and turns
  // the image into noise (Euler 64 steps: RMSE 127); at 3 the warp shows Figure 5's well-defined
  // swirls (look at figure5.png).
  double frequency = 3.0;
  NoiseBasis noise = NoiseBasis::simplex;
  std::uint64_t seed = 1;
  int threads = 0;

  void validate() const;  // throws std::invalid_argument naming the option
};

// One row of Table 2: integrator, steps, Newton reprojection steps (Eq. 12) after each step.
struct WarpVariant {
  Integrator integrator = Integrator::rk4;
  int steps = 64;
  int newton_steps = 0;  // 0: no reprojection
  std::string label() const;  // e.g. "rk4-64-newton1"
};

// The source image: a wave/stripe pattern in [0, 1], evaluated analytically at any point, with x
// across the width in [0, 1] and y down the height in [0, height / width].
double wave_pattern(double x, double y);

// Every pixel centre is traced along the 2D field for `time` (Algorithm 1) and the source pattern is
// read where it lands (backward warping, no interpolation). Deterministic; thread-count independent.
// `field_evaluations`, if given, receives the number of field evaluations: the deterministic measure
// of the work, which tests compare instead of times.
GrayImage warp_image(const WarpConfig& config, const WarpVariant& variant, std::int64_t* field_evaluations = nullptr);

// The unwarped source image at the configured size.
GrayImage source_image(const WarpConfig& config);

// Root mean square difference in 8-bit units.
double rmse(const GrayImage& a, const GrayImage& b);

}  // namespace dfvn
