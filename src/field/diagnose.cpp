#include "dfvn/field/diagnose.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>

#include "dfvn/core/hash.hpp"
#include "dfvn/core/parallel.hpp"
#include "dfvn/core/quantile.hpp"
#include "dfvn/core/stopwatch.hpp"
#include "dfvn/io/csv.hpp"

namespace dfvn {

void DiagnosisOptions::validate() const {
  if (dimension < kMinDimension || dimension > kMaxDimension)
    throw std::invalid_argument(fmt::format("dimension must be in {}..{}, got {}", kMinDimension, kMaxDimension, dimension));
  field.validate();
  if (points < 10) throw std::invalid_argument(fmt::format("diagnosis needs at least 10 points, got {}", points));
  if (!std::isfinite(periods) || !(periods > 0.0)) throw std::invalid_argument("periods must be finite and positive");
  if (!std::isfinite(difference_step) || !(difference_step > 0.0))
    throw std::invalid_argument("difference step must be finite and positive");
}

namespace {

template <int N>
FieldDiagnosis diagnose(const DiagnosisOptions& options, const FractionProgress& progress) {
  Stopwatch stopwatch;
  const DfvnField<N> field(options.seed, options.field);
  const double extent = options.periods / options.field.frequency;
  const double h = options.difference_step / options.field.frequency;
  const auto count = static_cast<std::int64_t>(options.points);
  std::vector<double> speed(count), divergence(count), value2(count), gradient2(count);
#pragma omp parallel for schedule(dynamic, 256) num_threads(resolve_threads(options.threads))
  for (std::int64_t i = 0; i < count; ++i) {
    Vec<N> x;
    for (int j = 0; j < N; ++j)
      x[j] = extent * random_unit(options.seed, Stream::field_diagnosis, static_cast<std::uint64_t>(i), static_cast<std::uint64_t>(j));
    const FieldSample<N> s = field.evaluate(x);
    speed[i] = s.velocity.norm();
    double v2 = 0.0, g2 = 0.0;
    for (int k = 0; k < N - 1; ++k) {
      v2 += s.value[k] * s.value[k];
      g2 += s.gradient[k].squaredNorm();
    }
    value2[i] = v2;
    gradient2[i] = g2;
    double div = 0.0, jacobian2 = 0.0;
    for (int j = 0; j < N; ++j) {
      Vec<N> xp = x, xm = x;
      xp[j] += h;
      xm[j] -= h;
      const Vec<N> column = (field.velocity(xp) - field.velocity(xm)) / (2.0 * h);
      div += column[j];
      jacobian2 += column.squaredNorm();
    }
    divergence[i] = jacobian2 > 0.0 ? std::abs(div) / std::sqrt(jacobian2) : -1.0;  // -1: still point
    if (progress && omp_get_thread_num() == 0 && i % 256 == 0)  // only the first thread reports
      progress(static_cast<double>(i) / static_cast<double>(count));
  }
  if (progress) progress(1.0);
  FieldDiagnosis d;
  d.options = options;
  // Sums in index order: the same for any thread count.
  double speed2 = 0.0, sum_value2 = 0.0, sum_gradient2 = 0.0;
  for (std::int64_t i = 0; i < count; ++i) {
    speed2 += speed[i] * speed[i];
    sum_value2 += value2[i];
    sum_gradient2 += gradient2[i];
  }
  d.rms_speed = std::sqrt(speed2 / static_cast<double>(count));
  const double rms = d.rms_speed > 0.0 ? d.rms_speed : 1.0;
  d.fraction_below_1_percent =
      static_cast<double>(std::count_if(speed.begin(), speed.end(), [&](double s) { return s < 0.01 * rms; })) /
      static_cast<double>(count);
  std::sort(speed.begin(), speed.end());
  d.median_over_rms = median_of_sorted(speed) / rms;
  d.q10_over_rms = quantile_of_sorted(speed, 0.1) / rms;
  std::vector<double> defined;
  defined.reserve(divergence.size());
  for (double v : divergence) {
    if (v >= 0.0) defined.push_back(v);
    else ++d.still_points;
  }
  if (!defined.empty()) {
    std::sort(defined.begin(), defined.end());
    d.divergence_median = median_of_sorted(defined);
    d.divergence_p95 = quantile_of_sorted(defined, 0.95);
    d.divergence_max = defined.back();
  }
  d.wavenumber_measured = sum_value2 > 0.0 ? std::sqrt(sum_gradient2 / sum_value2) : 0.0;
  d.wavenumber_expected = 2.0 * std::numbers::pi * field.frequency();  // on the torus: the realised one
  d.seconds = stopwatch.seconds();
  return d;
}

}  // namespace

FieldDiagnosis diagnose_field(const DiagnosisOptions& options, const FractionProgress& progress) {
  options.validate();
  return dispatch_dimension(options.dimension, [&]<int N>() { return diagnose<N>(options, progress); });
}

std::string diagnosis_csv_header() {
  return "dim,noise,frequency,seed,points,periods,rms_speed,median_over_rms,q10_over_rms,fraction_below_1pct,"
         "divergence_median,divergence_p95,divergence_max,still_points,k_eff_measured,k_eff_expected,"
         "k_eff_ratio,seconds,domain\n";
}

std::string diagnosis_csv_row(const FieldDiagnosis& d) {
  const DiagnosisOptions& o = d.options;
  // Reals as format_real writes them ("1.0", never "1"): statistics to 9 significant digits, the time
  // to 6 decimals, as in every CSV of the tool.
  return fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{:.6f},{}\n", o.dimension,
                     to_string(o.field.noise), format_real(o.field.frequency), o.seed, o.points, format_real(o.periods),
                     format_real(d.rms_speed), format_real(d.median_over_rms), format_real(d.q10_over_rms),
                     format_real(d.fraction_below_1_percent), format_real(d.divergence_median),
                     format_real(d.divergence_p95), format_real(d.divergence_max), d.still_points,
                     format_real(d.wavenumber_measured), format_real(d.wavenumber_expected),
                     format_real(d.wavenumber_measured / d.wavenumber_expected), d.seconds,
                     o.field.periodic ? "torus" : std::string(o.field.constraint == FieldConstraint::none
                                                                  ? "free"
                                                                  : to_string(o.field.constraint)));
}

}  // namespace dfvn
