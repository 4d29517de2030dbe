#include "dfvn/warp/image_warp.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <numbers>
#include <vector>
#include <stdexcept>

#include <fmt/format.h>
#include <omp.h>

#include "dfvn/core/parallel.hpp"
#include "dfvn/noise/gradient_noise.hpp"
#include "dfvn/noise/noise_domain.hpp"
#include "dfvn/warp/warp_lanes.hpp"

namespace dfvn {

void WarpConfig::validate() const {
  if (width < 2 || height < 2 || width > 20000 || height > 20000)
    throw std::invalid_argument(fmt::format("image size must be 2..20000 per side, got {}x{}", width, height));
  if (!std::isfinite(time)) throw std::invalid_argument("warp time must be finite");
  check_thread_count(threads);
  check_noise_frequency(frequency, "warp frequency");
  // Pixel centres lie in [0, 1] x [0, height / width]; the traces start there.
  const double extent = std::max(1.0, static_cast<double>(height) / width);
  if (!is_noise_argument(frequency * extent))
    throw std::invalid_argument(fmt::format("warp frequency {:g} over an image {:g} units tall leaves the noise domain "
                                            "(|frequency x coordinate| below 2^50)", frequency, extent));
  if (!std::isfinite(field_magnitude) || field_magnitude <= 0.0)
    throw std::invalid_argument(fmt::format("field magnitude must be finite and > 0, got {}", field_magnitude));
  const int side = static_cast<int>(std::lround(std::sqrt(static_cast<double>(samples))));
  if (samples < 1 || samples > 256 || side * side != samples)
    throw std::invalid_argument(fmt::format("samples per pixel must be a perfect square 1, 4, 9, ..., 256, got {}", samples));
}

WarpSetting parse_warp_setting(std::string_view name) {
  if (name == "shader") return WarpSetting::shader;
  if (name == "ours") return WarpSetting::ours;
  throw std::invalid_argument("unknown warp setting '" + std::string(name) + "' (allowed: shader, ours)");
}

std::string_view to_string(WarpSetting setting) { return setting == WarpSetting::shader ? "shader" : "ours"; }

WarpConfig shader_warp_config() {
  const QuinticGradientNoise<2> basis(0);  // the moments do not depend on the seed
  WarpConfig config;
  config.time = 0.5;
  config.noise = NoiseBasis::quintic_gradient;
  // Scale s = 2 pi F / k_eff lattice cells per width (DfvnField) equals 7 for this F.
  config.frequency = kShaderNoiseScale * basis.wavenumber() / (2.0 * std::numbers::pi);
  // Ours is amplitude() x grad n, the shader's 7 x grad n: the ratio is the magnitude.
  config.field_magnitude = kShaderNoiseScale / basis.amplitude();
  config.pattern = WarpPattern::shader_bands;
  return config;
}

WarpConfig ours_warp_config() {
  WarpConfig config;
  config.time = 0.5;
  config.noise = NoiseBasis::simplex;
  config.frequency = 3.0;
  config.field_magnitude = 1.0;
  config.pattern = WarpPattern::sine_stripes;
  return config;
}

WarpConfig warp_config(WarpSetting setting) {
  return setting == WarpSetting::shader ? shader_warp_config() : ours_warp_config();
}

std::string WarpVariant::label() const {
  std::string s = fmt::format("{}-{}", to_string(integrator), steps);
  if (newton_steps > 0) s += fmt::format("-newton{}", newton_steps);
  return s;
}

double warp_pattern(WarpPattern pattern, double x, double y) {
  switch (pattern) {
    case WarpPattern::sine_stripes: {
      const double phase = 10.0 * x + 0.6 * std::sin(2.0 * std::numbers::pi * 1.5 * y);
      return 0.5 + 0.5 * std::sin(2.0 * std::numbers::pi * phase);
    }
    case WarpPattern::shader_bands: {
      const double wavy_y = y + 0.05 * std::abs(std::cos(10.0 * std::numbers::pi * (x - y)));
      // Band index mod 10 (floor works for negative coordinates too: traces leave the image).
      const auto band = static_cast<std::int64_t>(std::floor(10.0 * wavy_y));
      const std::int64_t k = ((band % 10) + 10) % 10;
      return static_cast<double>((17 * k) % 13) / 13.0;
    }
  }
  throw std::invalid_argument("unknown warp pattern");
}

namespace {

// The centre of sub-pixel (a, b) of pixel (col, row) on a side x side grid; the image is one unit wide.
Vec<2> sample_point(int col, int row, int a, int b, int side, double pixel) {
  return Vec<2>((col + (b + 0.5) / side) * pixel, (row + (a + 0.5) / side) * pixel);
}

// Fills `image` a row at a time: row_values(row, values) writes the row's width x samples values, pixel after
// pixel, each pixel's m x m sub-pixel values in row-major order (sample_point), and every pixel is their
// average, summed in that order.
template <typename RowFunction>
FloatImage render_rows(const WarpConfig& config, RowFunction&& row_values, const FractionProgress& progress = {}) {
  FloatImage image{config.width, config.height, std::vector<float>(static_cast<std::size_t>(config.width) * config.height)};
  std::atomic<int> rows_started{0};
#pragma omp parallel num_threads(resolve_threads(config.threads))
  {
    std::vector<double> values(static_cast<std::size_t>(config.width) * config.samples);  // one per thread
#pragma omp for schedule(dynamic, 1)
    for (int row = 0; row < config.height; ++row) {
      if (progress) {  // rows started over rows; only the first thread reports
        const int started = rows_started.fetch_add(1, std::memory_order_relaxed);
        if (omp_get_thread_num() == 0) progress(static_cast<double>(started) / config.height);
      }
      row_values(row, values.data());
      for (int col = 0; col < config.width; ++col) {
        double sum = 0.0;
        for (int s = 0; s < config.samples; ++s) sum += values[static_cast<std::size_t>(col) * config.samples + s];
        image.values[static_cast<std::size_t>(row) * config.width + col] = static_cast<float>(sum / config.samples);
      }
    }
  }
  if (progress) progress(1.0);
  return image;
}

// render_rows with value_at(point) at every sample point.
template <typename PointFunction>
FloatImage render(const WarpConfig& config, PointFunction&& value_at, const FractionProgress& progress = {}) {
  const int side = static_cast<int>(std::lround(std::sqrt(static_cast<double>(config.samples))));
  const double pixel = 1.0 / config.width;
  return render_rows(config, [&](int row, double* values) {
    for (int col = 0; col < config.width; ++col)
      for (int a = 0; a < side; ++a)
        for (int b = 0; b < side; ++b) *values++ = value_at(sample_point(col, row, a, b, side, pixel));
  }, progress);
}

}  // namespace

FloatImage source_image(const WarpConfig& config) {
  config.validate();
  return render(config, [&](const Vec<2>& p) { return warp_pattern(config.pattern, p[0], p[1]); });
}

FloatImage warp_image(const WarpConfig& config, const WarpVariant& variant, std::int64_t* field_evaluations,
                      const FractionProgress& progress) {
  config.validate();
  TraceOptions options;
  options.integrator = variant.integrator;
  options.steps = variant.steps;
  options.reprojection = variant.newton_steps > 0 ? Reprojection::newton : Reprojection::none;
  options.reproject_iterations = variant.newton_steps;
  // The field's frequency is per unit length; the image is one unit wide.
  const DfvnField<2> field(config.seed, FieldOptions{config.noise, config.frequency});
  const Tracer<2> tracer(field, options);
  const double trace_time = config.time * config.field_magnitude;  // see WarpConfig::field_magnitude
  const int threads = resolve_threads(config.threads);
  std::vector<TraceStats> per_thread(static_cast<std::size_t>(threads));
  FloatImage image;
  if (const auto lanes = warp_lanes::quintic_field_2d(field, tracer.options())) {
    // The shader's field: a row's sample points traced a vector at a time (warp/warp_lanes.hpp), the same
    // bits as the tracer's; a trace that reaches the edge of the noise domain is the tracer's.
    const int side = static_cast<int>(std::lround(std::sqrt(static_cast<double>(config.samples))));
    const double pixel = 1.0 / config.width;
    const std::size_t count = static_cast<std::size_t>(config.width) * config.samples;
    image = render_rows(config, [&](int row, double* values) {
      std::vector<double> xs(count), ys(count), end_x(count), end_y(count);  // a row's points: no allocation per trace
      std::vector<std::int64_t> evaluations(count);
      std::vector<std::uint8_t> traced(count);
      std::size_t i = 0;
      for (int col = 0; col < config.width; ++col)
        for (int a = 0; a < side; ++a)
          for (int b = 0; b < side; ++b, ++i) {
            const Vec<2> p = sample_point(col, row, a, b, side, pixel);
            xs[i] = p[0], ys[i] = p[1];
          }
      warp_lanes::trace(*lanes, tracer.options(), trace_time, count, xs.data(), ys.data(), end_x.data(), end_y.data(),
                        evaluations.data(), traced.data());
      TraceStats& stats = per_thread[static_cast<std::size_t>(omp_get_thread_num())];
      for (i = 0; i < count; ++i) {
        if (traced[i]) {
          stats.field_evaluations += evaluations[i];
          values[i] = warp_pattern(config.pattern, end_x[i], end_y[i]);
        } else {
          const Vec<2> q = tracer.trace(Vec<2>(xs[i], ys[i]), trace_time, &stats);
          values[i] = warp_pattern(config.pattern, q[0], q[1]);
        }
      }
    }, progress);
  } else {
    image = render(config, [&](const Vec<2>& p) {
      const Vec<2> q = tracer.trace(p, trace_time, &per_thread[static_cast<std::size_t>(omp_get_thread_num())]);
      return warp_pattern(config.pattern, q[0], q[1]);
    }, progress);
  }
  if (field_evaluations) {
    *field_evaluations = 0;
    for (const auto& s : per_thread) *field_evaluations += s.field_evaluations;
  }
  return image;
}

double rmse(const FloatImage& a, const FloatImage& b) {
  if (a.width != b.width || a.height != b.height) throw std::invalid_argument("RMSE of images of different sizes");
  double sum = 0.0;
  for (std::size_t i = 0; i < a.values.size(); ++i) {
    const double d = 255.0 * (static_cast<double>(a.values[i]) - static_cast<double>(b.values[i]));
    sum += d * d;
  }
  return std::sqrt(sum / static_cast<double>(a.values.size()));
}

double rmse_8bit_wraparound(const GrayImage& a, const GrayImage& b) {
  if (a.width != b.width || a.height != b.height) throw std::invalid_argument("RMSE of images of different sizes");
  double sum = 0.0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i) {
    const auto difference = static_cast<std::uint8_t>(a.pixels[i] - b.pixels[i]);
    sum += static_cast<std::uint8_t>(difference * difference);
  }
  return std::sqrt(sum / static_cast<double>(a.pixels.size()));
}

GrayImage to_gray(const FloatImage& image) {
  GrayImage gray{image.width, image.height, std::vector<std::uint8_t>(image.values.size())};
  for (std::size_t i = 0; i < image.values.size(); ++i)
    gray.pixels[i] = static_cast<std::uint8_t>(std::lround(255.0 * std::clamp(static_cast<double>(image.values[i]), 0.0, 1.0)));
  return gray;
}

}  // namespace dfvn
