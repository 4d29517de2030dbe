// Power spectrum of 2D and 3D point sets (as pbrt-v4's pspec and UTK's Spectrum/RadialSpectrum): the
// periodogram P(k) = |sum_j exp(-2 pi i k . x_j)|^2 / n on integer frequencies k of the unit torus,
// averaged over realizations, its radial average and anisotropy.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "dfvn/core/point_set.hpp"
#include "dfvn/core/progress.hpp"

namespace dfvn {

// The periodogram sums n terms, each rounded to about 1e-16 relative: over a shell its relative
// variance from rounding alone is below (n 1e-16)^2, 1e-20 for n up to 1e6. Below this bound
// (-200 dB) a shell's power is constant, and its anisotropy (-Inf dB) is not written.
inline constexpr double kMinRelativeVariance = 1e-20;

struct PowerSpectrum {
  int dimension = 2;
  int max_frequency = 0;  // k in [-K, K]^N
  int realizations = 0;
  // The peak frequency of a lattice as dense as the sets: n^(1/N) for their mean count n; a jittered or
  // blue-noise set's power rises to it (the figure marks it).
  double lattice_peak = 0.0;
  // (2K+1)^N values, axis 0 fastest: index sum_a (k_a + K) (2K+1)^a. P(0) = n (the DC term).
  std::vector<double> power;
  double at(const int* k) const;

  // Radial average over shells |k| in [r - 1/2, r + 1/2), r = 1..K (the shell 0 is the DC term).
  std::vector<double> radial_mean;
  // Anisotropy per shell: 10 log10(var / mean^2) of P over the shell (Lagae and Dutre 2008), in dB;
  // for a periodogram of random points about 0 dB (an exponential variable has var = mean^2). Empty
  // where it is -Inf: the shell's power is 0 or constant to rounding (var / mean^2 below
  // kMinRelativeVariance), as for a set of identical points.
  std::vector<std::optional<double>> anisotropy_db;
  std::vector<int> shell_counts;
};

// Averages the periodograms of `sets` (each with the same dimension, 2 or 3, mapped from its domain to
// the unit cube). OpenMP-parallel over frequencies; independent of the thread count. Throws
// std::invalid_argument for other dimensions, an empty list or max_frequency < 1.
// `progress`: frequencies done over frequencies, over all sets.
PowerSpectrum power_spectrum(const std::vector<PointSet>& sets, int max_frequency, int threads,
                             const FractionProgress& progress = {});

// The lattice peak n^(1/N) of `points` points in N dimensions, and the default largest frequency K: twice
// it rounded up, so the figure shows the peak and what lies beyond it, but at most kMaxDefaultFrequency
// (its sums cost (2K+1)^N n).
double lattice_peak_frequency(double points, int dimension);
int default_spectrum_frequency(double points, int dimension);
// The expected cost of power_spectrum(sets, max_frequency, ...) in point_statistics_stage_weights' unit.
double expected_spectrum_cost(const std::vector<PointSet>& sets, int max_frequency);
inline constexpr int kMaxDefaultFrequency2d = 256, kMaxDefaultFrequency3d = 64;

// PREFIX.csv: k0,..,k{N-1},power for every frequency; PREFIX_radial.csv: frequency,power,anisotropy_db,
// frequencies (the shell's count), anisotropy_db empty where it is not defined. Then PREFIX.png (scripts/spectrum.gp, plot/gnuplot.hpp) when gnuplot is
// installed (otherwise `log` says how to get it). Throws PlotError if gnuplot fails.
// `what` names the points in the figure's title ("'pts.npy', 4 sets of 1024 points").
void write_spectrum_files(const std::string& prefix, const PowerSpectrum& spectrum,
                          const std::function<void(const std::string&)>& log, const std::string& what = "the points");
// What write_spectrum_files appends to the prefix: ".csv", "_radial.csv", ".png".
std::vector<std::string> spectrum_file_suffixes();

}  // namespace dfvn
