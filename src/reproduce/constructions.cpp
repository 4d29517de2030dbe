// The measurements of `reproduce constructions` (reproduce/constructions.hpp); constructions_files.cpp
// writes them.
#include "dfvn/reproduce/constructions.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "dfvn/core/hash.hpp"
#include "dfvn/core/machine.hpp"
#include "dfvn/core/parallel.hpp"
#include "dfvn/core/quantile.hpp"
#include "dfvn/core/stopwatch.hpp"
#include "dfvn/field/diagnose.hpp"
#include "dfvn/integrate/trace_table.hpp"
#include "dfvn/noise/noise_domain.hpp"

namespace dfvn {

namespace {

constexpr int kReferenceSteps = 2048;  // RK4, no reprojection: Table 2's reference
// Lanes of Stream::random_points: the accuracy starts, the escape starts and the speed points draw from
// disjoint lanes of the run's seed.
constexpr std::uint64_t kTraceLane = 0, kEscapeLane = 16, kSpeedLane = 32;
constexpr int kTimingPasses = 3;
constexpr std::size_t kTimingBlock = 250;

double evaluations_per_trace(const ConstructionVariant& v) {
  const double per_step = v.integrator == Integrator::rk4 ? 4.0 : 1.0;
  return v.steps * (per_step + (v.reprojection == Reprojection::none ? 0.0 : 1.5));
}

FieldOptions free_field(const ConstructionField& f, const ConstructionsConfig& config) {
  FieldOptions o;
  o.noise = f.noise;
  o.kind = f.kind;
  o.frequency = config.frequency;
  return o;
}

// The cube with Bridson's ramp on its faces and one sphere obstacle at the centre.
FieldOptions bounded_field(const ConstructionField& f, const ConstructionsConfig& config) {
  FieldOptions o = free_field(f, config);
  o.constraint = FieldConstraint::inside_cube;
  o.bound = Bound::ramp;
  o.transition_width = ConstructionsConfig::kBoundaryWidth;
  o.obstacles = {Obstacle{std::vector<double>(static_cast<std::size_t>(f.dimension), 0.5), ConstructionsConfig::kObstacleRadius}};
  return o;
}

template <int N>
Vec<N> random_point(std::uint64_t seed, std::uint64_t index, std::uint64_t lane, double extent) {
  Vec<N> x;
  for (int j = 0; j < N; ++j) x[j] = extent * random_unit(seed, Stream::random_points, index, lane + static_cast<std::uint64_t>(j));
  return x;
}

template <int N>
void measure_speed(const ConstructionsConfig& config, const DfvnField<N>& field, ConstructionField& out) {
  // The diagnosis's box: 1000 noise cycles per side, many independent regions.
  const double extent = DiagnosisOptions{}.periods / config.frequency;
  std::vector<Vec<N>> points(config.speed_points);
  for (std::uint64_t i = 0; i < config.speed_points; ++i) points[i] = random_point<N>(config.seed, i, kSpeedLane, extent);
  std::vector<double> speeds(points.size());
  // Blocks of kTimingBlock points, each timed kTimingPasses times, their fastest pass summed: the
  // machine's other load only ever adds time, and a short block is seldom interrupted in every pass.
  double seconds = 0.0;
  for (std::size_t begin = 0; begin < points.size(); begin += kTimingBlock) {
    const std::size_t end = std::min(points.size(), begin + kTimingBlock);
    double fastest = 0.0;
    for (int pass = 0; pass < kTimingPasses; ++pass) {
      Stopwatch stopwatch;
      for (std::size_t i = begin; i < end; ++i) speeds[i] = field.velocity(points[i]).norm();
      const double t = stopwatch.seconds();
      fastest = pass == 0 ? t : std::min(fastest, t);
    }
    seconds += fastest;
  }
  out.ns_per_evaluation = seconds * 1e9 / static_cast<double>(points.size());
  double sum = 0.0;
  for (double s : speeds) sum += s * s;
  out.speed_rms = std::sqrt(sum / static_cast<double>(speeds.size()));
  std::sort(speeds.begin(), speeds.end());
  out.speed_q01 = quantile_of_sorted(speeds, 0.01);
  out.speed_q10 = quantile_of_sorted(speeds, 0.10);
  out.speed_q50 = quantile_of_sorted(speeds, 0.50);
  out.speed_q90 = quantile_of_sorted(speeds, 0.90);
  out.speed_q99 = quantile_of_sorted(speeds, 0.99);
  const auto below = std::lower_bound(speeds.begin(), speeds.end(), 0.01 * out.speed_rms) - speeds.begin();
  out.fraction_below_1pct = static_cast<double>(below) / static_cast<double>(speeds.size());
}

template <int N>
TraceOptions trace_options(const ConstructionVariant& v) {
  TraceOptions t;
  t.integrator = v.integrator;
  t.steps = v.steps;
  t.reprojection = v.reprojection;
  return t;
}

template <int N>
TracedPoints trace_all(const DfvnField<N>& field, const TraceOptions& options, const std::vector<double>& starts,
                       std::vector<double>& ends, const ConstructionsConfig& config, const FractionProgress& progress) {
  ends.resize(starts.size());
  return trace_table<N>(field, options, starts.data(), starts.size() / N, ends.data(), config.trace_time,
                        [](const Vec<N>&) { return true; }, OnReject::drop, config.threads, progress);
}

template <int N>
void measure_field(const ConstructionsConfig& config, ConstructionField& f, const StageProgress& progress) {
  const std::string name = fmt::format("{}D {} {}", N, to_string(f.construction), to_string(f.noise));
  const auto stage = [&](const std::string& what) -> FractionProgress {
    if (!progress) return {};
    const std::string label = name + ": " + what;
    progress(label, 0.0);
    return [&progress, label](double fraction) { progress(label, fraction); };
  };
  const FieldOptions options = free_field(f, config);

  DiagnosisOptions diagnosis;
  diagnosis.dimension = N;
  diagnosis.field = options;
  diagnosis.seed = config.seed;
  diagnosis.points = config.divergence_points;
  diagnosis.threads = config.threads;
  const FieldDiagnosis d = diagnose_field(diagnosis, stage("divergence"));
  f.divergence_median = d.divergence_median;
  f.divergence_p95 = d.divergence_p95;
  f.divergence_max = d.divergence_max;
  f.still_points = d.still_points;

  const DfvnField<N> field(config.seed, options);
  if (progress) progress(name + ": speed", 0.0);
  measure_speed<N>(config, field, f);

  // Accuracy: the free field from uniform starts in [0,1]^N, against 2048 RK4 steps.
  std::vector<double> starts;
  for (std::uint64_t i = 0; i < config.trace_starts; ++i) {
    const Vec<N> x = random_point<N>(config.seed, i, kTraceLane, 1.0);
    starts.insert(starts.end(), x.data(), x.data() + N);
  }
  const FractionProgress accuracy = stage("accuracy");
  const std::vector<ConstructionVariant> variants = construction_variants(f.kind);
  double total_work = evaluations_per_trace({Integrator::rk4, kReferenceSteps, Reprojection::none}), work = 0.0;
  for (const auto& v : variants) total_work += evaluations_per_trace(v);
  const auto part = [&](double weight) -> FractionProgress {
    if (!accuracy) return {};
    const double before = work / total_work, share = weight / total_work;
    work += weight;
    return [&accuracy, before, share](double fraction) { accuracy(before + share * fraction); };
  };
  std::vector<double> reference, ends;
  const ConstructionVariant reference_variant{Integrator::rk4, kReferenceSteps, Reprojection::none};
  trace_all<N>(field, trace_options<N>(reference_variant), starts, reference, config, part(evaluations_per_trace(reference_variant)));
  for (const auto& v : variants) {
    ConstructionTraceRow row;
    row.variant = v;
    const TracedPoints traced = trace_all<N>(field, trace_options<N>(v), starts, ends, config, part(evaluations_per_trace(v)));
    double sum = 0.0;  // in index order: independent of the thread count
    for (std::size_t i = 0; i < ends.size(); ++i) sum += (ends[i] - reference[i]) * (ends[i] - reference[i]);
    row.endpoint_rmse = std::sqrt(sum / static_cast<double>(config.trace_starts));
    row.evaluations_per_trace =
        static_cast<double>(traced.stats.field_evaluations) / static_cast<double>(config.trace_starts);
    f.traces.push_back(row);
  }

  // Escapes: the bounded field from uniform starts in the cube outside the obstacle, one raw trace each
  // (no retracing: what a step does at the wall is what is counted).
  const FieldOptions bounded_options = bounded_field(f, config);
  const DfvnField<N> bounded(config.seed, bounded_options);
  starts.clear();
  for (std::uint64_t i = 0; starts.size() < config.escape_starts * N; ++i) {
    const Vec<N> x = random_point<N>(config.seed, i, kEscapeLane, 1.0);
    if (bounded.contains(x)) starts.insert(starts.end(), x.data(), x.data() + N);
  }
  const FractionProgress escape = stage("escapes");
  work = 0.0;
  total_work = 0.0;
  for (const auto& v : variants)
    if (v.steps == ConstructionsConfig::kEscapeSteps) total_work += evaluations_per_trace(v);
  const auto escape_part = [&](double weight) -> FractionProgress {
    if (!escape) return {};
    const double before = work / total_work, share = weight / total_work;
    work += weight;
    return [&escape, before, share](double fraction) { escape(before + share * fraction); };
  };
  for (auto& row : f.traces) {
    if (row.variant.steps != ConstructionsConfig::kEscapeSteps) continue;
    trace_all<N>(bounded, trace_options<N>(row.variant), starts, ends, config, escape_part(evaluations_per_trace(row.variant)));
    std::uint64_t out_of_cube = 0, in_obstacle = 0;
    for (std::size_t i = 0; i < ends.size(); i += N) {
      const Vec<N> x = Eigen::Map<const Vec<N>>(&ends[i]);
      out_of_cube += !satisfies_constraint<N>(FieldConstraint::inside_cube, x);
      in_obstacle += !outside_obstacles<N>(bounded_options.obstacles, x);
    }
    row.escape_cube = static_cast<double>(out_of_cube) / static_cast<double>(config.escape_starts);
    row.escape_obstacle = static_cast<double>(in_obstacle) / static_cast<double>(config.escape_starts);
  }
}

// Bridson's Figure 1: streamlines of 2D curl noise (the default basis) in the cube around the disc obstacle,
// from a grid of seeds, traced backward and forward with small RK4 steps until they meet a boundary.
std::vector<std::vector<std::array<double, 2>>> figure1_streamlines(const ConstructionsConfig& config) {
  ConstructionField f;
  f.dimension = 2;
  f.kind = FieldKind::curl;
  f.noise = kDefaultNoiseBasis;
  const DfvnField<2> field(config.seed, bounded_field(f, config));
  TraceOptions options;
  options.reprojection = Reprojection::none;
  const Tracer<2> tracer(field, options);
  constexpr int K = ConstructionsConfig::kFigureSeedsPerAxis;
  const double dt = ConstructionsConfig::kFigureLength / ConstructionsConfig::kFigureSteps;
  std::vector<std::vector<std::array<double, 2>>> lines;
  for (int a = 0; a < K; ++a)
    for (int b = 0; b < K; ++b) {
      const Vec<2> seed((a + 0.5) / K, (b + 0.5) / K);
      if (!field.contains(seed)) continue;
      std::vector<std::array<double, 2>> halves[2];
      for (int h = 0; h < 2; ++h) {
        Vec<2> x = seed;
        for (int s = 0; s < ConstructionsConfig::kFigureSteps; ++s) {
          const Vec<2> next = tracer.trace(x, h == 0 ? -dt : dt);
          if (!field.contains(next)) break;
          x = next;
          halves[h].push_back({x[0], x[1]});
        }
      }
      std::vector<std::array<double, 2>> line(halves[0].rbegin(), halves[0].rend());
      line.push_back({seed[0], seed[1]});
      line.insert(line.end(), halves[1].begin(), halves[1].end());
      lines.push_back(std::move(line));
    }
  return lines;
}

}  // namespace

std::string_view to_string(Construction construction) {
  switch (construction) {
    case Construction::curl: return "curl";
    case Construction::bitangent: return "bitangent";
    case Construction::dfvn: return "dfvn";
  }
  return "?";
}

void ConstructionsConfig::validate() const {
  if (!std::isfinite(frequency) || frequency < kMinNoiseFrequency || frequency > kMaxNoiseFrequency)
    throw std::invalid_argument(fmt::format("--frequency must be in [{:g}, {:g}] cycles per unit length, got {}",
                                            kMinNoiseFrequency, kMaxNoiseFrequency, frequency));
  if (!std::isfinite(trace_time) || !(trace_time > 0.0) || trace_time > 100.0)
    throw std::invalid_argument(fmt::format("--trace-time must be in (0, 100], got {}", trace_time));
  if (divergence_points < 100 || divergence_points > 100000000)
    throw std::invalid_argument(fmt::format("--divergence-points must be in [100, 1e8], got {}", divergence_points));
  if (speed_points < 100 || speed_points > 100000000)
    throw std::invalid_argument(fmt::format("--speed-points must be in [100, 1e8], got {}", speed_points));
  if (trace_starts < 1 || trace_starts > 10000000)
    throw std::invalid_argument(fmt::format("--trace-starts must be in [1, 1e7], got {}", trace_starts));
  if (escape_starts < 1 || escape_starts > 10000000)
    throw std::invalid_argument(fmt::format("--escape-starts must be in [1, 1e7], got {}", escape_starts));
  if (threads < 0) throw std::invalid_argument("--threads must be 0 (all cores) or positive");
}

std::vector<ConstructionVariant> construction_variants(FieldKind kind) {
  std::vector<ConstructionVariant> variants;
  for (Reprojection r : {Reprojection::none, Reprojection::gauss_newton}) {
    if (kind == FieldKind::curl && r != Reprojection::none) continue;  // curl noise has no reprojection
    for (int steps : {64, 512})
      for (Integrator integrator : {Integrator::euler, Integrator::rk4}) variants.push_back({integrator, steps, r});
  }
  return variants;
}

std::vector<ConstructionField> construction_fields() {
  std::vector<ConstructionField> fields;
  for (int n : {2, 3})
    for (FieldKind kind : {FieldKind::curl, FieldKind::dfvn})
      for (NoiseBasis noise : kAllNoiseBases) {
        ConstructionField f;
        f.dimension = n;
        f.kind = kind;
        f.noise = noise;
        const bool simplex = noise == NoiseBasis::simplex || noise == NoiseBasis::simplex_separate;
        f.construction = kind == FieldKind::curl ? Construction::curl
                         : (n == 3 && simplex)   ? Construction::bitangent
                                                 : Construction::dfvn;
        fields.push_back(f);
      }
  return fields;
}

std::vector<double> constructions_stage_weights(const ConstructionsConfig& config) {
  std::vector<double> weights;
  for (const ConstructionField& f : construction_fields()) {
    const double cost = f.dimension - 1.0;  // roughly: functions per evaluation
    weights.push_back(cost * static_cast<double>(config.divergence_points) * (2.0 * f.dimension + 1.0));
    weights.push_back(cost * kTimingPasses * static_cast<double>(config.speed_points));
    double trace = evaluations_per_trace({Integrator::rk4, kReferenceSteps, Reprojection::none}), escape = 0.0;
    for (const auto& v : construction_variants(f.kind)) {
      trace += evaluations_per_trace(v);
      if (v.steps == ConstructionsConfig::kEscapeSteps) escape += evaluations_per_trace(v);
    }
    weights.push_back(cost * static_cast<double>(config.trace_starts) * trace);
    weights.push_back(cost * static_cast<double>(config.escape_starts) * escape);
  }
  weights.push_back(4.0 * ConstructionsConfig::kFigureSteps * 2.0 * ConstructionsConfig::kFigureSeedsPerAxis *
                    ConstructionsConfig::kFigureSeedsPerAxis);
  return weights;
}

ConstructionsResult run_constructions(const ConstructionsConfig& config, const StageProgress& progress) {
  config.validate();
  ConstructionsResult result;
  result.config = config;
  result.threads = resolve_threads(config.threads);
  result.machine = machine_description();
  Stopwatch stopwatch;
  result.fields = construction_fields();
  for (ConstructionField& f : result.fields) {
    if (f.dimension == 2)
      measure_field<2>(config, f, progress);
    else
      measure_field<3>(config, f, progress);
  }
  if (progress) progress("figure 1: streamlines around a disc", 0.0);
  result.streamlines = figure1_streamlines(config);
  result.seconds = stopwatch.seconds();
  return result;
}

std::vector<ClaimCell> constructions_claim(const ConstructionsResult& result) {
  std::vector<ClaimCell> cells;
  for (const ConstructionField& cross : result.fields) {
    if (cross.kind != FieldKind::dfvn) continue;
    const ConstructionField* curl = nullptr;
    for (const ConstructionField& f : result.fields)
      if (f.kind == FieldKind::curl && f.dimension == cross.dimension && f.noise == cross.noise) curl = &f;
    if (!curl) continue;
    for (const ConstructionTraceRow& row : cross.traces) {
      if (row.variant.reprojection == Reprojection::none) continue;
      for (const ConstructionTraceRow& c : curl->traces)
        if (c.variant.integrator == row.variant.integrator && c.variant.steps == row.variant.steps)
          cells.push_back({cross.dimension, cross.noise, row.variant.integrator, row.variant.steps, row.endpoint_rmse,
                           c.endpoint_rmse});
    }
  }
  return cells;
}

}  // namespace dfvn
