#include "dfvn/stats/spectrum.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iterator>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>

#include "dfvn/core/parallel.hpp"
#include "dfvn/io/atomic_file.hpp"
#include "dfvn/io/csv.hpp"
#include "dfvn/plot/gnuplot.hpp"

namespace dfvn {

double PowerSpectrum::at(const int* k) const {
  std::size_t index = 0, stride = 1;
  for (int a = 0; a < dimension; ++a) {
    index += static_cast<std::size_t>(k[a] + max_frequency) * stride;
    stride *= static_cast<std::size_t>(2 * max_frequency + 1);
  }
  return power[index];
}

double lattice_peak_frequency(double points, int dimension) {
  return points > 0.0 && dimension > 0 ? std::pow(points, 1.0 / dimension) : 0.0;
}

int default_spectrum_frequency(double points, int dimension) {
  const int cap = dimension == 2 ? kMaxDefaultFrequency2d : kMaxDefaultFrequency3d;
  const double twice = std::ceil(2.0 * lattice_peak_frequency(points, dimension));
  return static_cast<int>(std::clamp(twice, 1.0, static_cast<double>(cap)));
}

double expected_spectrum_cost(const std::vector<PointSet>& sets, int max_frequency) {
  constexpr double kSineCosineCost = 30.0;  // per point and frequency; a discrepancy pair costs 1 per dimension
  double cost = 0.0;
  for (const PointSet& set : sets)
    cost += std::pow(2.0 * max_frequency + 1.0, set.dimension) * static_cast<double>(set.size()) * kSineCosineCost;
  return cost;
}

PowerSpectrum power_spectrum(const std::vector<PointSet>& sets, int max_frequency, int threads,
                             const FractionProgress& progress) {
  if (sets.empty()) throw std::invalid_argument("power spectrum: no point sets");
  const int n_dim = sets.front().dimension;
  if (n_dim != 2 && n_dim != 3) throw std::invalid_argument("power spectrum: only 2D and 3D sets are supported");
  if (max_frequency < 1) throw std::invalid_argument("power spectrum: the largest frequency must be at least 1");
  for (const auto& s : sets)
    if (s.dimension != n_dim || s.size() == 0) throw std::invalid_argument("power spectrum: every set needs the same dimension and a point");
  PowerSpectrum out;
  out.dimension = n_dim;
  out.max_frequency = max_frequency;
  out.realizations = static_cast<int>(sets.size());
  const int side = 2 * max_frequency + 1;
  std::size_t total = 1;
  for (int a = 0; a < n_dim; ++a) total *= static_cast<std::size_t>(side);
  out.power.assign(total, 0.0);
  double points = 0.0;
  for (const auto& set : sets) points += static_cast<double>(set.size()) / static_cast<double>(sets.size());
  out.lattice_peak = lattice_peak_frequency(points, n_dim);
  std::size_t set_index = 0;

  for (const auto& set : sets) {
    const std::size_t n = set.size();
    const std::size_t frequencies_before = set_index++ * total;
    // Unit-cube coordinates times 2 pi, axis-major for the inner loop.
    std::vector<double> phase_scale(n * static_cast<std::size_t>(n_dim));
    for (std::size_t j = 0; j < n; ++j)
      for (int a = 0; a < n_dim; ++a)
        phase_scale[static_cast<std::size_t>(a) * n + j] =
            2.0 * std::numbers::pi * (set.point(j)[a] - set.domain.lo) / set.domain.side;
#pragma omp parallel for schedule(dynamic, 16) num_threads(resolve_threads(threads))
    for (std::int64_t signed_index = 0; signed_index < static_cast<std::int64_t>(total); ++signed_index) {
      auto rest = static_cast<std::size_t>(signed_index);
      int k[3] = {0, 0, 0};
      for (int a = 0; a < n_dim; ++a) {
        k[a] = static_cast<int>(rest % static_cast<std::size_t>(side)) - max_frequency;
        rest /= static_cast<std::size_t>(side);
      }
      double re = 0.0, im = 0.0;  // in point order: the same for any thread count
      for (std::size_t j = 0; j < n; ++j) {
        double phase = 0.0;
        for (int a = 0; a < n_dim; ++a) phase += k[a] * phase_scale[static_cast<std::size_t>(a) * n + j];
        re += std::cos(phase);
        im -= std::sin(phase);
      }
      out.power[static_cast<std::size_t>(signed_index)] += (re * re + im * im) / static_cast<double>(n) / static_cast<double>(sets.size());
      if (progress && omp_get_thread_num() == 0 && signed_index % 64 == 0)  // only the first thread reports
        progress(static_cast<double>(frequencies_before + static_cast<std::size_t>(signed_index)) /
                 static_cast<double>(total * sets.size()));
    }
  }

  // Radial shells and their anisotropy: the shell of each frequency, then the means, then the variances
  // about them (two passes: the one-pass E[P^2] - E[P]^2 cancels to rounding noise for flat shells).
  const std::size_t shells = static_cast<std::size_t>(max_frequency) + 1;
  out.radial_mean.assign(shells, 0.0);
  out.anisotropy_db.assign(shells, std::nullopt);
  out.shell_counts.assign(shells, 0);
  std::vector<std::size_t> shell_of(total);
  for (std::size_t index = 0; index < total; ++index) {
    std::size_t rest = index;
    double radius2 = 0.0;
    for (int a = 0; a < n_dim; ++a) {
      const int k = static_cast<int>(rest % static_cast<std::size_t>(side)) - max_frequency;
      rest /= static_cast<std::size_t>(side);
      radius2 += double(k) * k;
    }
    shell_of[index] = static_cast<std::size_t>(std::lround(std::sqrt(radius2)));
    if (shell_of[index] >= shells) continue;  // corners of the cube: incomplete shells
    out.radial_mean[shell_of[index]] += out.power[index];
    ++out.shell_counts[shell_of[index]];
  }
  for (std::size_t r = 0; r < shells; ++r) out.radial_mean[r] /= out.shell_counts[r];
  std::vector<double> squares(shells, 0.0);
  for (std::size_t index = 0; index < total; ++index)
    if (shell_of[index] < shells) {
      const double deviation = out.power[index] - out.radial_mean[shell_of[index]];
      squares[shell_of[index]] += deviation * deviation;
    }
  for (std::size_t r = 0; r < shells; ++r) {
    const double count = out.shell_counts[r];
    const double mean2 = out.radial_mean[r] * out.radial_mean[r];
    const double variance = count > 1 ? squares[r] / (count - 1) : 0.0;
    if (mean2 > 0.0 && variance > kMinRelativeVariance * mean2) out.anisotropy_db[r] = 10.0 * std::log10(variance / mean2);
  }
  if (progress) progress(1.0);
  return out;
}

std::vector<std::string> spectrum_file_suffixes() { return {".csv", "_radial.csv", ".png"}; }

void write_spectrum_files(const std::string& prefix, const PowerSpectrum& spectrum,
                          const std::function<void(const std::string&)>& log, const std::string& what) {
  const int side = 2 * spectrum.max_frequency + 1;
  std::string grid = numbered_header("k", spectrum.dimension) + ",power\n";
  for (std::size_t index = 0; index < spectrum.power.size(); ++index) {
    std::size_t rest = index;
    for (int a = 0; a < spectrum.dimension; ++a) {
      fmt::format_to(std::back_inserter(grid), "{},", static_cast<int>(rest % static_cast<std::size_t>(side)) - spectrum.max_frequency);
      rest /= static_cast<std::size_t>(side);
    }
    grid += format_real(spectrum.power[index]) + '\n';
  }
  std::string radial = "frequency,power,anisotropy_db,frequencies\n";
  for (std::size_t r = 1; r < spectrum.radial_mean.size(); ++r)
    fmt::format_to(std::back_inserter(radial), "{},{},{},{}\n", r, format_real(spectrum.radial_mean[r]),
                   spectrum.anisotropy_db[r] ? format_real(*spectrum.anisotropy_db[r]) : std::string(),
                   spectrum.shell_counts[r]);
  write_file_atomically(prefix + ".csv", grid);
  write_file_atomically(prefix + "_radial.csv", radial);
  draw_figure(PlotProgram::spectrum, prefix + ".png",
              {prefix + ".csv", prefix + "_radial.csv", std::to_string(spectrum.dimension),
               fmt::format("{:.6g}", spectrum.lattice_peak), what},
              log);
}

}  // namespace dfvn
