// Field diagnostics measured from outside: the |c| distribution, the divergence and k_eff on uniform
// random points (not on points chosen where the field is active).
#pragma once

#include <cstdint>
#include <string>

#include "dfvn/core/progress.hpp"
#include "dfvn/field/dfvn_field.hpp"

namespace dfvn {

struct DiagnosisOptions {
  int dimension = 3;
  FieldOptions field;
  std::uint64_t seed = 1;
  std::uint64_t points = 100000;
  // The points are uniform in [0, periods / frequency]^N: `periods` noise cycles along each axis. Many
  // periods sample many independent regions: turning bands correlate along each band, so over 50
  // periods RMS |c| still varies by ~5% between seeds in 2D (1% over 1000).
  double periods = 1000.0;
  // Central-difference step for the divergence, in noise cycles (h = step / frequency). The truncation
  // error is O((2 pi step)^2) relative and the rounding error O(eps / (2 pi step)): 1e-5 balances them.
  double difference_step = 1e-5;
  int threads = 0;

  void validate() const;  // throws std::invalid_argument naming the option
};

struct FieldDiagnosis {
  DiagnosisOptions options;
  // |c| over the points, relative to its RMS.
  double rms_speed = 0.0;
  double median_over_rms = 0.0;
  double q10_over_rms = 0.0;
  double fraction_below_1_percent = 0.0;
  // |div c| / |Dc| (Frobenius norm of the central-difference Jacobian) over the points where Dc != 0.
  double divergence_median = 0.0;
  double divergence_p95 = 0.0;
  double divergence_max = 0.0;
  std::uint64_t still_points = 0;  // points where the difference Jacobian is exactly zero (excluded)
  // sqrt(sum_i E|grad f_i|^2 / sum_i E f_i^2), measured, against 2 pi F (on the torus F is the
  // field's realised frequency, DfvnField::frequency()).
  double wavenumber_measured = 0.0;
  double wavenumber_expected = 0.0;
  double seconds = 0.0;
};

// Deterministic for a seed; independent of the thread count.
// `progress`: points measured over points.
FieldDiagnosis diagnose_field(const DiagnosisOptions& options, const FractionProgress& progress = {});

// CSV: a header line and one row.
std::string diagnosis_csv_header();
std::string diagnosis_csv_row(const FieldDiagnosis& diagnosis);

}  // namespace dfvn
