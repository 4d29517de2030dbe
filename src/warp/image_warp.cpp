#include "warp/image_warp.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>

#include "core/parallel.hpp"
#include "noise/noise_domain.hpp"

#include <omp.h>

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
}

std::string WarpVariant::label() const {
  std::string s = fmt::format("{}-{}", to_string(integrator), steps);
  if (newton_steps > 0) s += fmt::format("-newton{}", newton_steps);
  return s;
}

double wave_pattern(double x, double y) {
  // Vertical stripes, 10 across the width, bent by a gentle horizontal wave.
  const double phase = 10.0 * x + 0.6 * std::sin(2.0 * std::numbers::pi * 1.5 * y);
  return 0.5 + 0.5 * std::sin(2.0 * std::numbers::pi * phase);
}

namespace {

std::uint8_t to_byte(double v) {
  return static_cast<std::uint8_t>(std::lround(255.0 * std::clamp(v, 0.0, 1.0)));
}

template <typename PixelFunction>
GrayImage render(const WarpConfig& config, PixelFunction&& pixel) {
  GrayImage image{config.width, config.height, std::vector<std::uint8_t>(static_cast<std::size_t>(config.width) * config.height)};
  const double scale = 1.0 / config.width;
#pragma omp parallel for schedule(dynamic, 1) num_threads(resolve_threads(config.threads))
  for (int row = 0; row < config.height; ++row)
    for (int col = 0; col < config.width; ++col)
      image.pixels[static_cast<std::size_t>(row) * config.width + col] =
          to_byte(pixel(Vec<2>((col + 0.5) * scale, (row + 0.5) * scale)));
  return image;
}

}  // namespace

GrayImage source_image(const WarpConfig& config) {
  config.validate();
  return render(config, [](const Vec<2>& p) { return wave_pattern(p[0], p[1]); });
}

GrayImage warp_image(const WarpConfig& config, const WarpVariant& variant, std::int64_t* field_evaluations) {
  config.validate();
  TraceOptions options;
  options.integrator = variant.integrator;
  options.steps = variant.steps;
  options.reprojection = variant.newton_steps > 0 ? Reprojection::newton : Reprojection::none;
  options.reproject_iterations = variant.newton_steps;
  // The field's frequency is per unit length; the image is one unit wide.
  const DfvnField<2> field(config.seed, FieldOptions{config.noise, config.frequency});
  const Tracer<2> tracer(field, options);
  const int threads = resolve_threads(config.threads);
  std::vector<TraceStats> per_thread(static_cast<std::size_t>(threads));
  GrayImage image = render(config, [&](const Vec<2>& p) {
    const Vec<2> q = tracer.trace(p, config.time, &per_thread[static_cast<std::size_t>(omp_get_thread_num())]);
    return wave_pattern(q[0], q[1]);
  });
  if (field_evaluations) {
    *field_evaluations = 0;
    for (const auto& s : per_thread) *field_evaluations += s.field_evaluations;
  }
  return image;
}

double rmse(const GrayImage& a, const GrayImage& b) {
  if (a.width != b.width || a.height != b.height) throw std::invalid_argument("RMSE of images of different sizes");
  double sum = 0.0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i) {
    const double d = static_cast<double>(a.pixels[i]) - static_cast<double>(b.pixels[i]);
    sum += d * d;
  }
  return std::sqrt(sum / static_cast<double>(a.pixels.size()));
}

}  // namespace dfvn
