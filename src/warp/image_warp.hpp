// Image warping by advecting pixel coordinates along 2D DFVN (Section 5.2, Table 2, Figure 5).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "dfvn/core/image.hpp"
#include "dfvn/core/progress.hpp"
#include "dfvn/integrate/trace.hpp"

namespace dfvn {

// The source image, a function of the point (x across the width in [0, 1], y down the height in
// [0, height / width]) that can be evaluated exactly wherever a trace lands:
// - sine_stripes: 10 smooth vertical sine stripes bent by a gentle horizontal wave (our earlier image).
// - shader_bands: the shader's wave image (data/PROTOCOL.md, Table 2): horizontal bands 0.1 high whose
//   boundaries are displaced by the wave 0.05 |cos(10 pi (x - y))|, band k (mod 10) at grey level
//   (17 k mod 13) / 13 (the shader maps that level through viridis; we keep it grey). Piecewise
//   constant, so a pixel's error is 0 or a whole band step: RMSE measures the area whose band changed.
enum class WarpPattern { sine_stripes, shader_bands };
double warp_pattern(WarpPattern pattern, double x, double y);

// The two settings `reproduce table2` can run (see shader_warp_config / ours_warp_config).
enum class WarpSetting { shader, ours };
WarpSetting parse_warp_setting(std::string_view name);  // "shader" | "ours"; throws std::invalid_argument
std::string_view to_string(WarpSetting setting);

struct WarpConfig {
  int width = 384;
  int height = 216;
  double time = 0.5;  // integration time t (the paper's t = 0.5)
  // Noise frequency in cycles per image width (one cycle = 2 pi / k_eff of the basis; the image is one
  // unit wide) and the field's RMS speed in image widths per unit time. The DFVN field has RMS |c| = 1
  // by construction; multiplying it by a constant M is the same as tracing for time M t with the same
  // number of steps (the step h M c is the same vector either way, and reprojection only sees the
  // iso-contours, which M does not change), which is how warp_image applies it.
  double frequency = 3.0;
  double field_magnitude = 1.0;
  NoiseBasis noise = NoiseBasis::simplex;
  WarpPattern pattern = WarpPattern::sine_stripes;
  // Samples per pixel: a perfect square S = m^2, read on an m x m grid of sub-pixel centres and averaged.
  int samples = 1;
  std::uint64_t seed = 1;
  int threads = 0;

  void validate() const;  // throws std::invalid_argument naming the option
};

// The paper's shader (data/PROTOCOL.md, Table 2; the authors' Shaders/image_warping.glsl): 2D quintic
// gradient noise n with gradient components uniform in [-1, 1], noise_scale 7 lattice cells across the
// image width, t = 0.5, and the velocity rot90(7 grad n(7 x)), i.e. the raw noise's gradient without
// any normalisation. Our basis has the shader's distribution, so the same field is ours at
//   frequency = 7 k_eff / (2 pi) = 4.562 cycles per width   (k_eff = 4.095 radians per cell, exact), and
//   field_magnitude = 7 sigma = 7 / amplitude() = 5.049 widths per unit time   (sigma^2 = E|grad n|^2 = 0.5202),
// both from the closed-form moments of noise/gradient_noise.cpp. The wave image is shader_bands.
WarpConfig shader_warp_config();
inline constexpr double kShaderNoiseScale = 7.0;  // the shader's noise_scale: lattice cells per image width

// Our earlier setting: simplex noise at 3 cycles across the width with RMS |c| = 1, smooth sine
// stripes. Slower and gentler than the shader's warp (about 1.5 noise features travelled in t = 0.5).
WarpConfig ours_warp_config();

WarpConfig warp_config(WarpSetting setting);

// One row of Table 2: integrator, steps, Newton reprojection steps (Eq. 12) after each step.
struct WarpVariant {
  Integrator integrator = Integrator::rk4;
  int steps = 64;
  int newton_steps = 0;  // 0: no reprojection
  std::string label() const;  // e.g. "rk4-64-newton1"
};

// Every sample point of every pixel is traced along the 2D field for `time` (Algorithm 1) and the
// pattern is evaluated exactly where it lands (backward warping, no interpolation, no rounding).
// Deterministic; thread-count independent. `field_evaluations`, if given, receives the number of
// field evaluations: the deterministic measure of the work, which tests compare instead of times.
// `progress`: image rows started over rows.
FloatImage warp_image(const WarpConfig& config, const WarpVariant& variant, std::int64_t* field_evaluations = nullptr,
                      const FractionProgress& progress = {});

// The unwarped source image at the configured size and sampling.
FloatImage source_image(const WarpConfig& config);

// Root mean square difference in 8-bit units (255 x the difference of values in [0, 1]), from the
// float values: no 8-bit rounding, so differences far below one grey level still count.
double rmse(const FloatImage& a, const FloatImage& b);

// RMSE of two 8-bit images computed the way unsigned 8-bit array arithmetic does it: the difference
// and its square each wrap modulo 256 (as (a - b)**2 on uint8 NumPy arrays), so the result never
// exceeds sqrt(255) = 15.97. Not a correct RMSE: kept to compare with the paper's Table 2, whose
// values all lie below that bound and agree with ours computed this way (table2.md).
double rmse_8bit_wraparound(const GrayImage& a, const GrayImage& b);

// Rounded to 8 bits for a PNG.
GrayImage to_gray(const FloatImage& image);

}  // namespace dfvn
